#!/usr/bin/env bash
# Regenerates docs/stability.md's "Numerical stability" table from lenslab_stability (every row, the slow
# ones included), so that the table is the program's output and nothing typed by hand.
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
readme = open("docs/stability.md").read()
begin, end = "<!-- stability-table:begin -->", "<!-- stability-table:end -->"
a, b = readme.index(begin), readme.index(end)
open("docs/stability.md", "w").write(readme[:a + len(begin)] + "\n" + table + readme[b:])
PY
echo "update-stability-table: docs/stability.md updated (lenslab_stability exit status $status)"
exit "$status"
