#!/usr/bin/env bash
# Each bundled lens (assets/lenses/*.lens) on each lens scene (assets/lens-scenes/: checker,
# street), rendered twice from the scene's camera.json: exactly (`raycast --lens`, every ray traced
# through every surface) and by the real-time camera fitted to the prescription (`render --lens`),
# put side by side, labelled, into assets/report/lenses/compare-SCENE-LENS.png, with the PSNR of
# each pair printed (8-bit sRGB pixels, peak 1, over RGB, as lenslab's own comparisons measure it).
#
# usage: tools/make-lens-comparison.sh [BUILD_DIR]      (default: build; runs build/lenslab)
#   SPP=64 WIDTH=480 APERTURE_SAMPLES=64 override the defaults below.
#
# With a build whose `render` takes no --lens, the fitted half is a grey panel saying so, the exact
# half is still made, and the script says so on stderr and exits 0. Where no thin lens fits (the
# fisheye's image circle inside a 36 x 24 mm sensor), `render --lens` traces the lens, and the label
# says so.
#
# Time: `time tools/make-lens-comparison.sh build`: real 1m04s, user 1m55s on the two-core
# development machine (8 ray casts at 480 x 320 and 64 samples per pixel, 8 `render --lens`).
#
# The panels are assembled and labelled with Pillow (/usr/bin/python3, python3-pil): oiiotool is
# installed here, but its --text needs a font file that a bare install does not have.
set -euo pipefail
build=$(realpath "${1:-build}")
lenslab="$build/lenslab"
[ -x "$lenslab" ] || { echo "make-lens-comparison: $lenslab is not an executable (give the build folder)" >&2; exit 1; }
cd "$(dirname "$0")/.."
spp=${SPP:-64}
width=${WIDTH:-480}
aperture_samples=${APERTURE_SAMPLES:-64}
out=assets/report/lenses
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fitted=yes
render_help=$("$lenslab" render --help)  # not piped into grep -q: pipefail and SIGPIPE would say "absent"
if ! grep -qE -- '^ *--lens\b' <<<"$render_help"; then
  fitted=no
  echo "make-lens-comparison: '$lenslab render' has no --lens option in this build: the fitted halves are placeholders" >&2
fi

pairs=()
for scene in checker street; do
  for lens_file in assets/lenses/*.lens; do
    lens=$(basename "$lens_file" .lens)
    scene_args=("assets/lens-scenes/$scene/$scene.gltf" --camera "assets/lens-scenes/$scene/camera.json"
                --lens "$lens_file" --width "$width" -q)
    # The telephoto's 9.9° field meets the street's lamps only from about 21 m on, where a focus
    # on the lantern at 0.8 m would blur each into a disc half the frame wide: it focuses at 20 m.
    note=""
    if [ "$scene/$lens" = street/telephoto-250mm ]; then
      scene_args+=(--focus-distance 20)
      note=", focus 20 m"
    fi
    "$lenslab" raycast "${scene_args[@]}" --spp "$spp" --out "$work/$scene-$lens-exact.png"
    if [ "$fitted" = yes ]; then
      "$lenslab" render "${scene_args[@]}" --aperture-samples "$aperture_samples" --out "$work/$scene-$lens-fitted.png" \
        --stats "$work/$scene-$lens-fitted.json"
    fi
    pairs+=("$scene/$lens/$note")
  done
done

/usr/bin/python3 - "$work" "$out" "$spp" "$aperture_samples" "${pairs[@]}" <<'PY'
import json
import math
import os
import sys
from PIL import Image, ImageChops, ImageDraw, ImageStat

work, out, spp, views, pairs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]
LABEL_PX = 16


def psnr_db(a, b):
    """10 log10(1 / mse) over the R, G and B values in [0, 1]: ImageCompare.h's psnrDb of the
    display-encoded images."""
    rms = ImageStat.Stat(ImageChops.difference(a, b)).rms  # per band, in 0..255
    mse = sum(r * r for r in rms) / len(rms) / (255.0 * 255.0)
    return math.inf if mse == 0 else 10.0 * math.log10(1.0 / mse)


for pair in pairs:
    scene, lens, note = pair.split("/")
    exact = Image.open(f"{work}/{scene}-{lens}-exact.png").convert("RGB")
    w, h = exact.size
    fitted_path = f"{work}/{scene}-{lens}-fitted.png"
    if os.path.exists(fitted_path):
        fitted = Image.open(fitted_path).convert("RGB")
        db = psnr_db(exact, fitted)
        # Where no thin lens fits (the fisheye's circle on this sensor), render --lens traces the lens.
        traced = json.load(open(f"{work}/{scene}-{lens}-fitted.json"))["renderer"].startswith("lenslab ray caster")
        if traced:
            fitted_label = "render --lens: no thin lens fits, so it traced the lens exactly"
            print(f"{scene:8s} {lens:20s} no fit: render --lens traced it exactly")
        else:
            fitted_label = f"fitted: render --lens, {views} views; PSNR {db:.1f} dB"
            print(f"{scene:8s} {lens:20s} PSNR {db:6.2f} dB")
    else:
        fitted = Image.new("RGB", (w, h), (96, 96, 96))
        ImageDraw.Draw(fitted).text((12, h // 2 - 6), "render --lens: not in this build yet", fill="white")
        fitted_label = "fitted: render --lens (not available)"
        print(f"{scene:8s} {lens:20s} PSNR n/a (no render --lens)")
    sheet = Image.new("RGB", (2 * w + 4, h + LABEL_PX), "white")
    draw = ImageDraw.Draw(sheet)
    draw.text((3, 2), f"{lens}.lens{note}, exact: raycast --lens, {spp} spp", fill="black")
    draw.text((w + 7, 2), fitted_label, fill="black")
    sheet.paste(exact, (0, LABEL_PX))
    sheet.paste(fitted, (w + 4, LABEL_PX))
    # 256 colours, no dithering, to keep each file near 100 KB instead of 300 KB: the ray-cast
    # checker holds fewer than 256 colours anyway (nothing changes), the street's double Gauss
    # about 430 (63.6 dB, at most 13/255 off). The PSNR printed above is of the full images.
    sheet.quantize(256, dither=Image.Dither.NONE).save(f"{out}/compare-{scene}-{lens}.png", optimize=True)
PY
echo "wrote $out/compare-{checker,street}-*.png"
