#!/usr/bin/env bash
# Exposure and view transforms as a user meets them (docs/exposure.md): --exposure, --shutter,
# --iso and --view-transform on render, raycast and capture; camera files' shutter_s and iso; the
# default PNG unchanged; the EXR never exposed; --stats and the manifest recording them; bad values
# refused in one line with no file written; --exposure auto's meter, held over a capture, and the
# warning for a physical exposure far from it.
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

# --- --exposure auto: the frame's meter (camera/Metering.h) ---
studio=$src/assets/environments/studio.hdr
for command in render raycast; do
  expect_refusal "$command --exposure auto with --shutter" "--exposure excludes --shutter" -- $command --camera "$dof" --exposure auto --shutter 1/30 --width 48 --out "$work/out.png"
  expect_refusal "$command --exposure bright" "--exposure: bright is not a number of stops; give a finite value from -64 to 64, or auto" -- $command --exposure bright --width 48 --out "$work/out.png"
done
expect_refusal "render --exposure auto in tiles" "no whole frame is there to meter" -- render --exposure auto --tile-size 32 --width 96 --out "$work/out.png"
expect_refusal "view --exposure auto" "--exposure auto: view takes --exposure EV" -- view --exposure auto --frames 1 --no-ui --screenshot "$work/out.png"
# A scene under twice the light meters one stop up, and auto shows both alike: rows with its unlit
# materials lit, so that the environment is all its light.
mkdir -p "$work/lit" && cp "$src"/assets/rows/*.bin "$src"/assets/rows/*.png "$work/lit/"
$python -c 'import json,sys; g=json.load(open(sys.argv[1])); [m.pop("extensions", None) for m in g["materials"]]; g.pop("extensionsUsed", None); json.dump(g,open(sys.argv[2],"w"))' \
  "$src/assets/rows/rows.gltf" "$work/lit/rows.gltf"
lit=("$work/lit/rows.gltf" --camera "$src/assets/rows/camera.json" --environment "$studio" --width 64 -q --exposure auto)
"$lenslab" render "${lit[@]}" --out "$work/once.png" --stats "$work/once.json" 2>/dev/null
"$lenslab" render "${lit[@]}" --environment-intensity 2 --out "$work/twice.png" --stats "$work/twice.json" 2>/dev/null
check $python -c 'import json,sys; a,b=(json.load(open(f))["display"] for f in sys.argv[1:]); sys.exit(0 if abs(b["metered_ev100"]-a["metered_ev100"]-1) < 0.05 else 1)' "$work/once.json" "$work/twice.json"
check holds "$work/once.json" 'j["display"]["exposure_source"] == "--exposure auto" and abs(j["display"]["used_ev100"] - j["display"]["metered_ev100"]) < 1e-9 and abs(j["display"]["exposure_scale"] - 1 / (1.2 * 2**j["display"]["metered_ev100"])) < 1e-12'
check idiff -fail 0.004 -warn 0.004 -q "$work/once.png" "$work/twice.png"
"$lenslab" raycast --camera "$dof" --width 32 --spp 1 -q --exposure auto --out "$work/ra.png" --stats "$work/ra.json" 2>/dev/null
check holds "$work/ra.json" 'abs(j["display"]["used_ev100"] - j["display"]["metered_ev100"]) < 1e-9 and "centre-weighted" in j["display"]["metering"]'
# --stats meters any run; auto wins over the camera file's shutter_s and iso, whose EV100 is reported.
check holds "$work/d.json" 'abs(j["display"]["used_ev100"] + math.log2(1.2)) < 1e-12 and j["display"]["metered_ev100"] > -5'
"$lenslab" render --camera "$work/cam.json" --width 48 -q --out "$work/fa.png" --exposure auto --stats "$work/fa.json" 2>/dev/null
check holds "$work/fa.json" 'j["display"]["exposure_source"] == "--exposure auto" and abs(j["display"]["camera_ev100"] - (math.log2(1.4**2 / 0.01) - 2)) < 1e-9'
# A black frame (from under the floor, looking down at a black background): one warning, 0 stops,
# no NaN.
"$lenslab" render --camera "$dof" --eye 0,-50,0 --target 0,-100,-1 --background 0,0,0 --width 48 -q --exposure auto --out "$work/black.png" --stats "$work/black.json" 2>"$work/black.err"
check grep -q "lenslab: warning: --exposure auto: no pixel of the frame holds light to meter" "$work/black.err"
check holds "$work/black.json" 'j["display"]["metered_ev100"] is None and j["display"]["exposure_stops"] == 0 and j["display"]["exposure_scale"] == 1'
# The user's story: f/2, 1/30 s, ISO 800 in the bundled studio scene, through pbr-neutral as the
# README shows it, puts the frame's metered average nearly black; one warning names the reading and
# what would meet it. Through none the same average shows at a code over 32: no warning.
bokeh=("$src/assets/bokeh/bokeh.gltf" --camera "$src/assets/bokeh/camera.json" --environment "$studio" --width 64 -q)
"$lenslab" render "${bokeh[@]}" --f-number 2 --shutter 1/30 --iso 800 --view-transform pbr-neutral \
  --out "$work/dark.png" --stats "$work/dark.json" 2>"$work/dark.err"
check test "$(grep -c "^lenslab: warning: f/2, 1/30 s, ISO 800: EV100 3.91, scale 0.0556 is .* stops under the frame's metered EV100 .*: its metered average shows at .* of 255 (nearly black) through pbr-neutral; give --exposure auto, or --shutter .* (at ISO 800), or --iso .* (at 1/30 s)$" "$work/dark.err")" -eq 1
check holds "$work/dark.json" 'j["display"]["used_ev100"] - j["display"]["metered_ev100"] > 1 and abs(j["display"]["used_ev100"] - j["display"]["ev100"]) < 1e-9'
"$lenslab" render "${bokeh[@]}" --f-number 2 --shutter 1/30 --iso 800 --out "$work/dim.png" 2>"$work/dim.err"
check test "$(grep -c 'metered EV100' "$work/dim.err")" -eq 0
"$lenslab" render "${bokeh[@]}" --f-number 2 --shutter 1/30 --iso 800 --out "$work/dim.exr" --view-transform pbr-neutral 2>"$work/dim.err"
check test "$(grep -c 'metered EV100' "$work/dim.err")" -eq 0  # an EXR is not exposed
"$lenslab" render --camera "$dof" --shutter 1 --iso 3200 --width 48 -q --out "$work/bright.png" 2>"$work/bright.err"
check grep -q "stops over the frame's metered EV100 .* (nearly white) through none; give --exposure auto" "$work/bright.err"
# A physical exposure at the meter's reading: no warning.
"$lenslab" render "${bokeh[@]}" --f-number 2 --view-transform pbr-neutral --out "$work/met.png" 2>"$work/met.err" \
  --shutter "$($python -c 'import json,sys; print(4 / 2**json.load(open(sys.argv[1]))["display"]["metered_ev100"])' "$work/dark.json")"
check test "$(grep -c 'metered EV100' "$work/met.err")" -eq 0
# capture holds the range's first frame's exposure; each line records its frame's own reading;
# another shard of the range holds the same.
"$lenslab" capture --path "$src/assets/rows/rack-focus.json" --frames 0:3 --width 32 --aperture-samples 2 -q \
  --exposure auto --out "$work/auto/frame_%04d.png" 2>/dev/null
check $python -c 'import json,sys; l=[json.loads(x)["display"] for x in open(sys.argv[1])]; sys.exit(0 if len(l) == 4 and all(x["exposure_stops"] == l[0]["exposure_stops"] and x["metered_ev100"] is not None for x in l) and abs(l[0]["used_ev100"] - l[0]["metered_ev100"]) < 1e-9 else 1)' "$work/auto/manifest.jsonl"
"$lenslab" capture --path "$src/assets/rows/rack-focus.json" --frames 0:3 --shard 1/2 --width 32 --aperture-samples 2 -q \
  --exposure auto --out "$work/shard/frame_%04d.png" 2>/dev/null
check $python -c 'import json,sys; a=json.loads(open(sys.argv[1]).readline())["display"]; l=[json.loads(x)["display"] for x in open(sys.argv[2])]; sys.exit(0 if len(l) == 2 and all(abs(x["exposure_stops"] - a["exposure_stops"]) < 1e-6 for x in l) else 1)' "$work/auto/manifest.jsonl" "$work/shard/manifest.jsonl"

echo "exposure: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
