#!/usr/bin/env bash
# Each bundled lens (assets/lenses) drawn in section with rays from the axis, 0.7 and the corner of
# the field, beside its distortion and relative illumination, into assets/report/lenses/NAME.svg for
# docs/lenses.md; and the bundled rows scene ray cast through each (raycast --lens, from the
# same place) into assets/report/lenses/rows-through-lenses.png. About a minute on two cores.
# (f/5.6, which every bundled lens can stop down to.)
# usage: tools/make-lens-pictures.sh [build/lenslab]
set -euo pipefail
lenslab=$(realpath "${1:-build/lenslab}")
cd "$(dirname "$0")/.."
out=assets/report/lenses
mkdir -p "$out"
for lens in double-gauss-50mm telephoto-250mm wide-angle-28mm; do
  "$lenslab" lens "assets/lenses/$lens.lens" --plot "$out/$lens.svg" >/dev/null
done
# The fisheye's image circle is 31.5 mm across: a square sensor inside it.
"$lenslab" lens assets/lenses/fisheye-10mm.lens --sensor 18x18 --plot "$out/fisheye-10mm.svg" >/dev/null
# The rows scene through each lens, from camera-dof.json's place, f/5.6, focused on its target
# (5.02 m); the telephoto's narrow view passes over the target to the floor 7 to 25 m away, so it
# focuses at 12 m. 2 x 2, labelled.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for lens in double-gauss-50mm telephoto-250mm wide-angle-28mm fisheye-10mm; do
  focus=5.02
  [ "$lens" = telephoto-250mm ] && focus=12
  "$lenslab" raycast --camera assets/rows/camera-dof.json --lens "assets/lenses/$lens.lens" --f-number 5.6 --focus-distance $focus --width 318 --spp 64 \
    --out "$work/$lens.png" -q
done
/usr/bin/python3 - "$work" "$out/rows-through-lenses.png" <<'PY'
import sys
from PIL import Image, ImageDraw
work, out = sys.argv[1], sys.argv[2]
names = ["double-gauss-50mm", "telephoto-250mm", "wide-angle-28mm", "fisheye-10mm"]
tiles = [Image.open(f"{work}/{n}.png").convert("RGB") for n in names]
w, h = tiles[0].size
sheet = Image.new("RGB", (2 * w + 6, 2 * (h + 18) + 6), "white")
draw = ImageDraw.Draw(sheet)
for i, (name, tile) in enumerate(zip(names, tiles)):
    x, y = (i % 2) * (w + 6), (i // 2) * (h + 24)
    draw.text((x + 2, y + 2), f"{name}.lens, f/5.6, focus {'12' if 'telephoto' in name else '5.02'} m", fill="black")
    sheet.paste(tile, (x, y + 16))
sheet.save(out)
PY
echo "wrote $out/*.svg and $out/rows-through-lenses.png"
