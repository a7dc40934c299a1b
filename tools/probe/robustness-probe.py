#!/usr/bin/env python3
"""A robustness probe of lenslab: adversarial inputs, faults and signals, each classified holds or fails.

A case holds when lenslab gives a correct image or a clear refusal:
  - an image: exit 0, the output decodes, every pixel finite (EXR outputs are read for NaN and
    infinity), no hidden temporary file or stray folder beside it;
  - a refusal: a non-zero exit (not a signal), one line on stderr besides progress and warning lines,
    starting "lenslab: error:", naming the option, file or field (the case's fragment), with no
    std::bad_alloc or other library text in it, and the case's folder exactly as it was before the
    run (no output file, no hidden temporary file, no folder made by the run).
It fails on a crash (a signal the probe did not send), a hang past the timeout, a non-finite image,
a multi-line or unhelpful message, anything left behind, or memory use past the address-space cap
(which shows as std::bad_alloc or a crash). Signal cases send a signal at a set point of the run
and then check what is left (and, for capture, that a rerun with --skip-existing completes a valid
manifest).

Every input is generated in a temporary folder; nothing outside it is written (a 16 KiB tmpfs is
mounted there when the user may mount, and the probe runs some cases as the user nobody when run as
root, as tests/cli/fault_test.sh does). The table names the case folder "D", so that it is the same
from run to run.

usage: python3 tools/probe/robustness-probe.py [build/lenslab] [--quick] [--markdown FILE]
       [--doc docs/robustness.md] [--only ID[,ID...]] [--keep]
"""
import argparse
import base64
import json
import os
import re
import resource
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ROWS = os.path.join(REPO, "assets", "rows")
TIMEOUT_SECONDS = 30  # a case running longer is a hang (the slowest that finishes takes about 5 s)
MEMORY_CAP_BYTES = 3 << 30  # address space: a run that needs more shows as bad_alloc or a crash
PROGRESS_LINE = re.compile(r"^lenslab: ([a-z]+: [0-9]+/[0-9]+ |warning: )")
UNHELPFUL = re.compile(r"bad_alloc|std::|what\(\)|terminate called|Assertion|Segmentation|core dumped|"
                       r"basic_string|nlohmann|json\.exception|\[json\.|vector::|out_of_range")
SIGNAL_NAMES = {int(s): s.name for s in signal.Signals}

# ---------------------------------------------------------------------------------------------
# Inputs


def box_mesh(half):
    """A cube of half-size `half` (per axis): 24 vertices with normals, 36 uint16 indices."""
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u, v = [(axis + 1) % 3, (axis + 2) % 3]
            base = len(positions)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis] = sign * half[axis]
                p[u] = a * half[u]
                p[v] = b * half[v]
                positions.append(p)
                normals.append(n)
            quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            indices += [base + i for i in quad]
    return positions, normals, indices


def gltf_boxes(boxes, camera=None):
    """A glTF document (dict) and its buffer (bytes) of boxes [(half-size xyz, translation xyz)]."""
    buffer = b""
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [],
           "accessors": [], "bufferViews": [], "buffers": [],
           "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.3, 0.2, 1.0]}}]}
    for half, translation in boxes:
        positions, normals, indices = box_mesh(half)
        first = len(doc["accessors"])
        for data, kind in ((positions, "VEC3"), (normals, "VEC3")):
            blob = b"".join(struct.pack("<3f", *p) for p in data)
            acc = {"bufferView": len(doc["bufferViews"]), "componentType": 5126, "count": len(data), "type": kind}
            if data is positions:
                acc["min"] = [min(p[i] for p in data) for i in range(3)]
                acc["max"] = [max(p[i] for p in data) for i in range(3)]
            doc["bufferViews"].append({"buffer": 0, "byteOffset": len(buffer), "byteLength": len(blob)})
            doc["accessors"].append(acc)
            buffer += blob
        blob = struct.pack("<%dH" % len(indices), *indices)
        blob += b"\0" * (-len(blob) % 4)
        doc["bufferViews"].append({"buffer": 0, "byteOffset": len(buffer), "byteLength": 2 * len(indices)})
        doc["accessors"].append({"bufferView": len(doc["bufferViews"]) - 1, "componentType": 5123,
                                 "count": len(indices), "type": "SCALAR"})
        buffer += blob
        doc["meshes"].append({"primitives": [{"attributes": {"POSITION": first, "NORMAL": first + 1},
                                              "indices": first + 2, "material": 0}]})
        doc["nodes"].append({"mesh": len(doc["meshes"]) - 1, "translation": list(translation)})
        doc["scenes"][0]["nodes"].append(len(doc["nodes"]) - 1)
    if camera is not None:
        doc["cameras"] = [camera[0]]
        doc["nodes"].append({"camera": 0, "translation": camera[1]})
        doc["scenes"][0]["nodes"].append(len(doc["nodes"]) - 1)
    doc["buffers"].append({"byteLength": len(buffer), "uri": "box.bin"})
    return doc, buffer


def write_gltf(folder, name, doc, buffer, bin_name="box.bin"):
    doc["buffers"][0]["uri"] = bin_name
    with open(os.path.join(folder, name), "w") as f:
        json.dump(doc, f)
    if bin_name and not bin_name.startswith("data:"):
        with open(os.path.join(folder, bin_name), "wb") as f:
            f.write(buffer)


def write_glb(path, doc, buffer, length_delta=0):
    doc = json.loads(json.dumps(doc))
    del doc["buffers"][0]["uri"]
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    buffer += b"\0" * (-len(buffer) % 4)
    body = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(buffer), 0x004E4942) + buffer
    with open(path, "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, 12 + len(body) + length_delta) + body)


def physical_camera(**fields):
    cam = {"eye": [0, 1, 3], "target": [0, 0.55, -2], "focal_length_mm": 35, "sensor_mm": [36, 24],
           "focus_distance": 4.0, "near": 0.05, "far": "infinity"}
    cam.update(fields)
    return cam


def write_text(folder, name, text):
    mode = "wb" if isinstance(text, bytes) else "w"
    with open(os.path.join(folder, name), mode) as f:
        f.write(text)


def write_json(folder, name, value):
    write_text(folder, name, json.dumps(value))


def box_scene(folder, name="box.gltf", half=(0.5, 0.5, 0.5), at=(0, 0, 0)):
    doc, buffer = gltf_boxes([(half, at)])
    write_gltf(folder, name, doc, buffer)


def colmap_model(folder, cameras, images):
    os.makedirs(os.path.join(folder, "model"))
    write_text(folder, "model/cameras.txt", cameras)
    write_text(folder, "model/images.txt", images)


COLMAP_IMAGES = "1 1 0 0 0 0 -0.5 5 1 a.png\n\n"

# ---------------------------------------------------------------------------------------------
# Cases


class Case:
    def __init__(self, cid, category, argv, expect, fragment=None, setup=None, quick=False, short=None,
                 user=None, fsize_kb=None, ignore_xfsz=True, send=None, after=None, needs=None,
                 watched=None, nonconstant=False, visible=False, partial=False, tmpfs_options="size=16k", unset=()):
        self.id, self.category, self.argv, self.expect = cid, category, argv, expect
        self.fragment = fragment  # str or tuple of str: the refusal must hold one of them
        self.setup, self.quick, self.short = setup, quick, short
        self.user = user  # "nobody": run as that user (root only)
        self.fsize_kb, self.ignore_xfsz = fsize_kb, ignore_xfsz
        self.send = send  # (signal, trigger): trigger(D) -> bool, polled until true, then the signal
        self.after = after  # after(D, result) -> (ok, note): a further check (e.g. resume a capture)
        self.needs = needs  # "tmpfs" or "nobody": skipped (with the reason) where unavailable
        self.watched = watched  # folder (relative to D) that must be unchanged by a refusal
        self.nonconstant = nonconstant  # the image must show something (not one colour)
        self.tmpfs_options = tmpfs_options  # the mount options of its tmpfs (needs="tmpfs")
        self.unset = unset  # environment variables the run goes without
        self.partial = partial  # a refused capture may keep the frames it finished (whole), nothing else
        self.visible = visible  # some surface must be in view (alpha above 0 somewhere): not the background alone


CASES = []


def case(*args, **kwargs):
    CASES.append(Case(*args, **kwargs))


def cam_setup(value, name="cam.json"):
    return lambda d: write_json(d, name, value)


def text_setup(text, name="cam.json"):
    return lambda d: write_text(d, name, text)


W = ["--width", "30", "-q"]  # small images: the probe must run in minutes on two busy cores
RENDER = ["render"] + W
RAYCAST = ["raycast", "--spp", "2"] + W


def hidden_file_present(d):
    for root, _, files in os.walk(d):
        if any(f.startswith(".") for f in files):
            return True
    return False


def manifest_lines_at_least(n, rel="frames/manifest.jsonl"):
    def trigger(d):
        try:
            with open(os.path.join(d, rel)) as f:
                return sum(1 for line in f if line.endswith("\n")) >= n
        except OSError:
            return False
    return trigger


def mid_frame_write(n):
    """After n frames, while the next frame's temporary file exists (a signal then lands mid-write)."""
    lines = manifest_lines_at_least(n)
    return lambda d: lines(d) and hidden_file_present(os.path.join(d, "frames"))


def image_before_its_line(n):
    """After n frames, when a frame's image exists and its manifest line does not yet."""
    def trigger(d):
        folder = os.path.join(d, "frames")
        try:
            images = sum(1 for f in os.listdir(folder) if re.fullmatch(r"f_\d{4}\.png", f))
            with open(os.path.join(folder, "manifest.jsonl")) as f:
                lines = sum(1 for line in f if line.endswith("\n"))
        except OSError:
            return False
        return lines >= n and images > lines
    return trigger


def after_seconds(s):
    start = []

    def trigger(_):
        if not start:
            start.append(time.monotonic())
        return time.monotonic() - start[0] >= s
    return trigger


def check_manifest(d, frames, rel="frames", stale_allowed=False):
    """Every manifest line parses and names an image that exists; one line per image; `frames` images.
    stale_allowed: a SIGKILLed run's temporary file may stay (SIGKILL cannot be caught)."""
    folder = os.path.join(d, rel)
    images = sorted(f for f in os.listdir(folder) if re.fullmatch(r"f_\d{4}\.(png|exr)", f))
    hidden = sorted(f for f in os.listdir(folder) if f.startswith("."))
    seen = {}
    try:
        with open(os.path.join(folder, "manifest.jsonl"), "rb") as f:
            raw = f.read()
    except OSError:
        raw = b""
    if raw and not raw.endswith(b"\n"):
        return False, "the manifest's last line is torn"
    for number, line in enumerate(raw.decode("utf-8", "replace").splitlines(), 1):
        try:
            entry = json.loads(line)
        except ValueError:
            return False, "manifest line %d is not JSON" % number
        name = os.path.basename(str(entry.get("file", "")))
        seen[name] = seen.get(name, 0) + 1
    if hidden and not stale_allowed:
        return False, "left %d hidden file(s)" % len(hidden)
    if len(images) != frames:
        return False, "%d of %d frame images" % (len(images), frames)
    missing = [i for i in images if seen.get(i, 0) == 0]
    doubled = [i for i in images if seen.get(i, 0) > 1]
    extra = [n for n in seen if n not in images]
    if missing or doubled or extra:
        return False, "manifest: %d image(s) without a line, %d with two or more, %d line(s) naming no image" % (
            len(missing), len(doubled), len(extra))
    stale = "; the SIGKILLed run's temporary file stays" if hidden else ""
    return True, "manifest: one valid line per frame, %d frames%s" % (frames, stale)


CAPTURE = ["capture", "--path", os.path.join(ROWS, "rack-focus.json"), "--frames", "0:11", "--width", "30", "-q",
           "--out", "{D}/frames/f_%04d.png"]
CAPTURE_SHORT = "capture --path rack-focus.json --frames 0:11 --width 30 --out D/frames/f_%04d.png"


def resume_capture(d, run, killed=False):
    """Rerun the capture with --skip-existing; the manifest must then be whole."""
    r = run(CAPTURE + ["--skip-existing"])
    if r["rc"] != 0:
        return False, "resume exited %s: %s" % (r["rc"], first_line(r["stderr"]))
    return check_manifest(d, 12, stale_allowed=killed)


def define_cases():
    dof = os.path.join(ROWS, "camera-dof.json")
    rows_gltf = os.path.join(ROWS, "rows.gltf")

    # ---- 1. faults -------------------------------------------------------------------------
    F = "faults"
    case("F01", F, RENDER[:1] + ["--width", "320", "-q", "--out", "{D}/small/x.png"], "refuse", "No space left on device",
         needs="tmpfs", quick=True, watched="small", short="render --width 320 --out D/small/x.png (a 16 KiB tmpfs)")
    case("F02", F, ["raycast", "--spp", "1", "--width", "200", "-q", "--out", "{D}/small/x.exr"], "refuse",
         "No space left on device", needs="tmpfs", watched="small",
         short="raycast --spp 1 --width 200 --out D/small/x.exr (a 16 KiB tmpfs)")
    case("F03", F, ["capture", "--path", os.path.join(ROWS, "rack-focus.json"), "--frames", "0:3", "--width", "200", "-q",
                    "--out", "{D}/small/f_%04d.exr"], "refuse", "No space left on device", needs="tmpfs",
         short="capture --path rack-focus.json --frames 0:3 --width 200 --out D/small/f_%04d.exr (16 KiB tmpfs)",
         partial=True)
    case("F04", F, RENDER + ["--out", "{D}/x.png", "--stats", "{D}/small/full/s.json"], "refuse", "--stats", needs="tmpfs",
         setup=lambda d: os.makedirs(os.path.join(d, "small", "full")),
         short="render --out D/x.png --stats D/small/full/s.json (a full 16 KiB tmpfs)")
    case("F05", F, ["capture", "--path", os.path.join(ROWS, "rack-focus.json"), "--frames", "0:3", "--width", "160", "-q",
                    "--out", "{D}/frames/f_%04d.exr"], "refuse", "File too large", fsize_kb=16, quick=True,
         short="capture --frames 0:3 --width 160 --out D/frames/f_%04d.exr (ulimit -f 16)",
         partial=True)
    case("F06", F, RAYCAST + ["--out", "{D}/ro/x.png"], "refuse", ("Permission denied", "ro"), user="nobody", needs="nobody",
         setup=lambda d: (os.mkdir(os.path.join(d, "ro")), os.chmod(os.path.join(d, "ro"), 0o555)), quick=True,
         short="raycast --out D/ro/x.png (read-only folder, as nobody)")
    case("F07", F, ["capture"] + CAPTURE[1:] + ["--manifest", "{D}/ro/m.jsonl"], "refuse", ("--manifest", "ro"),
         user="nobody", needs="nobody", setup=lambda d: (os.mkdir(os.path.join(d, "ro")), os.chmod(os.path.join(d, "ro"), 0o555)),
         short="capture ... --manifest D/ro/m.jsonl (read-only folder, as nobody)")
    case("F08", F, RENDER + ["--out", "{D}/sticky/x.png"], "refuse", "x.png", user="nobody", needs="nobody",
         setup=lambda d: (os.mkdir(os.path.join(d, "sticky")), write_text(d, "sticky/x.png", b"root's file"),
                          os.chmod(os.path.join(d, "sticky"), 0o1777)),
         short="render --out D/sticky/x.png (root's file in a sticky folder, as nobody)")
    case("F09", F, RENDER + ["--out", "{D}/folder.png"], "refuse", "folder.png", setup=lambda d: os.mkdir(os.path.join(d, "folder.png")),
         quick=True, short="render --out D/folder.png (a folder)")
    case("F10", F, RENDER + ["--out", "{D}/fifo.png"], "either", "fifo.png", setup=lambda d: os.mkfifo(os.path.join(d, "fifo.png")),
         short="render --out D/fifo.png (a FIFO)")
    case("F11", F, RENDER + ["--out", "{D}/dangling.png"], "either", "dangling.png",
         setup=lambda d: os.symlink(os.path.join(d, "nowhere", "x.png"), os.path.join(d, "dangling.png")),
         short="render --out D/dangling.png (a symlink to nowhere)")
    case("F12", F, ["capture"] + CAPTURE[1:5] + ["--width", "30", "-q", "--out", "{D}/a/b/c/f_%04d.png"], "either", "a/b/c",
         short="capture --frames 0:11 --out D/a/b/c/f_%04d.png (missing parents)",
         after=lambda d, run: check_manifest(d, 12, "a/b/c"))
    case("F13", F, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.png", "--stats", "{D}/cam.json"], "refuse", "cam.json",
         setup=cam_setup(physical_camera()), short="render --camera D/cam.json --stats D/cam.json (input = output)")
    case("F14", F, RENDER + ["--out", "{D}/x.png", "--stats", "{D}/x.png"], "refuse", "x.png", quick=True,
         short="render --out D/x.png --stats D/x.png (two outputs, one file)")
    case("F15", F, ["capture"] + CAPTURE[1:] + ["--manifest", "{D}/frames/f_0002.png"], "refuse", ("f_0002.png", "--manifest"),
         short="capture --out D/frames/f_%04d.png --manifest D/frames/f_0002.png")
    case("F16", F, RENDER + ["--out", "{D}/x.jpg"], "refuse", ("x.jpg", ".png"), short="render --out D/x.jpg")
    case("F17", F, RENDER + ["--out", ""], "refuse", "--out", short="render --out ''")
    case("F18", F, RENDER + ["--out", "{D}/" + "n" * 300 + ".png"], "refuse", ("File name too long", "--out"),
         short="render --out D/nnn...(300 characters).png")
    case("F19", F, ["sweep", "--out", "{D}/file", "--width", "16", "--reference-spp", "2", "--max-views", "2",
                    "--methods", "concentric", "-q"], "refuse", "file", setup=text_setup("a file", "file"),
         short="sweep --out D/file (an existing file)")
    case("F20", F, RENDER + ["--out", "{D}/small/x.png"], "refuse", ("No space left on device", "x.png"), needs="tmpfs",
         tmpfs_options="size=1m,nr_inodes=1", watched="small", short="render --out D/small/x.png (a tmpfs with no free inode)")
    case("F21", F, CAPTURE + ["--colmap-out", "{D}/ro/model"], "refuse", ("--colmap-out", "ro"), user="nobody", needs="nobody",
         setup=lambda d: (os.mkdir(os.path.join(d, "ro")), os.chmod(os.path.join(d, "ro"), 0o555)),
         short="capture ... --colmap-out D/ro/model (read-only folder, as nobody)")
    case("F22", F, ["info", "{D}/box.gltf", "--camera", "{D}/noread.json"], "refuse", "Permission denied", user="nobody", needs="nobody",
         setup=lambda d: (box_scene(d), write_json(d, "noread.json", physical_camera()), os.chmod(os.path.join(d, "noread.json"), 0)),
         short="info box.gltf --camera D/noread.json (mode 000, as nobody)")
    case("F23", F, ["view", "--frames", "1", "--screenshot", "{D}/x.png"], "refuse", "DISPLAY",
         unset=("DISPLAY", "WAYLAND_DISPLAY"), short="view --frames 1 --screenshot D/x.png (no DISPLAY)")

    # ---- 2. signals ------------------------------------------------------------------------
    S = "signals"
    tiled = ["render", "--width", "2400", "--tile-size", "64", "-q", "--out", "{D}/t.png"]
    tiled_short = "render --width 2400 --tile-size 64 --out D/t.png"
    slow_render = ["render", "--camera", dof, "--width", "480", "--aperture-samples", "4096", "-q", "--out", "{D}/x.exr"]
    slow_short = "render --camera camera-dof.json --width 480 --aperture-samples 4096 --out D/x.exr"
    for cid, sig, quick in (("S01", signal.SIGINT, True), ("S02", signal.SIGTERM, False), ("S03", signal.SIGHUP, False)):
        case(cid, S, tiled, "signal", send=(sig, hidden_file_present), quick=quick,
             short="%s; %s while the image is written" % (tiled_short, signal.Signals(sig).name))
    case("S04", S, tiled, "sigkill", send=(signal.SIGKILL, hidden_file_present),
         short="%s; SIGKILL while the image is written, then the same again" % tiled_short,
         after=lambda d, run: rerun_writes(d, run, tiled, "t.png"))
    case("S05", S, slow_render, "signal", send=(signal.SIGINT, after_seconds(1.0)), short=slow_short + "; SIGINT after 1 s")
    case("S06", S, slow_render, "signal", send=(signal.SIGTERM, after_seconds(2.0)), short=slow_short + "; SIGTERM after 2 s")
    case("S07", S, ["raycast", "--spp", "4096", "--width", "120", "-q", "--out", "{D}/x.png"], "signal",
         send=(signal.SIGTERM, after_seconds(1.0)), short="raycast --spp 4096 --width 120; SIGTERM after 1 s")
    for cid, sig, mid, quick in (("S08", signal.SIGINT, True, True), ("S09", signal.SIGTERM, True, False),
                                 ("S10", signal.SIGHUP, None, False), ("S11", signal.SIGKILL, False, True)):
        case(cid, S, CAPTURE, "sigkill" if sig == signal.SIGKILL else "signal",
             send=(sig, {True: mid_frame_write(3), False: manifest_lines_at_least(3), None: image_before_its_line(3)}[mid]),
             quick=quick,
             after=lambda d, run, k=(sig == signal.SIGKILL): resume_capture(d, run, k),
             short="%s; %s %s, then --skip-existing" % (CAPTURE_SHORT, signal.Signals(sig).name,
                                                         {True: "while frame 4 is written", False: "after 3 frames",
                                                          None: "between frame 4's image and its manifest line"}[mid]))
    case("S12", S, ["sweep", "--out", "{D}/sweep", "--width", "64", "--reference-spp", "65536", "--max-views", "4",
                    "--max-spp", "4", "-q"], "signal", send=(signal.SIGINT, after_seconds(1.5)),
         short="sweep --out D/sweep --width 64 --reference-spp 65536; SIGINT after 1.5 s")
    case("S13", S, ["render", "--width", "320", "-q", "--out", "{D}/x.png"], "refuse", "File too large", fsize_kb=16,
         ignore_xfsz=False, quick=True, short="render --width 320 --out D/x.png (ulimit -f 16, SIGXFSZ not ignored)")
    case("S14", S, CAPTURE[:3] + ["--frames", "0:3", "--width", "160", "-q", "--out", "{D}/frames/f_%04d.exr"], "refuse",
         "File too large", fsize_kb=16, ignore_xfsz=False,
         short="capture --frames 0:3 --width 160 --out D/frames/f_%04d.exr (ulimit -f 16, SIGXFSZ not ignored)")

    # ---- 3. numeric extremes ---------------------------------------------------------------
    N = "numeric"
    for cid, option, value, quick in (
            ("N01", "--width", "nan", True), ("N02", "--width", "99999999999", True), ("N03", "--width", "-5", False),
            ("N04", "--height", "1e309", False), ("N05", "--focal-length", "nan", True), ("N06", "--focal-length", "inf", False),
            ("N07", "--f-number", "-0", True), ("N09", "--focus-distance", "nan", True),
            ("N10", "--focus-distance", "-inf", False), ("N11", "--focus-distance", "-0", False),
            ("N12", "--time", "nan", False), ("N13", "--seed", "-1", False), ("N14", "--seed", "99999999999999999999", False),
            ("N15", "--aperture-samples", "-3", False), ("N16", "--target-psnr", "nan", False),
            ("N17", "--tile-size", "99999999999", False), ("N18", "--max-samples", "1e3", False)):
        base = ["render", "-q"] if option in ("--width", "--height") else RENDER
        case(cid, N, base + [option, value, "--out", "{D}/x.exr"], "refuse", option, quick=quick)
    for cid, option, values in (("N19", "--eye", "nan,1,3"), ("N20", "--target", "0,inf,0"), ("N21", "--background", "nan,0,0"),
                                ("N22", "--background", "1e309,0,0"), ("N23", "--focus-at", "nan,3")):
        case(cid, N, RENDER + [option] + values.split(",") + ["--out", "{D}/x.exr"], "refuse", option,
             short="render %s %s" % (option, values.replace(",", " ")))
    case("N08", N, RENDER + ["--f-number", "1e-320", "--out", "{D}/x.exr"], "either", "--f-number", visible=True)
    case("N24", N, RENDER + ["--sensor", "1e-320x1e-320", "--out", "{D}/x.exr"], "either", "--sensor", visible=True)
    case("N25", N, RENDER + ["--sensor", "nanx24", "--out", "{D}/x.exr"], "refuse", "--sensor")
    case("N26", N, RENDER + ["--focus-at", "100000", "100000", "--out", "{D}/x.exr"], "refuse", "--focus-at",
         short="render --focus-at 100000 100000 (outside the image)")
    case("N27", N, RENDER + ["--eye", "0", "1", "3", "--target", "0", "1", "3", "--out", "{D}/x.exr"], "refuse",
         ("--target", "--eye"), quick=True, short="render --eye 0 1 3 --target 0 1 3 (eye = target)")
    case("N28", N, RAYCAST[:1] + ["--spp", "0"] + W + ["--out", "{D}/x.exr"], "refuse", "--spp")
    case("N29", N, ["capture", "--fps", "1e-320", "--width", "30", "-q", "--out", "{D}/f_%04d.png"], "refuse", "--fps")
    case("N30", N, CAPTURE + ["--shard", "3/2"], "refuse", "--shard", short="capture ... --shard 3/2")
    case("N31", N, CAPTURE[:3] + ["--frames", "0:99999999999"] + CAPTURE[5:], "refuse", "--frames",
         short="capture --path rack-focus.json --frames 0:99999999999")
    # JSON fields
    for cid, fields, frag, expect, quick in (
            ("N32", {"focal_length_mm": 1e309}, ("focal_length_mm", "1e309"), "refuse", True),
            ("N33", {"f_number": -0.0}, "f_number", "refuse", False),
            ("N34", {"focus_distance": 1e-320}, "focus_distance", "refuse", False),
            ("N35", {"eye": [1e300, 1, 3]}, "eye", "either", False),
            ("N36", {"near": -1}, "near", "refuse", False),
            ("N37", {"near": 1e-320}, "near", "either", False),
            ("N38", {"sensor_mm": [1e-320, 1e-320]}, "sensor_mm", "either", False),
            ("N39", {"focus_distance": 0.035 * (1 + 1e-12), "f_number": 2.8}, "focus_distance", "either", True),
            ("N40", {"f_number": 1e-6}, "f_number", "either", False),
            ("N41", {"f_number": 1e12}, "f_number", "either", False),
            ("N42", {"up": [0, 0, 0]}, "up", "refuse", False)):
        text = json.dumps(physical_camera(**fields)).replace("Infinity", "1e309")
        short = "render --camera cam.json (%s)" % json.dumps(fields).strip("{}")
        case(cid, N, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr"], expect, frag, setup=text_setup(text),
             short=short, quick=quick, visible=True)
    case("N43", N, RENDER + ["--out", "{D}/x.exr", "{D}/far.gltf"], "image", None, nonconstant=True, visible=True, quick=True,
         setup=lambda d: box_scene(d, "far.gltf", at=(1e12, 0, 0)), short="render far.gltf (a box translated by 1e12; automatic framing)")
    case("N44", N, RAYCAST + ["--out", "{D}/x.exr", "{D}/far.gltf"], "image", None, nonconstant=True, visible=True,
         setup=lambda d: box_scene(d, "far.gltf", at=(1e12, 0, 0)), short="raycast far.gltf (a box translated by 1e12)")
    case("N45", N, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr", "{D}/deep.gltf"], "either", "cam.json",
         setup=lambda d: (write_gltf(d, "deep.gltf", *gltf_boxes([((1e-4,) * 3, (0, 0, -1e-3)), ((1e8,) * 3, (0, 0, -1e9))])),
                          write_json(d, "cam.json", {"eye": [0, 0, 0], "target": [0, 0, -1], "focal_length_mm": 35})),
         short="render deep.gltf (a 2e-4 box at 1e-3 before a 2e8 box at 1e9)")
    case("N46", N, ["capture", "--path", "{D}/path.json", "--width", "30", "-q", "--out", "{D}/f_%04d.png"], "refuse", "fps",
         setup=text_setup(json.dumps({"fps": 1e309, "keys": [dict(physical_camera(), time=0), dict(physical_camera(), time=1)]})
                          .replace("Infinity", "1e309"), "path.json"),
         short="capture --path path.json (\"fps\": 1e309)")
    case("N47", N, ["capture", "--path", "{D}/path.json", "--width", "30", "-q", "--out", "{D}/f_%04d.png"], "refuse", "frames",
         setup=cam_setup({"fps": 24, "frames": 10 ** 12, "keys": [dict(physical_camera(), time=0)]}, "path.json"),
         short="capture --path path.json (\"frames\": 1e12)")
    case("N48", N, ["capture", "--path", "{D}/path.json", "--width", "30", "-q", "--out", "{D}/f_%04d.png"], "either", "time",
         setup=cam_setup({"fps": 24, "keys": [dict(physical_camera(), time=0), dict(physical_camera(), time=1e-320)]}, "path.json"),
         short="capture --path path.json (key times 0 and 1e-320)")
    case("N49", N, CAPTURE + ["--shard", "0/0"], "refuse", "--shard", short="capture ... --shard 0/0")
    case("N50", N, CAPTURE[:3] + ["--frames", "5:2"] + CAPTURE[5:], "refuse", "--frames", short="capture ... --frames 5:2")
    case("N54", N, ["raycast", "--width", "16384", "--height", "16384", "--spp", "1", "-q", "--out", "{D}/x.exr"], "refuse",
         ("memory", "--width"), short="raycast --width 16384 --height 16384 (2^28 pixels, the limit; 3 GiB address space)")
    case("N55", N, ["render", "--width", "65536", "--height", "65536", "-q", "--out", "{D}/x.png"], "refuse", "--width",
         short="render --width 65536 --height 65536 (2^32 pixels)")
    opencv = {"intrinsics": {"fx": 600, "fy": 600, "cx": 319.5, "cy": 239.5, "width": 640, "height": 480},
              "eye": [0, 1, 3], "target": [0, 0.55, -2]}
    case("N51", N, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr"], "refuse", ("width", "cam.json"),
         setup=cam_setup(dict(opencv, intrinsics=dict(opencv["intrinsics"], width=99999999999))),
         short="render --camera cam.json (OpenCV intrinsics, width 99999999999)")
    case("N52", N, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr"], "either", "fx", visible=True,
         setup=cam_setup(dict(opencv, intrinsics=dict(opencv["intrinsics"], fx=1e-320))),
         short="render --camera cam.json (OpenCV intrinsics, fx 1e-320)")
    case("N53", N, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr"], "either", ("fx", "cam.json"), visible=True,
         setup=cam_setup(dict(opencv, intrinsics=dict(opencv["intrinsics"], fx=1e300, fy=1e300))),
         short="render --camera cam.json (OpenCV intrinsics, fx = fy = 1e300)")

    # ---- 4. malformed files ----------------------------------------------------------------
    M = "malformed"
    good = json.dumps(physical_camera())
    for cid, content, frag, quick in (
            ("M01", good[:len(good) // 2], "cam.json", True),
            ("M02", good[:-1] + ', "eye": [0, 2, 3]}', "eye", True),
            ("M03", json.dumps(physical_camera(eye="abc")), "eye", False),
            ("M04", "[" * 100000 + "]" * 100000, "cam.json", True),
            ("M05", json.dumps(physical_camera(comment="x" * (50 << 20))), "cam.json", False),
            ("M06", b"\xef\xbb\xbf" + good.encode(), "cam.json", False),
            ("M07", good[:20] + "\0" + good[20:], "cam.json", False),
            ("M08", "", "cam.json", False),
            ("M09", "3", "cam.json", False),
            ("M10", json.dumps(physical_camera(distortion={"k1": "0.1"})), "k1", False)):
        expect = "either" if cid == "M06" else "refuse"
        labels = {"M01": "truncated", "M02": "a duplicate key", "M03": "\"eye\": \"abc\"", "M04": "100000 nested arrays",
                  "M05": "a 50 MB string", "M06": "a UTF-8 BOM", "M07": "a NUL byte", "M08": "empty", "M09": "the number 3",
                  "M10": "\"k1\": \"0.1\""}
        case(cid, M, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.png"], expect, frag, setup=text_setup(content),
             short="render --camera cam.json (%s)" % labels[cid], quick=quick)
    case("M11", M, RENDER + ["--camera", "/dev/zero", "--out", "{D}/x.png"], "refuse", "/dev/zero", quick=True)
    case("M12", M, RENDER + ["--camera", "{D}/fifo.json", "--out", "{D}/x.png"], "refuse", "fifo.json",
         setup=lambda d: os.mkfifo(os.path.join(d, "fifo.json")), short="render --camera D/fifo.json (a FIFO, no writer)")
    case("M13", M, RENDER + ["--camera", "{D}", "--out", "{D}/x.png"], "refuse", ("folder", "directory"), short="render --camera D (a folder)")
    case("M14", M, RENDER + ["--out", "{D}/x.png", "/dev/zero"], "refuse", "/dev/zero", short="render /dev/zero (as the scene)")
    case("M15", M, RENDER + ["--out", "{D}/x.png", "{D}/fifo.gltf"], "refuse", "fifo.gltf",
         setup=lambda d: os.mkfifo(os.path.join(d, "fifo.gltf")), short="render D/fifo.gltf (a FIFO, no writer)")
    case("M16", M, ["info", "{D}/folder.gltf"], "refuse", "folder.gltf", setup=lambda d: os.mkdir(os.path.join(d, "folder.gltf")),
         short="info D/folder.gltf (a folder)")

    def bad_gltf(mutate, name="bad.gltf", bin_name="box.bin"):
        def setup(d):
            doc, buffer = gltf_boxes([((0.5, 0.5, 0.5), (0, 0, 0))])
            buffer = mutate(doc, buffer) or buffer
            write_gltf(d, name, doc, buffer, bin_name)
        return setup

    def index_out_of_range(doc, buffer):
        return buffer[:doc["bufferViews"][2]["byteOffset"]] + struct.pack("<H", 60000) + buffer[doc["bufferViews"][2]["byteOffset"] + 2:]
    for cid, mutate, label, frag, quick in (
            ("M17", index_out_of_range, "an index 60000 of 24 vertices", "bad.gltf", True),
            ("M18", lambda doc, b: doc["accessors"][0].update(count=2 ** 32 - 1), "POSITION count 2^32-1", "bad.gltf", True),
            ("M19", lambda doc, b: doc["bufferViews"][0].update(byteStride=13), "byteStride 13", "bad.gltf", False),
            ("M20", lambda doc, b: doc["accessors"][0].update(byteOffset=1 << 40), "byteOffset 2^40", "bad.gltf", False),
            ("M21", lambda doc, b: doc["accessors"][2].update(componentType=5130), "index componentType 5130", "bad.gltf", False),
            ("M22", lambda doc, b: doc["bufferViews"][1].update(byteLength=10 ** 15), "bufferView byteLength 1e15", "bad.gltf", False),
            ("M23", lambda doc, b: doc["nodes"][0].update(mesh=7), "node mesh 7 of 1", "bad.gltf", False),
            ("M24", lambda doc, b: doc["nodes"][0].update(children=[0]), "a node its own child", "bad.gltf", False)):
        case(cid, M, RENDER + ["--out", "{D}/x.png", "{D}/bad.gltf"], "refuse", frag, setup=bad_gltf(mutate),
             short="render bad.gltf (%s)" % label, quick=quick)
    case("M25", M, RENDER + ["--out", "{D}/x.png", "{D}/bad.gltf"], "refuse", ("box.bin", "bad.gltf"),
         setup=lambda d: (bad_gltf(lambda doc, b: None)(d), os.remove(os.path.join(d, "box.bin"))),
         short="render bad.gltf (its .bin missing)", quick=True)
    case("M26", M, RENDER + ["--out", "{D}/x.png", "{D}/bad.gltf"], "refuse", "bad.gltf",
         setup=bad_gltf(lambda doc, b: None, bin_name="data:application/octet-stream;base64,@@not base64!!"),
         short="render bad.gltf (a data URI of garbage)")
    case("M27", M, RENDER + ["--out", "{D}/x.png", "{D}/bad.gltf"], "refuse", "bad.gltf",
         setup=bad_gltf(lambda doc, b: None, bin_name="data:application/octet-stream;base64," + base64.b64encode(b"short").decode()),
         short="render bad.gltf (a data URI 5 bytes long)")
    case("M28", M, RENDER + ["--out", "{D}/x.png", "{D}/bad.glb"], "refuse", "bad.glb", quick=True,
         setup=lambda d: write_glb(os.path.join(d, "bad.glb"), *gltf_boxes([((0.5,) * 3, (0, 0, 0))]), length_delta=1 << 30),
         short="render bad.glb (header length 1 GiB too long)")
    case("M29", M, RENDER + ["--out", "{D}/x.png", "{D}/bad.glb"], "refuse", "bad.glb",
         setup=lambda d: write_glb(os.path.join(d, "bad.glb"), *gltf_boxes([((0.5,) * 3, (0, 0, 0))]), length_delta=-8),
         short="render bad.glb (header length 8 bytes short)")
    case("M30", M, RENDER + ["--out", "{D}/x.png", "{D}/deep.gltf"], "refuse", "deep.gltf",
         setup=text_setup('{"asset": {"version": "2.0"}, "extras": ' + "[" * 100000 + "]" * 100000 + "}", "deep.gltf"),
         short="render deep.gltf (100000 nested arrays in extras)")

    def vertex(value):
        return lambda doc, b: struct.pack("<f", value) + b[4:]
    case("M36", M, RENDER + ["--out", "{D}/x.exr", "{D}/bad.gltf"], "either", "bad.gltf", setup=bad_gltf(vertex(float("nan"))),
         short="render bad.gltf (a vertex coordinate NaN in the buffer)")
    case("M37", M, RAYCAST + ["--out", "{D}/x.exr", "{D}/bad.gltf"], "either", "bad.gltf", setup=bad_gltf(vertex(float("inf"))),
         short="raycast bad.gltf (a vertex coordinate +inf in the buffer)")
    case("M38", M, RENDER + ["--out", "{D}/x.exr", "{D}/bad.gltf"], "either", "bad.gltf", setup=bad_gltf(vertex(3.4e38)),
         short="render bad.gltf (a vertex coordinate 3.4e38 in the buffer)")

    def sparse(name, head, size=3 << 30):
        def setup(d):
            with open(os.path.join(d, name), "wb") as f:
                f.write(head)
                f.truncate(size)
        return setup
    case("M39", M, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.png"], "refuse", "cam.json",
         setup=sparse("cam.json", b'{"eye": [0, 1, 3], "comment": "'), short="render --camera cam.json (3 GiB, sparse)")
    case("M40", M, ["info", "{D}/big.gltf"], "refuse", "big.gltf", setup=sparse("big.gltf", b'{"asset": {"version": "2.0"}, "x": "'),
         short="info big.gltf (3 GiB, sparse)")
    case("M41", M, ["capture", "--path", "{D}/path.json", "--width", "30", "-q", "--out", "{D}/f_%04d.png"], "refuse", "keys",
         setup=cam_setup({"fps": 24, "keys": {}}, "path.json"), short="capture --path path.json (\"keys\": {})")
    case("M42", M, ["capture", "--path", "{D}/path.json", "--width", "30", "-q", "--out", "{D}/f_%04d.png"], "refuse", "path.json",
         setup=text_setup(open(os.path.join(ROWS, "rack-focus.json")).read()[:500], "path.json"),
         short="capture --path path.json (truncated)")
    colmap_cases = (
        ("M31", "1 PINHOLE 640 480 500 500 320\n", "cameras.txt", "cameras.txt: PINHOLE with 3 parameters", True),
        ("M32", "1 PINHOLE 640 480 500 500 320 240\n", "images.txt", "images.txt: an image line of 9 fields", False),
        ("M33", "1 PINHOLE 640 480 nan 500 320 240\n", "cameras.txt", "cameras.txt: fx nan", False),
        ("M34", "1 PINHOLE 0 480 500 500 320 240\n", "cameras.txt", "cameras.txt: WIDTH 0", False),
        ("M35", "1 SIMPLE_RADIAL 640 480 500 320 240 1e309\n", "cameras.txt", "cameras.txt: k 1e309", False),
        ("M43", "1 PINHOLE 640 480 500 500 320 240\n", "images.txt", "images.txt: quaternion 0 0 0 0", False),
        ("M44", "1 PINHOLE 99999999999 480 500 500 320 240\n", "cameras.txt", "cameras.txt: WIDTH 99999999999", False))
    for cid, cameras, frag, label, quick in colmap_cases:
        images = {"M32": "1 1 0 0 0 0 -0.5 5 1\n\n", "M43": "1 0 0 0 0 0 -0.5 5 1 a.png\n\n"}.get(cid, COLMAP_IMAGES)
        case(cid, M, RENDER + ["--colmap", "{D}/model", "--image", "a.png", "--out", "{D}/x.png"], "refuse", frag,
             setup=lambda d, c=cameras, i=images: colmap_model(d, c, i), short="render --colmap model --image a.png (%s)" % label,
             quick=quick)

    # ---- 5. cameras at the scale ends --------------------------------------------------------
    C = "scale"
    for cid, size, quick in (("C01", 1e-6, True), ("C02", 1e-3, False), ("C03", 1e3, False), ("C04", 1e-9, False),
                             ("C05", 1e9, False)):
        case(cid, C, RENDER + ["--out", "{D}/x.exr", "{D}/box.gltf"], "image", None, nonconstant=True, visible=True, quick=quick,
             setup=lambda d, s=size: box_scene(d, "box.gltf", half=(s / 2,) * 3, at=(s, -s, s / 3)),
             short="render box.gltf (a %g m box; automatic framing)" % size)
    case("C06", C, RAYCAST + ["--out", "{D}/x.exr", "{D}/box.gltf"], "image", None, nonconstant=True, visible=True,
         setup=lambda d: box_scene(d, "box.gltf", half=(5e-7,) * 3, at=(1e-6, 0, 0)),
         short="raycast box.gltf (a 1 µm box; automatic framing)")
    case("C07", C, RENDER + ["--out", "{D}/x.exr", "{D}/flat.gltf"], "either", "flat.gltf",
         setup=lambda d: box_scene(d, "flat.gltf", half=(0.0, 0.0, 0.0)), short="render flat.gltf (every vertex at one point)")
    # camera.json's view in the lecture form: from (0, 1, 3) at (0, 0.55, -2), a surface at the centre
    lecture = {"projection": "perspective", "vrp": [0, 0.55, -2], "vpn": [0, 0.45, 5], "vup": [0, 1, 0], "prp": [0, 0, 5],
               "window": [-1.5, -1, 1.5, 1]}
    for cid, fields, frag, label, quick in (
            ("C08", {"window": [-5e-10, -3.3e-10, 5e-10, 3.3e-10], "prp": [0, 0, 1]}, "window", "a field of view of 1e-9 rad", True),
            ("C09", {"prp": [0, 0, 1e-30]}, "prp", "PRP n = 1e-30", True),
            ("C10", {"projection": "parallel", "window": [-1e-30, -1e-30, 1e-30, 1e-30], "far": 20}, "window",
             "a parallel window 2e-30 wide", False),
            ("C11", {"distortion": {"k1": 1e6}}, "k1", "k1 = 1e6", True),
            ("C12", {"distortion": {"k1": -1e6}}, "k1", "k1 = -1e6", False),
            ("C13", {"aperture_radius": 0.01, "focus_distance": 4,
                     "chromatic": {"focus_distance_red": 1e-200, "focus_distance_blue": 4}}, "focus_distance_red",
             "focus_distance_red 1e-200", True),
            ("C14", {"aperture_radius": 0.01, "focus_distance": 4,
                     "chromatic": {"focus_distance_red": 4, "focus_distance_blue": 1e200}}, "focus_distance_blue",
             "focus_distance_blue 1e200", False)):
        cam = dict(lecture, **fields)
        case(cid, C, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr", rows_gltf], "either", frag,
             setup=cam_setup(cam), short="render --camera cam.json (lecture form, %s)" % label, quick=quick, visible=True)
    case("C15", C, RAYCAST + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr", rows_gltf], "either", "window", visible=True,
         setup=cam_setup(dict(lecture, window=[-5e-10, -3.3e-10, 5e-10, 3.3e-10], prp=[0, 0, 1])),
         short="raycast --camera cam.json (a field of view of 1e-9 rad)")
    case("C16", C, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr"], "either", "focal_length_mm", visible=True,
         setup=cam_setup(physical_camera(focal_length_mm=1e13, focus_distance="infinity")),
         short="render --camera cam.json (focal_length_mm 1e13: 3.6e-12 rad)")
    case("C17", C, RENDER + ["--focal-length", "0.01", "--out", "{D}/x.exr"], "either", "--focal-length",
         short="render --focal-length 0.01 (a 179.96° field of view)")
    case("C18", C, RENDER + ["--focal-length", "1000000", "--f-number", "1.4", "--out", "{D}/x.exr"], "either", "--focal-length",
         short="render --focal-length 1000000 --f-number 1.4 (automatic framing)")
    case("C19", C, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr"], "either", "corner_focus_distance", visible=True,
         setup=cam_setup(physical_camera(f_number=2.8, field_curvature={"corner_focus_distance": 1e-200})),
         short="render --camera cam.json (corner_focus_distance 1e-200)")
    case("C20", C, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr", "{D}/far.gltf"], "either", ("cam.json", "far.gltf"),
         setup=lambda d: (box_scene(d, "far.gltf", at=(0, 0, -1e15)),
                          write_json(d, "cam.json", {"eye": [0, 0, 0], "target": [0, 0, -1], "focal_length_mm": 1e5})),
         short="render far.gltf --camera cam.json (a 1 m box 1e15 away through a 1e5 mm lens)")
    case("C21", C, RENDER + ["--camera", "{D}/cam.json", "--out", "{D}/x.exr", rows_gltf], "either", "aperture_radius", visible=True,
         setup=cam_setup(dict(lecture, aperture_radius=1e300, focus_distance=5)),
         short="render --camera cam.json (lecture form, aperture_radius 1e300)")
    case("C22", C, RENDER + ["--out", "{D}/x.exr", "{D}/box.gltf"], "either", "box.gltf", nonconstant=True, visible=True,
         setup=lambda d: box_scene(d, "box.gltf", half=(5e-31,) * 3, at=(0, 0, 0)),
         short="render box.gltf (a 1e-30 m box; automatic framing)")

    # ---- 6. radiance, materials and the newer inputs --------------------------------------------
    R = "radiance"

    def material(mutate, lights=None):
        def setup(d):
            doc, buffer = gltf_boxes([((0.5, 0.5, 0.5), (0, 0, 0))])
            mutate(doc["materials"][0])
            doc["extensionsUsed"] = ["KHR_materials_emissive_strength", "KHR_texture_transform", "KHR_lights_punctual"]
            if lights is not None:
                doc["extensions"] = {"KHR_lights_punctual": {"lights": lights}}
                doc["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 2, 2]})
                doc["scenes"][0]["nodes"].append(len(doc["nodes"]) - 1)
            write_gltf(d, "m.gltf", doc, buffer)
        return setup

    def emissive(strength, factor=(1, 1, 1)):
        def mutate(m):
            m["emissiveFactor"] = list(factor)
            m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": strength}}
        return mutate
    case("R01", R, RENDER + ["--aperture-samples", "4", "--out", "{D}/x.exr", "{D}/m.gltf"], "image", None, visible=True,
         quick=True, setup=material(emissive(1e38)), short="render m.gltf --aperture-samples 4 (emission 1e38: summed views)")
    case("R02", R, RENDER + ["--out", "{D}/x.exr", "{D}/m.gltf"], "refuse", "emissiveStrength", setup=material(emissive(1e300)),
         short="render m.gltf (emissiveStrength 1e300)")
    case("R03", R, RENDER + ["--out", "{D}/x.exr", "{D}/m.gltf"], "refuse", "emissiveFactor",
         setup=material(emissive(1, (1, -1, 1))), short="render m.gltf (emissiveFactor -1)")
    case("R04", R, RENDER + ["--out", "{D}/x.exr", "{D}/m.gltf"], "refuse", "3.4e+38",
         setup=material(lambda m: None, [{"type": "point", "intensity": 3.5e38}]),
         short="render m.gltf (a point light of 3.5e38 cd)")

    def textured(scale):
        def setup(d):
            doc, buffer = gltf_boxes([((0.5, 0.5, 0.5), (0, 0, 0))])
            # The box's texture coordinates: each vertex's x and y, a 2x2 checker (PNG as a data URI).
            positions = box_mesh((0.5, 0.5, 0.5))[0]
            blob = b"".join(struct.pack("<2f", p[0] + 0.5, p[1] + 0.5) for p in positions)
            doc["bufferViews"].append({"buffer": 0, "byteOffset": len(buffer), "byteLength": len(blob)})
            doc["accessors"].append({"bufferView": len(doc["bufferViews"]) - 1, "componentType": 5126,
                                     "count": len(positions), "type": "VEC2"})
            buffer += blob
            doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = len(doc["accessors"]) - 1
            png = "iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAAAAABX3VL4AAAADElEQVR4nGNg+A+EAAYAAf+T0eSJAAAAAElFTkSuQmCC"
            doc["images"] = [{"uri": "data:image/png;base64," + png}]
            doc["textures"] = [{"source": 0}]
            doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {
                "index": 0, "extensions": {"KHR_texture_transform": {"scale": [scale, scale]}}}
            doc["extensionsUsed"] = ["KHR_texture_transform"]
            doc["buffers"][0]["byteLength"] = len(buffer)
            write_gltf(d, "t.gltf", doc, buffer)
        return setup
    for cid, scale, quick in (("R05", 1e12, True), ("R06", 1e20, False)):
        case(cid, R, RAYCAST + ["--out", "{D}/x.exr", "{D}/t.gltf"], "image", None, visible=True, quick=quick,
             setup=textured(scale), short="raycast t.gltf (KHR_texture_transform scale %g)" % scale)
    case("R07", R, RENDER + ["--out", "{D}/x.exr", "{D}/t.gltf"], "refuse", ("scale", "1e+30"), setup=textured(1e31),
         short="render t.gltf (KHR_texture_transform scale 1e31)")
    env = ["render"] + W + ["--out", "{D}/x.png", rows_gltf, "--environment"]
    case("R08", R, env + ["{D}/fifo.hdr"], "refuse", "fifo.hdr", quick=True,
         setup=lambda d: os.mkfifo(os.path.join(d, "fifo.hdr")), short="render --environment fifo.hdr (a FIFO)")
    case("R09", R, env + ["{D}/zero.hdr"], "refuse", "zero.hdr",
         setup=lambda d: os.symlink("/dev/zero", os.path.join(d, "zero.hdr")), short="render --environment zero.hdr (/dev/zero)")
    case("R10", R, env + ["{D}/folder.hdr"], "refuse", "folder.hdr",
         setup=lambda d: os.mkdir(os.path.join(d, "folder.hdr")), short="render --environment folder.hdr (a folder)")
    case("R11", R, env + ["{D}/huge.hdr"], "refuse", "huge.hdr",
         setup=text_setup(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 32768 +X 65536\n" + b"\x02" * 100, "huge.hdr"),
         short="render --environment huge.hdr (a 150-byte header claiming 65536 x 32768)")
    case("R12", R, env + ["{D}/short.hdr"], "refuse", "short.hdr",
         setup=text_setup(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2048 +X 4096\n" + b"\x02" * 10, "short.hdr"),
         short="render --environment short.hdr (a header claiming 4096 x 2048 over 10 bytes)")

    # ---- 7. inputs as people save them, and what their names and specifications promise --------
    T = "inputs"
    gauss = os.path.join(REPO, "assets", "lenses", "double-gauss-50mm.lens")
    with open(gauss, "rb") as f:
        gauss_bytes = f.read()
    lens = ["lens"]
    case("T01", T, lens + ["{D}/bom.lens"], "image", None, quick=True,
         setup=text_setup(b"\xef\xbb\xbf" + gauss_bytes.replace(b"\n", b"\r\n"), "bom.lens"),
         short="lens bom.lens (a UTF-8 byte-order mark and CRLF line ends)")
    case("T02", T, lens + ["{D}/utf16.lens"], "refuse", "UTF-16",
         setup=text_setup(b"\xff\xfe" + gauss_bytes.decode().encode("utf-16-le"), "utf16.lens"),
         short="lens utf16.lens (UTF-16)")
    case("T03", T, RENDER + ["--out", "{D}/x.png", "--camera", "{D}/cam.json"], "image", None,
         setup=text_setup(b"\xef\xbb\xbf" + json.dumps(physical_camera()).encode(), "cam.json"),
         short="render --camera cam.json (a UTF-8 byte-order mark)")
    case("T04", T, lens + ["{D}/thick.lens"], "refuse", ("thickness_mm", "10000"),
         setup=text_setup("50 1e300 1.5 20\n-50 5 1 20\n0 0 0 10\n", "thick.lens"),
         short="lens thick.lens (a thickness of 1e300 mm)")
    case("T05", T, lens + ["{D}/diverging.lens"], "refuse", "diverges",
         setup=text_setup("-50 5 1.5 20\n50 5 1 20\n0 0 0 10\n", "diverging.lens"),
         short="lens diverging.lens (a negative focal length)")
    case("T06", T, lens + ["{D}/rows.lens"], "refuse", "at most 128",
         setup=text_setup("inf 0.1 1 40\n" * 200 + "0 0 0 10\n", "rows.lens"),
         short="lens rows.lens (201 surface rows)")
    env7 = ["render"] + W + ["--out", "{D}/x.png", os.path.join(ROWS, "rows.gltf"), "--environment"]
    png = base64.b64decode("iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAAAAABX3VL4AAAADElEQVR4nGNg+A+EAAYAAf+T0eSJAAAAAElFTkSuQmCC")
    case("T07", T, env7 + ["{D}/png.hdr"], "refuse", "PNG image", setup=text_setup(png, "png.hdr"),
         short="render --environment png.hdr (a PNG renamed .hdr)")

    def node(mutate):
        def setup(d):
            doc, buffer = gltf_boxes([((0.5, 0.5, 0.5), (0, 0, 0))])
            mutate(doc["nodes"][0])
            write_gltf(d, "n.gltf", doc, buffer)
        return setup
    case("T08", T, RENDER + ["--out", "{D}/x.png", "{D}/n.gltf"], "refuse", "skews",
         setup=node(lambda n: [n.pop(k, None) for k in ("translation", "rotation", "scale")] and
                    n.update(matrix=[1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])),
         short="render n.gltf (a node matrix with a skew)")
    case("T09", T, RENDER + ["--out", "{D}/x.png", "{D}/n.gltf"], "refuse", "unit quaternion",
         setup=node(lambda n: n.update(rotation=[0, 0, 0, 2])), short="render n.gltf (a rotation of length 2)")

    def short_buffer(d):
        doc, buffer = gltf_boxes([((0.5, 0.5, 0.5), (0, 0, 0))])
        write_gltf(d, "s.gltf", doc, buffer)
        with open(os.path.join(d, "box.bin"), "r+b") as f:
            f.truncate(len(buffer) - 8)
    case("T10", T, RENDER + ["--out", "{D}/x.png", "{D}/s.gltf"], "refuse", "byteLength", setup=short_buffer,
         short="render s.gltf (a buffer file 8 bytes short of its byteLength)")
    case("T11", T, ["capture", "--path", os.path.join(ROWS, "rack-focus.json"), "--frames", "0:3"] + W +
         ["--out", "{D}/f/f_%04d.png", "--colmap-out", "{D}/f/f_0002.png"], "refuse", "folder of its own",
         short="capture --out f/f_%04d.png --colmap-out f/f_0002.png (a frame's name)")


def rerun_writes(d, run, argv, name):
    r = run(argv)
    if r["rc"] != 0:
        return False, "the rerun exited %s: %s" % (r["rc"], first_line(r["stderr"]))
    ok, note = image_ok(os.path.join(d, name), False)
    stale = sorted(f for f in os.listdir(d) if f.startswith("."))
    return ok, note + ("; a SIGKILLed run's temporary file stays (SIGKILL cannot be caught)" if stale else "")

# ---------------------------------------------------------------------------------------------
# Running and judging


def first_line(text, width=100):
    lines = [line for line in text.splitlines() if line.strip() and not PROGRESS_LINE.match(line)]
    line = lines[0] if lines else ""
    return line if len(line) <= width else line[:width - 3] + "..."


def listing(folder):
    out = []
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            out.append(os.path.relpath(os.path.join(root, name), folder))
    return sorted(out)


def image_ok(path, nonconstant, visible=False):
    if not os.path.isfile(path):
        return False, "no image at the output's name"
    if shutil.which("iinfo") is None:
        with open(path, "rb") as f:
            magic = f.read(8)
        ok = magic.startswith(b"\x89PNG") or magic.startswith(b"\x76\x2f\x31\x01")
        return ok, "image written" if ok else "not a PNG or EXR file"
    r = subprocess.run(["iinfo", "--stats", path], capture_output=True, text=True)
    if r.returncode != 0:
        return False, "the image does not decode"
    counts = {}
    for key in ("NanCount", "InfCount"):
        m = re.search(key + r":\s*([0-9 ]+)", r.stdout)
        counts[key] = sum(int(x) for x in m.group(1).split()) if m else 0
    if counts["NanCount"] or counts["InfCount"]:
        return False, "image with %d NaN and %d infinite values" % (counts["NanCount"], counts["InfCount"])
    constant = re.search(r"Constant:\s*Yes", r.stdout) is not None
    maxima = re.search(r"Stats Max:\s*([-0-9.e+ ]+)", r.stdout)
    if visible and maxima and len(maxima.group(1).split()) == 4 and float(maxima.group(1).split()[3]) == 0:
        return False, "no surface in view: the background alone, where the scene fills the view"
    if nonconstant and constant:
        return False, "image of one colour: the object is not in view"
    return True, "image, finite" + (", one colour" if constant else "")


class Environment:
    def __init__(self, root):
        self.root = root
        self.tmpfs_reason = None
        self.nobody_reason = None
        if os.geteuid() != 0:
            self.nobody_reason = None  # not root: chmod alone stops the user; run as is
        elif shutil.which("setpriv") is None:
            self.nobody_reason = "needs setpriv to run as nobody (root writes anywhere)"

    def mount_tmpfs(self, folder, options):
        os.makedirs(folder)
        r = subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", folder], capture_output=True, text=True)
        if r.returncode != 0:
            return (r.stderr.strip().splitlines() or ["mount failed"])[0]
        os.chmod(folder, 0o777)
        return None


def run_case(c, lenslab, env, root):
    d = os.path.join(root, c.id)
    os.makedirs(d)
    os.chmod(d, 0o777)
    mounted = None
    if c.needs == "tmpfs":
        reason = env.mount_tmpfs(os.path.join(d, "small"), c.tmpfs_options)
        if reason:
            return "skipped", "not run", "cannot mount a tmpfs (%s)" % reason.replace(d, "D").rstrip(".")
        mounted = os.path.join(d, "small")
    if c.needs == "nobody" and env.nobody_reason:
        return "skipped", "not run", env.nobody_reason
    try:
        if c.setup:
            c.setup(d)
        if mounted and c.id == "F04":
            with open(os.path.join(mounted, "filler"), "wb") as f:  # fill the tmpfs to the last byte
                try:
                    f.write(b"\0" * (1 << 20))
                except OSError:
                    pass
        return judge(c, lenslab, d)
    finally:
        if mounted:
            subprocess.run(["umount", mounted], capture_output=True)


def make_runner(c, lenslab, d):
    def run(argv, send=None):
        argv = [a.replace("{D}", d) for a in argv]
        prefix = []
        if c.user == "nobody" and os.geteuid() == 0:
            prefix = ["setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups"]

        def limits():
            resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP_BYTES, MEMORY_CAP_BYTES))
            resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
            if c.fsize_kb is not None:
                resource.setrlimit(resource.RLIMIT_FSIZE, (c.fsize_kb * 1024, c.fsize_kb * 1024))
                if c.ignore_xfsz:
                    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        err_path = os.path.join(os.path.dirname(d), "." + os.path.basename(d) + ".stderr")
        with open(err_path, "w+b") as err:
            env = {k: v for k, v in os.environ.items() if k not in c.unset}
            env["LENSLAB_PROGRESS_SECONDS"] = "1000"
            p = subprocess.Popen(prefix + [lenslab] + argv, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err,
                                 preexec_fn=limits, start_new_session=True, env=env)
            start = time.monotonic()
            sent = None
            timed_out = False
            try:
                while p.poll() is None:
                    if time.monotonic() - start > TIMEOUT_SECONDS:
                        os.killpg(p.pid, signal.SIGKILL)
                        p.wait()
                        timed_out = True
                        break
                    if send and sent is None and send[1](d):
                        os.kill(p.pid, send[0])
                        sent = send[0]
                    time.sleep(0.0005 if send and sent is None else 0.002)
            except BaseException:  # the probe itself interrupted: take its lenslab along
                if p.poll() is None:
                    os.killpg(p.pid, signal.SIGKILL)
                    p.wait()
                raise
            err.seek(0)
            stderr = err.read().decode("utf-8", "replace")
        os.remove(err_path)
        return {"rc": p.returncode, "stderr": stderr, "timed_out": timed_out, "sent": sent}
    return run


def exit_text(r):
    rc = r["rc"]
    if r["timed_out"]:
        return "no exit in %d s" % TIMEOUT_SECONDS
    if rc < 0:
        return "killed by %s" % SIGNAL_NAMES.get(-rc, str(-rc))
    return "exit %d" % rc


def judge(c, lenslab, d):
    """Returns (verdict, observed, reason)."""
    run = make_runner(c, lenslab, d)
    watched = os.path.join(d, c.watched) if c.watched else d
    before = listing(watched)
    r = run(c.argv, c.send)
    observed = exit_text(r)
    clean = lambda s: s.replace(d, "D").replace(REPO + "/", "")
    line = first_line(clean(r["stderr"]))
    if line:
        observed += ": " + line
    if r["timed_out"]:
        return "fails", observed, "hang"
    outputs = [a.replace("{D}", d) for a in out_args(c.argv)]

    if c.expect in ("signal", "sigkill"):
        sig = c.send[0]
        if r["sent"] is None:
            return "fails", observed, "finished before the signal could be sent: make the run longer"
        if r["rc"] == 0:
            return "fails", observed, "exit 0 after %s" % signal.Signals(sig).name
        if r["rc"] < 0 and -r["rc"] != sig:
            return "fails", observed, "crashed"
        if r["rc"] > 0 and r["rc"] not in (128 + sig,):
            reason = "exit status %d after %s (128 + %d expected)" % (r["rc"], signal.Signals(sig).name, sig)
            return "fails", observed, reason
        notes = []
        if sig != signal.SIGKILL:
            hidden = [p for p in listing(d) if os.path.basename(p).startswith(".")]
            if hidden:
                return "fails", observed, "left %d hidden temporary file(s)" % len(hidden)
            if any(os.path.isfile(o) for o in outputs if "%" not in o):
                return "fails", observed, "left an output file"
            if c.argv[0] == "sweep" and os.path.exists(os.path.join(d, "sweep")):
                return "fails", observed, "left the sweep's folder"
        else:
            if any(os.path.isfile(o) for o in outputs if "%" not in o):
                return "fails", observed, "an image under the output's name after SIGKILL"
        if c.after:
            ok, note = c.after(d, run)
            if not ok:
                return "fails", observed, note
            notes.append(note)
        return "holds", observed, "; ".join(notes) or "nothing left"

    if r["rc"] < 0:
        hidden = [p for p in listing(d) if os.path.basename(p).startswith(".")]
        return "fails", observed, "crashed" + (", left %d hidden file(s)" % len(hidden) if hidden else "")
    if r["rc"] == 0:
        if c.expect == "refuse":
            return "fails", observed, "accepted (exit 0)"
        images = [o for o in outputs if "%" not in o and re.search(r"\.(png|exr)$", o)]
        note = "exit 0"
        for o in images:
            ok, note = image_ok(o, c.nonconstant, c.visible)
            if not ok:
                return "fails", observed, note
        hidden = [p for p in listing(d) if os.path.basename(p).startswith(".")]
        if hidden:
            return "fails", observed, "left %d hidden file(s)" % len(hidden)
        if c.after:
            ok, note = c.after(d, run)
            if not ok:
                return "fails", observed, note
        return "holds", observed, note

    # a refusal
    if c.expect == "image":
        return "fails", observed, "refused a scene it should render"
    lines = [x for x in r["stderr"].splitlines() if x.strip() and not PROGRESS_LINE.match(x)]
    if len(lines) != 1:
        return "fails", observed, "%d lines on stderr" % len(lines)
    if not lines[0].startswith("lenslab: error:"):
        return "fails", observed, "not lenslab's error line"
    if UNHELPFUL.search(lines[0]):
        return "fails", observed, "a library's message, not the input's"
    fragments = c.fragment if isinstance(c.fragment, tuple) else (c.fragment,) if c.fragment else ()
    if fragments and not any(f.replace("{D}", d) in lines[0] for f in fragments):
        return "fails", observed, "does not name %s" % " or ".join(fragments)
    if c.partial:
        for p in sorted(set(listing(d)) - set(before)):
            full = os.path.join(d, p)
            if os.path.basename(p).startswith("."):
                return "fails", observed, "left a hidden file"
            if os.path.isdir(full) and not os.listdir(full):
                return "fails", observed, "left an empty folder"
            if re.search(r"\.(png|exr)$", p) and not image_ok(full, False)[0]:
                return "fails", observed, "left a broken frame"
    elif c.watched is not None or c.after is None:
        after = listing(watched)
        if before != after:
            new = sorted(set(after) - set(before))
            gone = sorted(set(before) - set(after))
            what = ("left " + ", ".join(new[:3])) if new else ("removed " + ", ".join(gone[:3]))
            return "fails", observed, clean(what)
    if c.after:
        ok, note = c.after(d, run)
        if not ok:
            return "fails", observed, note
    return "holds", observed, "refused in one line, nothing left"


def out_args(argv):
    outs = []
    for i, a in enumerate(argv[:-1]):
        if a in ("-o", "--out", "--stats", "--manifest"):
            outs.append(argv[i + 1])
    return outs


def short_command(c):
    if c.short:
        return c.short
    text = " ".join(a if a else "''" for a in c.argv)
    text = text.replace(" --width 30 -q", "").replace(" -q", "").replace("{D}/", "D/").replace(ROWS + "/", "")
    return text


def cell(text):
    return text.replace("|", "\\|").replace("\n", " ")


EXPECT_TEXT = {"refuse": "refused in one line", "either": "an image, or refused in one line",
               "image": "an image of the object", "signal": "ends by the signal; nothing left",
               "sigkill": "no partial output; a rerun completes"}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("lenslab", nargs="?", default=os.path.join(REPO, "build", "lenslab"))
    ap.add_argument("--quick", action="store_true", help="about a fifth of the cases, every category (about 20 s)")
    ap.add_argument("--markdown", help="write the table and the summary to this file")
    ap.add_argument("--doc", help="replace the table between the robustness-table markers of this page")
    ap.add_argument("--only", help="comma-separated case ids")
    ap.add_argument("--keep", action="store_true", help="keep the temporary folder (its path is printed)")
    args = ap.parse_args()
    lenslab = os.path.abspath(args.lenslab)
    if not os.access(lenslab, os.X_OK):
        sys.exit("robustness-probe: %s is not an executable: build lenslab first (cmake --build build)" % lenslab)

    def stop(signum, _):
        raise SystemExit(128 + signum)  # unwinds: the running case's lenslab is killed, the folder removed
    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)
    signal.signal(signal.SIGHUP, stop)

    define_cases()
    order = ["faults", "signals", "numeric", "malformed", "scale", "radiance", "inputs"]
    cases = sorted(CASES, key=lambda c: (order.index(c.category), c.id))
    if args.quick:
        cases = [c for c in cases if c.quick]
    if args.only:
        wanted = set(args.only.split(","))
        cases = [c for c in cases if c.id in wanted]

    root = tempfile.mkdtemp(prefix="lenslab-probe-")
    os.chmod(root, 0o755)
    env = Environment(root)
    rows = []
    start = time.monotonic()
    try:
        for c in cases:
            verdict, observed, reason = run_case(c, lenslab, env, root)
            rows.append((c, verdict, observed or "", reason or ""))
            print("%s %-7s %s: %s" % (c.id, verdict, observed or "", reason or ""), file=sys.stderr, flush=True)
    finally:
        if args.keep:
            print("robustness-probe: kept %s" % root, file=sys.stderr)
        else:
            subprocess.run(["chmod", "-R", "u+w", root])
            shutil.rmtree(root, ignore_errors=True)

    table = ["| case | category | command (D: the case's folder) | expected | observed | verdict |",
             "|---|---|---|---|---|---|"]
    for c, verdict, observed, reason in rows:
        shown = verdict if verdict != "fails" else "**fails**: " + reason
        if verdict == "skipped":
            shown = "skipped: " + reason
        table.append("| %s | %s | `%s` | %s | %s | %s |" % (c.id, c.category, cell(short_command(c)), EXPECT_TEXT[c.expect],
                                                           cell(observed), cell(shown)))
    counts = {v: sum(1 for r in rows if r[1] == v) for v in ("holds", "fails", "skipped")}
    summary = "%d cases: %d hold, %d fail, %d skipped." % (len(rows), counts["holds"], counts["fails"], counts["skipped"])
    text = "\n".join(table) + "\n\n" + summary + "\n"
    print(text)
    print("robustness-probe: %.0f s" % (time.monotonic() - start), file=sys.stderr)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text)
    if args.doc:
        doc = open(args.doc).read()
        begin, end = "<!-- robustness-table:begin -->", "<!-- robustness-table:end -->"
        a, b = doc.index(begin), doc.index(end)
        with open(args.doc, "w") as f:
            f.write(doc[:a + len(begin)] + "\n" + text + doc[b:])
    return 0


if __name__ == "__main__":
    sys.exit(main())
