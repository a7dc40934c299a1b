#!/usr/bin/env bash
# capture through a calibrated camera, as a vision researcher drives it: a path whose keys are
# OpenCV cameras (K with an off-centre principal point, distortion, R and t), one camera file held
# (--camera), a list of cameras in every form (--cameras), a previous run's manifest replayed, and
# every image of a COLMAP model (--colmap). Each frame's manifest K is the given K (to 1e-9), a
# replay gives the frames' pixels, and mistakes get one line, a non-zero exit and no frame.
# usage: capture_cameras_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"
cd "$work" || exit 1

# Pixels within 2 % in at most 0.1 % of the pixels: the same camera read back through a file whose
# numbers are rounded in the last digit may move an edge pixel.
close_pixels() { idiff -fail 0.02 -failpercent 0.1 "$1" "$2" >/dev/null 2>&1; }
# k_is MANIFEST K: every line's K within 1e-9 of the largest entry.
k_is() {
  $python - "$1" "$2" <<'PY'
import json, sys
want = json.loads(sys.argv[2])
lines = [json.loads(l) for l in open(sys.argv[1])]
assert lines, "no lines"
scale = max(abs(v) for row in want for v in row)
for l in lines:
    got = l["opencv"]["K"]
    assert all(abs(g - w) <= 1e-9 * scale for gr, wr in zip(got, want) for g, w in zip(gr, wr)), (got, want)
PY
}

# A calibration as OpenCV writes one: 1920 × 1080, the principal point off centre, k1 k2 p1 p2.
K='[[1500, 0, 962.3], [0, 1500.5, 541.7], [0, 0, 1]]'
lens="\"K\": $K, \"width\": 1920, \"height\": 1080, \"dist\": [-0.12, 0.03, 0.001, -0.0005]"
cat >path.json <<JSON
{"fps": 4, "interpolation": "linear", "keys": [
  {"time": 0, $lens, "eye": [3, 1.5, 4], "target": [0, 0.5, 0]},
  {"time": 1, $lens, "eye": [-3, 1.5, 4], "target": [0, 0.5, 0]}]}
JSON

# --- an OpenCV path: every frame's K is the calibration's, at the calibrated size and scaled ---
check "$lenslab" capture --path path.json --width 1920 --height 1080 --frames 2 --out full/f_%02d.png -q
check k_is full/manifest.jsonl "$K"
check holds full/manifest.jsonl 'close(j["opencv"]["dist"][:4], [-0.12, 0.03, 0.001, -0.0005], 1e-12)'
check holds full/f_02.camera.json 'close(sum(j["K"], []), [1500, 0, 962.3, 0, 1500.5, 541.7, 0, 0, 1])'
# --width alone keeps the calibrated shape: 192 × 108, K scaled by 1/10 about the image's corner
# (OpenCV's centres on integers: cx' + ½ = (cx + ½) / 10).
check "$lenslab" capture --path path.json --width 192 --out small/f_%02d.png --colmap-out small/model -q
scaled='[[150, 0, 95.78], [0, 150.05, 53.72], [0, 0, 1]]'
check $python - small/manifest.jsonl "$scaled" <<'PY'
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
want = json.loads(sys.argv[2])
assert sorted(l["frame"] for l in lines) == [0, 1, 2, 3, 4], lines
for l in lines:
    assert (l["width"], l["height"]) == (192, 108), l
    got = l["opencv"]["K"]
    assert all(abs(g - w) <= 1e-9 * 150 for gr, wr in zip(got, want) for g, w in zip(gr, wr)), (got, want)
    assert "focal_length_mm" not in l, "a calibrated camera has no focal length in mm"
PY
# One lens, one COLMAP camera.
check grep -q '^# Number of cameras: 1$' small/model/cameras.txt

# --- a manifest replayed, and the COLMAP model rendered: the frames' pixels ---
check "$lenslab" capture --cameras small/manifest.jsonl --out replay/f_%02d.png -q
check "$lenslab" capture --colmap small/model --out colmap/f_%02d.png -q
for f in 00 02 04; do
  check close_pixels small/f_$f.png replay/f_$f.png
  check close_pixels small/f_$f.png colmap/f_$f.png
done
check k_is replay/manifest.jsonl "$scaled"

# --- one camera file held (--camera), and a list of cameras in three forms with their times ---
echo "{$lens, \"R\": [[1, 0, 0], [0, -1, 0], [0, 0, -1]], \"t\": [0, 1, 5], \"focus_distance\": 5}" >cv.json
check "$lenslab" capture --camera cv.json --width 192 --out still/f_%02d.png -q
check k_is still/manifest.jsonl "$scaled"
{
  echo '{"time": 0.5, "eye": [0, 1, 5], "target": [0, 0.5, 0], "focal_length_mm": 50}'
  echo "{\"time\": 0.75, $lens, \"eye\": [1, 1, 5], \"target\": [0, 0.5, 0]}"
  echo ''
  echo '{"vrp": [0, 0.5, 0], "vpn": [0, 0.2, 1], "prp": [0.3, 0, 5], "window": [-1.5, -1, 1.5, 1]}'
} >list.jsonl
check "$lenslab" capture --cameras list.jsonl --width 96 --out list/f_%02d.png -q
check $python - list/manifest.jsonl <<'PY'
import json, sys
lines = sorted((json.loads(l) for l in open(sys.argv[1])), key=lambda l: l["frame"])
assert [l["frame"] for l in lines] == [0, 1, 2], lines
assert [l["time"] for l in lines] == [0.5, 0.75, 2 / 24], [l["time"] for l in lines]
assert lines[0]["focal_length_mm"] == 50, lines[0]
k = lines[1]["opencv"]["K"]
assert abs(k[0][2] - ((962.3 + 0.5) / 20 - 0.5)) < 1e-9 * 75, k
# The lecture form's oblique PRP is an off-centre principal point: cx = 48 + 0.3 / 3 · 96 − 0.5.
k = lines[2]["opencv"]["K"]
assert abs(k[0][2] - (48 + 0.3 / 3 * 96 - 0.5)) < 1e-9 * 100, k
PY

# --- a fisheye (OpenCV's fisheye model): one OPENCV_FISHEYE camera, its frames replayed from it ---
fish='"K": [[90, 0, 95.5], [0, 90, 53.5], [0, 0, 1]], "width": 192, "height": 108,
  "distortion": {"model": "fisheye", "k1": 0.02, "k2": -0.003}'
cat >fish.json <<JSON
{"fps": 4, "interpolation": "linear", "keys": [
  {"time": 0, $fish, "eye": [3, 1.5, 4], "target": [0, 0.5, 0]},
  {"time": 0.5, $fish, "eye": [-3, 1.5, 4], "target": [0, 0.5, 0]}]}
JSON
check "$lenslab" capture --path fish.json --out fish/f_%02d.png --colmap-out fish/model -q
check grep -q '^# Number of cameras: 1$' fish/model/cameras.txt
check grep -q '^1 OPENCV_FISHEYE 192 108 90 90 96 54 0.02 -0.003 0 0$' fish/model/cameras.txt
check holds fish/f_02.camera.json 'j["distortion"] == {"model": "fisheye", "k1": 0.02, "k2": -0.003}'
check "$lenslab" capture --colmap fish/model --out fishback/f_%02d.png -q
check close_pixels fish/f_01.png fishback/f_01.png
# The ray caster through the same camera file.
check "$lenslab" raycast --camera fish/f_01.camera.json --spp 4 --out fish-ray.png -q

# --- mistakes: one line, a non-zero exit, no frame ---
refused_outputs='out*'
echo '[1, 2]' >notobject.jsonl
printf '{"frame": 0, "camera": "gone.camera.json", "time": 0}\n' >gone.jsonl
: >empty.jsonl
expect_refusal "two sources" "--camera cv.json: --path path.json gives each frame's camera" -- \
  capture --path path.json --camera cv.json --out out/f_%02d.png
expect_refusal "list and path" "--cameras list.jsonl" -- capture --path path.json --cameras list.jsonl --out out/f_%02d.png
expect_refusal "list and colmap" "--colmap small/model: --cameras list.jsonl gives each frame's camera" -- \
  capture --cameras list.jsonl --colmap small/model --out out/f_%02d.png
expect_refusal "f-number on K" "'s keys give K, not a focal length in mm or an f-number" -- \
  capture --path path.json --f-number 2 --out out/f_%02d.png
expect_refusal "not an object" "notobject.jsonl:1: give a camera as a JSON object" -- \
  capture --cameras notobject.jsonl --out out/f_%02d.png
expect_refusal "camera file gone" "gone.jsonl:1: \"camera\": gone.camera.json is not there" -- \
  capture --cameras gone.jsonl --out out/f_%02d.png
expect_refusal "empty list" "empty.jsonl: holds no cameras" -- capture --cameras empty.jsonl --out out/f_%02d.png
sed 's/"K": \[\[90, 0/"K": [[60, 0/; s/\[0, 90, 53.5\]/[0, 60, 53.5]/' fish.json >fish90.json
expect_refusal "fisheye past 90" "the fisheye's image reaches 90° from the optical axis" -- \
  capture --path fish90.json --out out/f_%02d.png
sed 's/"k1": 0.02, "k2": -0.003}/"k1": 0.02, "k2": -0.003}, "aperture_radius": 0.01/; 0,/"fisheye"/s/"fisheye"/"opencv"/' \
  fish.json >fishmix.json
expect_refusal "fisheye and opencv keys" "\"distortion.model\" differs from the first key's" -- \
  capture --path fishmix.json --out out/f_%02d.png
expect_refusal "manifest is the list" "--manifest" -- \
  capture --cameras small/manifest.jsonl --out out/f_%02d.png --manifest small/manifest.jsonl
echo '{"time": -1, "eye": [0, 1, 5], "target": [0, 0, 0]}' >negative.jsonl
expect_refusal "negative time" "negative.jsonl:1: \"time\": -1 is out of range; give" -- \
  capture --cameras negative.jsonl --out out/f_%02d.png

echo "capture_cameras: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
