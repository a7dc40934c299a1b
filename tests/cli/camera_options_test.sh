#!/usr/bin/env bash
# The camera options as a user meets them on the command line: --focal-length, --f-number,
# --sensor, --eye, --target, --camera-node and --animation on render, raycast, view and capture
# (and --camera-node on info and sweep), over a glTF written here: composition with camera files,
# focus on a clicked pixel from these options alone, glTF cameras by name and index, clips, a
# capture that follows an animated glTF camera, warnings on a pinhole, refusals in one line.
# usage: camera_options_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"

# json FILE EXPRESSION: a value from a JSON file (j is the document).
json() { $python -c "import json,sys; j=json.load(open(sys.argv[1])); print($2)" "$1"; }
# near A B TOLERANCE: |A - B| <= TOLERANCE
near() { $python -c "import sys; a,b,t=map(float,sys.argv[1:]); sys.exit(0 if abs(a-b)<=t else 1)" "$1" "$2" "$3"; }

# The scene: a near quad (z = 2, left of centre) and a far quad (z = -4, right of centre), both
# facing +Z; cameras "Left" (node; its camera "LeftLens") and "Right" looking down -Z from z = 6;
# clip 0 "up" lifts the near quad by 1 over 1 s and moves "Left" back to z = 8; clip 1 "down"
# lowers the near quad by 1 over 2 s.
make_gltf=$(cat <<'EOF'
import base64, json, struct, sys
def quad(x0, x1, y0, y1, z): return [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]
pos = quad(-2.5, -0.3, -1.5, 1.5, 2.0) + quad(0.3, 4.0, -2.5, 2.5, -4.0)
idx = [0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7]
f = lambda *v: struct.pack("<%df" % len(v), *v)
chunks = [b"".join(f(*p) for p in pos), struct.pack("<12H", *idx),
          f(0, 1), f(0, 0, 0, 0, 1, 0), f(-1.4, 0, 6, -1.4, 0, 8), f(0, 2), f(0, 0, 0, 0, -1, 0)]
data, views = b"", []
for c in chunks:
    views.append({"buffer": 0, "byteOffset": len(data), "byteLength": len(c)})
    data += c + b"\0" * (-len(c) % 4)
acc = lambda v, t, n, c=5126: {"bufferView": v, "componentType": c, "count": n, "type": t}
accessors = [dict(acc(0, "VEC3", 8), min=[-2.5, -2.5, -4.0], max=[4.0, 2.5, 2.0]), acc(1, "SCALAR", 12, 5123),
             dict(acc(2, "SCALAR", 2), min=[0], max=[1]), acc(3, "VEC3", 2), acc(4, "VEC3", 2),
             dict(acc(5, "SCALAR", 2), min=[0], max=[2]), acc(6, "VEC3", 2)]
persp = lambda name: {"type": "perspective", "name": name, "perspective": {"yfov": 0.7, "aspectRatio": 1.5, "znear": 0.1}}
lin = lambda i, o: {"input": i, "output": o, "interpolation": "LINEAR"}
gltf = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"mesh": 0, "name": "quads"}, {"camera": 0, "name": "Left", "translation": [-1.4, 0, 6]},
                  {"camera": 1, "name": "Right", "translation": [2, 0, 6]}],
        "cameras": [persp("LeftLens"), persp("RightLens")],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "animations": [{"name": "up", "samplers": [lin(2, 3), lin(2, 4)],
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}},
                                     {"sampler": 1, "target": {"node": 1, "path": "translation"}}]},
                       {"name": "down", "samplers": [lin(5, 6)], "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}],
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": views, "accessors": accessors}
json.dump(gltf, open(sys.argv[1], "w"))
EOF
)
$python -c "$make_gltf" "$work/quads.gltf"
scene=$work/quads.gltf
"$lenslab" info "$scene" >"$work/info.txt" || fail "info"

# --- every image command takes the options; info lists cameras and clips ---
for cmd in render raycast view capture; do
  help=$("$lenslab" $cmd --help)
  for option in --focal-length --f-number --sensor --eye --target --camera-node --animation; do
    if grep -q -- "$option" <<<"$help"; then pass; else fail "$cmd --help lacks $option"; fi
  done
done
if "$lenslab" info --help | grep -q -- --camera-node; then pass; else fail "info --help lacks --camera-node"; fi
for option in --focal-length --f-number --sensor --eye --target --camera-node; do
  if "$lenslab" sweep --help | grep -q -- "$option"; then pass; else fail "sweep --help lacks $option"; fi
done
# A sweep needs an aperture: a glTF camera gets one from --f-number.
if "$lenslab" sweep "$scene" --camera-node Right --f-number 2 --width 24 --reference-spp 2 --max-views 2 \
     --methods concentric --out "$work/sweep" 2>/dev/null && grep -q "camera glTF camera 1 (Right) as .* mm on 36x24 mm, --f-number 2" "$work/sweep/sweep.md"; then pass
else fail "sweep --camera-node Right --f-number 2"; fi
for line in '\[0\] node "Left" (camera "LeftLens"): perspective, yfov 40.107' '\[1\] node "Right" (camera "RightLens")' \
            '\[0\] "up": 1 s, 2 channel' '\[1\] "down": 2 s, 1 channel'; do
  if grep -q "$line" "$work/info.txt"; then pass; else fail "info lacks $line: $(cat "$work/info.txt")"; fi
done
"$lenslab" info "$scene" --camera-node Right | grep -q '^render      camera: glTF camera 1 (Right)' && pass || fail "info --camera-node Right"

# --- depth of field from these options alone: the plane of focus at the clicked depth ---
# The camera at z = 10 looking at the origin: the near quad is 8 away (left, pixel 123,160 of
# 480x320), the far one 14 (right, pixel 340,160).
view=(--eye 0,0,10 --target 0,0,0 --width 480 --max-samples 8 -q)
for case in "123,160 8" "340,160 14"; do
  set -- $case
  if "$lenslab" render "$scene" "${view[@]}" --f-number 2 --focal-length 50 --focus-at "$1" --out "$work/focus.png" --stats "$work/focus.json"; then
    d=$(json "$work/focus.json" 'j["lens"]["focus_distance"]')
    if near "$d" "$2" 0.02; then pass; else fail "--focus-at $1: focus distance $d, the quad is $2 away"; fi
    if holds "$work/focus.json" 'close([j["lens"]["focal_length_mm"], j["lens"]["f_number"], j["lens"]["aperture_radius"]], [50, 2, 0.0125])'; then pass
    else fail "--focal-length 50 --f-number 2: $(json "$work/focus.json" 'j["lens"]')"; fi
  else
    fail "render --f-number 2 --focal-length 50 --focus-at $1"
  fi
done
# raycast focuses through the same options (its own depth).
if "$lenslab" raycast "$scene" --eye 0,0,10 --target 0,0,0 --width 120 -q --spp 2 --f-number 2 --focus-at 30,40 --out "$work/focus-rc.png" --stats "$work/focus-rc.json" &&
   near "$(json "$work/focus-rc.json" 'j["lens"]["focus_distance"]')" 8 0.05; then pass; else fail "raycast --focus-at"; fi
# The same from automatic framing: the scene without its cameras, a pixel just right of the centre on
# the far quad, whose corners lie between these depths along the view.
$python -c 'import json,sys; g=json.load(open(sys.argv[1])); del g["cameras"]; [n.pop("camera", None) for n in g["nodes"]]; json.dump(g, open(sys.argv[2], "w"))' \
  "$scene" "$work/nocam.gltf"
if "$lenslab" render "$work/nocam.gltf" --f-number 2 --focus-at 540,250 --max-samples 4 --out "$work/auto.png" --stats "$work/auto.json" -q; then
  if holds "$work/auto.json" '[min(d) <= j["lens"]["focus_distance"] <= max(d) for e, t in [(j["lens"]["eye"], j["lens"]["target"])]
      for f in [[b - a for a, b in zip(e, t)]] for n in [sum(x * x for x in f) ** 0.5]
      for d in [[sum((c - a) * b / n for a, b, c in zip(e, f, (x, y, -4.0))) for x in (0.3, 4.0) for y in (-2.5, 2.5)]]][0]'; then pass
  else fail "automatic framing --focus-at 540,250 is not on the far quad: $(json "$work/auto.json" 'j["lens"]')"; fi
  if grep -q '"camera": "automatic framing: ' "$work/auto.json"; then pass; else fail "not the automatic framing: $(json "$work/auto.json" 'j["camera"]')"; fi
else
  fail "render SCENE --f-number 2 --focus-at (automatic framing)"
fi

# --- glTF cameras by node name, camera name and index ---
"$lenslab" render "$scene" --camera-node Left --width 96 --out "$work/left.png" -q || fail "--camera-node Left"
"$lenslab" render "$scene" --camera-node 0 --width 96 --out "$work/left0.png" -q || fail "--camera-node 0"
"$lenslab" render "$scene" --camera-node RightLens --width 96 --out "$work/right.png" -q || fail "--camera-node RightLens"
if cmp -s "$work/left.png" "$work/left0.png"; then pass; else fail "--camera-node Left and 0 differ"; fi
if ! cmp -s "$work/left.png" "$work/right.png"; then pass; else fail "--camera-node Left and RightLens give the same view"; fi
"$lenslab" render "$scene" --width 96 --out "$work/first.png" -q || fail "default camera"
if cmp -s "$work/first.png" "$work/left.png"; then pass; else fail "the default is not the first glTF camera"; fi
expect_refusal "unknown camera node" '--camera-node Middle: no camera of '"$scene"' has that node or camera name; it has [0] node "Left" (camera "LeftLens"), [1] node "Right" (camera "RightLens")' \
  -- render "$scene" --camera-node Middle --out "$work/out.png"
expect_refusal "camera index beyond" "--camera-node 2: $scene has 2 camera(s)" -- raycast "$scene" --camera-node 2 --out "$work/out.png"
expect_refusal "camera node with a camera file" "give one or the other" -- render "$scene" --camera "$src/assets/rows/camera.json" --camera-node 0 --out "$work/out.png"
# A glTF camera as a lens keeps its view: --f-number infinity is the same image.
"$lenslab" render "$scene" --camera-node Left --f-number infinity --width 96 --out "$work/left-lens.png" -q || fail "--f-number infinity"
if idiff -fail 0.02 -failpercent 0.5 "$work/left.png" "$work/left-lens.png" >/dev/null 2>&1; then pass
else fail "a glTF camera as a pinhole lens changed the view"; fi

# --- clips: each poses the scene its own way; render --time plays the chosen one ---
for clip in up down 0 1 all; do
  "$lenslab" render "$scene" --animation $clip --time 1 --width 96 --out "$work/clip-$clip.png" -q || fail "--animation $clip"
done
if cmp -s "$work/clip-up.png" "$work/clip-0.png" && cmp -s "$work/clip-down.png" "$work/clip-1.png"; then pass; else fail "clip by name and index differ"; fi
if ! cmp -s "$work/clip-up.png" "$work/clip-down.png"; then pass; else fail "clips up and down pose alike"; fi
if ! cmp -s "$work/clip-up.png" "$work/left.png"; then pass; else fail "--animation up --time 1 draws the rest pose"; fi
expect_refusal "unknown clip" '--animation jump: no animation of '"$scene"' has that name; it has [0] "up", [1] "down", or all' \
  -- render "$scene" --animation jump --time 1 --out "$work/out.png"
expect_refusal "clip on a still scene" "has no animations" -- render "$src/assets/rows/rows.gltf" --animation 0 --out "$work/out.png"
"$lenslab" render "$scene" --animation down --width 48 --out "$work/no-time.png" 2>"$work/stderr" || fail "--animation without --time"
if grep -q "warning: --animation down: without --time the rest pose is drawn" "$work/stderr"; then pass; else fail "no warning for --animation without --time: $(cat "$work/stderr")"; fi

# --- --eye / --target over a camera file ---
if "$lenslab" render --camera "$src/assets/rows/camera-dof.json" --eye 1,1,4 --width 96 --max-samples 2 --out "$work/moved.png" --stats "$work/moved.json" -q &&
   holds "$work/moved.json" 'close(j["lens"]["eye"] + j["lens"]["target"] + [j["lens"]["focus_distance"], j["lens"]["f_number"]], [1, 1, 4, 0, 0.55, -2, 2, 1.4])'; then pass
else fail "--eye over camera-dof.json: $(json "$work/moved.json" 'j["lens"]')"; fi
# camera.json is focused at 4 m, not on its target: moving the target keeps that; a sensor and lens change.
if "$lenslab" render --target 0,0.55,0 --sensor aps-c --focal-length 24 --width 96 --out "$work/moved2.png" --stats "$work/moved2.json" -q &&
   holds "$work/moved2.json" 'close(j["lens"]["target"] + [j["lens"]["focus_distance"]] + j["lens"]["sensor_mm"] + [j["lens"]["focal_length_mm"]], [0, 0.55, 0, 4, 23.6, 15.6, 24])'; then pass
else fail "--target --sensor --focal-length over camera.json: $(json "$work/moved2.json" 'j["lens"]')"; fi
cat >"$work/lecture.json" <<'EOF'
{"vrp": [0, 0.5, 0], "vpn": [0, 0, 1], "prp": [0, 0, 4], "window": [-1.5, -1, 1.5, 1]}
EOF
expect_refusal "f-number on the lecture form" "--f-number 2: $work/lecture.json is in the lecture form, which has no focal length: give --focal-length too, or aperture_radius in the file" \
  -- render --camera "$work/lecture.json" --f-number 2 --out "$work/out.png"
if "$lenslab" render --camera "$work/lecture.json" --f-number 2 --focal-length 50 --width 64 --max-samples 2 --out "$work/lecture.png" --stats "$work/lecture-s.json" -q &&
   near "$(json "$work/lecture-s.json" 'j["lens"]["aperture_radius"]')" 0.0125 1e-12; then pass; else fail "lecture form with --f-number and --focal-length"; fi
expect_refusal "eye on the lecture form" "--eye: $work/lecture.json is in the lecture form" -- render --camera "$work/lecture.json" --eye 0,0,3 --out "$work/out.png"
expect_refusal "sensor on the lecture form" "(it has no sensor)" -- raycast --camera "$work/lecture.json" --sensor aps-c --out "$work/out.png"

# --- warnings on a pinhole, refusals of bad values ---
for focus in "--focus-distance 3" "--focus-at 40,30"; do
  if "$lenslab" render $focus --width 64 --out "$work/pinhole.png" 2>"$work/stderr" && [ -s "$work/pinhole.png" ] &&
     grep -q "warning: ${focus%% *} .*the camera has no aperture (a pinhole), so focus changes nothing; give --f-number" "$work/stderr"; then pass
  else fail "$focus on a pinhole: $(cat "$work/stderr")"; fi
done
if "$lenslab" render --camera "$src/assets/rows/camera-dof.json" --focus-distance 3 --width 48 --max-samples 2 --out "$work/lens.png" 2>"$work/stderr" &&
   ! grep -q warning "$work/stderr"; then pass; else fail "a warning with an aperture: $(cat "$work/stderr")"; fi
expect_refusal "f-number zero" "--f-number 0: give a positive number" -- render --f-number 0 --out "$work/out.png"
expect_refusal "sensor word" "--sensor 36by24: give WIDTHxHEIGHT in millimetres (e.g. 36x24), or one of full-frame (36x24)" -- render --sensor 36by24 --out "$work/out.png"
expect_refusal "eye with two numbers" "--eye" -- render --eye 1,2 --out "$work/out.png"
expect_refusal "target not finite" "--target" -- render --target 1,nan,2 --out "$work/out.png"
expect_refusal "focal length zero" "--focal-length" -- render --focal-length 0 --out "$work/out.png"
expect_refusal "eye at the target" "eye and target are the same point" -- render "$scene" --eye 1,1,1 --target 1,1,1 --out "$work/out.png"

# --- capture: options over every key; a glTF camera followed through its clip ---
expect_refusal "capture --path with --eye" "--eye: --path $src/assets/rows/rack-focus.json gives each frame's eye and target" \
  -- capture --path "$src/assets/rows/rack-focus.json" --eye 0,1,3 --out "$work/out.d/f_%d.png"
expect_refusal "capture --path with --camera-node" "give one or the other" -- capture "$scene" --path "$src/assets/rows/rack-focus.json" --camera-node 0 --out "$work/out.d/f_%d.png"
if "$lenslab" capture --path "$src/assets/rows/rack-focus.json" --frames 0:1 --f-number 8 --focal-length 50 --width 48 --out "$work/rack/f_%d.png" -q &&
   [ "$($python -c 'import json,sys; print(sorted({(l["f_number"], l["focal_length_mm"]) for l in map(json.loads, open(sys.argv[1]))}))' "$work/rack/manifest.jsonl")" = "[(8.0, 50.0)]" ]; then pass
else fail "capture --path with --f-number 8 --focal-length 50: $(cat "$work/rack/manifest.jsonl")"; fi
# "Left" moves from z = 6 to 8 over clip "up" (1 s): 5 frames at 4 fps, each frame's camera there.
if "$lenslab" capture "$scene" --camera-node Left --animation up --fps 4 --width 48 --out "$work/follow/f_%d.png" -q; then
  if [ "$(ls "$work"/follow/f_*.png | wc -l)" -eq 5 ]; then pass; else fail "capture --fps 4 over 1 s: $(ls "$work/follow")"; fi
  for k in "0 6" "2 7" "4 8"; do
    set -- $k
    z=$(json "$work/follow/f_$1.camera.json" 'j["eye"][2]')
    if near "$z" "$2" 1e-9; then pass; else fail "frame $1: the camera's eye at z = $z, the node at $2"; fi
  done
  # A frame's camera file and its time reproduce it with render.
  seed=$($python -c 'import json,sys; print([l for l in map(json.loads, open(sys.argv[1])) if l["frame"] == 2][0]["seed"])' "$work/follow/manifest.jsonl")
  "$lenslab" render "$scene" --camera "$work/follow/f_2.camera.json" --animation up --time 0.5 --seed "$seed" --out "$work/follow-r.png" -q
  if cmp -s "$work/follow-r.png" "$work/follow/f_2.png"; then pass; else fail "render of frame 2's camera differs from the frame"; fi
else
  fail "capture --camera-node Left --animation up --fps 4"
fi
expect_refusal "capture with neither path nor scene" "--path: give a camera path (or --cameras, --colmap, --camera), or a SCENE" -- capture --out "$work/out.d/f_%d.png"

# --- lens effects' planes of focus: each command refuses one inside the focal length ---
# (raycast and sweep used to abort in Embree, rc 134, on these; render drew garbage)
for effect in '"chromatic": {"focus_distance_red": 1e-200}' '"field_curvature": {"corner_focus_distance": 1e-200}'; do
  $python -c 'import json,sys; c=json.load(open(sys.argv[1])); c.update(json.loads("{"+sys.argv[2]+"}")); json.dump(c,open(sys.argv[3],"w"))' \
    "$src/assets/rows/camera-dof.json" "$effect" "$work/near-focus.json"
  field=$($python -c 'import sys; print("chromatic.focus_distance_red" if "chromatic" in sys.argv[1] else "field_curvature.corner_focus_distance")' "$effect")
  for command in render raycast; do
    expect_refusal "$command with $field 1e-200" "near-focus.json: $field is 1e-200; it must be beyond the focal length (0.035" \
      -- $command --camera "$work/near-focus.json" --width 48 --out "$work/out.png"
  done
  expect_refusal "sweep with $field 1e-200" "$field is 1e-200; it must be beyond the focal length" \
    -- sweep --camera "$work/near-focus.json" --width 48 --out "$work/out.d"
  expect_refusal "render --focal-length 50 over $field" "$field is 1e-200" \
    -- render --camera "$work/near-focus.json" --focal-length 50 --width 48 --out "$work/out.png"
done

# --- the aperture's shape: --blades, --squeeze and the camera file's "aperture" ---
"$lenslab" render --camera "$src/assets/rows/camera-dof.json" --blades 6 --squeeze 1.5 --aperture-samples 8 --width 48 \
  --out "$work/shaped.png" --stats "$work/shaped.json" 2>"$work/stderr"
if [ -s "$work/shaped.png" ] && holds "$work/shaped.json" 'j["lens"]["aperture"]["blades"] == 6 and close(j["lens"]["aperture"]["anamorphic_squeeze"], 1.5)'; then pass
else fail "render --blades 6 --squeeze 1.5: $(cat "$work/stderr")"; fi
for bad in "--blades 2|--blades is 2; give 0 (a circle) or 3 to 64 blades" "--blades 65|--blades is 65" \
           "--squeeze 0|--squeeze is 0; give a ratio from 0.1 to 10" "--squeeze 40|--squeeze is 40"; do
  option=${bad%%|*}
  for command in render raycast; do
    expect_refusal "$command $option" "${bad#*|}" -- $command --camera "$src/assets/rows/camera-dof.json" $option --width 48 --out "$work/out.png"
  done
  expect_refusal "sweep $option" "${bad#*|}" -- sweep --camera "$src/assets/rows/camera-dof.json" $option --width 48 --out "$work/out.d"
done
$python -c 'import json,sys; c=json.load(open(sys.argv[1])); c["aperture"]={"blades": 1}; json.dump(c,open(sys.argv[2],"w"))' \
  "$src/assets/rows/camera-dof.json" "$work/blades.json"
for command in render raycast; do
  expect_refusal "$command with aperture.blades 1" 'blades.json: "aperture.blades" is 1; give 0 (a circle) or 3 to 64 blades' \
    -- $command --camera "$work/blades.json" --width 48 --out "$work/out.png"
done
if "$lenslab" render --blades 6 --width 48 --out "$work/pinhole-blades.png" 2>"$work/stderr" &&
   grep -q "warning: --blades 6: the camera has no aperture (a pinhole), so nothing is blurred into the aperture's shape" "$work/stderr"; then pass
else fail "--blades on a pinhole: $(cat "$work/stderr")"; fi

# capture: over every frame's camera, written into the frame's camera file
if "$lenslab" capture --path "$src/assets/rows/dolly-zoom.json" --f-number 2 --blades 5 --squeeze 1.5 --width 48 \
     --aperture-samples 4 --frames 96 --out "$work/cap/f_%04d.png" -q 2>"$work/stderr" &&
   holds "$work/cap/f_0096.camera.json" 'j["aperture"]["blades"] == 5 and close(j["aperture"]["anamorphic_squeeze"], 1.5)'; then pass
else fail "capture --blades 5 --squeeze 1.5: $(cat "$work/stderr"; ls "$work/cap" 2>&1)"; fi
expect_refusal "capture --blades 2" "--blades is 2; give 0 (a circle) or 3 to 64 blades" \
  -- capture --path "$src/assets/rows/dolly-zoom.json" --blades 2 --width 48 --frames 96 --out "$work/cap2/f_%04d.png"

echo "camera options: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
