#!/usr/bin/env bash
# Regenerates the pictures that README.md and docs/ show from single lenslab runs:
#   assets/screenshots/view.png                 lenslab view under its own Xvfb (docs/viewer.md)
#   assets/screenshots/lecture-diagram.png      the outside view cut from it (docs/lecture-model.md)
#   assets/report/rows-lens/grid-lens.png       render, grid through camera-lens.json (docs/lens-effects.md)
#   assets/report/rows-lens/raster-and-raycast.png  render and raycast of rows through camera-lens.json,
#                                               side by side (docs/lens-effects.md)
# The other pictures come from their own scripts (see "Pictures" in docs/development.md):
# tools/update-goldens.sh (tests/golden/*.png), tools/make-capture-pictures.sh (assets/report/capture/)
# and `lenslab sweep` (assets/report/*/error_vs_time.png). Look at every changed picture before
# committing it. About 3 minutes on two busy cores, most of it the two lens pictures; the view
# needs Xvfb (tools/install-deps.sh).
# usage: tools/make-screenshots.sh [build/lenslab]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
lenslab=$(realpath "${1:-$top/build/lenslab}")
cd "$top"
work=$(mktemp -d)
xvfb_pid=""
cleanup() {
  if [ -n "$xvfb_pid" ]; then kill "$xvfb_pid" 2>/dev/null || true; wait "$xvfb_pid" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
mkdir -p assets/screenshots assets/report/rows-lens

# ---- the viewer, on an X server of its own (a display number Xvfb picks, as tests/view/view_test.sh) ----
command -v Xvfb >/dev/null || { echo "make-screenshots: Xvfb is not installed (bash tools/install-deps.sh)" >&2; exit 1; }
exec 5>"$work/display"
Xvfb -displayfd 5 -screen 0 1600x1000x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
exec 5>&-
for _ in $(seq 1 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || { echo "make-screenshots: Xvfb did not start: $(cat "$work/xvfb.log")" >&2; exit 1; }
export DISPLAY=":$(head -n1 "$work/display")"

# The f/1.4 camera at the viewer's default image width, run until its planned samples are done.
"$lenslab" view --camera assets/rows/camera-dof.json --width 640 --window-size 1280,800 \
  --frames 30 --screenshot "$work/view.png" --stats "$work/view.json"
cat "$work/view.json"; echo
oiiotool "$work/view.png" --ch R,G,B -d uint8 -o assets/screenshots/view.png
# The outside view with the lecture's diagram: its middle, where the 1280x800 layout puts it
# (image top left, outside view below it, 850x400 from y = 400; panel on the right).
oiiotool "$work/view.png" --ch R,G,B --cut 700x330+150+420 -d uint8 -o assets/screenshots/lecture-diagram.png

# ---- the lens pictures ----
"$lenslab" render assets/grid/grid.gltf --camera assets/grid/camera-lens.json \
  --out assets/report/rows-lens/grid-lens.png --quiet
"$lenslab" render --camera assets/rows/camera-lens.json --width 480 --aperture-samples 256 \
  --out "$work/raster.png" --stats "$work/raster.json" --quiet
"$lenslab" raycast --camera assets/rows/camera-lens.json --width 480 --spp 64 \
  --out "$work/raycast.png" --stats "$work/raycast.json" --quiet
oiiotool "$work/raster.png" "$work/raycast.png" --mosaic 2x1 -d uint8 -o assets/report/rows-lens/raster-and-raycast.png
for f in raster raycast; do
  printf '%s: %s s\n' "$f" "$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["seconds"])' "$work/$f.json")"
done

ls -l assets/screenshots/*.png assets/report/rows-lens/*.png
