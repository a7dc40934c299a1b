#!/usr/bin/env bash
# The README's pictures of the two bundled camera paths: every frame captured, then a contact sheet
# of eight (tools/contact_sheet.py; its --gif makes an animated one too, ~0.9 MB each, which the
# repository leaves out). About 15 s on two cores.
# usage: tools/make-capture-pictures.sh [build/lenslab]
set -euo pipefail
lenslab=${1:-build/lenslab}
cd "$(dirname "$0")/.."
out=assets/report/capture
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
for name in rack-focus dolly-zoom; do
  "$lenslab" capture --path "assets/rows/$name.json" --width 320 --target-psnr 35 --out "$work/$name/frame_%04d.png"
  /usr/bin/python3 tools/contact_sheet.py "$work/$name/manifest.jsonl" "$out/$name-sheet.png"
done
ls -l "$out"
