#!/usr/bin/env bash
# Each bundled lens (assets/lenses) drawn in section with rays from the axis, 0.7 and the corner of
# the field, beside its distortion and relative illumination, into assets/report/lenses/NAME.svg for
# docs/lenses.md. A second or two.
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
echo "wrote $out/*.svg"
