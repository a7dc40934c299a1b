#!/usr/bin/env bash
# OpenCV and COLMAP cameras as a user meets them: capture --colmap-out writes the frames' cameras as
# a COLMAP text model, and render --colmap DIR --image NAME gives each frame's pixels back from it;
# a manifest line's opencv block is a camera file that gives its frame's pixels; shards writing one
# model at once leave the files one run writes; bad models and options get one line and no image.
# usage: colmap_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"

# The same view from a camera built another way (COLMAP's K, R, t instead of eye and target, its
# view plane elsewhere): the rays agree to rounding (1e-16), the float pipeline's last bits do not,
# so a pixel may land one 8-bit step away. No channel more than one step (1/255 = 0.0039) off, and
# at most 1% of the pixels off at all. (A half-pixel shift, the OpenCV/COLMAP convention mixed up,
# fails this: checked below.)
close_pixels() { idiff -fail 0 -failpercent 1 -hardfail 0.004 -warn 1 "$1" "$2" >/dev/null 2>&1; }
seed_of() {  # seed_of MANIFEST FRAME
  $python -c 'import json,sys; print([l for l in map(json.loads, open(sys.argv[1])) if l["frame"] == int(sys.argv[2])][0]["seed"])' "$1" "$2"
}

# A pinhole path through the bundled rows scene: the camera moves and turns, and its focus (so its
# focal length in pixels) changes from frame to frame.
cat >"$work/path.json" <<'EOF'
{"fps": 4, "keys": [
  {"time": 0, "eye": [0, 1, 3], "target": [0, 0.55, -2]},
  {"time": 1, "eye": [1.2, 1.3, 3.5], "target": [-0.3, 0.5, -2], "up": [0.1, 1, 0]}]}
EOF
common=(--path "$work/path.json" --width 160 -q)

# --- capture writes the model ---
"$lenslab" capture "${common[@]}" --out "$work/frames/frame_%04d.png" --colmap-out "$work/sparse" || fail "capture --colmap-out"
for f in cameras images points3D; do
  if [ -f "$work/sparse/$f.txt" ]; then pass; else fail "no $f.txt"; fi
done
check_model=$(cat <<'EOF'
import sys
lines = lambda f: [l.rstrip("\n") for l in open(f)]
cams = [l.split() for l in lines(sys.argv[1] + "/cameras.txt") if l and not l.startswith("#")]
assert len(cams) == 5 and all(c[1] == "PINHOLE" and c[2:4] == ["160", "107"] and len(c) == 8 for c in cams), cams
body = [l for l in lines(sys.argv[1] + "/images.txt") if not l.startswith("#")]
assert len(body) == 10, body                       # two lines an image
imgs = [l.split() for l in body[0::2]]
assert all(p == "" for p in body[1::2]), body      # empty POINTS2D lines
assert [i[9] for i in imgs] == [f"frame_{f:04d}.png" for f in range(5)], imgs
assert [i[0] for i in imgs] == ["1", "2", "3", "4", "5"], imgs
for i in imgs:
    q = [float(x) for x in i[1:5]]
    assert abs(sum(x * x for x in q) - 1) < 1e-12 and q[0] >= 0, q
assert [l for l in lines(sys.argv[1] + "/points3D.txt") if not l.startswith("#")] == []
EOF
)
if out=$($python -c "$check_model" "$work/sparse" 2>&1); then pass; else fail "the model's layout: $out"; fi

# --- round trip: render --colmap gives each frame's pixels; raycast takes it too ---
for f in 0 2 4; do
  name=$(printf 'frame_%04d.png' "$f")
  seed=$(seed_of "$work/frames/manifest.jsonl" "$f")
  "$lenslab" render --colmap "$work/sparse" --image "$name" --seed "$seed" --out "$work/colmap_$f.png" -q || fail "render --colmap frame $f"
  if close_pixels "$work/colmap_$f.png" "$work/frames/$name"; then pass
  else fail "render --colmap $work/sparse --image $name differs from the frame: $(idiff "$work/colmap_$f.png" "$work/frames/$name" | tail -3 | tr '\n' ' ')"; fi
done
"$lenslab" raycast --colmap "$work/sparse" --image frame_0003.png --spp 1 --out "$work/ray_colmap.png" -q || fail "raycast --colmap"
"$lenslab" raycast --camera "$work/frames/frame_0003.camera.json" --spp 1 --out "$work/ray_camera.png" -q || fail "raycast --camera"
if close_pixels "$work/ray_colmap.png" "$work/ray_camera.png"; then pass; else fail "raycast --colmap differs from raycast --camera of the frame"; fi

# --- the binary model: the same cameras and images, read back by render --colmap ---
"$lenslab" capture "${common[@]}" --out "$work/frames/frame_%04d.png" --colmap-out "$work/sparse-bin" \
  --colmap-format binary || fail "capture --colmap-format binary"
for f in cameras images points3D; do
  if [ -f "$work/sparse-bin/$f.bin" ] && [ ! -e "$work/sparse-bin/$f.txt" ]; then pass; else fail "no $f.bin alone"; fi
done
check_binary=$(cat <<'EOF'
import struct, sys
data = open(sys.argv[1] + "/cameras.bin", "rb").read()
(n,) = struct.unpack_from("<Q", data, 0)
assert n == 5 and len(data) == 8 + n * (4 + 4 + 8 + 8 + 4 * 8), (n, len(data))
for k in range(n):
    cid, model, w, h = struct.unpack_from("<IiQQ", data, 8 + k * 56)
    assert (cid, model, w, h) == (k + 1, 1, 160, 107), (cid, model, w, h)  # 1: PINHOLE
text = [l.split() for l in open(sys.argv[2] + "/cameras.txt") if l.strip() and not l.startswith("#")]
for k, line in enumerate(text):
    params = struct.unpack_from("<4d", data, 8 + k * 56 + 24)
    assert [repr(p) for p in params] == [repr(float(x)) for x in line[4:]], (params, line)
assert open(sys.argv[1] + "/points3D.bin", "rb").read() == bytes(8)
EOF
)
if out=$($python -c "$check_binary" "$work/sparse-bin" "$work/sparse" 2>&1); then pass; else fail "the binary model: $out"; fi
seed=$(seed_of "$work/frames/manifest.jsonl" 2)
"$lenslab" render --colmap "$work/sparse-bin" --image frame_0002.png --seed "$seed" --out "$work/colmap_bin.png" -q \
  || fail "render --colmap of the binary model"
if close_pixels "$work/colmap_bin.png" "$work/frames/frame_0002.png"; then pass
else fail "render --colmap of the binary model differs from the frame"; fi

# The bound above is tight enough to see COLMAP's half pixel: the model with each principal point
# moved by 0.5 px (as if OpenCV's convention had been written) must not pass.
mkdir "$work/shifted"
cp "$work/sparse/images.txt" "$work/shifted/"
awk '/^#/ {print; next} {$7 += 0.5; $8 += 0.5; print}' "$work/sparse/cameras.txt" >"$work/shifted/cameras.txt"
seed=$(seed_of "$work/frames/manifest.jsonl" 2)
"$lenslab" render --colmap "$work/shifted" --image frame_0002.png --seed "$seed" --out "$work/shifted.png" -q
if [ -f "$work/shifted.png" ] && ! close_pixels "$work/shifted.png" "$work/frames/frame_0002.png"; then pass
else fail "a half-pixel shift of the principal point passed as the frame's pixels"; fi

# --- a manifest line's opencv block is a camera file giving its frame's pixels ---
block() {  # block MANIFEST FRAME OUT
  $python -c 'import json,sys; l=[l for l in map(json.loads, open(sys.argv[1])) if l["frame"] == int(sys.argv[2])][0]; json.dump(l["opencv"], open(sys.argv[3], "w"))' "$1" "$2" "$3"
}
for f in 1 4; do
  block "$work/frames/manifest.jsonl" "$f" "$work/block_$f.json"
  seed=$(seed_of "$work/frames/manifest.jsonl" "$f")
  "$lenslab" render --camera "$work/block_$f.json" --seed "$seed" --out "$work/block_$f.png" -q || fail "render --camera block $f"
  if same_pixels "$work/block_$f.png" "$(printf "$work/frames/frame_%04d.png" "$f")"; then pass; else fail "the opencv block of frame $f differs from the frame"; fi
done
# Depth of field too: the rack focus at f/1.4 (the block carries focus_distance and aperture_radius).
rack=(--path "$src/assets/rows/rack-focus.json" --width 64 --aperture-samples 4 --frames 40 -q)
"$lenslab" capture "${rack[@]}" --out "$work/rack/frame_%04d.png" --colmap-out "$work/rack-sparse" 2>"$work/rack.err" || fail "capture rack focus"
block "$work/rack/manifest.jsonl" 40 "$work/block_rack.json"
"$lenslab" render --camera "$work/block_rack.json" --seed "$(seed_of "$work/rack/manifest.jsonl" 40)" --aperture-samples 4 \
  --out "$work/block_rack.png" -q || fail "render --camera rack block"
if same_pixels "$work/block_rack.png" "$work/rack/frame_0040.png"; then pass; else fail "the opencv block of a depth-of-field frame differs from the frame"; fi
# Without -q, --colmap-out says once that the depth of field is not in COLMAP's pinhole model.
rm -rf "$work/rack-sparse"
"$lenslab" capture --path "$src/assets/rows/rack-focus.json" --width 32 --aperture-samples 1 --frames 38:41 \
  --out "$work/rack2/frame_%04d.png" --colmap-out "$work/rack-sparse" 2>"$work/rack.err" || fail "capture rack focus, not quiet"
if [ "$(grep -c 'warning: --colmap-out: the depth of field' "$work/rack.err")" -eq 1 ]; then pass
else fail "the depth-of-field warning: $(cat "$work/rack.err")"; fi

# A stepped range's model holds the frames the range takes, and no other.
"$lenslab" capture --path "$src/assets/rows/rack-focus.json" --width 32 --aperture-samples 1 --frames 0:72:24 \
  --out "$work/stepped/frame_%04d.png" --colmap-out "$work/stepped-sparse" -q || fail "capture --frames 0:72:24 --colmap-out"
names=$(grep -v '^#' "$work/stepped-sparse/images.txt" | awk 'NR % 2 == 1 {print $10}' | tr '\n' ' ')
if [ "$names" = "frame_0000.png frame_0024.png frame_0048.png frame_0072.png " ]; then pass
else fail "--frames 0:72:24 --colmap-out: images.txt names $names"; fi

# --- shards writing one model at once leave the files one run writes ---
for i in 0 1 2; do
  "$lenslab" capture "${common[@]}" --out "$work/sharded/frame_%04d.png" --colmap-out "$work/sharded-sparse" --shard "$i/3" &
done
wait
for f in cameras images points3D; do
  if cmp -s "$work/sparse/$f.txt" "$work/sharded-sparse/$f.txt"; then pass; else fail "the shards' $f.txt differs from one run's"; fi
done
if [ -z "$(find "$work/sharded-sparse" -name '.*tmp*')" ]; then pass; else fail "temporary files left: $(ls -a "$work/sharded-sparse")"; fi

# --- what COLMAP cannot hold is refused before any frame ---
cat >"$work/odd.json" <<'EOF'
{"fps": 1, "frames": 2, "keys": [{"time": 0, "eye": [0, 1, 3], "target": [0, 0.55, -2], "distortion": {"alpha": 0.05}}]}
EOF
if one_line_error "odd-power distortion" "alpha" -- capture --path "$work/odd.json" --width 64 --out "$work/odd/f_%d.png" \
     --colmap-out "$work/odd-sparse" -q; then
  if [ ! -e "$work/odd/f_0.png" ] && [ ! -e "$work/odd-sparse/cameras.txt" ]; then pass; else fail "odd-power distortion: files written"; fi
fi
if one_line_error "name with a space" "holds a space" -- capture "${common[@]}" --out "$work/spaced/frame %d.png" \
     --colmap-out "$work/spaced-sparse"; then
  if [ -z "$(ls "$work/spaced" 2>/dev/null)" ] && [ ! -e "$work/spaced-sparse/cameras.txt" ]; then pass; else fail "name with a space: files written"; fi
fi

# --- the model's folder may not be a frame's file or the manifest: refused before any frame ---
for target in "$work/clash/frame_0002.png" "$work/clash/frame_0001.camera.json" "$work/clash/manifest.jsonl"; do
  if one_line_error "--colmap-out $(basename "$target")" "give the model a folder of its own" -- capture "${common[@]}" \
       --frames 0:3 --out "$work/clash/frame_%04d.png" --colmap-out "$target" -q; then
    if [ ! -e "$work/clash/frame_0000.png" ] && [ ! -e "$target" ]; then pass; else fail "--colmap-out $target: files written"; fi
  fi
done

# --- a long path: the model is written as it is made (memory does not grow with the frames), one
# camera shared by the frames that hold the intrinsics, a camera a frame where a zoom changes them ---
cat >"$work/long.json" <<'EOF'
{"fps": 24, "frames": 60000, "keys": [
  {"time": 0, "eye": [0, 1, 3], "target": [0, 0.55, -2], "focal_length_mm": 35},
  {"time": 1000, "eye": [0, 1, 3], "target": [0, 0.55, -2], "focal_length_mm": 50}]}
EOF
if "$lenslab" capture --path "$work/long.json" --width 32 --shard 0/60000 --out "$work/long/f_%05d.png" \
     --colmap-out "$work/long-sparse" -q 2>"$work/err"; then
  # Frames 0 to 23 999 zoom (each its own focal length); from 24 000 on they hold 50 mm: one camera.
  check grep -qx "# Number of cameras: 24001" "$work/long-sparse/cameras.txt"
  check grep -q "^# Number of images: 60000," "$work/long-sparse/images.txt"
  check test "$(awk 'NF == 10 && $1 == 60000 {print $9}' "$work/long-sparse/images.txt")" = 24001
  check test "$(awk 'NF == 10 && $1 == 30000 {print $9}' "$work/long-sparse/images.txt")" = 24001
else
  fail "capture --colmap-out of 60000 frames: $(cat "$work/err")"
fi

# --- one lens, one camera: an orbit at 35 mm computes fx from each frame's view, and the 16th digit
# differs from frame to frame (it made 2 and 3 cameras); within 1e-9 they are one CAMERA_ID ---
cat >"$work/orbit.json" <<'EOF'
{"fps": 24, "frames": 24, "keys": [
  {"time": 0, "eye": [3, 1, 0], "target": [0, 0.5, 0], "focal_length_mm": 35},
  {"time": 0.5, "eye": [0, 1, 3], "target": [0, 0.5, 0], "focal_length_mm": 35},
  {"time": 1, "eye": [-3, 1, 0], "target": [0, 0.5, 0], "focal_length_mm": 35}]}
EOF
if "$lenslab" capture --path "$work/orbit.json" --width 160 --shard 0/24 --out "$work/orbit/f_%02d.png" \
     --colmap-out "$work/orbit-sparse" -q 2>"$work/err"; then
  check grep -qx "# Number of cameras: 1" "$work/orbit-sparse/cameras.txt"
  check test "$(awk 'NF == 10 && $1 != "#" {print $9}' "$work/orbit-sparse/images.txt" | sort -u)" = 1
else
  fail "capture an orbit --colmap-out: $(cat "$work/err")"
fi

# --- bad models and options: one line, no image ---
mkdir -p "$work/bad/fov" "$work/bad/binary" "$work/bad/nopoints"
printf '# FOV\n1 FOV 64 48 50 50 32 24 0.9\n' >"$work/bad/fov/cameras.txt"
printf '1 1 0 0 0 0 0 5 1 a.png\n\n' >"$work/bad/fov/images.txt"
touch "$work/bad/binary/cameras.bin" "$work/bad/binary/images.bin"
printf '1 PINHOLE 64 48 50 50 32 24\n' >"$work/bad/nopoints/cameras.txt"
printf '1 1 0 0 0 0 0 5 1 a.png\n2 1 0 0 0 0 0 5 1 b.png\n' >"$work/bad/nopoints/images.txt"
bad() {  # bad NAME FRAGMENT -- ARGS: one line holding FRAGMENT, and no image
  rm -f "$work/bad.png"
  if one_line_error "$@" --out "$work/bad.png"; then
    if [ ! -e "$work/bad.png" ]; then pass; else fail "$1: wrote an image"; fi
  fi
}
bad "--colmap without --image" "give --image" -- render --colmap "$work/sparse"
bad "--image without --colmap" "give --colmap" -- render --image frame_0000.png
bad "--colmap with --camera" "both give the camera" -- render --colmap "$work/sparse" --image frame_0000.png \
  --camera "$src/assets/rows/camera.json"
bad "unknown image" "frame_0000.png, frame_0001.png" -- render --colmap "$work/sparse" --image nothere.png
bad "no such folder" "not a folder" -- render --colmap "$work/missing" --image a.png
bad "FOV model" "cameras.txt:2: camera 1 is FOV" -- render --colmap "$work/bad/fov" --image a.png
bad "empty binary model" "cameras.bin: the file ends inside the number of cameras" \
  -- raycast --colmap "$work/bad/binary" --image a.png
bad "no POINTS2D lines" "images.txt:2:" -- render --colmap "$work/bad/nopoints" --image a.png
bad "--colmap with --camera-node" "gives the camera already" -- render --colmap "$work/sparse" --image frame_0000.png \
  --camera-node 0

# --- a COLMAP camera composes with the lens options: an aperture and a focus give depth of field ---
seed=$(seed_of "$work/frames/manifest.jsonl" 2)
if "$lenslab" render --colmap "$work/sparse" --image frame_0002.png --seed "$seed" --focal-length 50 --f-number 1.4 \
     --focus-distance 0.5 --aperture-samples 16 --out "$work/colmap_dof.png" --stats "$work/colmap_dof.json" -q; then
  if $python -c 'import json,sys; s=json.load(open(sys.argv[1])); sys.exit(0 if abs(s["lens"]["aperture_radius"] - 0.05/2.8) < 1e-9 else 1)' \
       "$work/colmap_dof.json"; then pass; else fail "--colmap with --focal-length 50 --f-number 1.4: aperture radius $(cat "$work/colmap_dof.json")"; fi
  if ! close_pixels "$work/colmap_dof.png" "$work/frames/frame_0002.png"; then pass
  else fail "--colmap with an aperture focused at 0.5 gives the pinhole frame's pixels"; fi
else
  fail "render --colmap with --focal-length, --f-number and --focus-distance"
fi

printf '{"K": [[50, 0.1, 32], [0, 50, 24], [0, 0, 1]], "width": 64, "height": 48, "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "t": [0, 0, 5]}' \
  >"$work/skew.json"
bad "skew" "skew" -- render --camera "$work/skew.json"

echo "colmap: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
