#!/usr/bin/env bash
# The AOVs in the forms vision pipelines read (--aov-format exr|npy|png16, --normal-convention):
# the same frame's ground truth written three ways holds the same values, each as its format
# promises (depth in metres as float32 .npy and in millimetres as 16-bit PNG, instance ids node + 1
# with instances.json naming them, normals in OpenCV's frame y and z negated), a PNG frame takes its
# AOVs beside it in one run, and mistakes get one line.
# usage: aov_formats_test.sh path/to/lenslab source-dir
. "$(dirname "$0")/test_lib.sh"
cli_test_setup "$@"
cd "$work" || exit 1

common=(--width 48 --height 32 --aperture-samples 1 -q)
all=depth,normal,albedo,instance
check "$lenslab" render "${common[@]}" --aov "$all" -o e.exr
check "$lenslab" render "${common[@]}" --aov "$all" --aov-format npy --normal-convention opencv -o n.png
check "$lenslab" render "${common[@]}" --aov "$all" --aov-format png16 -o p.png
check "$lenslab" render "${common[@]}" --aov depth -o x.png
for f in e.exr n.png n.depth.npy n.normal.npy n.albedo.npy n.instance.npy n.instances.json p.png p.depth.png \
  p.normal.png p.albedo.png p.instance.png p.instances.json x.png x.aov.exr; do
  check test -s "$f"
done
oiiotool --dumpdata e.exr >e.txt && oiiotool --dumpdata x.aov.exr >x.txt &&
  oiiotool --dumpdata p.depth.png >pd.txt && oiiotool --dumpdata p.instance.png >pi.txt &&
  oiiotool --dumpdata p.normal.png >pn.txt || fail "oiiotool --dumpdata"
check test "$(iinfo -v x.aov.exr | grep 'channel list')" = "    channel list: Z"
iinfo -v e.exr | grep 'channel list' >e.channels

check $python - <<'PY'
import ast, json, math, struct

def npy(name):
    data = open(name, "rb").read()
    assert data[:8] == b"\x93NUMPY\x01\x00", name
    n = struct.unpack("<H", data[8:10])[0]
    assert (10 + n) % 64 == 0, f"{name}: data not aligned to 64 bytes"
    header = ast.literal_eval(data[10:10 + n].decode("latin1"))
    code = {"<f4": "f", "<i4": "i"}[header["descr"]]
    assert header["fortran_order"] is False
    count = math.prod(header["shape"])
    body = data[10 + n:]
    assert len(body) == 4 * count, f"{name}: {len(body)} bytes for shape {header['shape']}"
    return header["shape"], list(struct.unpack(f"<{count}{code}", body))

def dump(name):  # oiiotool --dumpdata: one line a pixel, rows from the top; "(…)" the normalised values
    rows = [l.split(":", 1)[1].split("(")[0].split() for l in open(name) if l.strip().startswith("Pixel")]
    return [[float(v) for v in r] for r in rows]

# The EXR's channels by name, in the order its reader lists them (OpenEXR keeps its own order).
order = [c.strip() for c in open("e.channels").read().split(":", 1)[1].split(",")]
exr = [dict(zip(order, p)) for p in dump("e.txt")]
Z = [p["Z"] for p in exr]
N = [[p["N.X"], p["N.Y"], p["N.Z"]] for p in exr]
A = [[p["albedo.R"], p["albedo.G"], p["albedo.B"]] for p in exr]
I = [int(p["instance"]) for p in exr]

shape, depth = npy("n.depth.npy")
assert shape == (32, 48), shape
assert depth == [float(struct.unpack("<f", struct.pack("<f", z))[0]) for z in Z], "npy depth is not the EXR's Z"
assert any(math.isinf(d) for d in depth) and any(0 < d < 100 for d in depth), "the frame shows sky and ground"
shape, normal = npy("n.normal.npy")
assert shape == (32, 48, 3), shape
for k, n in enumerate(N):  # OpenCV's frame: x right, y down, z forward
    assert abs(normal[3 * k] - n[0]) < 1e-6 and abs(normal[3 * k + 1] + n[1]) < 1e-6 and abs(normal[3 * k + 2] + n[2]) < 1e-6, k
_, albedo = npy("n.albedo.npy")
assert all(abs(albedo[3 * k + c] - A[k][c]) < 1e-6 for k in range(len(A)) for c in range(3))
shape, ids = npy("n.instance.npy")
assert ids == [i + 1 for i in I], "npy instance ids are not node + 1"

png_depth = [int(p[0]) for p in dump("pd.txt")]
for z, mm in zip(Z, png_depth):
    want = 0 if math.isinf(z) else min(max(round(z * 1000), 1), 65535)
    assert abs(mm - want) <= 1, (z, mm)
assert [int(p[0]) for p in dump("pi.txt")] == [i + 1 for i in I], "png16 instance ids are not node + 1"
for n, p in zip(N, dump("pn.txt")):
    assert all(abs(p[c] - round((n[c] + 1) / 2 * 65535)) <= 1 for c in range(3)), (n, p)
assert [p[0] for p in dump("x.txt")] == Z, "x.aov.exr's Z is not the frame's depth"

names = json.load(open("n.instances.json"))
assert names["background"] == 0
by_id = {e["id"]: e for e in names["instances"]}
seen = set(ids) - {0}
assert seen and seen <= set(by_id), (seen, sorted(by_id))
for e in by_id.values():
    assert e["id"] == e["node"] + 1 and e["mesh"] and e["materials"], e
PY

# --- capture: PNG frames and npy ground truth from one run, the manifest naming the files ---
check "$lenslab" capture --path "$src/assets/rows/rack-focus.json" --frames 0:1 "${common[@]}" --aov depth,instance \
  --aov-format npy --out cap/f_%02d.png
for f in cap/f_00.png cap/f_00.depth.npy cap/f_01.instance.npy cap/instances.json; do check test -s "$f"; done
check $python - cap/manifest.jsonl <<'PY'
import json, os, sys
for line in map(json.loads, open(sys.argv[1])):
    assert line["aov_files"] == {"depth": f"f_{line['frame']:02d}.depth.npy",
                                 "instance": f"f_{line['frame']:02d}.instance.npy"}, line
    assert "channels" not in line, line
PY

# --- optical flow: each pixel's motion to the next frame, checked by warping frame 1 back onto 0 ---
# A camera looking down at the floor moves and turns (no occlusion changes) through a distorting lens.
cat >down.json <<'JSON'
{"fps": 4, "interpolation": "linear", "keys": [
 {"time": 0, "eye": [0, 3, 0], "target": [0, 0, 0], "up": [0, 0, -1], "focal_length_mm": 35, "distortion": {"k1": -0.15}},
 {"time": 1, "eye": [0.6, 2.7, 0.3], "target": [0.5, 0, 0.2], "up": [0.1, 0, -1], "focal_length_mm": 35,
  "distortion": {"k1": -0.15}}]}
JSON
check "$lenslab" capture --path down.json --width 96 --height 64 --aperture-samples 1 -q --aov flow --out flow/f_%02d.exr
check "$lenslab" capture --path down.json --width 96 --height 64 --aperture-samples 1 -q --aov flow --frames 0 \
  --aov-format npy --out flownpy/f_%02d.png
check "$lenslab" capture --path down.json --width 96 --height 64 --aperture-samples 1 -q --aov flow --frames 0 \
  --aov-format png16 --out flowpng/f_%02d.png
oiiotool --dumpdata flow/f_00.exr >f0.txt && oiiotool --dumpdata flow/f_01.exr >f1.txt &&
  oiiotool --dumpdata flow/f_04.exr >f4.txt && oiiotool --dumpdata flowpng/f_00.flow.png >kitti.txt &&
  iinfo -v flow/f_00.exr | grep 'channel list' >flow.channels || fail "oiiotool --dumpdata (flow)"
check $python - <<'PY'
import ast, math, struct
W, H = 96, 64
def dump(name):
    rows = [l.split(":", 1)[1].split("(")[0].split() for l in open(name) if l.strip().startswith("Pixel")]
    return [[float(v) for v in r] for r in rows]
order = [c.strip() for c in open("flow.channels").read().split(":", 1)[1].split(",")]
assert order == ["R", "G", "B", "A", "flow.X", "flow.Y"], order
a, b, last = dump("f0.txt"), dump("f1.txt"), dump("f4.txt")
def bilinear(img, x, y):  # pixel centres at i + 0.5
    x, y = x - 0.5, y - 0.5
    x0, y0 = math.floor(x), math.floor(y)
    if x0 < 0 or y0 < 0 or x0 + 1 >= W or y0 + 1 >= H: return None
    fx, fy = x - x0, y - y0
    at = lambda i, j, c: img[j * W + i][c]
    return [(1 - fx) * (1 - fy) * at(x0, y0, c) + fx * (1 - fy) * at(x0 + 1, y0, c) + (1 - fx) * fy * at(x0, y0 + 1, c)
            + fx * fy * at(x0 + 1, y0 + 1, c) for c in range(3)]
warped, still = [], []
for y in range(H):
    for x in range(W):
        p = a[y * W + x]
        assert not math.isnan(p[4]), "the floor fills the frame: every pixel has a flow"
        w, s = bilinear(b, x + 0.5 + p[4], y + 0.5 + p[5]), bilinear(b, x + 0.5, y + 0.5)
        if w and s:
            warped.append(sum(abs(w[c] - p[c]) for c in range(3)) / 3)
            still.append(sum(abs(s[c] - p[c]) for c in range(3)) / 3)
mw, ms = sum(warped) / len(warped), sum(still) / len(still)
# Frame 1 warped back by the flow matches frame 0 up to the checker's resampling at its edges.
assert mw < 0.05 and mw < 0.15 * ms, (mw, ms)
assert all(math.isnan(p[4]) and math.isnan(p[5]) for p in last), "the last frame has no next frame: NaN"
data = open("flownpy/f_00.flow.npy", "rb").read()
n = struct.unpack("<H", data[8:10])[0]
assert ast.literal_eval(data[10:10 + n].decode())["shape"] == (H, W, 2)
flow = struct.unpack(f"<{W * H * 2}f", data[10 + n:])
assert all(abs(flow[2 * i] - a[i][4]) < 1e-5 and abs(flow[2 * i + 1] - a[i][5]) < 1e-5 for i in range(W * H))
for p, k in zip(a, dump("kitti.txt")):  # KITTI: u·64 + 2^15, v·64 + 2^15, valid
    assert abs(k[0] - (p[4] * 64 + 32768)) <= 0.5 and abs(k[1] - (p[5] * 64 + 32768)) <= 0.5 and k[2] == 1, (p, k)
PY
expect_refusal "flow of one image" "--aov flow: flow is each pixel's motion to the next frame of a sequence" -- \
  render "${common[@]}" --aov flow -o out.exr

# --- mistakes ---
refused_outputs='out*'
expect_refusal "format without aovs" "--aov-format npy: give --aov LIST too" -- render "${common[@]}" --aov-format npy -o out.png
expect_refusal "convention without normals" "--normal-convention opencv: give --aov normal too" -- \
  render "${common[@]}" --aov depth --normal-convention opencv -o out.png
expect_refusal "unknown format" "--aov-format" -- render "${common[@]}" --aov depth --aov-format tiff -o out.png

echo "aov_formats: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
