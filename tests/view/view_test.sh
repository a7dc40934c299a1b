#!/usr/bin/env bash
# `lenslab view` in scripted mode, under its own Xvfb:
#   1. --no-ui screenshot = `lenslab render` of the same camera and samples (PSNR >= 35 dB)
#   2. a scripted click on a box focuses at its depth, computed here from the scene's geometry (1 %)
#   3. a screenshot with the UI shows the panel (non-trivial pixels where the panel is), and no
#      text of the panel is cut off on the right in a narrow (640) or a wide (1920) window
# plus bad input refused with one line. Exit 77 (ctest: skipped) when Xvfb cannot run.
# usage: view_test.sh path/to/lenslab path/to/lenslab_image_check source-dir
set -u
lenslab=$1
check=$2
src=$3
work=$(mktemp -d)
xvfb_pid=""
cleanup() {
  if [ -n "$xvfb_pid" ]; then kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null; fi
  rm -rf "$work"
}
trap cleanup EXIT
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

# ---- an X server of our own, on a display number it picks (-displayfd) ----
if ! command -v Xvfb >/dev/null 2>&1; then
  echo "SKIP: Xvfb is not installed (bash tools/install-deps.sh installs it)"
  exit 77
fi
exec 5>"$work/display"
Xvfb -displayfd 5 -screen 0 2048x1200x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
exec 5>&-
for _ in $(seq 1 100); do
  [ -s "$work/display" ] && break
  sleep 0.1
done
if [ ! -s "$work/display" ]; then
  echo "SKIP: Xvfb did not start: $(cat "$work/xvfb.log")"
  exit 77
fi
export DISPLAY=":$(head -n1 "$work/display")"
echo "Xvfb on $DISPLAY"

dof="$src/assets/rows/camera-dof.json"

# ---- 1. the image matches render ----
# 16 concentric samples over at least 4 frames, against render with the same camera, samples, seed.
if "$lenslab" view --camera "$dof" --width 240 --aperture-samples 16 --seed 3 --frames 4 --no-ui \
     --screenshot "$work/view.exr" --stats "$work/view.json" >"$work/view.out" 2>&1 &&
   "$lenslab" render --camera "$dof" --width 240 --aperture-samples 16 --seed 3 --out "$work/render.exr" -q; then
  if "$check" psnr "$work/view.exr" "$work/render.exr" 35; then pass; else fail "view --no-ui differs from render"; fi
  if grep -qF '"samples_done": 16' "$work/view.json" && grep -qF '"frames"' "$work/view.json"; then pass
  else fail "view stats: $(cat "$work/view.json")"; fi
else
  fail "view --no-ui or render failed: $(cat "$work/view.out")"
fi
# The same through a PNG, with auto samples (what a user gets by default), a different pattern.
if "$lenslab" view --camera "$dof" --width 200 --pattern r2 --max-samples 24 --frames 2 --no-ui --screenshot "$work/auto.png" >/dev/null 2>&1 &&
   "$lenslab" render --camera "$dof" --width 200 --pattern r2 --max-samples 24 --out "$work/auto-render.png" -q; then
  if "$check" psnr "$work/auto.png" "$work/auto-render.png" 35; then pass; else fail "auto samples: view differs from render"; fi
else
  fail "view/render with auto samples failed"
fi

# To a target error: view runs a round of per-tile budgets a frame, stops at the target, and
# shows what render makes with the same options.
if "$lenslab" view --camera "$dof" --width 240 --target-psnr 32 --frames 1 --no-ui --screenshot "$work/target.exr" \
     --stats "$work/target.json" >"$work/target.out" 2>&1 &&
   "$lenslab" render --camera "$dof" --width 240 --target-psnr 32 --out "$work/target-render.exr" -q; then
  if "$check" psnr "$work/target.exr" "$work/target-render.exr" 60; then pass; else fail "--target-psnr: view differs from render"; fi
  if grep -qF '"target_met": true' "$work/target.json" && grep -qF '"rounds"' "$work/target.json"; then pass
  else fail "--target-psnr view stats: $(cat "$work/target.json")"; fi
else
  fail "view/render --target-psnr failed: $(cat "$work/target.out")"
fi

# The same with every lens effect (the lens pass, per-channel views, the curvature warp).
lens="$src/assets/rows/camera-lens.json"
if "$lenslab" view --camera "$lens" --width 200 --aperture-samples 8 --frames 2 --no-ui --screenshot "$work/lens.exr" >/dev/null 2>&1 &&
   "$lenslab" render --camera "$lens" --width 200 --aperture-samples 8 --out "$work/lens-render.exr" -q; then
  if "$check" psnr "$work/lens.exr" "$work/lens-render.exr" 35; then pass; else fail "lens effects: view differs from render"; fi
else
  fail "view/render with lens effects failed"
fi

# The display's exposure and view transform: a --no-ui PNG is render's PNG with the same options
# (docs/exposure.md), and the panel-less window shows it.
if "$lenslab" view --camera "$dof" --width 200 --aperture-samples 16 --seed 3 --exposure 2 --view-transform pbr-neutral \
     --frames 2 --no-ui --screenshot "$work/exposed.png" --stats "$work/exposed.json" >/dev/null 2>&1 &&
   "$lenslab" render --camera "$dof" --width 200 --aperture-samples 16 --seed 3 --exposure 2 --view-transform pbr-neutral \
     --out "$work/exposed-render.png" -q; then
  if "$check" psnr "$work/exposed.png" "$work/exposed-render.png" 35; then pass; else fail "--exposure: view differs from render"; fi
  if python3 -c 'import json,sys; d=json.load(open(sys.argv[1]))["display"]; sys.exit(0 if d["exposure_stops"]==2 and d["view_transform"]=="pbr-neutral" else 1)' "$work/exposed.json"; then pass
  else fail "view --stats lacks the display: $(cat "$work/exposed.json")"; fi
else
  fail "view/render with --exposure failed"
fi

# A COLMAP image's camera (--colmap DIR --image NAME), from a model capture writes for a still path.
printf '{"fps": 1, "frames": 1, "keys": [{"time": 0, "eye": [0.5, 1.1, 3], "target": [0, 0.55, -2]}]}' >"$work/still.json"
if "$lenslab" capture --path "$work/still.json" --width 200 --out "$work/still/f_%d.png" --colmap-out "$work/still-model" -q &&
   "$lenslab" view --colmap "$work/still-model" --image f_0.png --max-samples 4 --frames 2 --no-ui --screenshot "$work/colmap.exr" >/dev/null 2>&1 &&
   "$lenslab" render --colmap "$work/still-model" --image f_0.png --max-samples 4 --out "$work/colmap-render.exr" -q; then
  if "$check" psnr "$work/colmap.exr" "$work/colmap-render.exr" 35; then pass; else fail "--colmap: view differs from render"; fi
else
  fail "capture --colmap-out, view --colmap or render --colmap failed"
fi

# The camera options compose with the camera file in view as in render.
lens=(--focal-length 50 --f-number 2 --sensor aps-c --eye 0.3,1,3.5 --width 160 --aperture-samples 8 --seed 2)
if "$lenslab" view "${lens[@]}" --frames 2 --no-ui --screenshot "$work/options.exr" >"$work/options.out" 2>&1 &&
   "$lenslab" render "${lens[@]}" --out "$work/options-render.exr" -q; then
  if "$check" psnr "$work/options.exr" "$work/options-render.exr" 35; then pass; else fail "camera options: view differs from render"; fi
else
  fail "view or render with camera options failed: $(cat "$work/options.out")"
fi

# ---- 2. click to focus ----
# The centre of the front face of the 4 m box of `rows` (x 0.75, half size 0.25, centre z −1, so
# the face is at z −0.75, y 0.25), projected by the lecture's formula through camera-dof.json
# (eye (0, 1, 3), target (0, 0.55, −2), 35 mm on 36 × 24 mm, focused at 2 m: the view plane at z_f
# with window = sensor·z_f/z_i, so pixel = centre + size·(z_i/sensor)·(X/Z, −Y/Z)). Z, the depth
# along the view direction from the PRP, is what the focus distance must become.
read -r click_x click_y depth < <(awk -v W=240 -v H=160 'BEGIN {
  f = 0.035; zf = 2; ex = 0; ey = 1; ez = 3; tx = 0; ty = 0.55; tz = -2; px = 0.75; py = 0.25; pz = -0.75
  nx = ex - tx; ny = ey - ty; nz = ez - tz; l = sqrt(nx*nx + ny*ny + nz*nz); nx /= l; ny /= l; nz /= l
  ux = nz; uz = -nx; l = sqrt(ux*ux + uz*uz); ux /= l; uz /= l          # u = up x n, up = +y
  vx = ny*uz; vy = nz*ux - nx*uz; vz = -ny*ux                             # v = n x u
  dx = px - ex; dy = py - ey; dz = pz - ez
  X = dx*ux + dz*uz; Y = dx*vx + dy*vy + dz*vz; Z = -(dx*nx + dy*ny + dz*nz)
  zi = f * zf / (zf - f)
  printf "%.3f %.3f %.6f\n", W/2 + W*(zi/0.036)*X/Z, H/2 - H*(zi/0.024)*Y/Z, Z }')
if "$lenslab" view --camera "$dof" --width 240 --max-samples 4 --frames 2 --no-ui --click "$click_x,$click_y" \
     --stats "$work/click.json" >"$work/click.out" 2>&1; then
  focus=$(grep -o '"focus_distance": [0-9.eE+-]*' "$work/click.json" | awk '{print $2}')
  if [ -n "$focus" ] && awk -v a="$focus" -v b="$depth" 'BEGIN { d = (a - b) / b; exit !(d < 0.01 && d > -0.01) }'; then
    pass
  else
    fail "click at $click_x,$click_y focused at '$focus', the box is at $depth"
  fi
  if grep -qF "focus distance" "$work/click.out"; then pass; else fail "click: no focus line on stdout"; fi
else
  fail "view --click failed: $(cat "$work/click.out")"
fi

# The camera after the click, saved as the panel saves it, renders the same image with `render`.
if "$lenslab" view --camera "$dof" --width 240 --aperture-samples 16 --frames 2 --no-ui --click "$click_x,$click_y" \
     --save-camera "$work/saved.json" --screenshot "$work/clicked.exr" >/dev/null 2>&1 &&
   "$lenslab" render --camera "$work/saved.json" --width 240 --aperture-samples 16 --out "$work/saved.exr" -q; then
  if "$check" psnr "$work/clicked.exr" "$work/saved.exr" 35; then pass; else fail "the saved camera renders differently"; fi
else
  fail "view --save-camera, or render of the saved camera, failed"
fi

# ---- 3. the panel is in the screenshot ----
# The panel takes the right 430 points of a 1200 x 800 window (scale 1 under Xvfb); left of it the
# image and the outside view. Both regions must hold content, not a flat fill.
if "$lenslab" view --camera "$dof" --width 320 --max-samples 8 --frames 3 --window-size 1200,800 \
     --screenshot "$work/ui.png" >"$work/ui.out" 2>&1; then
  if "$check" busy "$work/ui.png" 800 0 1200 800 0.05; then pass; else fail "no panel in the UI screenshot"; fi
  if "$check" busy "$work/ui.png" 0 420 760 800 0.05; then pass; else fail "no outside view in the UI screenshot"; fi
  # The control: the margin beside the letterboxed image is a flat fill, and the check says so.
  if ! "$check" busy "$work/ui.png" 0 0 60 380 0.05 >/dev/null; then pass; else fail "the busy check passes a flat region"; fi
else
  fail "view with UI failed: $(cat "$work/ui.out")"
fi
# Nothing of the panel's text is cut off on the right, in a narrow window (the panel half of it,
# labels above their fields) and a wide one; a scripted run opens every section, the lens effects
# camera fills them all. --stats counts the items cut off in the worst frame (view/PanelFit.h).
for size in 640,800 1920,1080; do
  if "$lenslab" view --camera "$src/assets/rows/camera-lens.json" --width 321 --max-samples 4 --frames 3 --window-size "$size" \
       --screenshot "$work/fit.png" --stats "$work/fit.json" >"$work/fit.out" 2>&1; then
    if grep -qF '"panel_clipped_items": 0' "$work/fit.json" && tr -d ' \n' <"$work/fit.json" | grep -qF "\"window\":[${size}]"; then pass
    else fail "window $size: panel text cut off: $(grep -E 'panel|window' "$work/fit.json" | tr -d '\n')"; fi
  else
    fail "view --window-size $size failed: $(cat "$work/fit.out")"
  fi
done
# The post-process baseline shown in place of the accumulated image.
if "$lenslab" view --camera "$dof" --width 320 --max-samples 8 --frames 2 --window-size 1200,800 --baseline \
     --screenshot "$work/baseline.png" >"$work/baseline.out" 2>&1; then
  if "$check" busy "$work/baseline.png" 100 0 700 400 0.05; then pass; else fail "baseline: flat image"; fi
else
  fail "view --baseline failed: $(cat "$work/baseline.out")"
fi
# Without the UI the image alone:
if "$lenslab" view --camera "$dof" --width 320 --max-samples 8 --frames 3 --window-size 1200,800 --no-ui \
     --screenshot "$work/noui.png" >/dev/null 2>&1; then
  if "$check" busy "$work/noui.png" 0 0 320 213 0.05 >/dev/null; then pass; else fail "--no-ui screenshot is flat"; fi
else
  fail "view --no-ui with a window size failed"
fi

# A width whose rounded height makes pixels not square is said once, with the sizes that keep them square.
if "$lenslab" view --camera "$dof" --width 320 --max-samples 2 --frames 1 --no-ui --screenshot "$work/sq.png" 2>"$work/sq.err" >/dev/null &&
   [ "$(grep -c "^lenslab: warning: 320x213 makes pixels 0.16 % taller than wide" "$work/sq.err")" -eq 1 ] &&
   grep -qF -- "--width 318 (212 high) or --width 321 (214 high)" "$work/sq.err"; then pass
else fail "view --width 320: $(cat "$work/sq.err")"; fi

# A scripted run reports progress in a log as render does (here a line at every frame).
if LENSLAB_PROGRESS_SECONDS=0 "$lenslab" view --camera "$dof" --width 96 --aperture-samples 16 --frame-budget-ms 1 --frames 2 --no-ui \
     --screenshot "$work/progress.png" 2>"$work/progress.err" >/dev/null &&
   grep -qE '^lenslab: view: [0-9]+/16 samples, [0-9.]+ s, [0-9.]+ s to go$' "$work/progress.err" &&
   [ "$(grep -E '^lenslab: view: ' "$work/progress.err" | tail -1 | grep -cE '^lenslab: view: 16/16 samples, [0-9.]+ s$')" -eq 1 ]; then pass
else fail "view progress lines: $(cat "$work/progress.err")"; fi

# ---- bad input: one line, non-zero exit ----
expect_refusal() {
  local name=$1 fragment=$2
  shift 2
  "$lenslab" "$@" >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  if [ "$rc" -eq 0 ]; then fail "$name: exit 0"; return; fi
  if [ "$(wc -l <"$work/stderr")" -ne 1 ]; then fail "$name: stderr: $(cat "$work/stderr")"; return; fi
  if ! grep -qF -- "$fragment" "$work/stderr"; then fail "$name: stderr lacks '$fragment': $(cat "$work/stderr")"; return; fi
  pass
}
expect_refusal "bad screenshot extension" "unsupported image type" view --frames 1 --screenshot "$work/out.jpg"
expect_refusal "screenshot without frames" "--frames" view --screenshot "$work/out.png"
expect_refusal "click on the sky" "--click 50,2: nothing of the scene" view --camera "$dof" --width 96 --frames 1 --no-ui --click 50,2
expect_refusal "click outside the image" "--click 500,2: the pixel is outside the 96x64 image" view --camera "$dof" --width 96 --frames 1 --no-ui --click 500,2
expect_refusal "focus outside the image" "--focus-at 500,2: the pixel is outside" view --camera "$dof" --width 96 --frames 1 --no-ui --focus-at 500,2
expect_refusal "missing camera" "nope.json" view --camera "$work/nope.json" --frames 1
expect_refusal "--image without --colmap" "give --colmap" view --image f_0.png --frames 1
[ ! -e "$work/out.png" ] && pass || fail "a refused run left a screenshot"

echo "view tests: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
