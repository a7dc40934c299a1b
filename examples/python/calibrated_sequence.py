#!/usr/bin/env python3
"""A calibrated sequence: an OpenCV camera (K and distortion, as a calibration gives them) on a
circle around the bundled scene, looking at its middle. Each frame: the image (PNG), its depth
(metres, float32) and instance mask (glTF node index, -1 for nothing; int32) as .npy, and the
camera as a camera file (`lenslab render --camera` reads it back).

usage: python3 calibrated_sequence.py [--out DIR] [--frames N] [--scene FILE.gltf]
(PYTHONPATH=build/python from a build tree, or after `pip install .`; docs/python.md)
"""
import argparse
import math
from pathlib import Path

import numpy as np

import lenslab


def look_at(eye, target, up=(0.0, 1.0, 0.0)):
    """OpenCV's R, t for a camera at `eye` looking at `target` (x right, y down, z forward)."""
    eye, target, up = (np.asarray(v, dtype=float) for v in (eye, target, up))
    z = (target - eye) / np.linalg.norm(target - eye)
    x = np.cross(z, -up)
    x /= np.linalg.norm(x)
    R = np.stack([x, np.cross(z, x), z])
    return R, -R @ eye


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="sequence", type=Path)
    parser.add_argument("--frames", default=8, type=int)
    parser.add_argument("--scene", default=None)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)

    # A 640 x 480 calibration with barrel distortion (OpenCV's k1 k2 p1 p2 k3).
    K = np.array([[520.0, 0.0, 319.5], [0.0, 520.0, 239.5], [0.0, 0.0, 1.0]])
    dist = np.array([-0.18, 0.05, 0.0005, -0.0003, 0.0])

    scene = lenslab.load(args.scene)
    (lo, hi) = (np.array(b) for b in scene.bounds)
    middle = (lo + hi) / 2
    radius = 0.6 * float(np.linalg.norm(hi - lo))
    renderer = lenslab.Renderer()
    for i in range(args.frames):
        angle = 2 * math.pi * i / args.frames
        eye = middle + np.array([radius * math.sin(angle), 0.4 * radius, radius * math.cos(angle)])
        R, t = look_at(eye, middle)
        camera = lenslab.Camera.from_opencv(K, dist, R, t, width=640, height=480)
        frame = renderer.render(scene, camera, aovs=("depth", "instance"))
        stem = args.out / f"frame_{i:04d}"
        lenslab.write_image(f"{stem}.png", frame)
        np.save(f"{stem}.depth.npy", frame.depth)
        np.save(f"{stem}.instance.npy", frame.instance)
        Path(f"{stem}.camera.json").write_text(frame.camera.to_json())
        seen = np.isfinite(frame.depth)
        print(f"{stem}.png: {seen.mean() * 100:.0f} % of pixels see a surface, "
              f"depth {frame.depth[seen].min():.2f} to {frame.depth[seen].max():.2f} m, "
              f"{len(np.unique(frame.instance[seen]))} instances")


if __name__ == "__main__":
    main()
