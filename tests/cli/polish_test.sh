#!/usr/bin/env bash
# What a new user meets first: progress in a log (not a terminal), a mistyped command or option,
# options a command does not take, messages that name the option given, the sweep's file names,
# capture's stepped frames and the warning for pixels that are not square.
# usage: polish_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"
unset LENSLAB_PROGRESS_SECONDS
dof=$src/assets/rows/camera-dof.json
lens=$src/assets/rows/camera-lens.json

# check_progress NAME FILE LABEL UNIT_REGEX: FILE's progress lines for LABEL are well formed, their
# counts never fall, there are at least two, and the last says done = total with no time to go.
check_progress() {
  local name=$1 file=$2 label=$3 unit=$4
  local lines
  lines=$(grep -E "^lenslab: $label: [0-9]+/[0-9]+ " "$file")
  if [ "$(wc -l <<<"$lines")" -lt 2 ]; then fail "$name: fewer than two progress lines: $(cat "$file")"; return; fi
  local format="^lenslab: $label: [0-9]+/[0-9]+ $unit, [0-9]+\.[0-9] s(, [0-9]+\.[0-9] s to go)?(; .*)?$"
  if grep -vqE "$format" <<<"$lines"; then fail "$name: a line not in the format: $(grep -vE "$format" <<<"$lines" | head -1)"; return; fi
  if ! awk -F'[ /]' '{ done = $3 + 0; if (done < last) exit 1; last = done }' <<<"$lines"; then
    fail "$name: done fell: $lines"; return
  fi
  local final
  final=$(tail -1 <<<"$lines")
  if ! grep -qE "^lenslab: $label: ([0-9]+)/\1 $unit, [0-9]+\.[0-9] s(; .*)?$" <<<"$final"; then
    fail "$name: the last line is not done = total: $final"; return
  fi
  pass
}

# ---- A. progress where stderr is not a terminal ----
# A line at every step (LENSLAB_PROGRESS_SECONDS=0), so that a short render shows the format.
if LENSLAB_PROGRESS_SECONDS=0 "$lenslab" render --camera "$dof" --width 96 --aperture-samples 8 --out "$work/p.png" 2>"$work/p.err"; then
  check_progress "render" "$work/p.err" render "samples"
  # The last progress line comes before the line saying the file was written.
  if tail -1 "$work/p.err" | grep -q "^lenslab: wrote " && tail -2 "$work/p.err" | head -1 | grep -q "^lenslab: render: 8/8 samples"; then pass
  else fail "render: the last lines are not the final progress and 'wrote': $(tail -2 "$work/p.err")"; fi
else
  fail "render with progress lines: $(cat "$work/p.err")"
fi
# The ray caster counts rows.
if LENSLAB_PROGRESS_SECONDS=0 "$lenslab" raycast --width 64 --spp 1 --out "$work/r.png" 2>"$work/r.err"; then
  check_progress "raycast" "$work/r.err" raycast "rows"
  if grep -q "samples" <(grep -E '^lenslab: raycast: [0-9]' "$work/r.err"); then fail "raycast progress speaks of samples"; else pass; fi
else
  fail "raycast with progress lines: $(cat "$work/r.err")"
fi
# Tiles: samples over all tiles, and the lens tables each tile builds first.
if LENSLAB_PROGRESS_SECONDS=0 "$lenslab" render --camera "$lens" --width 96 --tile-size 48 --aperture-samples 2 --out "$work/t.png" 2>"$work/t.err"; then
  check_progress "tiled render" "$work/t.err" render "samples over [0-9]+ tiles"
  if grep -qE '^lenslab: render: 0/[0-9]+ samples over [0-9]+ tiles, .*; tile 1 of [0-9]+: inverse lens table, [0-9]+/[0-9]+ rows$' "$work/t.err"; then pass
  else fail "tiled render: no lens-table progress: $(head -3 "$work/t.err")"; fi
else
  fail "tiled render with progress lines: $(cat "$work/t.err")"
fi
# Target error: tiles at the target.
if LENSLAB_PROGRESS_SECONDS=0 "$lenslab" render --camera "$dof" --width 96 --target-psnr 30 --out "$work/a.png" 2>"$work/a.err"; then
  check_progress "render to a target" "$work/a.err" render "tiles at the target"
else
  fail "render --target-psnr with progress lines: $(cat "$work/a.err")"
fi
# Capture: a line a frame.
if LENSLAB_PROGRESS_SECONDS=0 "$lenslab" capture --path "$src/assets/rows/rack-focus.json" --width 48 --aperture-samples 2 --frames 0:3 \
     --out "$work/cap/f_%02d.png" 2>"$work/c.err"; then
  check_progress "capture" "$work/c.err" capture "frames"
  if [ "$(grep -cE '^lenslab: capture: [0-9]+/4 frames, .*; frame [0-9]+: ' "$work/c.err")" -eq 4 ]; then pass
  else fail "capture: not one line per frame: $(cat "$work/c.err")"; fi
else
  fail "capture with progress lines: $(cat "$work/c.err")"
fi
# Work shorter than the interval prints no progress at all (an hour here, so that no machine is too
# slow for it; the default, 5 s, is the unit test's); --quiet prints nothing even at 0 s.
if LENSLAB_PROGRESS_SECONDS=3600 "$lenslab" render --camera "$dof" --width 66 --aperture-samples 4 --out "$work/d.png" 2>"$work/d.err" &&
   [ "$(wc -l <"$work/d.err")" -eq 1 ] && grep -q "^lenslab: wrote " "$work/d.err"; then pass
else fail "a short render printed more than its 'wrote' line: $(cat "$work/d.err")"; fi
if LENSLAB_PROGRESS_SECONDS=0 "$lenslab" render --camera "$dof" --width 66 --aperture-samples 4 -q --out "$work/q.png" 2>"$work/q.err" &&
   [ ! -s "$work/q.err" ]; then pass
else fail "--quiet still printed: $(cat "$work/q.err")"; fi
LENSLAB_PROGRESS_SECONDS=soon expect_refusal "bad progress interval" "LENSLAB_PROGRESS_SECONDS=soon" -- render --width 32 --out "$work/out.png"

# ---- B1. a mistyped command or option: the nearest name ----
# The lecture's pattern is 17 points: another count is refused by name, not ignored.
expect_refusal "lecture17 with 5 views" "--aperture-samples 5: --pattern lecture17 is the lecture's 17 points, always 17 views" -- \
  render --pattern lecture17 --aperture-samples 5 --width 32 --out "$work/out.png"
check "$lenslab" render --pattern lecture17 --aperture-samples 17 --f-number 2 --width 32 --out "$work/l17.png" -q
expect_refusal "unknown command" 'unknown command "rendr"; did you mean "render"? (see --help)' -- rendr --out "$work/out.png"
expect_refusal "unknown command, nothing near" 'unknown command "paint"; the commands are render, raycast, capture, sweep, info, lens, view' -- paint
expect_refusal "unknown option" 'render: unknown option --widht; did you mean --width? (see lenslab render --help)' -- render --widht 64 --out "$work/out.png"
expect_refusal "unknown option with a value" 'unknown option --focus-distanse; did you mean --focus-distance?' -- view --focus-distanse=3
expect_refusal "another command's option" 'render: unknown option --spp: raycast takes it, render does not' -- render --spp 4 --out "$work/out.png"

# ---- B3. options a command would ignore: absent from its help, or refused ----
help=$("$lenslab" raycast --help)
for option in --pattern --aperture-samples --max-samples --target-psnr --backend --tile-size; do
  if grep -qE -- "^ *$option " <<<"$help"; then fail "raycast --help lists $option, which the ray caster ignores"; else pass; fi
done
for option in --spp --seed --focus-distance --focus-at --width; do
  if grep -qE -- "^ *$option " <<<"$help"; then pass; else fail "raycast --help lacks $option"; fi
done
expect_refusal "raycast --pattern" "raycast: unknown option --pattern: render, capture, view and diagram take it, raycast does not" -- \
  raycast --pattern r2 --width 16 --out "$work/out.png"
expect_refusal "a cap with a fixed count" "--max-samples: caps the count that auto (or --target-psnr) chooses" -- \
  render --aperture-samples 8 --max-samples 4 --width 16 --out "$work/out.png"
expect_refusal "two focus options" "--focus-distance excludes --focus-at" -- render --focus-at 1,1 --focus-distance 3 --out "$work/out.png"
expect_refusal "sweep budget of a series not run" "--max-spp sets the raycast series' largest budget, which --methods leaves out" -- \
  sweep --out "$work/out.sweep" --methods concentric --max-spp 8
expect_refusal "sweep targets without adaptive" "--target-psnr sets the adaptive series' targets" -- \
  sweep --out "$work/out.sweep" --methods raycast --target-psnr 30
expect_refusal "view --stats without --frames" "--stats needs --frames N" -- view --stats "$work/out.json"
expect_refusal "view --save-camera without --frames" "--save-camera needs --frames N" -- view --save-camera "$work/out.json"
# sweep --height alone: the width follows the window (rows' camera-dof.json is 3:2), not 320.
if "$lenslab" sweep --out "$work/sweep-h" --height 20 --reference-spp 2 --max-views 1 --methods concentric -q &&
   grep -q ", 30x20" "$work/sweep-h/sweep.md"; then pass
else fail "sweep --height 20: $(grep -o '[0-9]*x[0-9]*' "$work/sweep-h/sweep.md" | head -1)"; fi

# ---- B4. the sweep: as many images written as it says, each named by its own parameter ----
# Two targets low enough to stop at the same mean sample count on this small image.
if LENSLAB_PROGRESS_SECONDS=0 "$lenslab" sweep "$src/assets/occluder/occluder.gltf" --camera "$src/assets/occluder/camera-dof.json" \
     --out "$work/sweep" --width 24 --reference-spp 4 --max-views 2 --max-spp 1 --target-psnr 15,16 2>"$work/s.err"; then
  said=$(sed -n 's/^lenslab: sweep: wrote .* and \([0-9]*\) images in .*/\1/p' "$work/s.err")
  written=$(find "$work/sweep/images" -type f | wc -l)
  if [ -n "$said" ] && [ "$said" -eq "$written" ] && [ "$written" -eq $(($(wc -l <"$work/sweep/sweep.csv") - 1)) ]; then pass
  else fail "sweep said '$said' images, wrote $written, has $(($(wc -l <"$work/sweep/sweep.csv") - 1)) rows"; fi
  if [ -f "$work/sweep/images/adaptive-sobol-15dB.png" ] && [ -f "$work/sweep/images/adaptive-sobol-16dB.png" ]; then pass
  else fail "sweep: adaptive images not named by target: $(ls "$work/sweep/images")"; fi
  check_progress "sweep" <(grep -E '^lenslab: sweep: [0-9]+/[0-9]+ images' "$work/s.err") sweep "images"
  check_progress "sweep reference" <(grep -E '^lenslab: sweep: [0-9]+/[0-9]+ reference rows' "$work/s.err") sweep "reference rows"
else
  fail "sweep: $(cat "$work/s.err")"
fi
if "$lenslab" sweep "$src/assets/occluder/occluder.gltf" --camera "$src/assets/occluder/camera-dof.json" --out "$work/sweep-q" \
     --width 18 --reference-spp 2 --max-views 1 --methods concentric -q 2>"$work/sq.err" && [ ! -s "$work/sq.err" ]; then pass
else fail "sweep -q printed: $(cat "$work/sq.err")"; fi
expect_refusal "sweep target given twice" "--target-psnr: 30 dB is given twice" -- sweep --out "$work/out.sweep" --target-psnr 30,40,30
# Targets that differ only past the 10 digits that name their images: refused before the reference
# is cast (its progress lines would come first at 0 s), with no folder made.
LENSLAB_PROGRESS_SECONDS=0 expect_refusal "sweep targets that name one image" \
  "--target-psnr: 40 and 40.00000000001 dB both name the image adaptive-sobol-40dB.png" -- \
  sweep --out "$work/out.sweep" --width 16 --reference-spp 1 --max-views 1 --methods adaptive --target-psnr 40,40.00000000001
if grep -q "reference" "$work/stderr"; then fail "sweep targets that name one image: refused after the reference: $(cat "$work/stderr")"
else pass; fi

# ---- B5. capture --frames A:B:STEP, with shards splitting the stepped frames ----
rack=$src/assets/rows/rack-focus.json
if "$lenslab" capture --path "$rack" --width 32 --aperture-samples 2 --frames 0:72:24 --out "$work/step/f_%02d.png" 2>"$work/step.err" &&
   [ "$(cd "$work/step" && ls f_*.png | tr '\n' ' ')" = "f_00.png f_24.png f_48.png f_72.png " ] &&
   grep -q "captured 4 frames of frames 0..72 step 24" "$work/step.err"; then pass
else fail "--frames 0:72:24: $(ls "$work/step" 2>&1 | tr '\n' ' ') $(cat "$work/step.err")"; fi
if "$lenslab" capture --path "$rack" --width 32 --aperture-samples 2 --frames ::24 --shard 1/2 --out "$work/shard/f_%02d.png" -q &&
   [ "$(cd "$work/shard" && ls f_*.png | tr '\n' ' ')" = "f_24.png f_72.png " ]; then pass
else fail "--frames ::24 --shard 1/2: $(ls "$work/shard" 2>&1 | tr '\n' ' ')"; fi
expect_refusal "a step of 0" "--frames 0:72:0: the step after the second colon must be a whole number of frames, 1 or more" -- \
  capture --path "$rack" --frames 0:72:0 --out "$work/out.%02d.png"
expect_refusal "a step that is not a number" "--frames 0:72:two: the step" -- capture --path "$rack" --frames 0:72:two --out "$work/out.%02d.png"

# ---- B8. pixels that are not square: one warning line with the nearest sizes that keep them square ----
square_hint="320x213 makes pixels 0.16 % taller than wide (the window is 1.5:1); --width 318 (212 high) or --width 321 (214 high) keeps them square"
for cmd in render raycast; do
  opts=(--width 320)
  [ "$cmd" = raycast ] && opts+=(--spp 1)  # one sample per pixel for the ray caster; render takes no --spp
  if "$lenslab" $cmd "${opts[@]}" --out "$work/sq-$cmd.png" 2>"$work/sq.err"; then
    if [ "$(grep -c '^lenslab: warning: ' "$work/sq.err")" -eq 1 ] && grep -qF "lenslab: warning: $square_hint" "$work/sq.err"; then pass
    else fail "$cmd --width 320: $(cat "$work/sq.err")"; fi
  else
    fail "$cmd --width 320: $(cat "$work/sq.err")"
  fi
done
if "$lenslab" render --width 321 --out "$work/sq-ok.png" 2>"$work/sq.err" && ! grep -q warning "$work/sq.err"; then pass
else fail "render --width 321 warned: $(cat "$work/sq.err")"; fi
if "$lenslab" render --width 320 --height 320 --out "$work/sq-both.png" 2>"$work/sq.err" &&
   grep -qF "320x320 makes pixels 50 % wider than tall" "$work/sq.err" && [ "$(grep -c warning "$work/sq.err")" -eq 1 ]; then pass
else fail "render --width 320 --height 320: $(cat "$work/sq.err")"; fi
# capture says it once, not once a frame
if "$lenslab" capture --path "$rack" --width 320 --aperture-samples 1 --frames 0:2 --out "$work/sqcap/f_%02d.png" 2>"$work/sq.err" &&
   [ "$(grep -c "^lenslab: warning: 320x213 makes pixels" "$work/sq.err")" -eq 1 ]; then pass
else fail "capture --width 320: $(cat "$work/sq.err")"; fi
# sweep's default width (about 320) is one that keeps pixels square: 321x214 on the 3:2 camera, no warning
if "$lenslab" sweep --out "$work/sweep-d" --reference-spp 1 --max-views 1 --methods concentric 2>"$work/sq.err" &&
   grep -q ", 321x214" "$work/sweep-d/sweep.md" && ! grep -q warning "$work/sq.err"; then pass
else fail "sweep's default size: $(grep -o '[0-9]*x[0-9]*' "$work/sweep-d/sweep.md" | head -1) $(grep warning "$work/sq.err")"; fi

echo "polish tests: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
