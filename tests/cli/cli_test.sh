#!/usr/bin/env bash
# The lenslab command line as a user meets it: help, a default render with --stats, and bad input
# (a missing file, invalid JSON, a degenerate camera, a bad extension) giving one line on stderr,
# a non-zero exit and no output file.
# usage: cli_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"

# Help.
if "$lenslab" --help | grep -q render && "$lenslab" render --help | grep -q -- "--camera"; then pass; else fail "--help"; fi

# The default render, with stats.
if "$lenslab" render --width 120 --out "$work/default.png" --stats "$work/stats.json" -q && [ -s "$work/default.png" ]; then
  pass
  for key in '"width": 120' '"height"' '"backend": "osmesa"' '"renderer"' '"seconds"' '"plan"' '"aperture_samples": 1'; do
    if grep -qF "$key" "$work/stats.json"; then pass; else fail "stats.json lacks $key"; fi
  done
else
  fail "default render"
fi
# EXR output.
if "$lenslab" render --width 64 --out "$work/default.exr" -q && [ -s "$work/default.exr" ]; then pass; else fail "exr render"; fi
# --background (linear R,G,B) for render and raycast; PNG is RGB, EXR RGBA (alpha = coverage).
for cmd in render raycast; do
  if "$lenslab" $cmd --width 48 --spp 4 --background 1,0,0 --out "$work/bg-$cmd.exr" -q 2>/dev/null ||
     "$lenslab" $cmd --width 48 --background 1,0,0 --out "$work/bg-$cmd.exr" -q; then
    # the sky: red at full strength, alpha 0; the floor: alpha 1
    stats=$(oiiotool "$work/bg-$cmd.exr" --printstats 2>&1)
    if grep -Eq "Stats Min: [0-9.]+ [0-9.]+ [0-9.]+ 0.000000" <<<"$stats" && grep -Eq "Stats Max: 1.000000 [0-9.]+ [0-9.]+ 1.000000" <<<"$stats"; then pass
    else fail "$cmd --background: alpha (coverage) never 0: $(oiiotool "$work/bg-$cmd.exr" --printstats 2>&1 | grep Stats)"; fi
  else
    fail "$cmd --background 1,0,0"
  fi
done
if "$lenslab" render --width 48 --out "$work/rgb.png" -q && oiiotool --info "$work/rgb.png" | grep -q "3 channel"; then pass; else fail "PNG is not RGB: $(oiiotool --info "$work/rgb.png")"; fi
# --aov: the AOVs as EXR channels beside RGBA, for render and raycast; the image itself unchanged.
aov_channels="R,G,B,A,Z,N.X,N.Y,N.Z,albedo.R,albedo.G,albedo.B,instance"
for cmd in render raycast; do
  extra=(--width 48 --seed 3 -q)
  [ "$cmd" = raycast ] && extra+=(--spp 2)
  if "$lenslab" $cmd "${extra[@]}" --aov depth,normal --aov albedo,instance --out "$work/aov-$cmd.exr" &&
     "$lenslab" $cmd "${extra[@]}" --out "$work/plain-$cmd.exr"; then
    # Compared as sets: OpenImageIO lists R, G, B, A first, then the rest in its own order.
    names=$(iinfo -v "$work/aov-$cmd.exr" | sed -n 's/^ *channel list: //p' | tr -d ' ' | tr ',' '\n' | sort | paste -sd,)
    want=$(tr ',' '\n' <<<"$aov_channels" | sort | paste -sd,)
    if [ "$names" = "$want" ]; then pass; else fail "$cmd --aov: channels $names, not $want"; fi
    if oiiotool "$work/aov-$cmd.exr" --ch R,G,B,A -o "$work/aov-rgba-$cmd.exr" &&
       idiff -fail 0 -warn 0 "$work/aov-rgba-$cmd.exr" "$work/plain-$cmd.exr" >/dev/null; then pass
    else fail "$cmd --aov changed the image"; fi
    # The rows scene shows the sky (instance -1) and its nodes (whole indices >= 0).
    stats=$(oiiotool "$work/aov-$cmd.exr" --ch instance --printstats 2>&1)
    if grep -Eq "Stats Min: -1.000000" <<<"$stats" && grep -Eq "Stats Max: [0-9]+\.000000" <<<"$stats"; then pass
    else fail "$cmd --aov instance: $(grep Stats <<<"$stats")"; fi
  else
    fail "$cmd --aov depth,normal --aov albedo,instance"
  fi
done
# Beside a PNG the AOVs go to an EXR of their own, IMAGE.aov.exr (docs/capture.md).
for cmd in render raycast; do
  check "$lenslab" $cmd --width 32 --aov depth,albedo --out "$work/aov-png-$cmd.png" -q
  check test -s "$work/aov-png-$cmd.aov.exr"
done
expect_refusal "render unknown aov" "--aov" -- render --aov normals --out "$work/out.exr"
expect_refusal "raycast unknown aov" "--aov" -- raycast --aov depth,Z --out "$work/out.exr"
expect_refusal "render aov of a tiled image" "--aov instance: " -- render --aov instance --width 66 --tile-size 16 --out "$work/out.exr"
expect_refusal "background with two values" "--background" -- render --background 1,2 --out "$work/out.png"
expect_refusal "negative background" "--background" -- raycast --background -1,0,0 --out "$work/out.png"

# EGL (Mesa's surfaceless platform here; a GPU where there is one) draws what OSMesa draws.
if "$lenslab" render --width 120 --backend egl --out "$work/egl.png" --stats "$work/egl.json" -q; then
  if grep -qF '"backend": "egl"' "$work/egl.json"; then pass; else fail "egl stats"; fi
  if cmp -s "$work/egl.png" "$work/default.png" || [ "$(grep -o '"renderer": "[^"]*"' "$work/egl.json")" != "$(grep -o '"renderer": "[^"]*"' "$work/stats.json")" ]; then
    pass  # identical on the same renderer; a different renderer (a GPU) may differ slightly
  else
    fail "egl and osmesa images differ on the same renderer"
  fi
else
  fail "egl render"
fi

# Depth of field: auto sample count, each pattern, focus tools.
if "$lenslab" render --camera "$src/assets/rows/camera-dof.json" --width 480 --max-samples 64 --out "$work/dof.png" --stats "$work/dof.json" -q; then
  # The count comes from the blur seen (a pre-pass: circles up to 5.6 px, ceil(pi/4 x 5.6^2) = 25),
  # not the bounds (which would ask for the cap, 64).
  if grep -qF '"aperture_samples": 25' "$work/dof.json" && grep -qF '"bounds_aperture_samples": 64' "$work/dof.json" &&
     grep -qF '"visible_blur"' "$work/dof.json" && grep -qF '"accumulate"' "$work/dof.json" && grep -qF '"coc_px"' "$work/dof.json"; then pass
  else fail "dof stats: $(cat "$work/dof.json")"; fi
else
  fail "dof render"
fi
for pattern in lecture17 concentric r2 random; do
  count=4
  [ $pattern = lecture17 ] && count=17  # always its 17 points (another count is refused)
  if "$lenslab" render --camera "$src/assets/occluder/camera-dof.json" --width 64 --pattern $pattern --aperture-samples $count --out "$work/p-$pattern.png" --stats "$work/p-$pattern.json" -q &&
     grep -qF "\"pattern\": \"$pattern\"" "$work/p-$pattern.json"; then pass; else fail "pattern $pattern"; fi
done
if "$lenslab" render --camera "$src/assets/rows/camera-dof.json" --width 96 --max-samples 4 --focus-at 66,42 --out "$work/focus.png" --stats "$work/focus.json" -q &&
   grep -qF 'focused at pixel 66,42' "$work/focus.json"; then pass; else fail "--focus-at"; fi
# A pinhole camera is anti-aliased by default (16 jittered views), one scene pass when asked for one.
if grep -qF '"aperture_samples": 16' "$work/stats.json" && grep -qF 'anti-aliasing' "$work/stats.json"; then pass
else fail "pinhole default is not anti-aliased: $(cat "$work/stats.json")"; fi
if "$lenslab" render --width 120 --aperture-samples 1 --out "$work/one.png" --stats "$work/one.json" -q &&
   ! grep -qF '"accumulate"' "$work/one.json" && grep -qF '"aperture_samples": 1' "$work/one.json"; then pass
else fail "--aperture-samples 1 with a pinhole accumulates"; fi
expect_refusal "bad sample count" "--aperture-samples" -- render --aperture-samples lots --out "$work/out.png"

# To a target error: the estimate and the samples in --stats; refusals name the option.
if "$lenslab" render --camera "$src/assets/rows/camera-dof.json" --width 128 --target-psnr 30 --out "$work/target.png" --stats "$work/target.json" -q; then
  if grep -qF '"estimate"' "$work/target.json" && grep -qF '"target_met": true' "$work/target.json" &&
     grep -qF '"pattern": "sobol"' "$work/target.json" && grep -qF '"mean"' "$work/target.json"; then pass
  else fail "--target-psnr stats: $(cat "$work/target.json")"; fi
else
  fail "render --target-psnr"
fi
# Out of reach within an odd cap: the cap is made even (the two streams stay equal) and the run ends.
if timeout 120 "$lenslab" render --camera "$src/assets/rows/camera-dof.json" --width 96 --target-psnr 90 --max-samples 15 \
     --out "$work/capped.png" --stats "$work/capped.json" 2>"$work/capped.err" &&
   grep -qF '"max": 14' "$work/capped.json" && grep -qF '"target_met": false' "$work/capped.json" &&
   grep -qF "short of --target-psnr" "$work/capped.err"; then pass
else fail "--target-psnr beyond an odd cap: $(cat "$work/capped.err")"; fi
expect_refusal "target with a stratified pattern" "--pattern concentric: --target-psnr" -- render --camera "$src/assets/rows/camera-dof.json" --target-psnr 30 --pattern concentric --out "$work/out.png"
expect_refusal "target with a count" "--aperture-samples 16: --target-psnr" -- render --camera "$src/assets/rows/camera-dof.json" --target-psnr 30 --aperture-samples 16 --out "$work/out.png"
expect_refusal "target out of range" "--target-psnr" -- render --target-psnr 5 --out "$work/out.png"
expect_refusal "target in tiles" "--target-psnr: " -- render --camera "$src/assets/rows/camera-dof.json" --width 256 --tile-size 64 --target-psnr 30 --out "$work/out.png"
expect_refusal "bad focus distance" "--focus-distance: focus_distance is -3" -- render --focus-distance -3 --out "$work/out.png"
expect_refusal "focus on nothing" "nothing of the scene" -- render --camera "$src/assets/rows/camera-dof.json" --width 96 --focus-at 50,2 --out "$work/out.png"

# Every number option, given what is not a finite number, is refused in one line naming it (a
# plain range check lets nan through; 1e309 overflows a double). VALUE stands for the bad number.
number_options=(
  "render --time VALUE" "render --focal-length VALUE" "render --focus-distance VALUE" "render --focus-at VALUE,1"
  "render --target-psnr VALUE" "render --eye VALUE,0,0" "render --target 0,VALUE,0" "render --background 0,0,VALUE"
  "render --f-number VALUE" "render --sensor VALUEx24" "render --lens-tolerance VALUE" "raycast --time VALUE" "raycast --focus-at 1,VALUE"
  "capture --fps VALUE" "sweep --target-psnr 30,VALUE" "sweep --focus-distance VALUE"
  "view --frame-budget-ms VALUE" "view --click VALUE,VALUE" "view --window-size VALUE,100" "view --time VALUE"
)
for template in "${number_options[@]}"; do
  read -r cmd option _ <<<"$template"
  for bad in nan inf -inf 1e309; do
    read -r -a args <<<"${template//VALUE/$bad}"
    out="$work/out.png"
    [ "$cmd" = sweep ] && out="$work/out.sweep"
    [ "$cmd" = capture ] && out="$work/out_%04d.png"
    if [ "$cmd" = view ]; then extra=(--frames 1 --screenshot "$work/out.png"); else extra=(--out "$out"); fi
    expect_refusal "$template with $bad" "$option" -- "${args[@]}" "${extra[@]}"
  done
done

# A camera path whose keys are valid but whose interpolation is not is refused before frame 0,
# naming the frame; no frame is written.
echo '{"fps": 4, "interpolation": "linear", "keys": [{"time": 0, "eye": [0, 1, 5], "target": [0, 1, 0]}, {"time": 1, "eye": [0, 1, -5], "target": [0, 1, 0]}]}' >"$work/through.json"
echo '{"fps": 4, "keys": [{"time": 0, "eye": [0, 1, 5], "target": [0, 1, 0]}, {"time": 1, "eye": [0, 1, 5], "target": [0, 1, 0], "up": [0, -1, 0]}]}' >"$work/flip.json"
expect_refusal "path through its target" "through.json: frame 2 (t = 0.5 s): eye meets target" -- capture --path "$work/through.json" --width 32 --out "$work/out_%04d.png"
if ls "$work"/out_0000.png >/dev/null 2>&1; then fail "path through its target: wrote frame 0"; rm -f "$work"/out_*.png; else pass; fi
expect_refusal "path whose up flips" "flip.json: frame 2 (t = 0.5 s): up is parallel" -- capture --path "$work/flip.json" --width 32 --out "$work/out_%04d.png"
if ls "$work"/out_0000.png >/dev/null 2>&1; then fail "path whose up flips: wrote frame 0"; rm -f "$work"/out_*.png; else pass; fi

# The ray-cast reference: same options, --spp, same outputs.
if "$lenslab" raycast --camera "$src/assets/occluder/camera-dof.json" --width 48 --spp 4 --out "$work/rc.exr" --stats "$work/rc.json" -q &&
   [ -s "$work/rc.exr" ] && grep -qF '"command": "raycast"' "$work/rc.json" && grep -qF '"aperture_samples": 4' "$work/rc.json"; then pass; else fail "raycast"; fi
if "$lenslab" raycast --camera "$src/assets/rows/camera-dof.json" --width 48 --spp 1 --focus-at 33,21 --out "$work/rcf.png" --stats "$work/rcf.json" -q &&
   grep -qF 'focused at pixel 33,21' "$work/rcf.json"; then pass; else fail "raycast --focus-at"; fi
expect_refusal "raycast bad spp" "--spp" -- raycast --spp 0 --out "$work/out.png"

# The sweep writes its CSV, table, plot and images.
if "$lenslab" sweep "$src/assets/occluder/occluder.gltf" --camera "$src/assets/occluder/camera-dof.json" --out "$work/sweep" --width 48 --reference-spp 8 --max-views 4 --max-spp 2 2>/dev/null &&
   [ -s "$work/sweep/sweep.csv" ] && [ -s "$work/sweep/sweep.md" ] && [ -s "$work/sweep/error_vs_time.png" ] &&
   head -1 "$work/sweep/sweep.csv" | grep -qx "method,pattern,samples,seconds,rmse,psnr,max_error,edge_rmse,target_psnr,estimate_psnr,mean_samples,max_tile_samples" &&
   grep -q "^adaptive,sobol," "$work/sweep/sweep.csv" &&
   grep -q "^postprocess,gather," "$work/sweep/sweep.csv" && ls "$work"/sweep/images/raster-concentric-4.png >/dev/null; then pass; else fail "sweep"; fi
# A lens whose views move as they are summed (distortion) cannot take the cell filter: that series
# is left out, said so, and the rest of the sweep is written.
if "$lenslab" sweep --camera "$src/assets/rows/camera-lens.json" --out "$work/sweep-lens" --width 32 --reference-spp 2 \
     --max-views 2 --max-spp 1 2>"$work/sweep-lens.err" &&
   grep -q "cell filter: left out (distortion" "$work/sweep-lens.err" && grep -q "^raster,sobol," "$work/sweep-lens/sweep.csv" &&
   ! grep -q "^cell-filter," "$work/sweep-lens/sweep.csv"; then pass; else fail "sweep of a distorting lens leaves the cell filter out"; fi
expect_refusal "sweep of a pinhole" "pinhole" -- sweep "$src/assets/occluder/occluder.gltf" --camera "$src/assets/occluder/camera.json" --out "$work/out-sweep" --width 16

# info.
if "$lenslab" info "$src/assets/rows/rows.gltf" | grep -q "^triangles"; then pass; else fail "info"; fi

# Bad input.
echo '{ "eye": [0, 0, 5], "target": ' >"$work/broken.json"
echo '{ "vrp": [0,0,0], "vpn": [0,0,0], "prp": [0,0,1], "window": [-1,-1,1,1] }' >"$work/zero-vpn.json"
echo '{ "vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,0], "window": [-1,-1,1,1] }' >"$work/prp-on-plane.json"
echo '{ "eye": [0,0,5], "target": [0,0,0], "focal_lenght_mm": 50 }' >"$work/typo.json"
expect_refusal "missing scene" "no-such-scene.gltf" -- render "$work/no-such-scene.gltf" --out "$work/out.png"
expect_refusal "missing camera" "no-such-camera.json" -- render --camera "$work/no-such-camera.json" --out "$work/out.png"
expect_refusal "invalid json" "not valid JSON" -- render --camera "$work/broken.json" --out "$work/out.png"
expect_refusal "zero vpn" "vpn" -- render --camera "$work/zero-vpn.json" --out "$work/out.png"
expect_refusal "prp on view plane" "view plane" -- render --camera "$work/prp-on-plane.json" --out "$work/out.png"
expect_refusal "unknown key" "focal_lenght_mm" -- render --camera "$work/typo.json" --out "$work/out.png"
expect_refusal "bad extension" "use .png" -- render --out "$work/out.jpg"
expect_refusal "bad width" "--width" -- render --width 0 --out "$work/out.png"
expect_refusal "missing output folder" "does not exist" -- render --width 32 --out "$work/nowhere/out.png"

# Input files: only a regular file is read, and only up to a limit (docs/camera-files.md). Each of
# these used to be read until memory ran out (std::bad_alloc) or to block on the FIFO; the runs are
# bounded here so that a regression fails rather than fills the machine.
mkfifo "$work/fifo.json" "$work/fifo.gltf"
truncate -s 67108865 "$work/huge.json"  # 64 MiB + 1, sparse
ln -s /dev/zero "$work/zero.glb"
ln -s /dev/zero "$work/zero.bin"
echo '{"asset": {"version": "2.0"}, "buffers": [{"uri": "zero.bin", "byteLength": 4}]}' >"$work/zero-buffer.gltf"
mkdir "$work/colmap-fifo" && mkfifo "$work/colmap-fifo/cameras.txt" && touch "$work/colmap-fifo/images.txt"
real_lenslab=$lenslab
lenslab=$work/bounded-lenslab
# The memory cap (ulimit -v) is left out under AddressSanitizer, whose shadow memory alone is past
# it; the timeout still catches a read that never ends.
memory_cap='ulimit -v 8000000'
grep -q __asan_init "$real_lenslab" && memory_cap=': no memory cap under AddressSanitizer'
printf '#!/usr/bin/env bash\n%s\nexec timeout 30 "%s" "$@"\n' "$memory_cap" "$real_lenslab" >"$lenslab" && chmod +x "$lenslab"
expect_refusal "camera /dev/zero" "/dev/zero: is not a regular file" -- render --camera /dev/zero --out "$work/out.png"
expect_refusal "path /dev/zero" "/dev/zero: is not a regular file" -- capture --path /dev/zero --out "$work/out_%04d.png"
expect_refusal "camera FIFO" "fifo.json: is not a regular file" -- render --camera "$work/fifo.json" --out "$work/out.png"
expect_refusal "camera folder" "is a folder; give the camera file as a file" -- render --camera "$work" --out "$work/out.png"
expect_refusal "camera over 64 MiB" "lenslab reads at most 64 MiB" -- render --camera "$work/huge.json" --out "$work/out.png"
expect_refusal "glb /dev/zero" "zero.glb: is not a regular file" -- render "$work/zero.glb" --out "$work/out.png"
expect_refusal "gltf FIFO" "fifo.gltf: is not a regular file" -- render "$work/fifo.gltf" --out "$work/out.png"
expect_refusal "buffer /dev/zero" "zero.bin: is not a regular file" -- render "$work/zero-buffer.gltf" --out "$work/out.png"
expect_refusal "COLMAP FIFO" "cameras.txt: is not a regular file" -- render --colmap "$work/colmap-fifo" --image a.png --out "$work/out.png"
mkfifo "$work/fifo.lens" && mkdir "$work/folder.lens" && ln -s /dev/zero "$work/zero.lens"
expect_refusal "lens FIFO" "fifo.lens: is not a regular file" -- lens "$work/fifo.lens"
expect_refusal "lens folder" "folder.lens: is a folder; give the lens file as a file" -- lens "$work/folder.lens"
expect_refusal "lens /dev/zero" "zero.lens: is not a regular file" -- raycast --lens "$work/zero.lens" --out "$work/out.png"
lenslab=$real_lenslab

# Text as editors save it: a UTF-8 byte-order mark and CRLF line ends read as plain UTF-8 does
# (camera file, camera path, lens prescription, COLMAP model); UTF-16 is refused by name.
mkdir -p "$work/enc/colmap"
bom() { printf '\xEF\xBB\xBF'; cat "$1"; }
crlf() { sed 's/$/\r/' "$1"; }
bom "$src/assets/rows/camera.json" >"$work/enc/bom-camera.json"
crlf "$src/assets/rows/camera.json" >"$work/enc/crlf-camera.json"
bom "$src/assets/rows/dolly-zoom.json" | sed 's/$/\r/' >"$work/enc/bom-crlf-path.json"
bom "$src/assets/lenses/double-gauss-50mm.lens" | sed 's/$/\r/' >"$work/enc/bom-crlf.lens"
printf '\xFF\xFE{\0}\0' >"$work/enc/utf16-camera.json"
"$lenslab" capture --path "$src/assets/rows/dolly-zoom.json" --frames 0:0 --width 32 --out "$work/enc/f/f_%d.png" \
  --colmap-out "$work/enc/model" -q || fail "capture for the COLMAP encodings"
for f in cameras images points3D; do bom "$work/enc/model/$f.txt" | sed 's/$/\r/' >"$work/enc/colmap/$f.txt"; done
check "$lenslab" render --camera "$work/enc/bom-camera.json" --width 32 --out "$work/enc/bom.png" -q
check "$lenslab" render --camera "$work/enc/crlf-camera.json" --width 32 --out "$work/enc/crlf.png" -q
check "$lenslab" capture --path "$work/enc/bom-crlf-path.json" --frames 0:0 --width 32 --out "$work/enc/p/f_%d.png" -q
check bash -c "\"$lenslab\" lens \"$work/enc/bom-crlf.lens\" >/dev/null"
check "$lenslab" render --colmap "$work/enc/colmap" --image f_0.png --width 32 --out "$work/enc/colmap.png" -q
expect_refusal "UTF-16 camera file" "utf16-camera.json: the camera file is UTF-16 text (it starts with a UTF-16 byte-order mark); save it as UTF-8" -- render --camera "$work/enc/utf16-camera.json" --out "$work/out.png"

# Lens effects: the passes that ran are listed, a zero-strength effect adds none, the ray caster
# takes the same camera, bad lens input is refused in one line.
if "$lenslab" render "$src/assets/grid/grid.gltf" --camera "$src/assets/grid/camera-distortion.json" --width 160 \
    --out "$work/distorted.png" --stats "$work/distorted.json" -q; then
  if grep -qF '"name": "lens"' "$work/distorted.json" && grep -qF '"distortion"' "$work/distorted.json"; then pass; else fail "lens pass not in stats"; fi
else
  fail "distorted render"
fi
if "$lenslab" render --camera "$src/assets/rows/camera-lens.json" --width 96 --aperture-samples 4 --out "$work/lens.png" --stats "$work/lens.json" -q &&
   grep -qF '"channel-focus"' "$work/lens.json" && grep -qF '"lateral-colour"' "$work/lens.json" && grep -qF '"views_per_sample": 3' "$work/lens.json"; then pass; else fail "lens camera stats"; fi
# The lens barrel with every lens effect: both renderers take it; a parallel projection refuses it.
sed 's/"near": 0.05,/"near": 0.05, "barrel": {"distance_mm": 40, "diameter_mm": 44},/' "$src/assets/rows/camera-lens.json" >"$work/barrel-lens.json"
if "$lenslab" render --camera "$work/barrel-lens.json" --width 96 --aperture-samples 4 --out "$work/barrel-lens.png" --stats "$work/barrel-stats.json" -q &&
   grep -qF '"barrel"' "$work/barrel-stats.json" && grep -qF '"lateral-colour"' "$work/barrel-stats.json" &&
   "$lenslab" raycast --camera "$work/barrel-lens.json" --width 48 --spp 1 --out "$work/barrel-lens-rc.png" -q && [ -s "$work/barrel-lens-rc.png" ]; then
  pass
else
  fail "barrel with lens effects"
fi
echo '{ "projection": "parallel", "vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,3], "window": [-1,-1,1,1], "far": 10, "barrel": {"distance_mm": 40, "diameter_mm": 30} }' >"$work/barrel-parallel.json"
expect_refusal "barrel on a parallel projection" '"barrel" needs a perspective projection' -- render --camera "$work/barrel-parallel.json" --out "$work/out.png"
echo '{ "vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,3], "window": [-1,-1,1,1], "distortion": {"k1": 0, "k2": 0}, "chromatic": {"lateral_red": 0} }' >"$work/zero-lens.json"
if "$lenslab" render --camera "$work/zero-lens.json" "$src/assets/grid/grid.gltf" --width 64 --out "$work/zero.png" --stats "$work/zero.json" -q &&
   ! grep -qF '"name": "lens"' "$work/zero.json" && grep -qF '"render_size": [' "$work/zero.json"; then pass; else fail "zero-strength effects added a pass"; fi
if "$lenslab" raycast "$src/assets/grid/grid.gltf" --camera "$src/assets/grid/camera-distortion.json" --width 48 --spp 1 --out "$work/distorted-rc.png" -q &&
   [ -s "$work/distorted-rc.png" ]; then pass; else fail "raycast with lens effects"; fi
echo '{ "vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,3], "window": [-2.1,-1.4,2.1,1.4], "distortion": {"k1": -0.9} }' >"$work/fold.json"
echo '{ "vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,3], "window": [-1,-1,1,1], "distortion": {"k1": -0.1, "q1": 2} }' >"$work/bad-lens-key.json"
echo '{ "vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,3], "window": [-1,-1,1,1], "chromatic": {"abbe_number": 40} }' >"$work/abbe-lecture.json"
expect_refusal "fold-over" "folds over" -- render --camera "$work/fold.json" --out "$work/out.png"
expect_refusal "fold-over raycast" "folds over" -- raycast --camera "$work/fold.json" --out "$work/out.png"
expect_refusal "unknown distortion key" "distortion.q1" -- render --camera "$work/bad-lens-key.json" --out "$work/out.png"
expect_refusal "abbe in lecture form" "abbe_number" -- render --camera "$work/abbe-lecture.json" --out "$work/out.png"

# Issue #12's stiff cases, as a user typed them: each used to abort, write garbage or be refused
# for the wrong reason (the stability table measures them; here the command line's side).
a="$src/assets"
if "$lenslab" raycast --camera "$a/rows/camera-dof.json" --focus-distance 1e300 --width 48 --spp 2 --out "$work/far-focus.png" -q &&
   [ -s "$work/far-focus.png" ]; then pass; else fail "raycast --focus-distance 1e300 (was an Embree abort)"; fi
echo '{"projection": "parallel", "vrp": [0, 0.5, 0.5], "vpn": [0, 0.3, 1], "prp": [0, 0, 1], "window": [-3, -2, 3, 2], "near": -1, "far": 60}' >"$work/negative-near.json"
if "$lenslab" raycast --camera "$work/negative-near.json" --width 48 --spp 2 --out "$work/negative-near.png" -q &&
   [ -s "$work/negative-near.png" ]; then pass; else fail "raycast of a parallel camera with near -1 (was an Embree abort)"; fi
sed 's/"focus_distance": 2.0/"focus_distance": 0.035/' "$a/rows/camera-dof.json" >"$work/focus-at-f.json"
expect_refusal "focus at f in the file" "focus_distance is 0.035; it must be beyond the focal length" -- render --camera "$work/focus-at-f.json" --out "$work/out.png"
expect_refusal "focus at f on the command line" "focus_distance is 0.035; it must be beyond the focal length" -- render --camera "$a/rows/camera-dof.json" --focus-distance 0.035 --out "$work/out.png"
sed 's/"near": 0.05,/"near": 0.05, "distortion": {"k1": 2, "k2": -2},/' "$a/rows/camera.json" >"$work/strong.json"
if "$lenslab" render --camera "$work/strong.json" --width 48 --out "$work/strong.png" -q && [ -s "$work/strong.png" ]; then pass
else fail "k1 2, k2 -2 (folds only beyond the image) was refused"; fi
expect_refusal "sweep beyond one render target" "sweep renders the whole 20000x13333 image into one render target" -- sweep --width 20000 --out "$work/out.sweep"

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
