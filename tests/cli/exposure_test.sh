#!/usr/bin/env bash
# Exposure and view transforms as a user meets them (docs/exposure.md): --exposure, --shutter,
# --iso and --view-transform on render, raycast and capture; camera files' shutter_s and iso; the
# default PNG unchanged; the EXR never exposed; --stats and the manifest recording them; bad values
# refused in one line with no file written.
# usage: exposure_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"
dof=$src/assets/rows/camera-dof.json  # physical, f/1.4

refused_outputs='out*'  # the refusals' outputs include folders named out

# --- refusals: one line naming the option or field, no file ---
for command in render raycast; do
  expect_refusal "$command --shutter 0" "--shutter: 0 is out of range" -- $command --camera "$dof" --shutter 0 --width 48 --out "$work/out.png"
  expect_refusal "$command --shutter 1/0" "--shutter: 1/0 is not a shutter time" -- $command --camera "$dof" --shutter 1/0 --width 48 --out "$work/out.png"
  expect_refusal "$command --iso 0" "--iso: 0 is out of range" -- $command --camera "$dof" --shutter 1/100 --iso 0 --width 48 --out "$work/out.png"
  expect_refusal "$command --iso alone" "--iso: an ISO exposes the image only with a shutter time" -- $command --camera "$dof" --iso 400 --width 48 --out "$work/out.png"
  expect_refusal "$command --exposure with --shutter" "--exposure excludes --shutter" -- $command --camera "$dof" --exposure 1 --shutter 1/100 --width 48 --out "$work/out.png"
  expect_refusal "$command --exposure nan" "--exposure: nan is not a finite number of stops" -- $command --exposure nan --width 48 --out "$work/out.png"
  expect_refusal "$command --view-transform agx" "--view-transform: agx not in {none,pbr-neutral}" -- $command --view-transform agx --width 48 --out "$work/out.png"
  expect_refusal "$command --shutter on a pinhole" "is a pinhole: give --f-number N" -- $command --shutter 1/100 --width 48 --out "$work/out.png"
  expect_refusal "$command --shutter and --stats" "--shutter: 0 is out of range" -- $command --camera "$dof" --shutter 0 --width 48 --out "$work/out.png" --stats "$work/out.json"
done
expect_refusal "capture --shutter on frames" "--iso: an ISO exposes" -- capture --path "$src/assets/rows/rack-focus.json" --iso 200 --frames 0:1 --width 32 --out "$work/out/frame_%04d.png"
for field in 'shutter_s": -1|"shutter_s": -1 is out of range' 'iso": 1e9|"iso": 1e+09 is out of range' 'iso": "fast"|"iso" must be a number'; do
  $python -c 'import json,sys; c=json.load(open(sys.argv[1])); k,v=sys.argv[3].split("\": "); c[k]=json.loads(v); json.dump(c,open(sys.argv[2],"w"))' \
    "$dof" "$work/cam.json" "${field%%|*}"
  expect_refusal "camera file ${field%%|*}" "cam.json: ${field#*|}" -- render --camera "$work/cam.json" --width 48 --out "$work/out.png"
done

# --- the default PNG is what it was; --exposure 0 is the default; the EXR is never exposed ---
"$lenslab" render --camera "$dof" --width 96 -q --out "$work/default.png" 2>/dev/null
"$lenslab" render --camera "$dof" --width 96 -q --out "$work/zero.png" --exposure 0 --view-transform none 2>/dev/null
check cmp -s "$work/default.png" "$work/zero.png"
"$lenslab" render --camera "$dof" --width 96 -q --out "$work/plain.exr" 2>/dev/null
"$lenslab" render --camera "$dof" --width 96 -q --out "$work/exposed.exr" --exposure 3 --view-transform pbr-neutral 2>/dev/null
check same_pixels "$work/plain.exr" "$work/exposed.exr"
# +3 EV through pbr-neutral differs from the default PNG (and from +3 EV clipped).
"$lenslab" render --camera "$dof" --width 96 -q --out "$work/plus3.png" --exposure 3 2>/dev/null
"$lenslab" render --camera "$dof" --width 96 -q --out "$work/plus3-neutral.png" --exposure 3 --view-transform pbr-neutral 2>/dev/null
if ! cmp -s "$work/default.png" "$work/plus3.png" && ! cmp -s "$work/plus3.png" "$work/plus3-neutral.png"; then pass; else fail "exposure or view transform changed nothing"; fi

# A tiled render exposes each tile as the whole image is exposed: the same PNG, within the one
# code value that tiling alone gives a few pixels (their sums add in another order). Two views: with
# more, an edge that one view's tile rasterizes on the other side of a pixel centre moves that
# pixel by 1/N of the contrast, which is tiling's, not exposure's.
"$lenslab" render --camera "$dof" --width 96 --aperture-samples 2 -q --out "$work/whole.png" --exposure 1 --view-transform pbr-neutral 2>/dev/null
"$lenslab" render --camera "$dof" --width 96 --aperture-samples 2 -q --out "$work/tiled.png" --exposure 1 --view-transform pbr-neutral --tile-size 32 --stats "$work/tiled.json" 2>/dev/null
check holds "$work/tiled.json" 'any(p["name"] == "tiles" for p in j["plan"]["passes"])'
check idiff -fail 0.004 -warn 0.004 -q "$work/whole.png" "$work/tiled.png"

# --- --stats records them ---
"$lenslab" render --camera "$dof" --width 48 -q --out "$work/s.png" --exposure -1.5 --view-transform pbr-neutral --stats "$work/s.json" 2>/dev/null
check holds "$work/s.json" 'j["display"]["exposure_stops"] == -1.5 and abs(j["display"]["exposure_scale"] - 2**-1.5) < 1e-12 and j["display"]["view_transform"] == "pbr-neutral" and j["display"]["exposure_source"] == "--exposure"'
"$lenslab" raycast --camera "$dof" --width 32 --spp 1 -q --out "$work/r.png" --shutter 1/4 --iso 3200 --stats "$work/r.json" 2>/dev/null
check holds "$work/r.json" 'abs(j["display"]["ev100"] - (math.log2(1.4**2 / 0.25) - math.log2(32))) < 1e-9 and j["display"]["shutter_s"] == 0.25 and j["display"]["iso"] == 3200 and j["display"]["exposure_source"] == "physical"'
# From the camera file; --exposure wins over it.
$python -c 'import json,sys; c=json.load(open(sys.argv[1])); c["shutter_s"]=0.01; c["iso"]=400; json.dump(c,open(sys.argv[2],"w"))' "$dof" "$work/cam.json"
"$lenslab" render --camera "$work/cam.json" --width 48 -q --out "$work/f.png" --stats "$work/f.json" 2>/dev/null
check holds "$work/f.json" 'abs(j["display"]["ev100"] - (math.log2(1.4**2 / 0.01) - 2)) < 1e-9 and abs(j["display"]["exposure_scale"] - 1 / (1.2 * 2**j["display"]["ev100"])) < 1e-12'
"$lenslab" render --camera "$work/cam.json" --width 48 -q --out "$work/g.png" --exposure 2 --stats "$work/g.json" 2>/dev/null
check holds "$work/g.json" 'j["display"]["exposure_source"] == "--exposure" and "ev100" not in j["display"]'
"$lenslab" render --width 48 -q --out "$work/d.png" --stats "$work/d.json" 2>/dev/null
check holds "$work/d.json" 'j["display"]["exposure_stops"] == 0 and j["display"]["view_transform"] == "none" and j["display"]["exposure_source"] == "none"'

# --- capture: the manifest says how the PNG frames were shown ---
"$lenslab" capture --path "$src/assets/rows/rack-focus.json" --frames 0:1 --width 32 --aperture-samples 2 -q \
  --exposure 1 --view-transform pbr-neutral --out "$work/cap/frame_%04d.png" 2>/dev/null
check $python -c 'import json,sys; l=[json.loads(x) for x in open(sys.argv[1])]; sys.exit(0 if l and all(x["display"]["view_transform"]=="pbr-neutral" and x["display"]["exposure_stops"]==1 for x in l) else 1)' "$work/cap/manifest.jsonl"

echo "exposure: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
