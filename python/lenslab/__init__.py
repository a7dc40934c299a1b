"""lenslab: the lecture's camera model, rendered.

Scenes are glTF 2.0 files (``lenslab.load``); cameras come in every form the command line reads
(``lenslab.Camera``); a ``lenslab.Renderer`` keeps its OpenGL context, programs and uploaded scene
open across frames and returns NumPy arrays. The same C++ as the ``lenslab`` command, so the same
pixels, checks and messages: a bad input raises ValueError with the command line's one line.
See docs/python.md.
"""

import warnings as _warnings

from . import _lenslab

# Bundled scenes are found from the module's own file (an installed package's share/ folder, or the
# source tree for a build tree's package), as the command finds them from its executable.
_lenslab._set_module_file(_lenslab.__file__)

from ._camera import Camera  # noqa: E402
from ._frame import Frame, Renderer  # noqa: E402
from ._lenslab import Scene, asset_directory, read_image  # noqa: E402
from ._sequence import Sequence, write  # noqa: E402

__all__ = ["Camera", "Frame", "Renderer", "Scene", "Sequence", "asset_directory", "load", "read_image", "write",
           "write_image"]


def load(path=None, *, animation=None, time=None, background=None):
    """The glTF scene at ``path`` (default: the bundled ``rows`` scene), posed at ``time`` seconds of
    its ``animation`` (a clip's name or index, or "all"; default the first clip, at the rest pose when
    no time is given). ``background``: linear RGB where no surface is seen, over the scene's."""
    scene, notes = _lenslab._load(str(path) if path is not None else "", "" if animation is None else str(animation),
                                  time, None if background is None else tuple(float(c) for c in background))
    for note in notes:
        _warnings.warn(note, stacklevel=2)
    return scene


def write_image(path, image):
    """Writes a frame (or float RGBA of shape (height, width, 4)) with the command line's writer:
    ``.png`` 8-bit sRGB, clamped to [0, 1]; ``.exr`` linear 32-bit float. Whole or not at all."""
    rgba = image.rgba if isinstance(image, Frame) else image
    _lenslab._write_image(str(path), rgba)


def _scene_camera(self, node=None, *, width=None, height=None):
    """The camera ``lenslab render`` would use for this scene: glTF camera ``node`` (index, node name
    or camera name); by default the bundled scene's camera file, else the first glTF camera, else an
    automatic framing of the scene. ``width`` and ``height`` (both) give a glTF camera without an
    aspect ratio its image's."""
    aspect = width / height if width and height else 0.0
    return Camera(_lenslab._scene_camera(self, "" if node is None else str(node), aspect))


Scene.camera = _scene_camera
