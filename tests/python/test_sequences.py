"""lenslab.Sequence and lenslab.write against `lenslab capture`: the same files, byte for byte (the
manifest line but for its "seconds"), from a camera path, a list of Camera objects and a COLMAP
model's images."""

import filecmp
import json
import os
import unittest

from support import ASSETS, lenslab, np, run_cli, scratch

PATH = ASSETS / "rows" / "rack-focus.json"


def files_under(folder):
    return sorted(os.path.relpath(os.path.join(root, f), folder) for root, _, names in os.walk(folder) for f in names)


def manifest_lines(path):
    lines = [json.loads(line) for line in open(path)]
    for line in lines:
        line.pop("seconds")  # how long the frame took
    return lines


class SequenceWritesCaptureFiles(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = lenslab.load()
        cls.renderer = lenslab.Renderer()

    def capture_both(self, d, cli_args, **python_args):
        status, err = run_cli("capture", *cli_args, "--width", 81, "--out", f"{d}/cli/f_%04d.png", "--aov",
                              "depth,normal,instance", "--aov-format", "npy", "--colmap-out", f"{d}/cli/model",
                              "--quiet")
        self.assertEqual(status, 0, err)
        # The COLMAP model's pinholes leave the depth of field out: said as a Python warning.
        with self.assertWarnsRegex(UserWarning, "--colmap-out: the depth of field"):
            sequence = lenslab.Sequence(self.scene, width=81, out=f"{d}/py/f_%04d.png",
                                        aovs=("depth", "normal", "instance"), aov_format="npy",
                                        colmap_out=f"{d}/py/model", **python_args)
        lines = [lenslab.write(frame) for frame in self.renderer.frames(sequence)]
        return sequence, lines

    def assert_same_files(self, d):
        cli, py = files_under(f"{d}/cli"), files_under(f"{d}/py")
        self.assertEqual(cli, py)
        self.assertIn("model/images.txt", cli)
        for name in cli:
            if name != "manifest.jsonl":
                self.assertTrue(filecmp.cmp(f"{d}/cli/{name}", f"{d}/py/{name}", shallow=False), name)
        self.assertEqual(manifest_lines(f"{d}/cli/manifest.jsonl"), manifest_lines(f"{d}/py/manifest.jsonl"))

    def test_a_camera_path_gives_captures_bytes(self):
        with scratch() as d:
            sequence, lines = self.capture_both(d, ["--path", PATH, "--frames", "0:4:2"], path=PATH, frames="0:4:2")
            self.assert_same_files(d)
            self.assertEqual(sequence.frame_numbers, [0, 2, 4])
            self.assertEqual([line["frame"] for line in lines], [0, 2, 4])

    def test_frames_carry_their_number_time_seed_and_camera(self):
        with scratch() as d:
            sequence = lenslab.Sequence(self.scene, path=PATH, frames="3", width=64, out=f"{d}/f_%02d.exr",
                                        aovs=("depth",))
            frame = next(sequence.frames(self.renderer))
            self.assertEqual(frame.index, 3)
            self.assertAlmostEqual(frame.time, sequence.time(3))
            self.assertFalse(frame.rgba.flags.writeable)  # a view of what write() writes
            line = lenslab.write(frame)
            self.assertEqual(line["seed"], frame.seed)
            written = lenslab.read_image(sequence.image_file(3))
            self.assertTrue(np.array_equal(written, frame.rgba))
            # The frame's camera file renders the frame again (render --camera FILE --seed SEED).
            again = self.renderer.render(self.scene, lenslab.Camera.from_file(f"{d}/f_03.camera.json"),
                                         seed=frame.seed, width=64)
            self.assertTrue(np.array_equal(again.rgba, frame.rgba))

    def test_a_list_of_cameras_and_a_colmap_model_give_captures_bytes(self):
        with scratch() as d:
            # Cameras from the path's frames, written as a list: one capture replays it.
            path_sequence = lenslab.Sequence(self.scene, path=PATH, frames="0:2", width=81, out=f"{d}/src/f_%d.png")
            lines = [json.dumps(json.loads(frame.camera.to_json())) for frame in self.renderer.frames(path_sequence)]
            with open(f"{d}/cameras.jsonl", "w") as out:
                out.write("".join(line + "\n" for line in lines))
            cameras = [lenslab.Camera.from_json(line) for line in lines]
            self.capture_both(d, ["--cameras", f"{d}/cameras.jsonl"], cameras=cameras)
            self.assert_same_files(d)
            # The COLMAP model just written: a frame for each of its images.
            sequence = lenslab.Sequence(self.scene, colmap=f"{d}/py/model", out=f"{d}/colmap/f_%d.png")
            self.assertEqual(len(sequence), 3)
            frames = list(sequence.frames(self.renderer))
            self.assertEqual([f.size for f in frames], [(81, 54)] * 3)

    def test_bad_input_is_refused_with_the_clis_line(self):
        with scratch() as d:
            with self.assertRaisesRegex(ValueError, "give one of path, cameras and colmap"):
                lenslab.Sequence(self.scene, path=PATH, cameras=[lenslab.Camera.from_file(PATH.parent / "camera.json")])
            with self.assertRaisesRegex(ValueError, "--out"):
                lenslab.Sequence(self.scene, path=PATH, out=f"{d}/no_frame_number.png")
            with self.assertRaisesRegex(ValueError, "fps: 0 is out of range"):
                lenslab.Sequence(self.scene, cameras=[lenslab.Camera.from_file(PATH.parent / "camera.json")], fps=0,
                                 out=f"{d}/f_%d.png")
            with self.assertRaisesRegex(ValueError, "cameras: an empty list"):
                lenslab.Sequence(self.scene, cameras=[], out=f"{d}/f_%d.png")
            with self.assertRaisesRegex(ValueError, "give the path of a frame"):
                lenslab.write(self.renderer.render(self.scene, width=32))
            self.assertEqual(os.listdir(d), [])  # nothing written


class WriteGivesRenderFiles(unittest.TestCase):
    """lenslab.write of a single frame: `lenslab render --out PATH --aov ... --aov-format F`'s files."""

    def test_the_image_and_aov_files_are_the_clis_bytes(self):
        scene = lenslab.load()
        renderer = lenslab.Renderer(width=96)
        camera = lenslab.Camera.from_file(ASSETS / "rows" / "camera.json")
        for aov_format, normals in (("npy", "opencv"), ("png16", "gl")):
            with self.subTest(aov_format=aov_format), scratch() as d:
                os.mkdir(f"{d}/cli")
                os.mkdir(f"{d}/py")
                status, err = run_cli("render", "--camera", ASSETS / "rows" / "camera.json", "--width", 96, "--aov",
                                      "depth,normal,albedo,instance", "--aov-format", aov_format,
                                      "--normal-convention", normals, "--out", f"{d}/cli/f.png", "--quiet")
                self.assertEqual(status, 0, err)
                frame = renderer.render(scene, camera, aovs=("depth", "normal", "albedo", "instance"),
                                        normals=normals)
                self.assertIsNone(lenslab.write(frame, f"{d}/py/f.png", aov_format=aov_format))
                cli, py = files_under(f"{d}/cli"), files_under(f"{d}/py")
                self.assertEqual(cli, py)
                self.assertIn("f.instances.json", cli)
                for name in cli:
                    self.assertTrue(filecmp.cmp(f"{d}/cli/{name}", f"{d}/py/{name}", shallow=False), name)

    def test_a_bad_aov_format_writes_nothing(self):
        scene = lenslab.load()
        frame = lenslab.Renderer(width=32).render(scene, aovs=("depth",))
        with scratch() as d:
            with self.assertRaisesRegex(ValueError, "aov_format"):
                lenslab.write(frame, f"{d}/f.png", aov_format="tiff")
            self.assertEqual(os.listdir(d), [])


if __name__ == "__main__":
    unittest.main()
