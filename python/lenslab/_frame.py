"""lenslab.Renderer and lenslab.Frame: frames as NumPy arrays, from a renderer that stays open."""

from . import _lenslab
from ._camera import Camera


class Frame:
    """One rendered frame. ``rgba`` is float32 linear RGB and alpha, shape (height, width, 4), rows
    from the top; ``rgb`` and ``alpha`` are views of it. The AOVs asked for, each one exact value per
    pixel along the ray from the lens centre through the pixel centre (docs/python.md):
    ``depth`` float32 (H, W), distance along the optical axis in world units (metres), +inf where
    nothing is hit; ``normal`` float32 (H, W, 3), unit, camera space in the convention asked for
    (0 where nothing is hit); ``albedo`` float32 (H, W, 3), linear; ``instance`` int32 (H, W), the
    glTF node index, −1 where nothing is hit; ``flow`` float32 (H, W, 2) for a Sequence's frame, the
    motion to the next frame in pixels. ``camera``: the camera as rendered (near and far fitted to
    the scene). A Sequence's frame also has ``index``, ``time`` and ``seed``, and its arrays are
    read-only views of what ``lenslab.write`` writes (copy one to change it)."""

    def __init__(self, fields):
        self.rgba = fields["rgba"]
        self.depth = fields.get("depth")
        self.normal = fields.get("normal")
        self.albedo = fields.get("albedo")
        self.instance = fields.get("instance")
        self.samples = fields["samples"]
        self.warnings = list(fields["warnings"])
        self.camera = Camera(fields["camera"])
        self.flow = fields.get("flow")
        # A Sequence's frame: its frame number, time in seconds and seed (else None).
        self.index = fields.get("index")
        self.time = fields.get("time")
        self.seed = fields.get("seed")
        self._captured = fields.get("captured")
        self._scene = None

    @property
    def rgb(self):
        return self.rgba[..., :3]

    @property
    def alpha(self):
        return self.rgba[..., 3]

    @property
    def size(self):
        """(width, height)"""
        return self.rgba.shape[1], self.rgba.shape[0]

    def __repr__(self):
        width, height = self.size
        where = "" if self.index is None else f"frame {self.index}, "
        return f"<lenslab.Frame {where}{width}x{height}, {self.samples} samples>"


class Renderer:
    """An OpenGL 4.5 context (OSMesa on the CPU by default, ``backend="egl"`` for a GPU) with its
    programs and the last scene uploaded, kept across frames. ``width`` / ``height``: the default
    image size (one side: the other follows the camera's window; none: 960 wide, or a calibrated
    camera's own size). A renderer answers the thread that made it; make one per thread."""

    def __init__(self, width=None, height=None, backend="osmesa"):
        self._native = _lenslab._Renderer(width, height, backend)

    @property
    def gl_renderer(self):
        """GL_RENDERER and GL_VERSION of the context."""
        return self._native.gl_renderer()

    def render(self, scene, camera=None, *, aperture_samples=None, pattern=None, seed=1, aovs=(), normals="gl",
               width=None, height=None):
        """Rasterizes ``scene`` through ``camera`` (default: ``scene.camera()``), as ``lenslab render``
        does: ``aperture_samples`` views accumulated over the lens (None: chosen from the largest
        circle of confusion in view), placed by ``pattern`` (default sobol) and ``seed``. ``aovs``:
        any of "depth", "normal", "albedo", "instance"; ``normals``: "gl" (x right, y up, z toward
        the viewer) or "opencv" (x right, y down, z forward)."""
        camera = scene.camera() if camera is None else camera
        samples = "auto" if aperture_samples is None else str(int(aperture_samples))
        frame = Frame(self._native.render(scene, camera._native, samples, pattern or "", width, height, seed,
                                          list(aovs), normals))
        frame._scene = scene  # the instance ids' names, for lenslab.write
        return frame

    def raycast(self, scene, camera=None, *, spp=64, seed=1, aovs=(), normals="gl", width=None, height=None):
        """The same frame from the CPU ray caster (Embree), ``spp`` stratified pixel × lens samples
        per pixel: the reference ``render`` converges to."""
        camera = scene.camera() if camera is None else camera
        frame = Frame(self._native.raycast(scene, camera._native, int(spp), width, height, seed, list(aovs), normals))
        frame._scene = scene
        return frame

    def frames(self, sequence):
        """A ``Sequence``'s frames, rendered in order (as ``sequence.frames(self)``)."""
        return sequence.frames(self)
