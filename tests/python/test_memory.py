"""A loop of frames keeps memory flat: the arrays own their buffers and free them, the renderer
reuses its context, programs and uploaded scene."""

import unittest

from support import lenslab


def resident_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


class FrameLoop(unittest.TestCase):
    def test_a_hundred_frames_keep_memory_flat(self):
        scene = lenslab.load()
        renderer = lenslab.Renderer(width=96)
        camera = scene.camera()
        for _ in range(10):  # warm: programs compiled, scene uploaded, allocator settled
            renderer.render(scene, camera, aovs=("depth", "instance"))
        before = resident_bytes()
        for _ in range(100):
            frame = renderer.render(scene, camera, aovs=("depth", "instance"))
        grown = resident_bytes() - before
        # One frame's arrays are about 96 x 64 x 24 bytes; a leak of one frame each would be ~15 MB.
        self.assertLess(grown, 8 << 20, f"resident memory grew by {grown / 2**20:.1f} MiB over 100 frames")
        self.assertEqual(frame.depth.shape, (64, 96))


if __name__ == "__main__":
    unittest.main()
