#!/usr/bin/env bash
# Two Khronos glTF sample models (DamagedHelmet, CC BY 4.0; Avocado, CC0) as lenslab shades them:
# under its default light and lit by the bundled studio environment, each image labelled with its
# options, into assets/report/materials/khronos.png for docs/materials.md. The models are not in
# this repository: fetch them with tools/fetch-gltf-corpus.sh (the default folder below) or give
# the folder that holds DamagedHelmet/ and Avocado/. About 30 s on two cores (the studio's
# prefiltering is cached after the first run).
# usage: tools/make-material-pictures.sh [build/lenslab] [SAMPLES_FOLDER]
set -euo pipefail
lenslab=$(realpath "${1:-build/lenslab}")
cd "$(dirname "$0")/.."
samples=${2:-build/gltf-corpus/samples}
for model in DamagedHelmet/glTF-Binary/DamagedHelmet.glb Avocado/glTF/Avocado.gltf; do
  [ -f "$samples/$model" ] || { echo "make-material-pictures: no $samples/$model (run tools/fetch-gltf-corpus.sh, or give the samples folder)" >&2; exit 1; }
done
out=assets/report/materials
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
render() {  # NAME MODEL [OPTIONS...]
  local name=$1 model=$2
  shift 2
  "$lenslab" render "$samples/$model" --width 480 --aperture-samples 16 --view-transform pbr-neutral --out "$work/$name.png" -q "$@"
}
studio=(--environment assets/environments/studio.hdr --environment-rotation 200)
render helmet-default DamagedHelmet/glTF-Binary/DamagedHelmet.glb
render helmet-studio DamagedHelmet/glTF-Binary/DamagedHelmet.glb "${studio[@]}"
render avocado-default Avocado/glTF/Avocado.gltf
render avocado-studio Avocado/glTF/Avocado.gltf "${studio[@]}"
/usr/bin/python3 - "$work" "$out" <<'PY'
import sys
from PIL import Image, ImageDraw
work, out = sys.argv[1], sys.argv[2]
cells = [("helmet-default", "DamagedHelmet: default light"), ("helmet-studio", "--environment studio.hdr --environment-rotation 200"),
         ("avocado-default", "Avocado: default light"), ("avocado-studio", "--environment studio.hdr --environment-rotation 200")]
tiles = []
for file, label in cells:
    im = Image.open(f"{work}/{file}.png").convert("RGB")
    ImageDraw.Draw(im).text((8, 6), label, fill=(255, 255, 255))
    tiles.append(im)
w, h = tiles[0].size
s = Image.new("RGB", (2 * w + 4, 2 * h + 4), (255, 255, 255))
for i, t in enumerate(tiles):
    s.paste(t, ((i % 2) * (w + 4), (i // 2) * (h + 4)))
s.save(f"{out}/khronos.png", optimize=True)
PY
ls -l "$out"
