"""examples/python/calibrated_sequence.py runs and writes what it says: PNG, depth and instance
.npy, and a camera file that reads back as the camera it rendered."""

import subprocess
import sys
import unittest
from pathlib import Path

from support import lenslab, np, scratch

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "python" / "calibrated_sequence.py"


class CalibratedSequenceExample(unittest.TestCase):
    def test_two_frames(self):
        with scratch() as d:
            done = subprocess.run([sys.executable, str(EXAMPLE), "--out", d, "--frames", "2"], capture_output=True,
                                  text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            for i in range(2):
                stem = Path(d) / f"frame_{i:04d}"
                image = lenslab.read_image(f"{stem}.png")
                depth = np.load(f"{stem}.depth.npy")
                instance = np.load(f"{stem}.instance.npy")
                self.assertEqual(image.shape, (480, 640, 4))
                self.assertEqual(depth.shape, (480, 640))
                self.assertEqual(instance.dtype, np.int32)
                self.assertTrue((np.isinf(depth) == (instance == -1)).all())
                camera = lenslab.Camera.from_file(f"{stem}.camera.json")
                self.assertEqual(camera.calibrated_size, (640, 480))


if __name__ == "__main__":
    unittest.main()
