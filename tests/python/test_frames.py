"""The package's frames against the command line's files, bit for bit, and its AOVs against closed
forms computed here with NumPy."""

import unittest

from support import ASSETS, lenslab, look_at_pose, np, opencv_undistort, run_cli, scratch

CAMERA_DOF = ASSETS / "rows" / "camera-dof.json"


class FramesEqualTheCommandLine(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = lenslab.load()
        cls.renderer = lenslab.Renderer(width=160)

    def test_render_of_rows_is_the_cli_exr_bit_for_bit(self):
        frame = self.renderer.render(self.scene, lenslab.Camera.from_file(CAMERA_DOF))
        self.assertEqual(frame.rgba.dtype, np.float32)
        self.assertGreater(frame.samples, 1)  # f/1.4: the plan accumulates views
        with scratch() as d:
            status, err = run_cli("render", "--camera", CAMERA_DOF, "--width", 160, "--out", f"{d}/cli.exr", "--quiet")
            self.assertEqual(status, 0, err)
            cli = lenslab.read_image(f"{d}/cli.exr")
        self.assertEqual(cli.shape, frame.rgba.shape)
        self.assertTrue(np.array_equal(cli, frame.rgba), f"largest difference {np.abs(cli - frame.rgba).max()}")

    def test_raycast_is_the_cli_exr_bit_for_bit(self):
        frame = self.renderer.raycast(self.scene, lenslab.Camera.from_file(CAMERA_DOF), spp=4, width=96)
        with scratch() as d:
            status, err = run_cli("raycast", "--camera", CAMERA_DOF, "--width", 96, "--spp", 4, "--out",
                                  f"{d}/cli.exr", "--quiet")
            self.assertEqual(status, 0, err)
            self.assertTrue(np.array_equal(lenslab.read_image(f"{d}/cli.exr"), frame.rgba))

    def test_write_image_gives_the_cli_files(self):
        # The PNG byte for byte; the EXR holds its capture date (capDate), so its pixels.
        frame = self.renderer.render(self.scene)
        with scratch() as d:
            for name in ("frame.png", "frame.exr"):
                status, err = run_cli("render", "--width", 160, "--out", f"{d}/cli-{name}", "--quiet")
                self.assertEqual(status, 0, err)
                lenslab.write_image(f"{d}/py-{name}", frame)
            with open(f"{d}/cli-frame.png", "rb") as a, open(f"{d}/py-frame.png", "rb") as b:
                self.assertEqual(a.read(), b.read())
            self.assertTrue(np.array_equal(lenslab.read_image(f"{d}/cli-frame.exr"),
                                           lenslab.read_image(f"{d}/py-frame.exr")))

    def test_egl_beside_osmesa_on_one_thread(self):
        # Two contexts on one thread: each call makes its own current (the frames would mix
        # otherwise). EGL here is Mesa's surfaceless platform where no GPU is, a GPU's where one is.
        egl = lenslab.Renderer(width=96, backend="egl")
        osmesa = lenslab.Renderer(width=96)
        camera = lenslab.Camera.from_file(CAMERA_DOF)
        first = egl.render(self.scene, camera).rgba
        between = osmesa.render(self.scene, camera).rgba
        again = egl.render(self.scene, camera).rgba
        self.assertTrue(np.array_equal(first, again))
        with scratch() as d:
            for backend, frame in (("egl", first), ("osmesa", between)):
                status, err = run_cli("render", "--backend", backend, "--camera", CAMERA_DOF, "--width", 96, "--out",
                                      f"{d}/{backend}.exr", "--quiet")
                self.assertEqual(status, 0, err)
                cli = lenslab.read_image(f"{d}/{backend}.exr")
                self.assertTrue(np.array_equal(cli, frame), f"{backend}: up to {np.abs(cli - frame).max()}")

    def test_an_unknown_backend(self):
        with self.assertRaisesRegex(ValueError, "backend \"vulkan\": give \"osmesa\""):
            lenslab.Renderer(backend="vulkan")

    def test_the_bundled_scene_renders_through_its_own_camera_by_default(self):
        frame = self.renderer.render(self.scene)
        self.assertEqual(frame.size, (160, 107))
        self.assertEqual(frame.camera.source, str(ASSETS / "rows" / "camera.json"))
        self.assertTrue(np.isfinite(frame.rgba).all())
        self.assertGreater(frame.rgb.mean(), 0.01)


class AovsAgainstClosedForms(unittest.TestCase):
    """rows' floor is the plane y = 0 (node 0); a calibrated camera with OpenCV's distortion looks
    at it. Each pixel centre's ray, undistorted and intersected with y = 0 here in NumPy, gives the
    depth and normal the AOVs must hold."""

    def test_depth_normal_and_instance_on_the_floor(self):
        K = np.array([[150.0, 0.0, 79.5], [0.0, 150.0, 59.5], [0.0, 0.0, 1.0]])
        dist = [-0.12, 0.03, 0.001, -0.0015, 0.0]
        R, t = look_at_pose((0.3, 1.2, 3.0), (0.0, 0.0, 0.0))
        camera = lenslab.Camera.from_opencv(K, dist, R, t, width=160, height=120)
        frame = lenslab.Renderer().raycast(lenslab.load(), camera, spp=1, aovs=("depth", "normal", "instance"),
                                           normals="opencv")
        self.assertEqual(frame.size, (160, 120))  # the calibrated size by default
        self.assertEqual(frame.instance.dtype, np.int32)

        floor = frame.instance == 0
        self.assertGreater(floor.sum(), 2000)
        ys, xs = np.nonzero(floor)
        x, y = opencv_undistort(np.stack([xs, ys], axis=1).astype(float), K, dist)
        rays = np.stack([x, y, np.ones_like(x)], axis=1) @ R  # camera rays into the world (z = 1)
        centre = -R.T @ t
        along = -centre[1] / rays[:, 1]  # to y = 0, in units of camera z
        np.testing.assert_allclose(frame.depth[ys, xs], along, rtol=1e-4)
        np.testing.assert_allclose(frame.normal[ys, xs], np.tile(R @ [0.0, 1.0, 0.0], (len(xs), 1)), atol=1e-4)

        nothing = frame.instance == -1
        self.assertTrue(np.isinf(frame.depth[nothing]).all())
        self.assertTrue((frame.normal[nothing] == 0).all())
        hit = ~nothing
        self.assertTrue(set(np.unique(frame.instance[hit])) <= {i for i, _ in lenslab.load().instances})


if __name__ == "__main__":
    unittest.main()
