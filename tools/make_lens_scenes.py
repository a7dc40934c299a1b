#!/usr/bin/python3
"""Writes the two scenes that show a real lens's faults, exact against fitted, into assets/lens-scenes/.

    /usr/bin/python3 tools/make_lens_scenes.py [OUT_DIR]   # default: assets/lens-scenes

Python's standard library only, deterministic (the same bytes every run: the ctest `lens_scenes`
regenerates them into a temporary folder and compares). World units are metres, +Y up. Every
surface is unlit (KHR_materials_unlit) and every lamp emits over a thousand times what it
reflects, so a pixel's value is a surface's colour or a lamp's light and nothing else: what
differs between two renders of these scenes is the lens, not the shading.

  checker  a flat black-and-white checkerboard wall facing the camera, 16 squares across a
           50 mm lens's 36 x 24 mm frame and five times as wide, so the wide angle and most of
           the fisheye's circle see it too: straight lines show distortion, edges blur and colour
  street   a street of lights at night: lamps (small emissive spheres) in two rows on each side,
           at the kerb and overhead, receding 45 m along a dark road; the camera focuses on a
           lantern 0.8 m away, so the lamps blur into discs that vignetting cuts to cat's eyes
           toward the corners (the rows reach the frame's corners 4.2 m away)

Each scene is OUT_DIR/<name>/<name>.gltf with its .bin and camera.json (physical form, no
f_number: `raycast --lens` opens the lens fully). The glTF also holds a camera node matching
camera.json, so `lenslab render <name>.gltf` without --camera sees the same view.
"""

import json
import math
import os
import struct
import sys

FLOAT, UNSIGNED_SHORT = 5126, 5123
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963


def f32(x):
    """x rounded to float32, as the buffer holds it (accessor min/max must match it exactly)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


class Gltf:
    """The smallest glTF 2.0 writer these two scenes need: unlit meshes, nodes, one camera."""

    def __init__(self, name):
        self.name = name
        self.bin = bytearray()
        self.doc = {
            "asset": {"version": "2.0", "generator": "lenslab tools/make_lens_scenes.py"},
            "extensionsUsed": ["KHR_materials_unlit"],
            "scene": 0, "scenes": [{"name": name, "nodes": []}],
            "nodes": [], "meshes": [], "materials": [], "accessors": [], "bufferViews": [],
        }

    def _view(self, data, target):
        while len(self.bin) % 4:
            self.bin += b"\x00"
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data),
                                        "target": target})
        self.bin += data
        return len(self.doc["bufferViews"]) - 1

    def positions(self, points):
        flat = [c for p in points for c in p]
        view = self._view(struct.pack("<%df" % len(flat), *flat), ARRAY_BUFFER)
        self.doc["accessors"].append({
            "bufferView": view, "componentType": FLOAT, "count": len(points), "type": "VEC3",
            "min": [f32(min(p[i] for p in points)) for i in range(3)],
            "max": [f32(max(p[i] for p in points)) for i in range(3)]})
        return len(self.doc["accessors"]) - 1

    def indices(self, indices):
        assert max(indices) <= 65535
        view = self._view(struct.pack("<%dH" % len(indices), *indices), ELEMENT_ARRAY_BUFFER)
        self.doc["accessors"].append({"bufferView": view, "componentType": UNSIGNED_SHORT,
                                      "count": len(indices), "type": "SCALAR"})
        return len(self.doc["accessors"]) - 1

    def material(self, name, color, double_sided=False):
        """Unlit: the base colour is what is seen."""
        mat = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(color) + [1.0],
                                                      "metallicFactor": 0.0},
               "extensions": {"KHR_materials_unlit": {}}}
        if double_sided:
            mat["doubleSided"] = True
        self.doc["materials"].append(mat)
        return len(self.doc["materials"]) - 1

    def lamp_material(self, name, emissive, strength):
        """A black rough dielectric emitting emissive × strength. Not unlit: the glTF validator warns
        that KHR_materials_unlit may not combine with KHR_materials_emissive_strength. Under
        lenslab's default light it reflects at most about 0.02, against an emitted 20 to 30."""
        mat = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0],
                                                      "metallicFactor": 0.0, "roughnessFactor": 1.0},
               "emissiveFactor": list(emissive),
               "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": strength}}}
        if "KHR_materials_emissive_strength" not in self.doc["extensionsUsed"]:
            self.doc["extensionsUsed"].append("KHR_materials_emissive_strength")
        self.doc["materials"].append(mat)
        return len(self.doc["materials"]) - 1

    def mesh(self, name, position_accessor, index_accessor, material):
        """No NORMAL: every material is unlit, and glTF asks a reader to make flat normals."""
        self.doc["meshes"].append({"name": name, "primitives": [
            {"attributes": {"POSITION": position_accessor}, "indices": index_accessor, "material": material}]})
        return len(self.doc["meshes"]) - 1

    def node(self, name, **fields):
        self.doc["nodes"].append(dict(name=name, **fields))
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def camera_from(self, cam):
        """A glTF perspective camera matching a physical camera.json: yfov spans the sensor's height
        at the image distance of the focus (as lenslab turns the physical form into a window)."""
        eye, target = cam["eye"], cam["target"]
        f_m = cam["focal_length_mm"] / 1000.0
        focus_m = math.dist(eye, target)
        image_m = f_m * focus_m / (focus_m - f_m)
        sensor_mm = cam["sensor_mm"]
        yfov = 2.0 * math.atan(sensor_mm[1] / 1000.0 / (2.0 * image_m))
        forward = normalize([target[i] - eye[i] for i in range(3)])
        right = normalize(cross(forward, [0.0, 1.0, 0.0]))
        up = cross(right, forward)
        back = [-c for c in forward]
        self.doc["cameras"] = [{"name": "camera", "type": "perspective", "perspective": {
            "yfov": yfov, "aspectRatio": sensor_mm[0] / sensor_mm[1], "znear": cam["near"]}}]
        self.node("camera", camera=0, matrix=right + [0.0] + up + [0.0] + back + [0.0] + list(eye) + [1.0])

    def write(self, folder, camera):
        os.makedirs(folder, exist_ok=True)
        while len(self.bin) % 4:
            self.bin += b"\x00"
        self.doc["buffers"] = [{"name": self.name, "uri": self.name + ".bin", "byteLength": len(self.bin)}]
        with open(os.path.join(folder, self.name + ".bin"), "wb") as f:
            f.write(bytes(self.bin))
        with open(os.path.join(folder, self.name + ".gltf"), "w") as f:
            json.dump(self.doc, f, indent=1, sort_keys=True)
            f.write("\n")
        with open(os.path.join(folder, "camera.json"), "w") as f:
            json.dump(camera, f, indent=2)
            f.write("\n")


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalize(a):
    n = math.sqrt(sum(c * c for c in a))
    return [c / n for c in a]


def quad(g, name, a, b, c, material):
    """The parallelogram a, b, c, a + c − b (counter-clockwise seen from its front) as a mesh."""
    d = [a[i] + c[i] - b[i] for i in range(3)]
    return g.mesh(name, g.positions([a, b, c, d]), g.indices([0, 1, 2, 0, 2, 3]), material)


def sphere(radius_m, rings=8, segments=16):
    """A UV sphere: (positions, indices), counter-clockwise seen from outside."""
    points, indices = [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2.0 * math.pi * s / segments
            points.append([radius_m * math.sin(theta) * math.cos(phi), radius_m * math.cos(theta),
                           -radius_m * math.sin(theta) * math.sin(phi)])
    for r in range(rings):
        for s in range(segments):
            a, b = r * (segments + 1) + s, (r + 1) * (segments + 1) + s
            indices += [a, b, a + 1, a + 1, b, b + 1]
    return points, indices


# ---------------------------------------------------------------- checker

CHECKER_SQUARE_M = 0.13       # 16.3 squares across a 50 mm lens's 36 mm frame at 3 m (2.12 m wide)
CHECKER_COLUMNS, CHECKER_ROWS = 80, 56   # 10.4 x 7.3 m: the 28 mm lens sees 3.9 x 2.6 m of it
CHECKER_DISTANCE_M = 3.0


def make_checker(out_dir):
    """The wall in the plane z = 0, facing +z, a square's corner on the optical axis. The two
    colours share one grid of vertices (every grid point is a corner of both), each colour
    drawing its own squares from it: 55 KB of positions instead of four vertices a square."""
    g = Gltf("checker")
    half_w = 0.5 * CHECKER_COLUMNS * CHECKER_SQUARE_M
    half_h = 0.5 * CHECKER_ROWS * CHECKER_SQUARE_M
    grid = [[-half_w + i * CHECKER_SQUARE_M, -half_h + j * CHECKER_SQUARE_M, 0.0]
            for j in range(CHECKER_ROWS + 1) for i in range(CHECKER_COLUMNS + 1)]
    positions = g.positions(grid)
    squares = {0: [], 1: []}
    for j in range(CHECKER_ROWS):
        for i in range(CHECKER_COLUMNS):
            a = j * (CHECKER_COLUMNS + 1) + i   # lower left; +x right, +y up, seen from +z
            b, c, d = a + 1, a + CHECKER_COLUMNS + 2, a + CHECKER_COLUMNS + 1
            squares[(i + j) % 2] += [a, b, c, a, c, d]
    # White below 1 so that neither renderer clips it; black above 0 so that the dark corners
    # and the blur into black stay measurable.
    white = g.material("white", (0.8, 0.8, 0.8))
    black = g.material("black", (0.01, 0.01, 0.01))
    g.node("white squares", mesh=g.mesh("white squares", positions, g.indices(squares[0]), white))
    g.node("black squares", mesh=g.mesh("black squares", positions, g.indices(squares[1]), black))
    camera = {"eye": [0.0, 0.0, CHECKER_DISTANCE_M], "target": [0.0, 0.0, 0.0], "up": [0, 1, 0],
              "focal_length_mm": 50, "sensor_mm": [36, 24], "focus_distance": CHECKER_DISTANCE_M,
              "near": 0.05, "far": "infinity"}
    g.camera_from(camera)
    g.write(os.path.join(out_dir, "checker"), camera)


# ---------------------------------------------------------------- street

EYE_HEIGHT_M = 1.2
ROW_X_M = 1.5                     # the rows' distance either side of the camera's axis
ROW_HEIGHTS_M = (0.2, 2.2)        # kerb and overhead: ±1.0 m about the eye, 1.5 : 1 as the frame,
                                  # so each row reaches the 36 x 24 frame's corner 4.17 m away at 50 mm
LAMP_SPACING_M, LAMP_COUNT = 1.5, 30
LAMP_RADIUS_M = 0.04
LANTERN_M = (0.08, 1.12, -0.8)    # the near light the camera focuses on


def make_street(out_dir):
    g = Gltf("street")
    # A dark road between dark house fronts 12 m apart, closed by houses 48 m away and a night sky
    # 30 m up: a box open only behind the camera, so that every lens, the fisheye too, sees night
    # wherever it sees no lamp (never lenslab's grey-blue background).
    asphalt = g.material("asphalt", (0.012, 0.012, 0.014))
    night = g.material("night", (0.004, 0.004, 0.006), double_sided=True)
    g.node("road", mesh=quad(g, "road", [-6.0, 0.0, 2.0], [6.0, 0.0, 2.0], [6.0, 0.0, -48.0], asphalt))
    g.node("houses left", mesh=quad(g, "houses left", [-6.0, 0.0, 2.0], [-6.0, 0.0, -48.0], [-6.0, 30.0, -48.0], night))
    g.node("houses right", mesh=quad(g, "houses right", [6.0, 0.0, -48.0], [6.0, 0.0, 2.0], [6.0, 30.0, 2.0], night))
    g.node("houses ahead", mesh=quad(g, "houses ahead", [-6.0, 0.0, -48.0], [6.0, 0.0, -48.0], [6.0, 30.0, -48.0], night))
    g.node("sky", mesh=quad(g, "sky", [-6.0, 30.0, -48.0], [6.0, 30.0, -48.0], [6.0, 30.0, 2.0], night))
    points, indices = sphere(LAMP_RADIUS_M)
    lamp_positions, lamp_indices = g.positions(points), g.indices(indices)
    # Emitted radiance 30 (warm) and 20 (cool): a lamp 4 m away blurred at 50 mm f/2 into a disc
    # of ~13 px at 480 px spreads over ~15 times its own image, and should still clip near 1.
    warm = g.lamp_material("lamp-warm", (1.0, 0.72, 0.42), 30.0)
    cool = g.lamp_material("lamp-cool", (0.55, 0.75, 1.0), 20.0)
    warm_lamp = g.mesh("lamp-warm", lamp_positions, lamp_indices, warm)
    cool_lamp = g.mesh("lamp-cool", lamp_positions, lamp_indices, cool)
    for side, x in (("left", -ROW_X_M), ("right", ROW_X_M)):
        for height, mesh in zip(ROW_HEIGHTS_M, (cool_lamp, warm_lamp)):
            for k in range(LAMP_COUNT):
                z = -LAMP_SPACING_M * (k + 1)
                g.node("lamp %s %.1f m %d" % (side, height, k + 1), mesh=mesh, translation=[x, height, z])
    # A quarter of a lamp's size: in focus 0.8 m away, a 1 cm sphere is 8 px across at 480 px.
    g.node("lantern", mesh=warm_lamp, translation=list(LANTERN_M), scale=[0.25, 0.25, 0.25])
    camera = {"eye": [0.0, EYE_HEIGHT_M, 0.0], "target": [0.0, EYE_HEIGHT_M, LANTERN_M[2]], "up": [0, 1, 0],
              "focal_length_mm": 50, "sensor_mm": [36, 24], "focus_distance": -LANTERN_M[2],
              "near": 0.05, "far": "infinity"}
    g.camera_from(camera)
    g.write(os.path.join(out_dir, "street"), camera)


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "lens-scenes")
    out_dir = sys.argv[1] if len(sys.argv) > 1 else root
    make_checker(out_dir)
    make_street(out_dir)


if __name__ == "__main__":
    main()
