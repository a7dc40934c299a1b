#!/usr/bin/env python3
"""Frames per second of a sequence: one `lenslab render` process per frame (context, shaders and
scene made again each time, the EXR written and read back) against one lenslab.Renderer kept open
(docs/python.md). Interleaved, A B A B ..., each pair the same camera; prints both rates and the
median of the per-pair ratios, with its spread.

usage: PYTHONPATH=build/python python3 tools/bench-python-frames.py [--cli build/lenslab]
       [--frames 20] [--width 321] [--camera assets/rows/camera-dof.json]
"""
import argparse
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import lenslab


def main():
    root = Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default=str(root / "build" / "lenslab"))
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--width", type=int, default=321)
    parser.add_argument("--camera", default=str(root / "assets" / "rows" / "camera-dof.json"))
    args = parser.parse_args()

    scene = lenslab.load()
    renderer = lenslab.Renderer(width=args.width)
    base = lenslab.Camera.from_file(args.camera)
    renderer.render(scene, base)  # programs compiled and scene uploaded once, as a sequence would
    cli_seconds, python_seconds, ratios = [], [], []
    with tempfile.TemporaryDirectory() as d:
        for i in range(args.frames):
            out = Path(d) / f"frame{i}.exr"
            t = time.perf_counter()
            subprocess.run([args.cli, "render", "--camera", args.camera, "--width", str(args.width), "--seed",
                            str(i + 1), "--out", str(out), "--quiet"], check=True)
            lenslab.read_image(out)  # a Python user of the command line reads the frame back
            cli_seconds.append(time.perf_counter() - t)
            t = time.perf_counter()
            renderer.render(scene, base, seed=i + 1)
            python_seconds.append(time.perf_counter() - t)
            ratios.append(cli_seconds[-1] / python_seconds[-1])
    q = statistics.quantiles(ratios, n=4)
    print(f"{args.frames} frames of {args.width} px, {Path(args.camera).name}, {renderer.gl_renderer}")
    print(f"  lenslab render per frame: {1 / statistics.median(cli_seconds):.2f} frames/s "
          f"(median {statistics.median(cli_seconds) * 1000:.0f} ms)")
    print(f"  lenslab.Renderer:         {1 / statistics.median(python_seconds):.2f} frames/s "
          f"(median {statistics.median(python_seconds) * 1000:.0f} ms)")
    print(f"  speed-up, median of {len(ratios)} interleaved ratios: {statistics.median(ratios):.2f}x "
          f"(quartiles {q[0]:.2f}-{q[2]:.2f})")


if __name__ == "__main__":
    main()
