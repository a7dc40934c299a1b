#!/usr/bin/env bash
# The environment as a user meets it (docs/environment.md): --environment, --environment-intensity
# and --environment-rotation on render, raycast, capture and sweep; bad files and values refused in one
# line naming the file or option, with no output written; the prefiltered maps cached under
# $XDG_CACHE_HOME/lenslab (a second run a hit, a corrupt entry recomputed, an unwritable folder a
# warning only); --stats reporting it; no environment, no change.
# usage: environment_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"
studio=$src/assets/environments/studio.hdr
export XDG_CACHE_HOME=$work/cache

refused_outputs='out*'  # the refusals' outputs include folders named out

# --- bad files and values ---
oiiotool --pattern constant:color=1,1,1 16x16 3 -d float -o "$work/square.exr" >/dev/null 2>&1
oiiotool --pattern constant:color=1,1 16x8 2 -d float -o "$work/two.exr" >/dev/null 2>&1
oiiotool --pattern constant:color=1,-1,1 16x8 3 -d float -o "$work/negative.exr" >/dev/null 2>&1
oiiotool --pattern constant:color=1,1,1 16x8 3 -o "$work/sky.png" >/dev/null 2>&1
oiiotool --pattern constant:color=1e20,1e20,1e20 16x8 3 -d float -o "$work/bright.exr" >/dev/null 2>&1
printf 'not an image' >"$work/broken.hdr"
for command in render raycast; do
  expect_refusal "$command square" "square.exr: the environment is 16 × 16; an equirectangular image is twice as wide as high" -- \
    $command --environment "$work/square.exr" --width 48 --out "$work/out.png"
  expect_refusal "$command two channels" "two.exr: the environment has 2 channels; it must have 3 (RGB) or 4 (RGBA)" -- \
    $command --environment "$work/two.exr" --width 48 --out "$work/out.png"
  expect_refusal "$command negative" "negative.exr: pixel (0, 0) holds -1; an environment's radiance is finite and ≥ 0" -- \
    $command --environment "$work/negative.exr" --width 48 --out "$work/out.png" --stats "$work/out.json"
  expect_refusal "$command png" "sky.png: an environment is a .hdr or .exr file" -- \
    $command --environment "$work/sky.png" --width 48 --out "$work/out.png"
  expect_refusal "$command broken" "broken.hdr: the file is not the Radiance HDR image its name says" -- \
    $command --environment "$work/broken.hdr" --width 48 --out "$work/out.png"
  expect_refusal "$command missing" "missing.hdr" -- \
    $command --environment "$work/missing.hdr" --width 48 --out "$work/out.png"
  expect_refusal "$command intensity" "--environment-intensity" -- \
    $command --environment "$studio" --environment-intensity -1 --width 48 --out "$work/out.png"
  expect_refusal "$command intensity past a float" "exceeds a float's largest radiance" -- \
    $command --environment "$work/bright.exr" --environment-intensity 1e20 --width 48 --out "$work/out.png"
  expect_refusal "$command rotation nan" "--environment-rotation" -- \
    $command --environment "$studio" --environment-rotation nan --width 48 --out "$work/out.png"
done
expect_refusal "capture square" "square.exr: the environment is 16 × 16" -- \
  capture --path "$src/assets/rows/rack-focus.json" --environment "$work/square.exr" --frames 0:1 --width 32 --out "$work/out/frame_%04d.png"

# --- the cache: computed once, then a hit; a corrupt entry is computed again ---
"$lenslab" render --environment "$studio" --width 64 -q --out "$work/first.exr" --stats "$work/first.json" 2>"$work/err1"
check holds "$work/first.json" 'j["environment"]["from_cache"] == False and j["environment"]["width"] == 1024'
"$lenslab" render --environment "$studio" --width 64 -q --out "$work/second.exr" --stats "$work/second.json" 2>"$work/err2"
check holds "$work/second.json" 'j["environment"]["from_cache"] == True and j["environment"]["specular_levels"] >= 2'
check same_pixels "$work/first.exr" "$work/second.exr"
entry=$(ls -t "$XDG_CACHE_HOME"/lenslab/environment-*.bin | head -1)  # the newest: the studio's
printf 'garbage' | dd of="$entry" bs=1 seek=100 conv=notrunc 2>/dev/null
"$lenslab" render --environment "$studio" --width 64 -q --out "$work/third.exr" --stats "$work/third.json" 2>/dev/null
check holds "$work/third.json" 'j["environment"]["from_cache"] == False'
check same_pixels "$work/first.exr" "$work/third.exr"
# An unwritable cache folder: a warning, and the image all the same.
mkdir -p "$work/locked" && chmod a-w "$work/locked"
if XDG_CACHE_HOME=$work/locked/sub "$lenslab" render --environment "$studio" --width 64 -q --out "$work/locked.exr" 2>"$work/err4" &&
  [ -f "$work/locked.exr" ] && { [ "$(id -u)" -eq 0 ] || grep -q "warning: environment cache not written" "$work/err4"; }; then
  pass
else
  fail "unwritable cache folder: $(cat "$work/err4")"
fi

# --- raycast and capture take it; rotation and intensity change the picture; no environment, none in --stats ---
"$lenslab" raycast --environment "$studio" --spp 4 --width 64 -q --out "$work/rc.exr" --stats "$work/rc.json" 2>/dev/null
check holds "$work/rc.json" 'j["environment"]["from_cache"] == True'
"$lenslab" render --environment "$studio" --environment-rotation 180 --environment-intensity 2 --width 64 -q --out "$work/turned.exr" 2>/dev/null
if ! same_pixels "$work/first.exr" "$work/turned.exr"; then pass; else fail "rotation and intensity changed nothing"; fi
"$lenslab" capture --path "$src/assets/rows/rack-focus.json" --environment "$studio" --frames 0:1 --width 32 -q --out "$work/cap/frame_%04d.exr" 2>/dev/null
check test -f "$work/cap/frame_0000.exr"
check $python -c "import json,sys; l=json.loads(open(sys.argv[1]).readline()); sys.exit(0 if l['environment']['file'].endswith('studio.hdr') else 1)" "$work/cap/manifest.jsonl"
"$lenslab" render --width 64 -q --out "$work/plain.exr" --stats "$work/plain.json" 2>/dev/null
check holds "$work/plain.json" '"environment" not in j'

# --- sweep takes it: the report names it, and its reference cache is kept apart per environment ---
sweep_args=(sweep --camera "$src/assets/rows/camera-dof.json" --width 24 --reference-spp 2 --max-views 2 --methods concentric -q)
expect_refusal "sweep intensity" "--environment-intensity" -- \
  "${sweep_args[@]}" --environment "$studio" --environment-intensity -1 --out "$work/out.sweep"
expect_refusal "sweep square" "square.exr: the environment is 16 × 16" -- \
  "${sweep_args[@]}" --environment "$work/square.exr" --out "$work/out.sweep"
if "$lenslab" "${sweep_args[@]}" --environment "$studio" --environment-intensity 2 --environment-rotation 90 --out "$work/sw" 2>/dev/null &&
  [ -s "$work/sw/sweep.csv" ] && grep -q "^raster,concentric," "$work/sw/sweep.csv" &&
  grep -q "environment .*studio.hdr.*intensity 2, rotation 90" "$work/sw/sweep.md" && ! grep -q "from the cache" "$work/sw/sweep.md"; then
  pass
else
  fail "sweep --environment: $(ls "$work/sw" 2>&1)"
fi
# The same environment again: the cached reference; another rotation or none: a new one.
"$lenslab" "${sweep_args[@]}" --environment "$studio" --environment-intensity 2 --environment-rotation 90 --out "$work/sw" 2>/dev/null
check grep -q "from the cache" "$work/sw/sweep.md"
"$lenslab" "${sweep_args[@]}" --environment "$studio" --environment-intensity 2 --environment-rotation 91 --out "$work/sw" 2>/dev/null
if ! grep -q "from the cache" "$work/sw/sweep.md"; then pass; else fail "sweep: another rotation reused the reference"; fi
"$lenslab" "${sweep_args[@]}" --out "$work/sw" 2>/dev/null
if ! grep -q "from the cache" "$work/sw/sweep.md" && ! grep -q "environment" "$work/sw/sweep.md"; then pass
else fail "sweep without an environment reused the reference or named one"; fi

echo "environment cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
