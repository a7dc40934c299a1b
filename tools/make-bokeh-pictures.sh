#!/usr/bin/env bash
# The aperture's shape where it shows: the bundled `bokeh` scene (lamps 5 to 30 m behind a box and
# three spheres in focus at 2 m, lit by its spot light, its sun and the bundled studio environment)
# through a round aperture, six blades, a 2x anamorphic squeeze and a lens barrel (cat's eye), and
# at f/8 beside f/1.4; each image cropped to the lamps and labelled with its command's options.
# About a minute on two cores.
# usage: tools/make-bokeh-pictures.sh [build/lenslab]
set -euo pipefail
lenslab=${1:-build/lenslab}
cd "$(dirname "$0")/.."
out=assets/report/bokeh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
render() {  # NAME CAMERA [OPTIONS...]
  local name=$1 camera=$2
  shift 2
  "$lenslab" render assets/bokeh/bokeh.gltf --camera "assets/bokeh/$camera" --width 720 --aperture-samples 256 \
    --environment assets/environments/studio.hdr --environment-intensity 0.4 \
    --view-transform pbr-neutral --out "$work/$name.png" -q "$@"
}
render round camera.json
render blades camera-blades.json
render anamorphic camera-anamorphic.json
render cats-eye camera-cats-eye.json
render f8 camera.json --f-number 8
/usr/bin/python3 - "$work" "$out" <<'PY'
import sys
from PIL import Image, ImageDraw
work, out = sys.argv[1], sys.argv[2]
def sheet(cells, name, crop):
    tiles = []
    for file, label in cells:
        im = Image.open(f"{work}/{file}.png").convert("RGB").crop(crop)
        ImageDraw.Draw(im).text((8, 6), label, fill=(255, 255, 255))
        tiles.append(im)
    w, h = tiles[0].size
    columns = 2
    rows = (len(tiles) + columns - 1) // columns
    s = Image.new("RGB", (columns * w + (columns - 1) * 4, rows * h + (rows - 1) * 4), (255, 255, 255))
    for i, t in enumerate(tiles):
        s.paste(t, ((i % columns) * (w + 4), (i // columns) * (h + 4)))
    s.save(f"{out}/{name}.png", optimize=True)
sheet([("round", "camera.json: round, f/1.4"), ("blades", "camera-blades.json: 6 blades, rotated 15 deg"),
       ("anamorphic", "camera-anamorphic.json: anamorphic squeeze 2"), ("cats-eye", "camera-cats-eye.json: lens barrel (cat's eye)")],
      "shapes", (60, 0, 660, 230))
sheet([("round", "f/1.4"), ("f8", "--f-number 8")], "f-numbers", (0, 0, 720, 480))
PY
ls -l "$out"
