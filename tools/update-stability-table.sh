#!/usr/bin/env bash
# Regenerates docs/stability.md's numerical-stability table from lenslab_stability (every row, the
# slow ones included), so that the table is the program's output and nothing typed by hand. The
# ctest entry `stability` then checks the page against each run (lenslab_stability --check-doc:
# rows by their case and bound, figures within the tolerances of tests/stability/TableCheck.h).
# usage: tools/update-stability-table.sh [build-dir]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake --build "$build" --target lenslab_stability
table=$(mktemp)
trap 'rm -f "$table"' EXIT
# The rows may fail their bounds; the table then says so ("(fails)") and the exit status is kept.
status=0
"$build/tests/lenslab_stability" --long --markdown "$table" || status=$?
python3 - "$table" <<'PY'
import sys
table = open(sys.argv[1]).read()
doc = open("docs/stability.md").read()
begin, end = "<!-- stability-table:begin -->", "<!-- stability-table:end -->"
a, b = doc.index(begin), doc.index(end)
open("docs/stability.md", "w").write(doc[:a + len(begin)] + "\n" + table + doc[b:])
PY
echo "update-stability-table: docs/stability.md updated (lenslab_stability exit status $status)"
exit "$status"
