#!/usr/bin/env python3
"""Seconds for a sequence: one `lenslab capture` process for the whole sequence (the frames and
their files written; then read back, as a Python user of the command line would) against
lenslab.Sequence on a lenslab.Renderer kept open, once writing the same files with lenslab.write
and once keeping the frames as arrays only (docs/python.md). Interleaved, A B C A B C ..., each
round the same frames; prints the medians and the medians of the per-round ratios.

usage: PYTHONPATH=build/python python3 tools/bench-python-sequence.py [--cli build/lenslab]
       [--rounds 7] [--frames 0:11] [--width 321] [--path assets/rows/rack-focus.json]
"""
import argparse
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

import lenslab


def main():
    root = Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default=str(root / "build" / "lenslab"))
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--frames", default="0:11")
    parser.add_argument("--width", type=int, default=321)
    parser.add_argument("--path", default=str(root / "assets" / "rows" / "rack-focus.json"))
    args = parser.parse_args()

    scene = lenslab.load()
    renderer = lenslab.Renderer()
    common = dict(path=args.path, frames=args.frames, width=args.width, aovs=("depth",), aov_format="npy")
    capture, written, arrays = [], [], []
    with tempfile.TemporaryDirectory() as d:
        for r in range(args.rounds):
            out = f"{d}/cli{r}/f_%04d.png"
            t = time.perf_counter()
            subprocess.run([args.cli, "capture", "--path", args.path, "--frames", args.frames, "--width",
                            str(args.width), "--aov", "depth", "--aov-format", "npy", "--out", out, "--quiet"],
                           check=True)
            images = sorted(Path(f"{d}/cli{r}").glob("f_*.png"))
            for image in images:  # read back: the image and its depth
                lenslab.read_image(image)
                np.load(str(image)[: -len(".png")] + ".depth.npy")
            capture.append(time.perf_counter() - t)

            t = time.perf_counter()
            sequence = lenslab.Sequence(scene, out=f"{d}/py{r}/f_%04d.png", **common)
            for frame in renderer.frames(sequence):
                lenslab.write(frame)
            written.append(time.perf_counter() - t)

            t = time.perf_counter()
            sequence = lenslab.Sequence(scene, out=f"{d}/arrays{r}/f_%04d.png", **common)
            kept = [(frame.rgba, frame.depth) for frame in renderer.frames(sequence)]
            arrays.append(time.perf_counter() - t)
        count = len(kept)
    print(f"{args.rounds} rounds of {count} frames of {args.width} px, {Path(args.path).name}, depth AOV, "
          f"{renderer.gl_renderer}")
    for name, seconds in (("lenslab capture + read back", capture), ("Sequence + lenslab.write", written),
                          ("Sequence, arrays only", arrays)):
        print(f"  {name:28s} median {statistics.median(seconds):.3f} s")
    for name, seconds in (("Sequence + write", written), ("arrays only", arrays)):
        ratios = [c / s for c, s in zip(capture, seconds)]
        print(f"  capture / {name}: median of {len(ratios)} interleaved ratios {statistics.median(ratios):.2f}x "
              f"(range {min(ratios):.2f}-{max(ratios):.2f})")


if __name__ == "__main__":
    main()
