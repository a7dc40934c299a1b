"""lenslab.Camera: the camera forms of the command line's camera files, as Python objects.

Each constructor writes the camera-file form it names (docs/camera-files.md) and reads it with the
command line's reader, so a camera built here has the same checks and one-line messages (raised as
ValueError) as ``lenslab render --camera FILE``.
"""

import json
import math

import numpy as np

from . import _lenslab


def _number(value):
    value = float(value)
    return "infinity" if value == math.inf else value


def _vector(value, length, name, where):
    array = np.asarray(value, dtype=float)
    if array.shape != (length,):
        raise ValueError(f"{where}: {name} has shape {array.shape}: give {length} numbers")
    return array.tolist()


def _matrix(value, rows, columns, name, where):
    array = np.asarray(value, dtype=float)
    if array.shape != (rows, columns):
        raise ValueError(f"{where}: {name} has shape {array.shape}: give a {rows}x{columns} matrix")
    return array.tolist()


def _put(fields, key, value, convert=_number):
    if value is not None:
        fields[key] = convert(value)


class Camera:
    """A camera as ``lenslab render`` uses one. Build it with one of the class methods."""

    def __init__(self, native):
        if not isinstance(native, _lenslab._Camera):
            raise TypeError("lenslab.Camera: build one with Camera.from_file, lecture, physical, from_opencv, "
                            "from_colmap, from_json or Scene.camera")
        self._native = native

    # ---- the forms ----

    @classmethod
    def from_file(cls, path):
        """A camera file (lecture, physical or OpenCV form)."""
        return cls(_lenslab._camera_from_file(str(path)))

    @classmethod
    def from_json(cls, text, where="lenslab.Camera.from_json"):
        """A camera file's content: JSON text, or a dict of it."""
        if not isinstance(text, str):
            text = json.dumps(text)
        return cls(_lenslab._camera_from_json(text, where))

    @classmethod
    def lecture(cls, *, vrp, vpn, prp, window, vup=(0.0, 1.0, 0.0), projection="perspective", near=None, far=None,
                aperture_radius=None, focus_distance=None):
        """The lecture's viewing description: VRP, VPN, VUP (world), PRP (u, v, n) and the window
        (umin, vmin, umax, vmax) on the view plane; a thin lens of ``aperture_radius``."""
        where = "lenslab.Camera.lecture"
        fields = {"projection": projection, "vrp": _vector(vrp, 3, "vrp", where), "vpn": _vector(vpn, 3, "vpn", where),
                  "vup": _vector(vup, 3, "vup", where), "prp": _vector(prp, 3, "prp", where),
                  "window": _vector(window, 4, "window", where)}
        _put(fields, "near", near)
        _put(fields, "far", far)
        _put(fields, "aperture_radius", aperture_radius)
        _put(fields, "focus_distance", focus_distance)
        return cls.from_json(fields, where)

    @classmethod
    def physical(cls, *, eye, target, up=(0.0, 1.0, 0.0), focal_length_mm=35.0, f_number=None, focus_distance_m=None,
                 sensor_mm=(36.0, 24.0), near=None, far=None):
        """A photographer's description (metres): a lens of ``focal_length_mm`` at ``f_number``
        (None: a pinhole) focused at ``focus_distance_m`` (default |target − eye|) on a sensor."""
        where = "lenslab.Camera.physical"
        fields = {"eye": _vector(eye, 3, "eye", where), "target": _vector(target, 3, "target", where),
                  "up": _vector(up, 3, "up", where), "focal_length_mm": float(focal_length_mm),
                  "sensor_mm": _vector(sensor_mm, 2, "sensor_mm", where)}
        _put(fields, "f_number", f_number)
        _put(fields, "focus_distance", focus_distance_m)
        _put(fields, "near", near)
        _put(fields, "far", far)
        return cls.from_json(fields, where)

    @classmethod
    def from_opencv(cls, K, dist=None, R=None, t=None, *, width, height, focus_distance=None, aperture_radius=None):
        """A calibrated camera in OpenCV's terms: K (3x3), distCoeffs (up to 12, OpenCV's order), and
        the pose X_cam = R·X_world + t (x right, y down, z forward) for an image width × height."""
        where = "lenslab.Camera.from_opencv"
        fields = {"K": _matrix(K, 3, 3, "K", where), "width": int(width), "height": int(height)}
        if R is not None or t is not None:
            if R is None or t is None:
                raise ValueError(f"{where}: give both R and t (the pose), or neither")
            fields["R"] = _matrix(R, 3, 3, "R", where)
            fields["t"] = _vector(t, 3, "t", where)
        if dist is not None:
            fields["dist"] = np.asarray(dist, dtype=float).ravel().tolist()
        _put(fields, "focus_distance", focus_distance)
        _put(fields, "aperture_radius", aperture_radius)
        return cls.from_json(fields, where)

    @classmethod
    def from_colmap(cls, folder, image):
        """The camera of photograph ``image`` (its name) in a COLMAP model (text or binary)."""
        return cls(_lenslab._camera_from_colmap(str(folder), str(image)))

    # ---- back out ----

    def to_json(self, width=None, height=None):
        """The camera file for this camera: the OpenCV form (K, R, t, distCoeffs, focus and aperture,
        for an image of that size) for a perspective camera, the lecture form for a parallel one."""
        if not self.perspective:
            return self._native._lecture_json()
        return self._native._opencv_json(width, height)

    def opencv(self, width=None, height=None):
        """(K, dist, R, t) as NumPy arrays, in OpenCV's convention (pixel centres on integers, x right,
        y down, z forward), for an image of that size (default: the camera's own)."""
        fields = json.loads(self.to_json(width, height))
        dist = fields.get("distortion", [])
        if isinstance(dist, dict):
            raise ValueError(f"{self.source}: its distortion is not OpenCV's radial-tangential model; "
                             "to_json() gives it in full")
        return (np.array(fields["K"], dtype=float), np.array(dist, dtype=float), np.array(fields["R"], dtype=float),
                np.array(fields["t"], dtype=float))

    def project(self, points, width=None, height=None):
        """Where world points (shape (N, 3)) show on an image of that size, as an (N, 2) array of
        pixels in OpenCV's convention (pixel centres on integers, x right, y down), through the
        lens's distortion as the renderers draw it; NaN for a point not in front of the lens."""
        pixels = self._native._project(np.asarray(points, dtype=float).reshape(-1, 3), width, height)
        return pixels - 0.5

    def image_size(self, width=None, height=None):
        """(width, height) of the image this camera renders when given that width and/or height."""
        return self._native.image_size(width, height)

    @property
    def source(self):
        return self._native.source

    @property
    def perspective(self):
        return self._native.perspective

    @property
    def aperture_radius(self):
        return self._native.aperture_radius

    @property
    def focus_distance(self):
        return self._native.focus_distance

    @property
    def calibrated_size(self):
        return self._native.calibrated_size

    def __repr__(self):
        return f"<lenslab.Camera {self.source}>"
