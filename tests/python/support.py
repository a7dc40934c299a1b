"""What the Python tests share: the package (PYTHONPATH=build/python, set by ctest), the command
line beside it (LENSLAB_EXE), the bundled assets, and a NumPy implementation of OpenCV's projection
(cv::projectPoints' model: radial k1, k2, k3 and tangential p1, p2), written from OpenCV's
documentation, to check lenslab against an answer that is not lenslab's."""

import os
import subprocess
import tempfile
from pathlib import Path

import numpy as np  # run.py checks that it is there

import lenslab

EXE = os.environ.get("LENSLAB_EXE", "")
ASSETS = Path(lenslab.asset_directory())


def run_cli(*args):
    """The command line's exit status and stderr."""
    done = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)
    return done.returncode, done.stderr


def scratch():
    return tempfile.TemporaryDirectory(prefix="lenslab-python-")


def opencv_project(points, K, dist, R, t):
    """Pixels (OpenCV's convention) of world points through K, distCoeffs (k1 k2 p1 p2 k3) and R, t."""
    k1, k2, p1, p2, k3 = (list(dist) + [0.0] * 5)[:5]
    cam = points @ np.asarray(R).T + np.asarray(t)
    x, y = cam[:, 0] / cam[:, 2], cam[:, 1] / cam[:, 2]
    r2 = x * x + y * y
    radial = 1 + k1 * r2 + k2 * r2 * r2 + k3 * r2 * r2 * r2
    xd = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x)
    yd = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y
    return np.stack([K[0][0] * xd + K[0][2], K[1][1] * yd + K[1][2]], axis=1)


def opencv_undistort(pixels, K, dist, iterations=50):
    """Normalised (x, y) of OpenCV pixels: the distortion inverted by fixed-point iteration (as
    cv::undistortPoints does), run until it stops moving."""
    k1, k2, p1, p2, k3 = (list(dist) + [0.0] * 5)[:5]
    xd = (pixels[:, 0] - K[0][2]) / K[0][0]
    yd = (pixels[:, 1] - K[1][2]) / K[1][1]
    x, y = xd.copy(), yd.copy()
    for _ in range(iterations):
        r2 = x * x + y * y
        radial = 1 + k1 * r2 + k2 * r2 * r2 + k3 * r2 * r2 * r2
        dx = 2 * p1 * x * y + p2 * (r2 + 2 * x * x)
        dy = p1 * (r2 + 2 * y * y) + 2 * p2 * x * y
        x, y = (xd - dx) / radial, (yd - dy) / radial
    return x, y


def look_at_pose(eye, target, up=(0.0, 1.0, 0.0)):
    """OpenCV's R, t of a camera at `eye` looking at `target` (x right, y down, z forward)."""
    eye, target, up = (np.asarray(v, dtype=float) for v in (eye, target, up))
    z = target - eye
    z /= np.linalg.norm(z)
    x = np.cross(z, -up)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    R = np.stack([x, y, z])
    return R, -R @ eye
