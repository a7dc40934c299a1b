#!/usr/bin/python3
"""Writes lenslab's bundled scenes and their camera files into assets/.

    /usr/bin/python3 tools/make_assets.py   # Debian's Python, which has python3-pil; then: bash tools/validate-assets.sh

Python's standard library and Pillow (python3-pil), deterministic (the same bytes every run). World units are metres, +Y up,
glTF's conventions throughout. Each scene is assets/<name>/<name>.gltf with one .bin and its PNG
textures beside it, and assets/<name>/camera.json, the default camera of `lenslab render`.

  rows         textured objects at 2, 4, 8, 16 and 32 m over a checker floor: the default scene
               and the depth-of-field showcase
  occluder     a fence of thin bars 1 m from the camera before a textured wall at 4 m: partial
               obscuration
  grid         a plane of dots facing the camera, the view plane on it: distortion
  depth-range  objects from 0.01 to 1e5 m, and two quads 1e-5 apart (relative) at 1 km: depth
               precision
"""

import json
import math
import os
import struct

from PIL import Image  # Debian: python3-pil

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets")

# glTF enums
FLOAT, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5123, 5125
REPEAT, CLAMP_TO_EDGE = 10497, 33071
LINEAR, LINEAR_MIPMAP_LINEAR, NEAREST = 9729, 9987, 9728


# ---------------------------------------------------------------- PNG

def write_png(path, width, height, pixels):
    """pixels: bytes of RGBA8, rows from the top. Pillow writes it (deterministic: no timestamp)."""
    Image.frombytes("RGBA", (width, height), bytes(pixels)).save(path, format="PNG", optimize=False, compress_level=9)


def image(width, height, fn):
    """fn(x, y) -> (r, g, b) in 0..255 (sRGB-encoded, as PNG textures are)."""
    out = bytearray()
    for y in range(height):
        for x in range(width):
            r, g, b = fn(x, y)
            out += bytes((r, g, b, 255))
    return bytes(out)


def checker(cell_px, light=(235, 235, 235), dark=(40, 40, 40)):
    def fn(x, y):
        return light if (x // cell_px + y // cell_px) % 2 == 0 else dark
    return fn


def stripes(x, y):
    palette = [(230, 60, 50), (245, 190, 40), (60, 170, 80), (40, 110, 210), (150, 70, 190)]
    return palette[((x + y) // 16) % len(palette)]


def rings(x, y):
    r = math.hypot(x - 63.5, y - 63.5)
    return (250, 250, 250) if int(r // 8) % 2 == 0 else (200, 30, 60)


def bricks(x, y):
    row = y // 16
    offset = 16 if row % 2 else 0
    mortar = y % 16 < 2 or (x + offset) % 32 < 2
    return (210, 205, 195) if mortar else (165, 70, 45)


def tile_height(x, y, size=128, tiles=4, bevel=0.2):
    """Raised square tiles with bevelled edges, height 0 (groove) to 1 (tile top), x and y in pixels."""
    cell = size / tiles
    fx, fy = ((x + 0.5) % cell) / cell, ((y + 0.5) % cell) / cell
    edge = min(fx, 1 - fx, fy, 1 - fy)  # 0 at the groove, 0.5 at the tile's centre
    return min(1.0, edge / bevel)


def tiles_normal(x, y, size=128, depth_px=6.0):
    """The tiles' tangent-space normal map (glTF: +X right, +Y up in the image, +Z out), 8-bit linear."""
    hx = (tile_height(x + 1, y) - tile_height(x - 1, y)) * 0.5 * depth_px
    hy = (tile_height(x, y - 1) - tile_height(x, y + 1)) * 0.5 * depth_px  # image rows run down; +Y is up
    n = normalize([-hx, -hy, 1.0])
    return tuple(int(round((c * 0.5 + 0.5) * 255)) for c in n)


def tiles_occlusion(x, y):
    """Ambient occlusion of the tiles: the grooves see less of the sky."""
    a = int(round(255 * (0.45 + 0.55 * tile_height(x, y))))
    return (a, a, a)


def tiles_metal_rough(x, y, size=128, tiles=4):
    """glTF metallic-roughness: G = roughness, B = metallic. Alternate tiles are polished metal and
    rough paint; the grooves are rough."""
    cell = size // tiles
    metal = (x // cell + y // cell) % 2 == 0 and tile_height(x, y) > 0.99
    return (0, 60 if metal else 200, 255 if metal else 0)


# ---------------------------------------------------------------- glTF builder

class Gltf:
    def __init__(self, name):
        self.name = name
        self.bin = bytearray()
        self.doc = {
            "asset": {"version": "2.0", "generator": "lenslab tools/make_assets.py"},
            "scene": 0,
            "scenes": [{"name": name, "nodes": []}],
            "nodes": [], "meshes": [], "materials": [], "accessors": [], "bufferViews": [],
        }
        self.images = []  # (file name, width, height, pixels)

    def _view(self, data, target=None):
        while len(self.bin) % 4:
            self.bin += b"\x00"
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.bin += data
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, values, kind, components):
        flat = [c for v in values for c in v]
        view = self._view(struct.pack("<%df" % len(flat), *flat), 34962)
        acc = {"bufferView": view, "componentType": FLOAT, "count": len(values), "type": kind}
        if kind == "VEC3" and components == 3:
            acc["min"] = [min(v[i] for v in values) for i in range(3)]
            acc["max"] = [max(v[i] for v in values) for i in range(3)]
            # min/max must hold the float32 values exactly
            acc["min"] = [struct.unpack("<f", struct.pack("<f", m))[0] for m in acc["min"]]
            acc["max"] = [struct.unpack("<f", struct.pack("<f", m))[0] for m in acc["max"]]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def _indices(self, indices):
        big = max(indices) > 65535
        fmt = "<%d%s" % (len(indices), "I" if big else "H")
        view = self._view(struct.pack(fmt, *indices), 34963)
        self.doc["accessors"].append({"bufferView": view, "componentType": UNSIGNED_INT if big else UNSIGNED_SHORT,
                                      "count": len(indices), "type": "SCALAR"})
        return len(self.doc["accessors"]) - 1

    def texture(self, name, width, height, pixels, wrap=REPEAT, mipmaps=True):
        doc = self.doc
        doc.setdefault("images", []).append({"name": name, "uri": name + ".png"})
        doc.setdefault("samplers", []).append({
            "name": name + "-sampler", "wrapS": wrap, "wrapT": wrap, "magFilter": LINEAR,
            "minFilter": LINEAR_MIPMAP_LINEAR if mipmaps else LINEAR})
        doc.setdefault("textures", []).append({"name": name, "source": len(doc["images"]) - 1,
                                               "sampler": len(doc["samplers"]) - 1})
        self.images.append((name + ".png", width, height, pixels))
        return len(doc["textures"]) - 1

    def material(self, name, color=(1, 1, 1, 1), texture=None, unlit=False, emissive=None, strength=1.0,
                 metallic=0.0, roughness=1.0, mr_texture=None, normal_texture=None, normal_scale=1.0,
                 occlusion_texture=None, occlusion_strength=1.0, occlusion_texcoord=0, transforms=None):
        """transforms: {"baseColorTexture": {"offset": .., "rotation": .., "scale": ..}, ...} (KHR_texture_transform)."""
        transforms = transforms or {}

        def ref(slot, index, texcoord=0, **extra):
            r = {"index": index}
            if texcoord:
                r["texCoord"] = texcoord
            r.update(extra)
            if slot in transforms:
                r["extensions"] = {"KHR_texture_transform": transforms[slot]}
                self._use("KHR_texture_transform")
            return r

        pbr = {"baseColorFactor": list(color), "metallicFactor": metallic, "roughnessFactor": roughness}
        if texture is not None:
            pbr["baseColorTexture"] = ref("baseColorTexture", texture)
        if mr_texture is not None:
            pbr["metallicRoughnessTexture"] = ref("metallicRoughnessTexture", mr_texture)
        mat = {"name": name, "pbrMetallicRoughness": pbr}
        if normal_texture is not None:
            mat["normalTexture"] = ref("normalTexture", normal_texture, **({"scale": normal_scale} if normal_scale != 1.0 else {}))
        if occlusion_texture is not None:
            mat["occlusionTexture"] = ref("occlusionTexture", occlusion_texture, occlusion_texcoord,
                                          **({"strength": occlusion_strength} if occlusion_strength != 1.0 else {}))
        extensions = {}
        if unlit:
            extensions["KHR_materials_unlit"] = {}
        if emissive is not None:
            mat["emissiveFactor"] = list(emissive)
            if strength != 1.0:
                extensions["KHR_materials_emissive_strength"] = {"emissiveStrength": strength}
        if extensions:
            mat["extensions"] = extensions
            for name_used in sorted(extensions):
                self._use(name_used)
        self.doc["materials"].append(mat)
        return len(self.doc["materials"]) - 1

    def _use(self, extension):
        used = self.doc.setdefault("extensionsUsed", [])
        if extension not in used:
            used.append(extension)

    def light(self, name, kind, color=(1, 1, 1), intensity=1.0, range_m=None, inner=None, outer=None):
        """A KHR_lights_punctual light (lux for directional, candela for point and spot); place it with node(light=)."""
        light = {"name": name, "type": kind, "color": list(color), "intensity": intensity}
        if range_m is not None:
            light["range"] = range_m
        if kind == "spot":
            light["spot"] = {"innerConeAngle": inner, "outerConeAngle": outer}
        lights = self.doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})["lights"]
        lights.append(light)
        self._use("KHR_lights_punctual")
        return len(lights) - 1

    def mesh(self, name, geometry, material, normals=True, colors=None, uv1=False):
        """uv1: also a TEXCOORD_1, the same coordinates as TEXCOORD_0 (for a map that asks for set 1)."""
        positions, geo_normals, uvs, indices = geometry
        attributes = {"POSITION": self._accessor(positions, "VEC3", 3)}
        if normals:
            attributes["NORMAL"] = self._accessor(geo_normals, "VEC3", 0)
        attributes["TEXCOORD_0"] = self._accessor(uvs, "VEC2", 2)
        if uv1:
            attributes["TEXCOORD_1"] = self._accessor(uvs, "VEC2", 2)
        if colors:
            attributes["COLOR_0"] = self._accessor(colors, "VEC4", 4)
        self.doc["meshes"].append({"name": name, "primitives": [
            {"attributes": attributes, "indices": self._indices(indices), "material": material}]})
        return len(self.doc["meshes"]) - 1

    def node(self, name, mesh=None, translation=None, scale=None, matrix=None, camera=None, light=None, rotation=None):
        node = {"name": name}
        if light is not None:
            node["extensions"] = {"KHR_lights_punctual": {"light": light}}
        if rotation is not None:
            node["rotation"] = list(rotation)
        if mesh is not None:
            node["mesh"] = mesh
        if camera is not None:
            node["camera"] = camera
        if matrix is not None:
            node["matrix"] = matrix
        if translation is not None:
            node["translation"] = list(translation)
        if scale is not None:
            node["scale"] = list(scale)
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)
        return len(self.doc["nodes"]) - 1

    def camera_from(self, cam):
        """A glTF perspective camera node matching a physical camera.json."""
        eye, target, up = cam["eye"], cam["target"], cam.get("up", [0, 1, 0])
        f = cam["focal_length_mm"] / 1000.0
        zf = cam["focus_distance"]
        zi = f * zf / (zf - f)
        sensor = cam.get("sensor_mm", [36, 24])
        yfov = 2.0 * math.atan(sensor[1] / 1000.0 / (2.0 * zi))
        forward = normalize(sub(target, eye))
        right = normalize(cross(forward, up))
        true_up = cross(right, forward)
        self._camera_node(eye, forward, true_up, right, yfov, sensor[0] / sensor[1], cam["near"], cam.get("far", "infinity"))

    def camera_from_lecture(self, cam):
        """A glTF perspective camera node matching a lecture-form (perspective, on-axis) camera.json:
        the eye at the PRP, looking along −VPN, yfov spanning the window's height at the PRP's n."""
        vrp, vpn, vup, prp, window = cam["vrp"], normalize(cam["vpn"]), cam["vup"], cam["prp"], cam["window"]
        assert prp[0] == 0.5 * (window[0] + window[2]) and prp[1] == 0.5 * (window[1] + window[3]), "off-axis PRP"
        u = normalize(cross(vup, vpn))
        v = cross(vpn, u)
        eye = [vrp[i] + prp[0] * u[i] + prp[1] * v[i] + prp[2] * vpn[i] for i in range(3)]
        yfov = 2.0 * math.atan(0.5 * (window[3] - window[1]) / prp[2])
        aspect = round((window[2] - window[0]) / (window[3] - window[1]), 12)  # 1.5, not 1.5000000000000002
        self._camera_node(eye, [-c for c in vpn], v, u, yfov, aspect, cam["near"], cam["far"])

    def _camera_node(self, eye, forward, up, right, yfov, aspect, near, far):
        back = [-c for c in forward]
        matrix = list(right) + [0.0] + list(up) + [0.0] + back + [0.0] + list(eye) + [1.0]
        identity = [1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0]
        perspective = {"yfov": yfov, "aspectRatio": aspect, "znear": near}
        if far != "infinity":
            perspective["zfar"] = far
        self.doc.setdefault("cameras", []).append({"name": "camera", "type": "perspective",
                                                   "perspective": perspective})
        self.node("camera", camera=len(self.doc["cameras"]) - 1,
                  matrix=None if matrix == identity else matrix)  # glTF: no default matrix

    def write(self, camera_json):
        folder = os.path.join(ROOT, self.name)
        os.makedirs(folder, exist_ok=True)
        while len(self.bin) % 4:
            self.bin += b"\x00"
        self.doc["buffers"] = [{"name": self.name, "uri": self.name + ".bin", "byteLength": len(self.bin)}]
        with open(os.path.join(folder, self.name + ".bin"), "wb") as f:
            f.write(bytes(self.bin))
        with open(os.path.join(folder, self.name + ".gltf"), "w") as f:
            json.dump(self.doc, f, indent=1, sort_keys=True)
            f.write("\n")
        for file_name, width, height, pixels in self.images:
            write_png(os.path.join(folder, file_name), width, height, pixels)
        with open(os.path.join(folder, "camera.json"), "w") as f:
            json.dump(camera_json, f, indent=2)
            f.write("\n")


# ---------------------------------------------------------------- geometry

def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalize(a):
    n = math.sqrt(sum(c * c for c in a))
    return [c / n for c in a]


def box(hx, hy, hz, uv_scale=1.0):
    """A box centred at the origin: 24 vertices, outward normals, counter-clockwise faces."""
    positions, normals, uvs, indices = [], [], [], []
    faces = [((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
             ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
             ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0))]
    half = (hx, hy, hz)
    for n, a, b in faces:  # a × b = n: a is "right", b is "up" seen from outside
        base = len(positions)
        for s, t in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            positions.append([half[i] * (n[i] + s * a[i] + t * b[i]) for i in range(3)])
            normals.append(list(n))
            uvs.append([(s + 1) * 0.5 * uv_scale, (1 - t) * 0.5 * uv_scale])
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, uvs, indices


def quad(width, height, uv_repeat=1.0):
    """A quad in z = 0 facing +z, centred at the origin."""
    w, h = width / 2, height / 2
    positions = [[-w, -h, 0], [w, -h, 0], [w, h, 0], [-w, h, 0]]
    normals = [[0, 0, 1]] * 4
    uvs = [[0, uv_repeat], [uv_repeat, uv_repeat], [uv_repeat, 0], [0, 0]]
    return positions, normals, uvs, [0, 1, 2, 0, 2, 3]


def floor(size, uv_repeat):
    """A quad in y = 0 facing +y."""
    s = size / 2
    positions = [[-s, 0, s], [s, 0, s], [s, 0, -s], [-s, 0, -s]]
    normals = [[0, 1, 0]] * 4
    uvs = [[0, uv_repeat], [uv_repeat, uv_repeat], [uv_repeat, 0], [0, 0]]
    return positions, normals, uvs, [0, 1, 2, 0, 2, 3]


def disc(radius, sides=8):
    """A regular polygon in z = 0 facing +z (a dot)."""
    positions = [[0, 0, 0]] + [[radius * math.cos(2 * math.pi * k / sides), radius * math.sin(2 * math.pi * k / sides), 0]
                               for k in range(sides)]
    normals = [[0, 0, 1]] * (sides + 1)
    uvs = [[0.5, 0.5]] * (sides + 1)
    indices = []
    for k in range(sides):
        indices += [0, 1 + k, 1 + (k + 1) % sides]
    return positions, normals, uvs, indices


def sphere(radius, rings=24, segments=48):
    """A uv sphere centred at the origin: u once around from +z towards +x, v from the top (+y) down."""
    positions, normals, uvs, indices = [], [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2 * math.pi * j / segments
            n = [math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi)]
            positions.append([radius * c for c in n])
            normals.append(n)
            uvs.append([j / segments, i / rings])
    for i in range(rings):
        for j in range(segments):
            a = i * (segments + 1) + j
            b = a + segments + 1
            if i > 0:
                indices += [a, b, a + 1]
            if i < rings - 1:
                indices += [a + 1, b, b + 1]
    return positions, normals, uvs, indices


def merge(parts):
    """Concatenates (geometry, offset) pairs into one geometry."""
    positions, normals, uvs, indices = [], [], [], []
    for (p, n, t, i), offset in parts:
        base = len(positions)
        positions += [[v[k] + offset[k] for k in range(3)] for v in p]
        normals += n
        uvs += t
        indices += [base + j for j in i]
    return positions, normals, uvs, indices


# ---------------------------------------------------------------- scenes

def make_rows():
    g = Gltf("rows")
    checker_tex = g.texture("checker", 64, 64, image(64, 64, checker(8)))
    stripes_tex = g.texture("stripes", 128, 128, image(128, 128, stripes))
    rings_tex = g.texture("rings", 128, 128, image(128, 128, rings))
    bricks_tex = g.texture("bricks", 128, 128, image(128, 128, bricks))

    floor_mat = g.material("floor", texture=checker_tex)
    g.node("floor", g.mesh("floor", floor(60.0, 30.0), floor_mat))

    eye = [0.0, 1.0, 3.0]
    # distance from the eye along -z, sideways offset, half size, what it is
    rows = [
        (2.0, -0.55, 0.15, "stripes"),
        (4.0, 0.75, 0.25, "rings-unlit"),
        (8.0, -1.6, 0.4, "red-no-normals"),
        (16.0, 2.8, 0.7, "vertex-colours"),
        (32.0, -4.5, 1.2, "bricks"),
    ]
    for distance, x, h, kind in rows:
        z = eye[2] - distance
        name = "box-%gm" % distance
        if kind == "stripes":
            mesh = g.mesh(name, box(h, h, h), g.material("stripes", texture=stripes_tex))
        elif kind == "rings-unlit":
            mesh = g.mesh(name, box(h, h, h), g.material("rings-unlit", texture=rings_tex, unlit=True))
        elif kind == "red-no-normals":
            # No NORMAL attribute: the loader must generate flat normals.
            mesh = g.mesh(name, box(h, h, h), g.material("red", color=(0.8, 0.1, 0.08, 1.0)), normals=False)
        elif kind == "vertex-colours":
            geometry = box(h, h, h)
            colors = [[(p[0] / h + 1) / 2, (p[1] / h + 1) / 2, (p[2] / h + 1) / 2, 1.0] for p in geometry[0]]
            mesh = g.mesh(name, geometry, g.material("vertex-colours"), colors=colors)
        else:
            mesh = g.mesh(name, box(h, h, h), g.material("bricks", texture=bricks_tex))
        g.node(name, mesh, translation=(x, h, z))
    # A slim unlit column behind the first box, for a strongly out-of-focus foreground edge.
    column = g.mesh("column", box(0.025, 0.45, 0.025), g.material("column-unlit", color=(0.95, 0.85, 0.2, 1), unlit=True))
    g.node("column-1.5m", column, translation=(0.62, 0.45, eye[2] - 1.5))

    camera = {"eye": eye, "target": [0.0, 0.55, -2.0], "up": [0, 1, 0], "focal_length_mm": 35,
              "sensor_mm": [36, 24], "focus_distance": 4.0, "near": 0.05, "far": "infinity"}
    g.camera_from(camera)
    g.write(camera)
    write_camera("rows", "camera-dof.json", dict(camera, f_number=1.4, focus_distance=2.0))
    # Every lens effect at once (issue 5): OpenCV-style barrel with tangential terms, lateral and
    # axial colour, and a focal surface that curves toward the lens at the corners.
    write_camera("rows", "camera-lens.json", dict(
        camera, f_number=2.8, focus_distance=2.0,
        distortion={"k1": -0.15, "k2": 0.03, "p1": 0.001, "p2": -0.0005},
        chromatic={"lateral_red": 0.004, "lateral_blue": -0.004, "focus_distance_red": 2.2, "focus_distance_blue": 1.85},
        field_curvature={"corner_focus_distance": 1.6}))
    # Camera paths for headless capture (issue 14; src/io/CameraPathJson.h). A rack focus at f/1.4:
    # held on the nearest box (2 m), pulled to the 16 m box over two seconds, held there.
    lens = dict(camera, f_number=1.4)
    write_camera("rows", "rack-focus.json", {"fps": 24, "interpolation": "smooth", "keys": [
        dict(lens, time=0.0, focus_distance=2.0), dict(lens, time=0.5, focus_distance=2.0),
        dict(lens, time=2.5, focus_distance=16.0), dict(lens, time=3.0, focus_distance=16.0)]})
    # A dolly zoom: the camera backs away from the 4 m box while the focal length grows with the
    # distance (f/d constant, 8.75 mm per metre), so the box keeps its size and the background
    # swells behind it — the lecture's field of view made visible. Eye and target at the box's
    # height; linear, so that f/d stays exact between keys; focus on the box at each key.
    subject = [0.0, 0.55, eye[2] - 4.0]
    write_camera("rows", "dolly-zoom.json", {"fps": 24, "interpolation": "linear", "keys": [
        dict(camera, time=float(k), eye=[0.0, 0.55, subject[2] + d], target=subject, focal_length_mm=8.75 * d,
             focus_distance=float(d), f_number=2.8)
        for k, d in enumerate([4, 5, 6, 7, 8])]})


def write_camera(scene, name, camera):
    with open(os.path.join(ROOT, scene, name), "w") as f:
        json.dump(camera, f, indent=2)
        f.write("\n")


def make_occluder():
    g = Gltf("occluder")
    wall_tex = g.texture("wall-checker", 256, 256, image(256, 256, checker(16, (250, 250, 250), (15, 15, 15))),
                         wrap=CLAMP_TO_EDGE, mipmaps=True)
    wall = g.mesh("wall", quad(4.0, 3.0), g.material("wall", texture=wall_tex, unlit=True))
    g.node("wall-4m", wall, translation=(0.0, 1.0, -4.0))
    # Fence: bars 1.5 cm wide, 12 cm apart, 1 m from the camera.
    bar_geometry = merge([(box(0.0075, 0.8, 0.0075), (x * 0.12, 0.0, 0.0)) for x in range(-5, 6)])
    fence = g.mesh("fence", bar_geometry, g.material("fence", color=(0.9, 0.45, 0.1, 1.0), unlit=True))
    g.node("fence-1m", fence, translation=(0.0, 1.0, -1.0))
    camera = {"eye": [0.0, 1.0, 0.0], "target": [0.0, 1.0, -4.0], "up": [0, 1, 0], "focal_length_mm": 50,
              "sensor_mm": [36, 24], "focus_distance": 4.0, "near": 0.05, "far": "infinity"}
    g.camera_from(camera)
    g.write(camera)
    write_camera("occluder", "camera-dof.json", dict(camera, f_number=2.0))


def make_grid():
    g = Gltf("grid")
    plane = g.mesh("plane", quad(8.0, 6.0), g.material("plane", color=(0.04, 0.04, 0.05, 1.0), unlit=True))
    g.node("plane", plane)
    # 21 × 15 dots, 0.25 m apart, 1 mm in front of the plane; the view plane runs through them.
    dots = merge([(disc(0.04), (0.25 * i, 0.25 * j, 0.0)) for j in range(-7, 8) for i in range(-10, 11)])
    g.node("dots", g.mesh("dots", dots, g.material("dots", color=(1, 1, 1, 1), unlit=True)),
           translation=(0.0, 0.0, 0.001))
    camera = {"projection": "perspective", "vrp": [0.0, 0.0, 0.001], "vpn": [0, 0, 1], "vup": [0, 1, 0],
              "prp": [0.0, 0.0, 3.0], "window": [-2.1, -1.4, 2.1, 1.4], "near": 0.1, "far": 100.0}
    g.camera_from_lecture(camera)
    g.write(camera)
    # The same view as an OpenCV calibration gives it (pixels, principal point slightly off centre,
    # barrel with tangential terms), for the distortion tests and the README.
    write_camera("grid", "camera-distortion.json", {
        "eye": [0.0, 0.0, 3.001], "target": [0.0, 0.0, 0.001], "up": [0, 1, 0], "near": 0.1, "far": 100.0,
        "intrinsics": {"fx": 686.0, "fy": 686.0, "cx": 482.5, "cy": 317.5, "width": 960, "height": 640},
        "distortion": [-0.22, 0.05, 0.002, -0.001]})
    # The same lens with chromatic aberration and an aperture: colour fringes growing toward the
    # corners (lateral) and coloured halos around every dot (axial: red focused behind the dots,
    # blue in front of them). For the README.
    write_camera("grid", "camera-lens.json", {
        "eye": [0.0, 0.0, 3.001], "target": [0.0, 0.0, 0.001], "up": [0, 1, 0], "near": 0.1, "far": 100.0,
        "intrinsics": {"fx": 686.0, "fy": 686.0, "cx": 482.5, "cy": 317.5, "width": 960, "height": 640},
        "aperture_radius": 0.08,
        "distortion": [-0.22, 0.05, 0.002, -0.001],
        "chromatic": {"lateral_red": 0.006, "lateral_blue": -0.006, "focus_distance_red": 3.3, "focus_distance_blue": 2.75}})


def make_depth_range():
    g = Gltf("depth-range")
    cube = box(1.0, 1.0, 1.0)
    colours = [(0.9, 0.2, 0.2), (0.9, 0.6, 0.1), (0.8, 0.9, 0.2), (0.3, 0.85, 0.3),
               (0.2, 0.8, 0.8), (0.25, 0.4, 0.95), (0.6, 0.3, 0.9), (0.9, 0.3, 0.7)]
    distances = [0.01, 0.1, 1.0, 10.0, 100.0, 1e3, 1e4, 1e5]
    for k, d in enumerate(distances):
        angle = math.radians(45.0 * k + 22.5)
        direction = normalize([0.28 * math.cos(angle), 0.22 * math.sin(angle), -1.0])
        mesh = g.mesh("cube-%g" % d, cube, g.material("cube-%g" % d, color=colours[k] + (1.0,)))
        g.node("cube-%gm" % d, mesh, translation=[d * c for c in direction], scale=[0.03 * d] * 3)
    # Two quads at 1 km, 1 cm (1e-5 relative) apart: the nearer, smaller red one must win.
    near_quad = g.mesh("near-quad", quad(120.0, 120.0), g.material("near-quad", color=(0.9, 0.1, 0.1, 1), unlit=True))
    far_quad = g.mesh("far-quad", quad(240.0, 240.0), g.material("far-quad", color=(0.1, 0.8, 0.2, 1), unlit=True))
    g.node("far-quad", far_quad, translation=(0.0, 0.0, -1000.0 * (1.0 + 1e-5)))
    g.node("near-quad", near_quad, translation=(0.0, 0.0, -1000.0))
    camera = {"eye": [0.0, 0.0, 0.0], "target": [0.0, 0.0, -1.0], "up": [0, 1, 0], "focal_length_mm": 35,
              "sensor_mm": [36, 24], "focus_distance": 1.0, "near": 0.001, "far": "infinity"}
    g.camera_from(camera)
    g.write(camera)


def make_bokeh():
    """An in-focus subject at 2 m and small bright lamps (emissive, radiance 8 to 40) from 5 to 30 m
    behind it: out of focus, each lamp takes the aperture's shape."""
    g = Gltf("bokeh")
    floor_tex = g.texture("floor-checker", 256, 256, image(256, 256, checker(32, (120, 120, 120), (25, 25, 25))))
    g.node("floor", g.mesh("floor", floor(80.0, 40.0), g.material("floor", texture=floor_tex, roughness=0.6)),
           translation=(0.0, 0.0, -30.0))
    subject_tex = g.texture("subject-stripes", 128, 128, image(128, 128, stripes))
    # The subject uses every map lenslab reads: base colour, metallic-roughness, a normal map, an
    # occlusion map through TEXCOORD_1, and a KHR_texture_transform (the stripes turned by 90°).
    normal_tex = g.texture("subject-normal", 128, 128, image(128, 128, tiles_normal))
    occlusion_tex = g.texture("subject-occlusion", 128, 128, image(128, 128, tiles_occlusion))
    mr_tex = g.texture("subject-metal-rough", 128, 128, image(128, 128, tiles_metal_rough))
    subject = g.material("subject", texture=subject_tex, metallic=1.0, roughness=1.0, mr_texture=mr_tex,
                         normal_texture=normal_tex, occlusion_texture=occlusion_tex, occlusion_texcoord=1,
                         transforms={"baseColorTexture": {"rotation": math.pi / 2, "offset": [0.0, 1.0]}})
    g.node("subject-2m", g.mesh("subject", box(0.12, 0.12, 0.12), subject, uv1=True), translation=(-0.3, 0.12, -2.0))
    # Three spheres beside it: gold (polished metal), a glossy white dielectric, a rough blue one.
    for k, (name, color, metallic, roughness) in enumerate([
            ("gold", (1.0, 0.77, 0.34, 1.0), 1.0, 0.25), ("white-gloss", (0.85, 0.85, 0.85, 1.0), 0.0, 0.15),
            ("blue-rough", (0.1, 0.25, 0.7, 1.0), 0.0, 0.7)]):
        g.node("sphere-" + name, g.mesh("sphere-" + name, sphere(0.07), g.material(name, color=color, metallic=metallic,
                                                                                  roughness=roughness)),
               translation=(-0.05 + 0.17 * k, 0.07, -2.0 + 0.05 * k))
    # A spot light above and to the right of the subject (candela), and a low sun over the floor (lux).
    spot = g.light("key-spot", "spot", color=(1.0, 0.95, 0.88), intensity=12.0, inner=0.2, outer=0.45)
    # The spot at (0.6, 1.2, -1.2) looks along its node's -Z, turned to face the subject at (0, 0.1, -2):
    # a rotation taking -Z to that direction (quaternion built from the shortest arc).
    aim = normalize(sub([0.0, 0.1, -2.0], [0.6, 1.2, -1.2]))
    axis = cross([0.0, 0.0, -1.0], aim)
    half = math.acos(max(-1.0, min(1.0, -aim[2]))) / 2
    axis = normalize(axis)
    g.node("key-spot", light=spot, translation=(0.6, 1.2, -1.2),
           rotation=[axis[0] * math.sin(half), axis[1] * math.sin(half), axis[2] * math.sin(half), math.cos(half)])
    sun = g.light("sun", "directional", color=(1.0, 0.97, 0.92), intensity=2.0)
    g.node("sun", light=sun, rotation=[-0.3826834, 0.0, 0.0, 0.9238795])  # tilted 45° down, towards -Z
    warm = g.material("lamp-warm", color=(0, 0, 0, 1), unlit=True, emissive=(1.0, 0.62, 0.3), strength=6.0)
    cool = g.material("lamp-cool", color=(0, 0, 0, 1), unlit=True, emissive=(0.45, 0.65, 1.0), strength=6.0)
    warm_lamps, cool_lamps = [], []
    # A deterministic scatter (no random module: the same bytes every run); each lamp 4 mm across
    # per metre of distance, so that all look alike in focus.
    for k in range(36):
        depth = 5.0 + 25.0 * ((k * 0.61803398875) % 1.0)
        x = 0.18 * depth * (((k * 0.7548776662) % 1.0) * 2.0 - 1.0)
        y = 0.2 + 0.12 * depth * ((k * 0.5698402910) % 1.0)
        (warm_lamps if k % 3 else cool_lamps).append((disc(0.004 * depth, sides=12), (x, y, -depth)))
    g.node("lamps-warm", g.mesh("lamps-warm", merge(warm_lamps), warm))
    g.node("lamps-cool", g.mesh("lamps-cool", merge(cool_lamps), cool))
    camera = {"eye": [0.0, 0.45, 0.0], "target": [0.0, 0.25, -2.0], "up": [0, 1, 0], "focal_length_mm": 50,
              "sensor_mm": [36, 24], "f_number": 1.4, "focus_distance": 2.0, "near": 0.05, "far": "infinity"}
    g.camera_from(camera)
    g.write(camera)
    write_camera("bokeh", "camera-blades.json", dict(camera, aperture={"blades": 6, "rotation_deg": 15.0}))
    write_camera("bokeh", "camera-anamorphic.json", dict(camera, aperture={"anamorphic_squeeze": 2.0}))
    write_camera("bokeh", "camera-cats-eye.json", dict(camera, barrel={"distance_mm": 60.0, "diameter_mm": 40.0}))


def main():
    make_rows()
    make_occluder()
    make_grid()
    make_depth_range()
    make_bokeh()
    with open(os.path.join(ROOT, "README.md"), "w") as f:
        f.write(__doc__.split("\n\n", 1)[0] + "\n\n" + README)


README = """Regenerate with `python3 tools/make_assets.py`; check with `bash tools/validate-assets.sh`
(the Khronos glTF validator, from npm). Everything here is generated by that script and is CC0,
except `report/` (outputs of `lenslab sweep` and renders shown in the top-level README) and
`screenshots/` (the interactive demo's window, taken under Xvfb).

| scene | what it is for | camera |
|---|---|---|
| `rows` | the default scene and depth-of-field showcase: boxes at 2, 4, 8, 16, 32 m over a 60 m checker floor; textured, plain, unlit, vertex-coloured, one without normals; a thin column at 1.5 m | physical, 35 mm, focus 4 m |
| `occluder` | partial obscuration: eleven 1.5 cm bars, 12 cm apart, 1 m away, before a 4 × 3 m checker wall at 4 m | physical, 50 mm, focus 4 m |
| `grid` | distortion: 21 × 15 dots (octagons of radius 4 cm, 0.25 m apart) in the plane z = 0.001, on a dark 8 × 6 m plane | lecture form, view plane on the dots, PRP 3 m in front |
| `depth-range` | depth precision: cubes at 0.01, 0.1, 1, 10, 100, 1e3, 1e4 and 1e5 m, each 6 % of its distance wide; a red 120 m quad at 1 km in front of a green 240 m quad 1 cm farther | physical, near 0.001, far infinity |
| `bokeh` | out-of-focus highlights and materials: at 2 m a tiled box with every map (base colour through a texture transform, metallic-roughness, normal, occlusion on TEXCOORD_1) and gold, glossy white and rough blue spheres, lit by a spot light and a low sun (KHR_lights_punctual), over a checker floor; 36 small lamps (emissive, strength 6) from 5 to 30 m behind them | physical, 50 mm f/1.4, focus 2 m; `camera-blades.json` (6 blades), `camera-anamorphic.json` (2x squeeze), `camera-cats-eye.json` (a lens barrel) |

`rows/camera-dof.json` (f/1.4, focused on the nearest box at 2 m) and `occluder/camera-dof.json` (f/2) are the same cameras with an
aperture: the depth-of-field showcase and the partial-obscuration case. Lens effects:
`grid/camera-distortion.json` is the grid's view as an OpenCV calibration gives it (intrinsics in
pixels, distortion `[-0.22, 0.05, 0.002, -0.001]`), `grid/camera-lens.json` the same lens with an
aperture and lateral and axial colour, and `rows/camera-lens.json` the rows camera at f/2.8 with
every effect (distortion, lateral and axial colour, field curvature).

Camera paths (for headless capture, `src/io/CameraPathJson.h`): `rows/rack-focus.json` pulls focus
at f/1.4 from the nearest box (2 m) to the 16 m box over two seconds; `rows/dolly-zoom.json` backs
away from the 4 m box from 4 to 8 m while the focal length grows from 35 to 70 mm, so the box keeps
its size while the background swells.

Each `<scene>.gltf` also holds a glTF perspective camera node matching its `camera.json` (same eye,
direction, field of view, 3:2 aspect, near and far; for `grid` the eye is the PRP, 3.001 m from the
plane), so `lenslab render <scene>.gltf` without `--camera` sees the same view.
"""

if __name__ == "__main__":
    main()
