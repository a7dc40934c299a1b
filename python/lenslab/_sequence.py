"""lenslab.Sequence and lenslab.write: the frames ``lenslab capture`` renders, from Python."""

import json
import warnings as _warnings

from . import _lenslab
from ._frame import Frame


class Sequence:
    """The frames of a sequence as ``lenslab capture`` makes them, each frame's camera from one of:
    ``path`` (a camera path file), ``cameras`` (a list of ``Camera`` objects, or a JSON-lines camera
    list or earlier manifest), ``colmap`` (a COLMAP model's folder: every image, in IMAGE_ID order),
    or else the scene's own camera (``camera``: a camera file; ``camera_node``; else the scene's
    default) over its animation at ``fps``. Frame N's seed is capture's hash of ``seed`` and N, its
    camera is written as capture writes it and read back, so ``lenslab.write`` gives capture's bytes.

    ``out``: the frames' files, a pattern with one %d (``.png`` or ``.exr``); each frame's camera
    file goes beside it and its line into ``manifest`` (default: manifest.jsonl beside the frames).
    ``aovs``, ``aov_format`` ("exr", "npy" or "png16") and ``normals`` as capture's --aov,
    --aov-format and --normal-convention; ``frames``: "A:B" or "A:B:STEP". ``colmap_out``: the
    frames' cameras written at once as a COLMAP model in that folder (``colmap_format`` "text" or
    "binary"). Files are checked (and folders made) here, before any frame is rendered.

    ``renderer.frames(sequence)`` (or ``sequence.frames(renderer)``) renders them one by one."""

    def __init__(self, scene, *, path=None, cameras=None, colmap=None, camera=None, camera_node=None, fps=None,
                 width=None, height=None, frames=None, out="frames/frame_%04d.png", manifest=None, aovs=(),
                 aov_format="exr", normals="gl", aperture_samples=None, pattern=None, seed=1, colmap_out=None,
                 colmap_format="text"):
        cameras_file, camera_list = "", None
        if isinstance(cameras, (list, tuple)):
            camera_list = [c._native for c in cameras]
        elif cameras is not None:
            cameras_file = str(cameras)
        samples = "auto" if aperture_samples is None else str(int(aperture_samples))
        self._native = _lenslab._Sequence(
            scene, "" if path is None else str(path), cameras_file, camera_list, "" if colmap is None else str(colmap),
            "" if camera is None else str(camera), "" if camera_node is None else str(camera_node), fps, width, height,
            "" if frames is None else str(frames), str(out), "" if manifest is None else str(manifest), list(aovs),
            aov_format, normals, samples, pattern or "", seed, "" if colmap_out is None else str(colmap_out),
            colmap_format)
        for note in self._native.take_notes():
            _warnings.warn(note, stacklevel=2)

    def __len__(self):
        return len(self._native.frame_numbers)

    @property
    def frame_numbers(self):
        """The frames to render, in order (``frames=`` and its step)."""
        return list(self._native.frame_numbers)

    @property
    def manifest(self):
        return self._native.manifest

    def time(self, frame):
        """Frame ``frame``'s time in seconds."""
        return self._native.time(frame)

    def image_file(self, frame):
        """Where ``lenslab.write`` puts frame ``frame``'s image."""
        return self._native.image_file(frame)

    def frames(self, renderer):
        """Renders the frames in order on ``renderer``, yielding each ``Frame`` (with ``index``,
        ``time``, ``seed`` and its ``camera``)."""
        for frame in self._native.frame_numbers:
            yield self.render(renderer, frame)

    def render(self, renderer, frame):
        """Frame number ``frame`` on ``renderer``."""
        result = Frame(renderer._native.render_frame(self._native, frame))
        for note in self._native.take_notes():
            _warnings.warn(note, stacklevel=3)
            result.warnings.append(note)
        return result


def write(frame, path=None, *, aov_format="exr"):
    """Writes a frame with the command line's writers, whole or not at all.

    A ``Sequence``'s frame (no ``path``): as ``lenslab capture`` writes it — the image at the
    sequence's ``out`` for its frame number, the AOV files (and instances.json) beside it, its camera
    file, and its line appended to the manifest; returns the line (a dict).

    A frame from ``Renderer.render`` or ``raycast``: as ``lenslab render --out PATH --aov ...
    --aov-format F`` writes it — the image at ``path`` (``.png`` 8-bit sRGB, ``.exr`` linear float)
    and the frame's AOVs as ``aov_format`` "exr" (channels of the EXR, or PATH.aov.exr beside a PNG),
    "npy" or "png16", with PATH.instances.json for the instance ids; returns None."""
    if frame._captured is not None:
        if path is not None:
            raise ValueError("lenslab.write: a Sequence's frame goes where the sequence's out= puts it; give no path")
        return json.loads(frame._captured.write())
    if path is None:
        raise ValueError("lenslab.write: give the path of a frame from Renderer.render or raycast")
    _lenslab._write_frame(str(path), frame.rgba, frame.depth, frame.normal, frame.albedo, frame.instance, aov_format,
                          frame._scene)
    return None
