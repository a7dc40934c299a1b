#!/usr/bin/env bash
# The lecture's lens effects from the command line: --distortion (or --fisheye), --lateral-color and
# --axial-color give the same image as the camera file's keys they stand for (render, raycast,
# capture), replace the camera's own effect, and are refused in one line when out of range, on a
# camera without a focal length (--axial-color), or where the distortion folds inside the image.
# usage: lens_effect_options_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"

# with_keys IN OUT PYTHON: a copy of camera file IN with the keys the Python dict literal gives.
with_keys() { $python -c "import json,sys; j=json.load(open(sys.argv[1])); j.update($3); json.dump(j, open(sys.argv[2], 'w'))" "$1" "$2"; }

rows=$src/assets/rows
small=(--width 66 --aperture-samples 4 -q)

# Each option against the camera file's key it stands for: the same pixels.
with_keys "$rows/camera.json" "$work/barrel.json" '{"distortion": {"k1": -0.25, "k2": 0.06, "k5": 0.01}}'
"$lenslab" render --camera "$rows/camera.json" --distortion -0.25,0.06,0,0,0,0,0.01 "${small[@]}" --out "$work/flag.exr"
"$lenslab" render --camera "$work/barrel.json" "${small[@]}" --out "$work/file.exr"
check same_pixels "$work/flag.exr" "$work/file.exr"
"$lenslab" render --camera "$rows/camera.json" "${small[@]}" --out "$work/plain.exr"
if same_pixels "$work/flag.exr" "$work/plain.exr"; then fail "--distortion changed nothing"; else pass; fi
"$lenslab" raycast --camera "$rows/camera.json" --distortion -0.25,0.06,0,0,0,0,0.01 --width 66 --spp 4 -q --out "$work/rflag.exr"
"$lenslab" raycast --camera "$work/barrel.json" --width 66 --spp 4 -q --out "$work/rfile.exr"
check same_pixels "$work/rflag.exr" "$work/rfile.exr"

# --fisheye: OpenCV's fisheye model, as the camera file's "model": "fisheye" gives it.
with_keys "$rows/camera.json" "$work/fisheye.json" '{"distortion": {"model": "fisheye", "k1": 0.02, "k2": -0.004}}'
"$lenslab" render --camera "$rows/camera.json" --fisheye 0.02,-0.004 "${small[@]}" --out "$work/flag.exr"
"$lenslab" render --camera "$work/fisheye.json" "${small[@]}" --out "$work/file.exr"
check same_pixels "$work/flag.exr" "$work/file.exr"
if same_pixels "$work/flag.exr" "$work/plain.exr"; then fail "--fisheye changed nothing"; else pass; fi

with_keys "$rows/camera.json" "$work/lateral.json" '{"chromatic": {"lateral_red": 0.004, "lateral_blue": -0.004}}'
"$lenslab" render --camera "$rows/camera.json" --lateral-color 0.004 "${small[@]}" --out "$work/flag.exr"
"$lenslab" render --camera "$work/lateral.json" "${small[@]}" --out "$work/file.exr"
check same_pixels "$work/flag.exr" "$work/file.exr"

with_keys "$rows/camera-dof.json" "$work/axial.json" '{"chromatic": {"abbe_number": 30}}'
"$lenslab" render --camera "$rows/camera-dof.json" --axial-color 30 "${small[@]}" --out "$work/flag.exr"
"$lenslab" render --camera "$work/axial.json" "${small[@]}" --out "$work/file.exr"
check same_pixels "$work/flag.exr" "$work/file.exr"

# The option replaces the camera's effect: the grid's calibrated barrel becomes a pincushion.
"$lenslab" render --camera "$src/assets/grid/camera-distortion.json" --distortion 0.1 --width 96 \
  --stats "$work/stats.json" -q --out "$work/grid.png"
"$lenslab" render --camera "$src/assets/grid/camera-distortion.json" --width 96 -q --out "$work/grid-own.png"
if same_pixels "$work/grid.png" "$work/grid-own.png"; then fail "--distortion kept the camera's own"; else pass; fi

# capture: every frame's camera file and manifest line carry it.
if "$lenslab" capture --path "$rows/dolly-zoom.json" --distortion -0.1,0,0,0,0,0.02 --lateral-color 0.002,-0.001 \
     --width 48 --aperture-samples 2 --frames 96 --out "$work/cap/f_%04d.png" -q 2>"$work/stderr" &&
   holds "$work/cap/f_0096.camera.json" 'close(j["distortion"], [-0.1, 0, 0, 0, 0, 0.02, 0, 0]) and close(j["chromatic"]["lateral_blue"], -0.001)' &&
   holds "$work/cap/manifest.jsonl" 'len(j["opencv"]["dist"]) == 8 and close(j["opencv"]["dist"][5], 0.02)'; then pass
else fail "capture --distortion --lateral-color: $(cat "$work/stderr"; ls "$work/cap" 2>&1)"; fi

# Refusals, one line each, nothing written.
expect_refusal "--axial-color on the lecture form" "--axial-color 30: an Abbe number needs the lens's focal length" \
  -- render --camera "$src/assets/grid/camera.json" --axial-color 30 --width 32 --out "$work/out.png"
expect_refusal "--distortion that folds" "with --distortion -0.9: distortion folds over inside the image" \
  -- render --camera "$src/assets/grid/camera.json" --distortion -0.9 --width 32 --out "$work/out.png"
expect_refusal "--distortion nan" "--distortion: nan is not a finite number" \
  -- render --distortion nan --width 32 --out "$work/out.png"
expect_refusal "--distortion 13 numbers" "--distortion: 13 numbers; give 1 to 12" \
  -- render --distortion 0,0,0,0,0,0,0,0,0,0,0,0,0 --width 32 --out "$work/out.png"
expect_refusal "--fisheye 5 numbers" "--fisheye: 5 numbers; give 1 to 4" \
  -- render --fisheye 0,0,0,0,0 --width 32 --out "$work/out.png"
expect_refusal "--fisheye with --distortion" "--distortion excludes --fisheye" \
  -- render --fisheye 0 --distortion 0.1 --width 32 --out "$work/out.png"
expect_refusal "--lateral-color 0.6" "--lateral-color: 0.6 is out of range; give a finite value from -0.49 to 0.49" \
  -- render --lateral-color 0.6 --width 32 --out "$work/out.png"
expect_refusal "--axial-color 0" "--axial-color: 0 is out of range" \
  -- render --axial-color 0 --width 32 --out "$work/out.png"

echo "lens effect options: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
