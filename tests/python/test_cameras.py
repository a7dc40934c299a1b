"""Cameras in every form the command line reads, their projection against a NumPy implementation of
OpenCV's, and their refusals: ValueError with the command line's own line."""

import math
import threading
import unittest

from support import ASSETS, lenslab, look_at_pose, np, opencv_project, run_cli, scratch


class OpenCvCameras(unittest.TestCase):
    K = np.array([[610.0, 0.0, 318.2], [0.0, 605.5, 241.7], [0.0, 0.0, 1.0]])
    dist = np.array([-0.21, 0.08, 0.0012, -0.0009, -0.015])

    def setUp(self):
        self.R, self.t = look_at_pose((1.0, 1.5, 4.0), (0.2, 0.3, -1.0))
        self.camera = lenslab.Camera.from_opencv(self.K, self.dist, self.R, self.t, width=640, height=480)

    def test_points_land_where_opencvs_projection_puts_them(self):
        rng = np.random.default_rng(7)
        # Points across the image (normalised radius up to about the corners), 1 to 30 m away.
        cam = np.column_stack([rng.uniform(-0.5, 0.5, 500), rng.uniform(-0.38, 0.38, 500), np.ones(500)])
        cam *= rng.uniform(1.0, 30.0, (500, 1))
        world = (cam - self.t) @ self.R  # R^T (X_cam - t)
        expected = opencv_project(world, self.K, self.dist, self.R, self.t)
        got = self.camera.project(world)
        self.assertLess(np.abs(got - expected).max(), 1e-3)

    def test_a_point_behind_the_camera_has_no_pixel(self):
        behind = (np.array([[0.0, 0.0, -2.0]]) - self.t) @ self.R
        self.assertTrue(np.isnan(self.camera.project(behind)).all())

    def test_opencv_gives_back_what_it_was_given(self):
        K, dist, R, t = self.camera.opencv()
        np.testing.assert_allclose(K, self.K, rtol=1e-12)
        np.testing.assert_allclose(dist[:5], self.dist, rtol=1e-12)
        np.testing.assert_allclose(R, self.R, atol=1e-12)
        np.testing.assert_allclose(t, self.t, atol=1e-12)
        self.assertEqual(self.camera.calibrated_size, (640, 480))

    def test_to_json_reads_back_as_the_same_camera(self):
        again = lenslab.Camera.from_json(self.camera.to_json())
        points = np.array([[0.1, 0.2, -1.0], [1.0, 0.5, -3.0]])
        np.testing.assert_allclose(again.project(points), self.camera.project(points), atol=1e-9)


class TheOtherForms(unittest.TestCase):
    def test_physical_equals_its_camera_file(self):
        from_file = lenslab.Camera.from_file(ASSETS / "rows" / "camera-dof.json")
        built = lenslab.Camera.physical(eye=(0, 1, 3), target=(0, 0.55, -2), focal_length_mm=35, f_number=1.4,
                                        focus_distance_m=2.0, near=0.05)
        self.assertAlmostEqual(built.aperture_radius, from_file.aperture_radius, places=12)
        self.assertAlmostEqual(built.focus_distance, 2.0, places=9)
        points = np.array([[0.0, 0.5, 0.0], [1.0, 0.2, -4.0]])
        np.testing.assert_allclose(built.project(points), from_file.project(points), atol=1e-9)

    def test_lecture_form_is_the_lectures_projection(self):
        # PRP 2 in front of a 2 x 2 window: a point (x, y, -z) lands at window point (2x/z, 2y/z).
        camera = lenslab.Camera.lecture(vrp=(0, 0, 0), vpn=(0, 0, 1), prp=(0, 0, 2), window=(-1, -1, 1, 1))
        pixel = camera.project([[0.5, 0.25, -2.0]], width=200, height=200)[0]
        u, v = 2 * 0.5 / 4.0, 2 * 0.25 / 4.0  # seen from the PRP at z = 2, the point is 4 away
        np.testing.assert_allclose(pixel, [(u + 1) / 2 * 200 - 0.5, (1 - v) / 2 * 200 - 0.5], atol=1e-9)

    def test_glTF_cameras_and_automatic_framing(self):
        scene = lenslab.load()
        self.assertEqual(len(scene.cameras), 1)
        self.assertIn("glTF camera 0", scene.camera(0).source)
        self.assertTrue(math.isfinite(scene.camera(0).focus_distance))

    def test_colmap_image(self):
        with scratch() as d:
            status, err = run_cli("capture", "--path", ASSETS / "rows" / "rack-focus.json", "--frames", "0:1",
                                  "--width", 64, "--colmap-out", d, "--out", f"{d}/frame_%04d.png", "--quiet")
            self.assertEqual(status, 0, err)
            camera = lenslab.Camera.from_colmap(d, "frame_0001.png")
            written = lenslab.Camera.from_file(f"{d}/frame_0001.camera.json")
        self.assertEqual(camera.calibrated_size[0], 64)
        points = np.array([[0.0, 0.5, 0.0], [1.0, 0.2, -4.0]])
        # COLMAP's text model holds its numbers to 17 significant digits: the same pixels.
        np.testing.assert_allclose(camera.project(points), written.project(points), atol=1e-6)


class Refusals(unittest.TestCase):
    def assertSameAsCli(self, call, *cli_args):
        """`call` raises ValueError whose text is the command line's error line without 'lenslab: error: '."""
        with self.assertRaises(ValueError) as raised:
            call()
        status, err = run_cli(*cli_args)
        self.assertEqual(status, 1)
        self.assertIn("lenslab: error: " + str(raised.exception), err)

    def test_a_missing_camera_file(self):
        self.assertSameAsCli(lambda: lenslab.Camera.from_file("/nonexistent/cam.json"),
                             "render", "--camera", "/nonexistent/cam.json", "--out", "/tmp/never.png")

    def test_a_missing_scene(self):
        self.assertSameAsCli(lambda: lenslab.load("/nonexistent/scene.gltf"),
                             "render", "/nonexistent/scene.gltf", "--out", "/tmp/never.png")

    def test_focus_inside_the_focal_length(self):
        with self.assertRaisesRegex(ValueError, "lenslab.Camera.physical.*focus"):
            lenslab.Camera.physical(eye=(0, 0, 1), target=(0, 0, 0), focal_length_mm=50, f_number=2,
                                    focus_distance_m=0.01)

    def test_an_unknown_aov_names_the_valid_ones(self):
        with self.assertRaisesRegex(ValueError, "aovs.*speed.*depth"):
            lenslab.Renderer(width=32).render(lenslab.load(), aovs=("speed",))

    def test_a_bad_shape(self):
        with self.assertRaisesRegex(ValueError, "K has shape"):
            lenslab.Camera.from_opencv(np.eye(2), width=10, height=10)


class Threads(unittest.TestCase):
    def test_another_thread_is_refused_by_name(self):
        renderer = lenslab.Renderer(width=32)
        caught = []

        def use():
            try:
                renderer.render(lenslab.load())
            except RuntimeError as e:
                caught.append(str(e))

        worker = threading.Thread(target=use)
        worker.start()
        worker.join()
        self.assertEqual(len(caught), 1)
        self.assertIn("one Renderer per thread", caught[0])

    def test_a_renderer_per_thread_gives_the_same_frames(self):
        scene = lenslab.load()
        alone = lenslab.Renderer(width=48).render(scene).rgba
        frames = [None, None]

        def draw(i):
            frames[i] = lenslab.Renderer(width=48).render(scene).rgba

        workers = [threading.Thread(target=draw, args=(i,)) for i in range(2)]
        for w in workers:
            w.start()
        for w in workers:
            w.join()
        for f in frames:
            self.assertTrue(np.array_equal(f, alone))


if __name__ == "__main__":
    unittest.main()
