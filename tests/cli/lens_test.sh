#!/usr/bin/env bash
# `lenslab lens` as a user meets it (docs/lenses.md): each bundled prescription described, as text
# and as JSON whose numbers agree with the design; bad files and options refused in one line.
# usage: lens_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"
lenses=$src/assets/lenses
refused() { if one_line_error "$@"; then pass; fi; }

# --- every bundled lens, text and JSON ---
for lens in double-gauss-50mm telephoto-250mm wide-angle-28mm fisheye-10mm; do
  sensor=36x24
  [ "$lens" = fisheye-10mm ] && sensor=18x18
  if "$lenslab" lens "$lenses/$lens.lens" --sensor "$sensor" >"$work/$lens.txt" 2>"$work/err"; then
    check grep -q '^focal length' "$work/$lens.txt"
    check grep -q '^field of view' "$work/$lens.txt"
  else
    fail "$lens: $(cat "$work/err")"
  fi
  if "$lenslab" lens "$lenses/$lens.lens" --sensor "$sensor" --json >"$work/$lens.json" 2>"$work/err"; then
    focal=${lens##*-}
    focal=${focal%mm}
    check holds "$work/$lens.json" "abs(j['focal_length_mm'] / $focal - 1) < 0.015 and len(j['field']) == 11 and j['field'][0]['relative_illumination'] == 1"
  else
    fail "$lens --json: $(cat "$work/err")"
  fi
done
check holds "$work/fisheye-10mm.json" "'equidistant_fit' in j and j['equidistant_fit']['rms_error_percent'] < 1"
check holds "$work/double-gauss-50mm.json" "'equidistant_fit' not in j and 2.0 < j['f_number'] < 2.1"

# Stopped down and focused close: the working f-number grows with the magnification.
if "$lenslab" lens "$lenses/double-gauss-50mm.lens" --f-number 8 --focus-mm 500 --json >"$work/close.json" 2>"$work/err"; then
  check holds "$work/close.json" "abs(j['f_number'] - 8) < 1e-6 and j['working_f_number'] > 8.5 and j['magnification'] < 0"
else
  fail "close focus: $(cat "$work/err")"
fi

# --plot: an SVG with the lens and its two charts; nothing written when refused.
if "$lenslab" lens "$lenses/double-gauss-50mm.lens" --plot "$work/gauss.svg" >/dev/null 2>"$work/err"; then
  check grep -q '^<svg ' "$work/gauss.svg"
  check grep -q 'distortion (%)' "$work/gauss.svg"
  check test "$(grep -c '<polyline' "$work/gauss.svg")" -gt 20
else
  fail "--plot: $(cat "$work/err")"
fi
refused "plot not svg" "give a file name ending in .svg" -- lens "$lenses/double-gauss-50mm.lens" --plot "$work/plot.png"
check test ! -e "$work/plot.png"
refused "plot beyond the image circle" "the lens covers a circle of" -- lens "$lenses/fisheye-10mm.lens" --plot "$work/fish.svg"
check test ! -e "$work/fish.svg"

# --- refusals ---
printf '0 2 0 10\n50 x 1.5 20\n-50 0 1 20\n' >"$work/bad.lens"
refused "bad number" "bad.lens: row 2 (line 2), column 2 (thickness_mm): 'x' is not a number" -- lens "$work/bad.lens"
refused "missing file" "no-such.lens" -- lens "$work/no-such.lens"
refused "beyond the image circle" "the lens covers a circle of" -- lens "$lenses/fisheye-10mm.lens"
refused "f-number too fast" "f/1 is faster than the design's full opening" -- lens "$lenses/double-gauss-50mm.lens" --f-number 1
refused "f-number past rounding" "f/1.95 is faster than the design's full opening, f/2.03" -- lens "$lenses/double-gauss-50mm.lens" --f-number 1.95
# As people type it: the f/2 double Gauss (f/2.03 by its numbers) takes --f-number 2, at its full opening.
if "$lenslab" lens "$lenses/double-gauss-50mm.lens" --f-number 2 --json >"$work/f2.json" 2>"$work/err"; then
  check holds "$work/f2.json" "abs(j['f_number'] - 2.03) < 0.01"
else
  fail "lens --f-number 2: $(cat "$work/err")"
fi
refused "bad sensor" "--sensor" -- lens "$lenses/double-gauss-50mm.lens" --sensor 36
refused "focus too close" "no real image" -- lens "$lenses/double-gauss-50mm.lens" --focus-mm 100

# --- raycast --lens: the reference image through a prescription ---
dof=$src/assets/rows/camera-dof.json
if "$lenslab" raycast --camera "$dof" --lens "$lenses/double-gauss-50mm.lens" --f-number 4 --width 48 --spp 4 \
     --out "$work/gauss.exr" --stats "$work/gauss.json" -q 2>"$work/err"; then
  check test -s "$work/gauss.exr"
  check holds "$work/gauss.json" "'double-gauss-50mm.lens' in j['plan']['passes'][0]['why']"
else
  fail "raycast --lens: $(cat "$work/err")"
fi
refused "lens faster than the design" "faster than the design's full opening" -- raycast --camera "$dof" --lens "$lenses/double-gauss-50mm.lens" --width 16 --spp 1 --out "$work/fast.png"
check test ! -e "$work/fast.png"
refused "lens with blades" "remove --blades and --squeeze" -- raycast --camera "$dof" --lens "$lenses/double-gauss-50mm.lens" --f-number 4 --blades 6 --width 16 --spp 1 --out "$work/blades.png"
refused "lens with the camera's effects" "the prescription has its own" -- raycast --camera "$src/assets/rows/camera-lens.json" --lens "$lenses/double-gauss-50mm.lens" --f-number 4 --width 16 --spp 1 --out "$work/effects.png"
refused "missing lens file" "no-such.lens" -- raycast --camera "$dof" --lens "$work/no-such.lens" --width 16 --spp 1 --out "$work/none.png"
check test ! -e "$work/none.png"

# --- render --lens: the fitted real-time lens, or the exact trace past --lens-tolerance ---
if "$lenslab" lens "$lenses/double-gauss-50mm.lens" --json >"$work/fit-report.json" 2>"$work/err"; then
  check holds "$work/fit-report.json" "j['fit']['usable'] and j['fit']['error']['position_um'] < 3 and j['fit']['barrel']['diameter_mm'] > 0"
else
  fail "lens --json fit: $(cat "$work/err")"
fi
if "$lenslab" render --camera "$dof" --lens "$lenses/double-gauss-50mm.lens" --f-number 4 --width 48 --aperture-samples 8 \
     --aov depth,instance --out "$work/fitted.exr" --stats "$work/fitted.json" 2>"$work/err"; then
  check grep -q "the fitted thin lens, off by up to" "$work/err"
  check holds "$work/fitted.json" "'(fitted)' in j['camera'] and j['lens']['barrel'] and j['renderer'] != 'lenslab ray caster (Embree, TBB)'"
else
  fail "render --lens: $(cat "$work/err")"
fi
if "$lenslab" render --camera "$dof" --lens "$lenses/double-gauss-50mm.lens" --f-number 4 --width 48 --aperture-samples 2 \
     --lens-tolerance 0 --aov depth,instance --out "$work/traced.exr" --stats "$work/traced.json" 2>"$work/err"; then
  check grep -q "above --lens-tolerance 0: tracing the lens exactly, 2 rays per pixel" "$work/err"
  check holds "$work/traced.json" "j['renderer'] == 'lenslab ray caster (Embree, TBB)' and j['command'] == 'render'"
else
  fail "render --lens --lens-tolerance 0: $(cat "$work/err")"
fi
# The AOVs follow the traced lens whichever renderer made the image (docs/capture.md): the same
# depth and instance from the fitted raster, the exact trace and raycast --lens.
"$lenslab" raycast --camera "$dof" --lens "$lenses/double-gauss-50mm.lens" --f-number 4 --width 48 --spp 1 \
  --aov depth,instance --out "$work/raycast-aov.exr" -q 2>"$work/err" || fail "raycast --lens --aov: $(cat "$work/err")"
for f in fitted traced raycast-aov; do oiiotool "$work/$f.exr" --ch Z,instance -o "$work/$f-aov.exr" 2>/dev/null; done
for f in traced raycast-aov; do
  if same_pixels "$work/fitted-aov.exr" "$work/$f-aov.exr"; then pass; else fail "render --lens --aov and $f differ in depth or instance"; fi
done

# Automatic framing under --lens frames the field the lens renders: the prescription's 50.36 mm,
# not the default 35 mm (which cropped the subject once the lens rendered it).
python3 - "$src/assets/grid/grid.gltf" "$work/nocam.gltf" <<'EOF'
import json, sys
g = json.load(open(sys.argv[1]))
g.pop("cameras", None)
for n in g["nodes"]:
    n.pop("camera", None)
json.dump(g, open(sys.argv[2], "w"))
EOF
cp "$src/assets/grid/grid.bin" "$work/"
if "$lenslab" render "$work/nocam.gltf" --lens "$lenses/double-gauss-50mm.lens" --width 48 --aperture-samples 4 \
     --out "$work/framed.png" --stats "$work/framed.json" -q 2>"$work/err"; then
  check holds "$work/framed.json" "j['camera'].startswith('automatic framing') and '50.358' in j['camera']"
else
  fail "render --lens, automatic framing: $(cat "$work/err")"
fi

# The focus asked for and the fitted lens's: --stats gives both and says why they differ (the film
# is placed for the paraxial image; the traced rays at f/2 are sharpest farther out).
if "$lenslab" render --lens "$lenses/double-gauss-50mm.lens" --f-number 2 --focus-distance 4.38 --width 48 \
     --aperture-samples 2 --out "$work/focus.png" --stats "$work/focus.json" -q 2>"$work/err"; then
  check holds "$work/focus.json" "close(j['lens']['asked_focus_distance'], 4.38) and j['lens']['focus_distance'] > 4.5 and 'paraxial' in j['lens']['focus_note']"
else
  fail "render --lens --focus-distance 4.38 --stats: $(cat "$work/err")"
fi
# Without --lens there is nothing to explain.
"$lenslab" render --width 32 --stats "$work/plain.json" --out "$work/plain.png" -q 2>/dev/null
check holds "$work/plain.json" "'focus_note' not in j['lens'] and 'asked_focus_distance' not in j['lens']"

# Past the fisheye's image circle no thin lens fits: render traces it exactly, as raycast does.
if "$lenslab" render --camera "$dof" --lens "$lenses/fisheye-10mm.lens" --f-number 5.6 --width 18 --aperture-samples 1 \
     --out "$work/fisheye.png" 2>"$work/err"; then
  check grep -q "no thin lens fits (no ray through the lens reaches the film" "$work/err"
  check test -s "$work/fisheye.png"
else
  fail "render --lens fisheye: $(cat "$work/err")"
fi
refused "render --lens with the camera's effects" "the prescription has its own" -- render --camera "$src/assets/rows/camera-lens.json" --lens "$lenses/double-gauss-50mm.lens" --f-number 4 --width 16 --out "$work/effects.png"
check test ! -e "$work/effects.png"

# --- sweep --lens: the fit against the exact lens, effect by effect ---
if "$lenslab" sweep --camera "$dof" --lens "$lenses/double-gauss-50mm.lens" --f-number 4 --width 32 --reference-spp 8 --max-views 4 \
     --max-spp 2 --methods sobol,raycast --out "$work/sweep" -q 2>"$work/err"; then
  check grep -q "## The fitted lens, effect by effect" "$work/sweep/sweep.md"
  check grep -q "| without distortion |" "$work/sweep/sweep.md"
  check grep -q "the reference and the ray-cast rows trace it exactly" "$work/sweep/sweep.md"
else
  fail "sweep --lens: $(cat "$work/err")"
fi

echo "lens: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
