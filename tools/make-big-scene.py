#!/usr/bin/python3
"""Writes a big glTF scene for benchmarks: a tessellated floor and a field of spheres at many
depths, about 1.1 M triangles by default, and a camera JSON beside it (the format of
assets/rows/camera-dof.json) focused on the middle rows, so that depth of field matters.

    tools/make-big-scene.py OUT_DIR [--triangles N]

writes OUT_DIR/big.gltf, OUT_DIR/big.bin and OUT_DIR/camera-dof.json. Python 3 standard library
only. Generated, not committed: the binary is tens of megabytes (write it to build/ or a temp folder).
"""
import argparse
import json
import math
import os
import struct
import sys
from array import array

FLOAT, UNSIGNED_INT = 5126, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963

SPHERE_SEGMENTS = 96   # around; rings are half as many: 2·96·47 = 9024 triangles a sphere
FLOOR_CELLS = 200      # per side: 80 000 triangles
FLOOR_HALF_M = 20.0


def sphere(segments):
    """Unit UV sphere: positions, normals (the same), uvs, indices (counter-clockwise outside)."""
    rings = segments // 2
    pos, uv, idx = array("f"), array("f"), array("I")
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2.0 * math.pi * s / segments
            pos.extend((math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)))
            uv.extend((s / segments, r / rings))
    row = segments + 1
    for r in range(rings):
        for s in range(segments):
            a, b = r * row + s, (r + 1) * row + s
            if r != 0:
                idx.extend((a, b, a + 1))
            if r != rings - 1:
                idx.extend((a + 1, b, b + 1))
    return pos, array("f", pos), uv, idx


def floor(cells, half):
    """Square in y = 0 facing up, cells × cells quads."""
    pos, nrm, uv, idx = array("f"), array("f"), array("f"), array("I")
    for j in range(cells + 1):
        for i in range(cells + 1):
            x, z = -half + 2 * half * i / cells, -half + 2 * half * j / cells
            pos.extend((x, 0.0, z))
            nrm.extend((0.0, 1.0, 0.0))
            uv.extend((i / 4.0, j / 4.0))
    row = cells + 1
    for j in range(cells):
        for i in range(cells):
            a, b = j * row + i, (j + 1) * row + i
            idx.extend((a, b, a + 1, a + 1, b, b + 1))
    return pos, nrm, uv, idx


class Writer:
    def __init__(self):
        self.blob = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "lenslab tools/make-big-scene.py"},
                    "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [],
                    "accessors": [], "bufferViews": [], "buffers": []}

    def _view(self, data, target):
        while len(self.blob) % 4:
            self.blob.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data), "target": target})
        self.blob += data
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, values, kind, components, bounds=False):
        acc = {"bufferView": self._view(values.tobytes(), ARRAY_BUFFER), "componentType": FLOAT,
               "count": len(values) // components, "type": kind}
        if bounds:
            acc["min"] = [min(values[c::components]) for c in range(components)]
            acc["max"] = [max(values[c::components]) for c in range(components)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def mesh(self, name, geometry, material):
        pos, nrm, uv, idx = geometry
        attributes = {"POSITION": self._accessor(pos, "VEC3", 3, bounds=True), "NORMAL": self._accessor(nrm, "VEC3", 3),
                      "TEXCOORD_0": self._accessor(uv, "VEC2", 2)}
        self.doc["accessors"].append({"bufferView": self._view(idx.tobytes(), ELEMENT_ARRAY_BUFFER),
                                      "componentType": UNSIGNED_INT, "count": len(idx), "type": "SCALAR"})
        self.doc["meshes"].append({"name": name, "primitives": [
            {"attributes": attributes, "indices": len(self.doc["accessors"]) - 1, "material": material}]})
        return len(self.doc["meshes"]) - 1

    def material(self, name, colour):
        self.doc["materials"].append({"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": list(colour) + [1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}})
        return len(self.doc["materials"]) - 1

    def node(self, name, mesh, translation, scale):
        self.doc["nodes"].append({"name": name, "mesh": mesh, "translation": list(translation), "scale": [scale] * 3})
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def write(self, folder, name):
        if sys.byteorder != "little":
            raise SystemExit("make-big-scene.py: glTF buffers are little-endian; this machine is not")
        self.doc["buffers"].append({"byteLength": len(self.blob), "uri": name + ".bin"})
        with open(os.path.join(folder, name + ".bin"), "wb") as f:
            f.write(self.blob)
        with open(os.path.join(folder, name + ".gltf"), "w") as f:
            json.dump(self.doc, f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out_dir")
    parser.add_argument("--triangles", type=int, default=1_100_000,
                        help="at least this many triangles in all (default 1100000; from 100000)")
    args = parser.parse_args()
    if args.triangles < 100_000:
        raise SystemExit(f"make-big-scene.py: --triangles {args.triangles} is below 100000 (the floor alone has 80000)")
    os.makedirs(args.out_dir, exist_ok=True)

    w = Writer()
    floor_geometry = floor(FLOOR_CELLS, FLOOR_HALF_M)
    sphere_geometry = sphere(SPHERE_SEGMENTS)
    floor_triangles, sphere_triangles = len(floor_geometry[3]) // 3, len(sphere_geometry[3]) // 3
    palette = [(0.8, 0.1, 0.08), (0.1, 0.5, 0.8), (0.9, 0.75, 0.2), (0.2, 0.7, 0.3), (0.85, 0.85, 0.85)]
    materials = [w.material(f"colour{i}", c) for i, c in enumerate(palette)]
    w.node("floor", w.mesh("floor", floor_geometry, w.material("floor", (0.6, 0.6, 0.6))), (0, 0, 0), 1.0)
    spheres = [w.mesh(f"sphere{i}", sphere_geometry, m) for i, m in enumerate(materials)]

    # Rows of spheres from 1 m to 30 m in front of the camera (which looks down −z from z = 3),
    # each row wider than the last, so the frame holds them from near to far.
    count = max(1, -(-(args.triangles - floor_triangles) // sphere_triangles))
    per_row = max(4, int(math.sqrt(count)))
    placed = 0
    row = 0
    while placed < count:
        depth_m = 1.0 + 29.0 * (row / max(1, count // per_row)) ** 1.5
        radius = 0.08 + 0.03 * depth_m
        width = 0.8 * depth_m + 1.0
        for i in range(per_row):
            if placed == count:
                break
            x = -width / 2 + width * (i + 0.5) / per_row + 0.3 * radius * ((row % 2) - 0.5)
            w.node(f"sphere{placed}", spheres[(i + row) % len(spheres)], (x, radius, 3.0 - depth_m), radius)
            placed += 1
        row += 1
    w.write(args.out_dir, "big")
    camera = {"eye": [0.0, 1.0, 3.0], "target": [0.0, 0.4, -2.0], "up": [0, 1, 0], "focal_length_mm": 35,
              "sensor_mm": [36, 24], "focus_distance": 4.0, "near": 0.05, "far": "infinity", "f_number": 1.4}
    with open(os.path.join(args.out_dir, "camera-dof.json"), "w") as f:
        json.dump(camera, f, indent=2)
    print(f"{os.path.join(args.out_dir, 'big.gltf')}: {floor_triangles + placed * sphere_triangles} triangles "
          f"({placed} spheres of {sphere_triangles}, floor {floor_triangles})")


if __name__ == "__main__":
    main()
