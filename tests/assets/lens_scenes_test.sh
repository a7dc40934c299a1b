#!/usr/bin/env bash
# The committed lens scenes (assets/lens-scenes/) are exactly what tools/make_lens_scenes.py
# writes: it runs into a temporary folder and every file must match byte for byte, with none
# missing and none extra, so that the scenes and their generator cannot drift apart.
# usage: lens_scenes_test.sh SOURCE_DIR
set -euo pipefail
src=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp" "$tmp.diff"' EXIT
python3 "$src/tools/make_lens_scenes.py" "$tmp"
if ! diff -r "$src/assets/lens-scenes" "$tmp" >"$tmp.diff" 2>&1; then
  head -20 "$tmp.diff"
  echo "FAIL: assets/lens-scenes/ differs from what tools/make_lens_scenes.py writes;" \
       "regenerate with: /usr/bin/python3 tools/make_lens_scenes.py" >&2
  exit 1
fi
echo "assets/lens-scenes/ matches tools/make_lens_scenes.py"
