#!/usr/bin/env bash
# lenslab capture as a user and a cluster meet it: three shards run at once give the frames one
# run gives; `render` with a frame's camera file and seed gives that frame's pixels; the manifest
# stays valid JSON lines with every frame once; --skip-existing leaves whole frames alone; bad
# paths and options get one line, a non-zero exit and no frame.
# usage: capture_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"

path=$src/assets/rows/rack-focus.json
common=(--path "$path" --width 64 --aperture-samples 4 --frames 10:21 --aov depth -q)

# --- one run, and three shards as parallel processes into one folder and one manifest ---
"$lenslab" capture "${common[@]}" --out "$work/one/frame_%04d.exr" || fail "one run"
for i in 0 1 2; do
  "$lenslab" capture "${common[@]}" --out "$work/sharded/frame_%04d.exr" --shard "$i/3" &
done
wait
for f in $(seq 10 21); do
  name=$(printf 'frame_%04d' "$f")
  if [ -f "$work/sharded/$name.exr" ] && same_pixels "$work/one/$name.exr" "$work/sharded/$name.exr"; then pass
  else fail "frame $f: the shards' image differs from one run's"; fi
  if cmp -s "$work/one/$name.camera.json" "$work/sharded/$name.camera.json"; then pass
  else fail "frame $f: the shards' camera file differs from one run's"; fi
done
# The manifests: valid JSON lines, each frame once, the same seed for a frame in both runs.
check_manifest=$(cat <<'EOF'
import json, sys
one = [json.loads(l) for l in open(sys.argv[1])]
sharded = [json.loads(l) for l in open(sys.argv[2])]
for name, lines in (("one", one), ("sharded", sharded)):
    frames = sorted(l["frame"] for l in lines)
    assert frames == list(range(10, 22)), f"{name}: frames {frames}"
    for l in lines:
        for key in ("frame", "time", "file", "camera", "seed", "samples", "seconds"):
            assert key in l, f"{name}: line lacks {key}: {l}"
        assert abs(l["time"] - l["frame"] / 24) < 1e-12, l
seeds = {l["frame"]: l["seed"] for l in one}
assert all(seeds[l["frame"]] == l["seed"] for l in sharded), "seeds differ between one run and the shards"
assert len(set(seeds.values())) == len(seeds), "two frames share a seed"
assert sorted({l["shard"] for l in sharded}) == ["0/3", "1/3", "2/3"], "not every shard wrote"
EOF
)
if out=$($python -c "$check_manifest" "$work/one/manifest.jsonl" "$work/sharded/manifest.jsonl" 2>&1); then pass
else fail "manifest: $out"; fi

# --- every AOV: the frame's EXR holds their channels, the manifest names them ---
if "$lenslab" capture --path "$path" --width 32 --aperture-samples 1 --frames 10:11 --aov depth,normal,albedo,instance \
     --out "$work/aovs/frame_%04d.exr" -q; then
  check_aovs=$(cat <<'EOF'
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
assert len(lines) == 2, lines
for l in lines:
    assert l["aov"] == ["depth", "normal", "albedo", "instance"], l["aov"]
    assert l["channels"] == ["R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z", "albedo.R", "albedo.G", "albedo.B", "instance"], l["channels"]
EOF
)
  if out=$($python -c "$check_aovs" "$work/aovs/manifest.jsonl" 2>&1); then pass; else fail "aov manifest: $out"; fi
  names=$(iinfo -v "$work/aovs/frame_0010.exr" | sed -n 's/^ *channel list: //p' | tr -d ' ')
  for c in Z N.X N.Y N.Z albedo.R albedo.G albedo.B instance; do
    if tr ',' '\n' <<<"$names" | grep -qxF "$c"; then pass; else fail "capture --aov: no channel $c in: $names"; fi
  done
else
  fail "capture --aov depth,normal,albedo,instance"
fi

# --- the cluster scripts as their schedulers would run them ---
# Slurm: an array 2-6:2 (it need not start at 0 nor step by 1), each task with the variables Slurm sets.
for task in 2 4 6; do
  SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_MIN=2 SLURM_ARRAY_TASK_STEP=2 SLURM_ARRAY_TASK_COUNT=3 LENSLAB=$lenslab \
    bash "$src/tools/slurm/capture.sbatch" "$src/assets/rows/rows.gltf" "$path" "$work/slurm" \
    --width 64 --aperture-samples 4 --frames 10:21 --aov depth -q &
done
wait
# Kubernetes: the Job's own arguments, $(JOB_COMPLETION_INDEX) expanded as the kubelet does, the
# volume's paths mapped here, and the test's size options added.
k8s_args=$(cat <<'EOF'
import sys, yaml
job = yaml.safe_load(open(sys.argv[1]))
spec = job["spec"]
assert spec["completionMode"] == "Indexed"
n = spec["completions"]
args = spec["template"]["spec"]["containers"][0]["args"]
shard = args[args.index("--shard") + 1]
assert shard == f"$(JOB_COMPLETION_INDEX)/{n}", f"--shard {shard} does not match completions {n}"
places = {"/data/scene.gltf": sys.argv[2], "/data/path.json": sys.argv[3], "/data/frames": sys.argv[4]}
for i in range(n):
    line = []
    for a in args:
        a = a.replace("$(JOB_COMPLETION_INDEX)", str(i))
        for k, v in places.items():
            a = a.replace(k, v)
        line.append(a)
    print("\t".join(line))
EOF
)
if k8s=$($python -c "$k8s_args" "$src/tools/k8s/capture-job.yaml" "$src/assets/rows/rows.gltf" "$path" "$work/k8s" 2>&1); then
  pass
  while IFS=$'\t' read -r -a job_args; do
    "$lenslab" "${job_args[@]}" --width 64 --aperture-samples 4 --frames 10:21 -q &
  done <<<"$k8s"
  wait
else
  fail "tools/k8s/capture-job.yaml: $k8s"
fi
for dir in slurm k8s; do
  for f in $(seq 10 21); do
    name=$(printf 'frame_%04d' "$f")
    if [ -f "$work/$dir/$name.exr" ] && same_pixels "$work/one/$name.exr" "$work/$dir/$name.exr"; then pass
    else fail "$dir: frame $f differs from one run's (or is missing)"; fi
  done
  if [ "$(cat "$work/$dir"/manifest.*.jsonl | wc -l)" -eq 12 ]; then pass; else fail "$dir: manifests hold $(cat "$work/$dir"/manifest.*.jsonl | wc -l) lines, not 12"; fi
done

# --- render reproduces a frame from its camera file and its seed ---
seed=$($python -c 'import json,sys; print([l for l in map(json.loads, open(sys.argv[1])) if l["frame"] == 15][0]["seed"])' "$work/one/manifest.jsonl")
"$lenslab" render --camera "$work/one/frame_0015.camera.json" --seed "$seed" --aperture-samples 4 --out "$work/rendered.exr" -q
oiiotool "$work/one/frame_0015.exr" --ch R,G,B,A -o "$work/frame15-rgba.exr"
if same_pixels "$work/rendered.exr" "$work/frame15-rgba.exr"; then pass; else fail "render --camera frame_0015.camera.json --seed $seed differs from the frame"; fi
# The camera file holds OpenCV intrinsics for the frame's size.
if $python -c 'import json,sys; k=json.load(open(sys.argv[1]))["intrinsics"]; assert k["width"] == 64 and k["fx"] > 0 and abs(k["cx"] - 31.5) < 1e-9, k' \
     "$work/one/frame_0015.camera.json"; then pass; else fail "camera file intrinsics"; fi
# The depth channel: finite on the floor, +inf in the sky.
stats=$(oiiotool "$work/one/frame_0015.exr" --ch Z --printstats 2>&1)
if grep -Eq "InfCount: [1-9]" <<<"$stats" && grep -Eq "NanCount: 0" <<<"$stats"; then pass; else fail "Z channel: $stats"; fi

# --- --skip-existing: whole frames are left alone, a missing one is made ---
rm "$work/one/frame_0013.exr"
before=$(stat -c %Y.%s "$work/one/frame_0012.exr")
lines_before=$(wc -l <"$work/one/manifest.jsonl")
sleep 1
"$lenslab" capture "${common[@]}" --out "$work/one/frame_%04d.exr" --skip-existing || fail "--skip-existing run"
if [ "$(stat -c %Y.%s "$work/one/frame_0012.exr")" = "$before" ]; then pass; else fail "--skip-existing rewrote frame 12"; fi
if [ -f "$work/one/frame_0013.exr" ]; then pass; else fail "--skip-existing did not make the missing frame 13"; fi
if [ "$(wc -l <"$work/one/manifest.jsonl")" -eq $((lines_before + 1)) ]; then pass; else fail "--skip-existing: manifest lines $lines_before -> $(wc -l <"$work/one/manifest.jsonl"), expected one more"; fi

# --- the manifest: a frame and its line together or not at all ---
# manifest_holds FILE FRAMES...: every line valid JSON, each of FRAMES on exactly one line, no other.
manifest_holds() {
  $python - "$@" <<'EOF'
import json, sys
frames = []
with open(sys.argv[1], "rb") as f:
    data = f.read()
if data and not data.endswith(b"\n"):
    sys.exit("the last line has no newline: %r" % data[-80:])
for n, line in enumerate(data.decode().splitlines(), 1):
    try:
        frames.append(json.loads(line)["frame"])
    except Exception as e:
        sys.exit("line %d is not a frame's JSON (%s): %.120s" % (n, e, line))
want = sorted(int(a) for a in sys.argv[2:])
if sorted(frames) != want:
    sys.exit("frames %s, expected each of %s once" % (sorted(frames), want))
EOF
}
small=(--path "$path" --width 32 --aperture-samples 2 -q)
m=$work/manifest
"$lenslab" capture "${small[@]}" --frames 0:3 --out "$m/f_%04d.png" || fail "manifest: first run"
# A kill between a frame's image and its line (simulated: the line taken away): --skip-existing
# renders the frame again and writes its line, rather than skipping it forever.
sed -i '$d' "$m/manifest.jsonl"
"$lenslab" capture "${small[@]}" --frames 0:3 --out "$m/f_%04d.png" --skip-existing || fail "manifest: resume after a lost line"
if out=$(manifest_holds "$m/manifest.jsonl" 0 1 2 3 2>&1); then pass; else fail "an image without its line is skipped by --skip-existing: $out"; fi
# A last line cut short (a kill mid-write, an older lenslab on a full disk): the resume cuts it off
# before appending, instead of gluing the next frame's line to it; that frame (3) is made again,
# and a new one (4) after it.
truncate -s -100 "$m/manifest.jsonl"
"$lenslab" capture "${small[@]}" --frames 0:4 --out "$m/f_%04d.png" --skip-existing || fail "manifest: resume after a partial line"
if out=$(manifest_holds "$m/manifest.jsonl" 0 1 2 3 4 2>&1); then pass; else fail "a partial last line is not repaired: $out"; fi

# A line that does not fit (each file limited to 2 KiB: the fourth ~600-byte line is cut short by
# EFBIG, as by a full disk): one error line, no part of the line left, and no frame 3 without its
# line; the resume then makes frames 3 to 5, each with one line.
d=$work/full
mkdir -p "$d"
( trap '' XFSZ; ulimit -f 2; exec "$lenslab" capture "${small[@]}" --frames 0:5 --out "$d/f_%04d.png" ) 2>"$work/stderr"
rc=$?
if [ "$rc" -ne 0 ] && grep -qF "$d/manifest.jsonl: cannot append to it: File too large" "$work/stderr" \
   && out=$(manifest_holds "$d/manifest.jsonl" 0 1 2 2>&1) && [ ! -e "$d/f_0003.png" ] && [ ! -e "$d/f_0003.camera.json" ] \
   && [ -z "$(find "$d" -name '.*')" ]; then pass
else fail "a manifest line that does not fit: exit $rc, ${out:-} $(ls -A "$d" | tr '\n' ' ') $(cat "$work/stderr")"; fi
"$lenslab" capture "${small[@]}" --frames 0:5 --out "$d/f_%04d.png" --skip-existing || fail "manifest: resume after a full disk"
if out=$(manifest_holds "$d/manifest.jsonl" 0 1 2 3 4 5 2>&1); then pass; else fail "resume after a line that did not fit: $out"; fi

# A manifest that cannot be appended to is refused before rendering: no frame without its line.
# (Root appends to a read-only file regardless: as root the run is made as 'nobody'.)
r=$work/ro-manifest
mkdir -p "$r"
: >"$r/manifest.jsonl"
chmod 444 "$r/manifest.jsonl"
as=()
ro=("${small[@]}")
if [ "$(id -u)" -eq 0 ]; then
  chmod 755 "$work" && chmod 777 "$r"
  # The source tree may lie under a folder only root can enter (a CI clone in a mktemp -d): the
  # scene and the path go with the run, into a folder 'nobody' can read.
  mkdir -p "$work/ro-assets" && cp -r "$src/assets/rows" "$work/ro-assets/" && chmod -R a+rX "$work/ro-assets"
  as=(env LENSLAB_ASSET_DIR="$work/ro-assets" setpriv --reuid=nobody --regid=nogroup --clear-groups)
  ro=(--path "$work/ro-assets/rows/rack-focus.json" --width 32 --aperture-samples 2 -q)
fi
if ! "${as[@]}" "$lenslab" --help >/dev/null 2>&1; then
  echo "SKIPPED: read-only manifest: cannot run lenslab as nobody here (no setpriv, or its binary is out of nobody's reach)"
elif "${as[@]}" "$lenslab" capture "${ro[@]}" --frames 0:1 --out "$r/f_%04d.png" >"$work/stdout" 2>"$work/stderr"; then
  fail "a read-only manifest: exit 0"
elif grep -qF -- "--manifest $r/manifest.jsonl: cannot append to it: Permission denied" "$work/stderr" \
     && [ "$(ls -A "$r")" = manifest.jsonl ]; then pass
else fail "a read-only manifest: $(ls -A "$r" | tr '\n' ' ') $(cat "$work/stderr")"; fi
chmod 700 "$work"

# --- a glTF node animation plays: frames move, and `render --time` reproduces a frame ---
# A unit quad sliding from x = -1 to x = +1 over one second (LINEAR translation), written here.
make_gltf=$(cat <<'EOF'
import base64, json, struct, sys
pos = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
idx = [0, 1, 2, 0, 2, 3]
times = [0.0, 1.0]
moves = [(-1.0, 0, 0), (1.0, 0, 0)]
data = b"".join(struct.pack("<3f", *p) for p in pos) + struct.pack("<6H", *idx) + b"\0" * 4 \
     + struct.pack("<2f", *times) + b"".join(struct.pack("<3f", *m) for m in moves)
gltf = {
  "asset": {"version": "2.0"},
  "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "animations": [{"samplers": [{"input": 2, "output": 3, "interpolation": "LINEAR"}],
                  "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}],
  "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12},
                  {"buffer": 0, "byteOffset": 64, "byteLength": 8}, {"buffer": 0, "byteOffset": 72, "byteLength": 24}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
    {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0.0], "max": [1.0]},
    {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC3"}]}
json.dump(gltf, open(sys.argv[1], "w"))
EOF
)
$python -c "$make_gltf" "$work/slide.gltf"
printf '{"fps": 4, "frames": 5, "keys": [{"time": 0, "eye": [0, 0, 4], "target": [0, 0, 0], "near": 0.1, "far": 10}]}' >"$work/still.json"
"$lenslab" capture "$work/slide.gltf" --path "$work/still.json" --width 64 --out "$work/slide/f_%d.png" -q || fail "capture of an animated glTF"
if ! cmp -s "$work/slide/f_0.png" "$work/slide/f_4.png" && ! cmp -s "$work/slide/f_1.png" "$work/slide/f_2.png"; then pass
else fail "the animated quad does not move between frames"; fi
# Frame 1 is t = 0.25 s, the quad at x = -0.5: render --time 0.25 with the frame's camera gives it;
# without --time render draws the rest pose (the node has no translation: x = 0).
seed=$($python -c 'import json,sys; print([l for l in map(json.loads, open(sys.argv[1])) if l["frame"] == 1][0]["seed"])' "$work/slide/manifest.jsonl")
"$lenslab" render "$work/slide.gltf" --camera "$work/slide/f_1.camera.json" --seed "$seed" --time 0.25 --out "$work/slide-r.png" -q
if cmp -s "$work/slide-r.png" "$work/slide/f_1.png"; then pass; else fail "render --time 0.25 differs from frame 1"; fi
"$lenslab" render "$work/slide.gltf" --camera "$work/slide/f_1.camera.json" --seed "$seed" --out "$work/slide-rest.png" -q
if ! cmp -s "$work/slide-rest.png" "$work/slide/f_1.png"; then pass; else fail "render without --time drew the pose at 0.25 s, not the rest pose"; fi
# The frame at the centre is left-right symmetric; frame 0 (x = -1) has the quad's colour on the left only.
symmetry=$(cat <<'EOF'
import sys
from PIL import Image
def coverage(path):
    im = Image.open(path).convert("L"); w, h = im.size; bg = im.getpixel((0, 0))
    cols = [x for x in range(w) for y in range(h) if abs(im.getpixel((x, y)) - bg) > 10]
    return min(cols), max(cols), w
lo, hi, w = coverage(sys.argv[1])
assert abs((lo + hi + 1) / 2 - w / 2) <= 1, f"centre frame: covered columns {lo}..{hi} of {w}"
lo0, hi0, _ = coverage(sys.argv[2])
assert hi0 < w / 2, f"frame 0: covered columns {lo0}..{hi0} of {w}, expected the left half"
EOF
)
if out=$($python -c "$symmetry" "$work/slide/f_2.png" "$work/slide/f_0.png" 2>&1); then pass; else fail "animated quad placement: $out"; fi

# --- the dolly zoom renders end to end (first and last frame) ---
if "$lenslab" capture --path "$src/assets/rows/dolly-zoom.json" --width 48 --aperture-samples 2 --frames 96 \
     --out "$work/dolly/d_%02d.png" -q && [ -s "$work/dolly/d_96.png" ]; then pass; else fail "dolly zoom, last frame"; fi

# --- refusals: one line, non-zero exit, no frame written ---
expect_refusal() {
  rm -rf "$work/bad"
  one_line_error "$@" || return
  if [ -n "$(find "$work/bad" -type f 2>/dev/null)" ]; then fail "$1: left a file: $(find "$work/bad" -type f)"; return; fi
  pass
}
key='{"time": 0, "eye": [0, 1, 3], "target": [0, 0.5, -2]}'
key2='{"time": 1, "eye": [0, 1, 4], "target": [0, 0.5, -2]}'
printf '{"fps": 24, "keys": []}' >"$work/empty.json"
printf '{"fps": 24, "keys": [%s, %s]}' "$key2" "$key" >"$work/unsorted.json"
printf '{"fps": 24, "keys": [%s, %s]}' "$key" "$(sed 's/"time": 1/"time": 0/' <<<"$key2")" >"$work/repeated.json"
printf '{"fps": 24, "keys": [%s, {"time": 1, "eye": [0, 1, 4], "target": [0, 0.5, -2], "fov": 40}]}' "$key" >"$work/unknown.json"
printf '{"fps": 24, "keys": [%s], "speed": 2}' "$key" >"$work/unknown-top.json"
printf '{"keys": [%s]}' "$key" >"$work/nofps.json"
printf '{"fps": 24, "keys": [{"time": 0, "vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,2], "window": [-1,-1,1,1]}, {"time": 1, "eye": [0,1,5], "target": [0,0,0]}]}' >"$work/lecture.json"
bad=(--width 32 --aperture-samples 1 --out "$work/bad/f_%02d.png")
expect_refusal "no keys" "keys" -- capture --path "$work/empty.json" "${bad[@]}"
expect_refusal "unsorted times" "keys[1]" -- capture --path "$work/unsorted.json" "${bad[@]}"
expect_refusal "repeated times" "keys[1]" -- capture --path "$work/repeated.json" "${bad[@]}"
expect_refusal "unknown camera key" 'keys[1]: unknown key "fov"' -- capture --path "$work/unknown.json" "${bad[@]}"
expect_refusal "unknown path key" 'unknown key "speed"' -- capture --path "$work/unknown-top.json" "${bad[@]}"
expect_refusal "no fps" "fps" -- capture --path "$work/nofps.json" "${bad[@]}"
expect_refusal "lecture and physical keys" "keys[1]: is in the physical form where keys[0] is not" -- capture --path "$work/lecture.json" "${bad[@]}"
expect_refusal "missing path file" "missing.json" -- capture --path "$work/missing.json" "${bad[@]}"
expect_refusal "no frame number" "%d" -- capture --path "$path" --out "$work/bad/frame.png"
expect_refusal "two frame numbers" "one %d" -- capture --path "$path" --out "$work/bad/f_%d_%d.png"
expect_refusal "frames past the end" "--frames 70:80" -- capture --path "$path" --frames 70:80 "${bad[@]}"
expect_refusal "frames backwards" "--frames 5:2" -- capture --path "$path" --frames 5:2 "${bad[@]}"
expect_refusal "shard index" "--shard 3/3" -- capture --path "$path" --shard 3/3 "${bad[@]}"
expect_refusal "shard form" "--shard 1" -- capture --path "$path" --shard 1 "${bad[@]}"
expect_refusal "normal convention without normals" "--normal-convention opencv: give --aov normal too" -- \
  capture --path "$path" --aov depth --normal-convention opencv "${bad[@]}"
expect_refusal "unknown aov" "--aov" -- capture --path "$path" --aov normals "${bad[@]}"

echo "capture: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
