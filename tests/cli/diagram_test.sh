#!/usr/bin/env bash
# `lenslab diagram`: the lecture's outside view of the camera as a headless picture. The window
# (white), the PRP (yellow) and the view volume are drawn for every camera; the aperture (cyan)
# only with one; the viewpoint options move the picture; bad options are refused in one line and
# leave no file.
# usage: diagram_test.sh path/to/lenslab path/to/lenslab_image_check source-dir
set -u
lenslab=$1
check_image=$2
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$lenslab" "$3"

# count IMG R G B: pixels of that display colour (within 2/255).
count() { "$check_image" count "$1" "$2" "$3" "$4" 0.008; }
at_least() { [ "$1" -ge "$2" ]; }

"$lenslab" diagram --width 320 -q --out "$work/pinhole.png"
check test -s "$work/pinhole.png"
check at_least "$(count "$work/pinhole.png" 1 1 1)" 50       # the window's outline
check at_least "$(count "$work/pinhole.png" 1 0.9 0.2)" 3    # the PRP's cross
check [ "$(count "$work/pinhole.png" 0.3 0.9 1)" -eq 0 ]     # no aperture on a pinhole

"$lenslab" diagram --camera "$src/assets/rows/camera-dof.json" --aperture-samples 5 --width 320 -q --out "$work/lens.png"
check at_least "$(count "$work/lens.png" 0.3 0.9 1)" 20      # the aperture's outline
check at_least "$(count "$work/lens.png" 1 0.25 0.25)" 20    # rays from the samples
"$lenslab" diagram --camera "$src/assets/rows/camera-dof.json" --aperture-samples 5 --width 320 --azimuth -60 \
  --elevation 10 --zoom 1.5 -q --out "$work/moved.png"
if "$check_image" psnr "$work/lens.png" "$work/moved.png" 30 >/dev/null; then fail "--azimuth/--elevation/--zoom changed nothing"; else pass; fi

# A size of its own; .exr too.
"$lenslab" diagram --width 200 --height 100 -q --out "$work/size.exr"
check grep -qE '200 x +100' <(oiiotool --info "$work/size.exr")

expect_refusal "--elevation 90" "--elevation: 90 is out of range" -- diagram --elevation 90 --out "$work/out.png"
expect_refusal "--aperture-scale 0.5" "--aperture-scale: 0.5 is out of range" \
  -- diagram --aperture-scale 0.5 --out "$work/out.png"
expect_refusal "--out .jpg" "unsupported image type '.jpg'" -- diagram --out "$work/out.jpg"

echo "diagram: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
