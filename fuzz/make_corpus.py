#!/usr/bin/env python3
"""Writes the fuzz seed corpus (fuzz/corpus/gltf, fuzz/corpus/camera) from lenslab's own assets
plus a few hand-made edge cases. Run from anywhere:  python3 fuzz/make_corpus.py
Every file it writes is committed; rerun it when the assets change (it first empties the two
folders). Seeds are self-contained, as the fuzz targets load them from an empty scratch folder:
the .gltf seeds carry their buffers and images as data: URIs, the .glb seeds in the BIN chunk.
The grid scene is left out: its 106 KB buffer would make it the largest seed by far, and libFuzzer
mutates inputs up to the largest seed's size (the other scenes cover what it holds)."""
import base64
import json
import pathlib
import shutil
import struct
import zlib

ROOT = pathlib.Path(__file__).resolve().parent.parent
ASSETS = ROOT / "assets"
OUT = ROOT / "fuzz" / "corpus"


def data_uri(data, mime="application/octet-stream"):
    return f"data:{mime};base64," + base64.b64encode(data).decode()


def glb(gltf, bin_bytes, extra_chunks=()):
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    chunks = [(0x4E4F534A, text)]
    if bin_bytes:
        chunks.append((0x004E4942, bin_bytes + b"\0" * (-len(bin_bytes) % 4)))
    chunks += list(extra_chunks)
    body = b"".join(struct.pack("<II", len(d), t) + d for t, d in chunks)
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


def asset_scene(name):
    """The asset's JSON with its images moved into the buffer (bufferViews), and the buffer bytes."""
    folder = ASSETS / name
    gltf = json.loads((folder / f"{name}.gltf").read_text())
    buffer = bytearray((folder / gltf["buffers"][0]["uri"]).read_bytes())
    for image in gltf.get("images", []):
        png = (folder / image.pop("uri")).read_bytes()
        buffer += b"\0" * (-len(buffer) % 4)
        gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(buffer), "byteLength": len(png)})
        buffer += png
        image["bufferView"] = len(gltf["bufferViews"]) - 1
        image["mimeType"] = "image/png"
    gltf["buffers"] = [{"byteLength": len(buffer)}]
    return gltf, bytes(buffer)


def with_data_uri(gltf, buffer):
    g = json.loads(json.dumps(gltf))
    g["buffers"] = [{"byteLength": len(buffer), "uri": data_uri(buffer)}]
    return g


def png(width, height, bit_depth=8, colour_type=6):
    """A tiny PNG (filter 0 rows of a gradient)."""
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour_type]
    row_bytes = width * channels * bit_depth // 8
    raw = b"".join(b"\0" + bytes((x * 37 + y * 11) & 0xFF for x in range(row_bytes)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def square_bin():
    """Four positions of a unit square, six uint16 indices, four UVs."""
    positions = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0)
    indices = struct.pack("<6H", 0, 1, 2, 0, 2, 3) + b"\0" * 4  # to offset 64
    uvs = struct.pack("<8f", 0, 1, 1, 1, 1, 0, 0, 0)
    return positions, indices, uvs


def square_gltf(extra_images=None):
    positions, indices, uvs = square_bin()
    buffer = positions + indices + uvs
    gltf = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -2, 1]},
                  {"camera": 0, "translation": [0, 0, 3], "rotation": [0, 0, 0, 1], "scale": [1, 1, 1],
                   "children": [2]},
                  {"camera": 1, "name": "ortho"}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "aspectRatio": 1.5}},
                    {"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0, "zfar": 10}}],
        "meshes": [{"name": "square", "primitives": [
            {"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "indices": 1, "material": 0, "mode": 4}]}],
        "materials": [{"name": "unlit", "extensions": {"KHR_materials_unlit": {}}, "doubleSided": True,
                       "alphaMode": "MASK", "alphaCutoff": 0.5,
                       "pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 1], "baseColorTexture": {"index": 0}}}],
        "textures": [{"sampler": 0, "source": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9987, "wrapS": 33648, "wrapT": 33071}],
        "extensionsUsed": ["KHR_materials_unlit"],
        "extensionsRequired": ["KHR_materials_unlit"],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48, "target": 34962},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 12, "target": 34963},
                        {"buffer": 0, "byteOffset": 64, "byteLength": 32}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
                      {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"}],
        "images": [{"uri": data_uri(png(4, 4), "image/png")}],
        "buffers": [{"byteLength": len(buffer), "uri": data_uri(buffer)}],
    }
    return gltf, buffer


def hand_made_gltf():
    seeds = {}
    g, buffer = square_gltf()
    seeds["square-textured.gltf"] = json.dumps(g).encode()
    # The same in a GLB, its image in a bufferView and an unknown chunk after BIN.
    img = png(2, 2, 16, 0)
    gb = json.loads(json.dumps(g))
    del gb["buffers"][0]["uri"]
    padded = buffer + b"\0" * (-len(buffer) % 4)
    gb["bufferViews"].append({"buffer": 0, "byteOffset": len(padded), "byteLength": len(img)})
    gb["images"] = [{"bufferView": 3, "mimeType": "image/png", "name": "grey16"}]
    gb["buffers"][0]["byteLength"] = len(padded) + len(img)
    seeds["square-grey16-unknown-chunk.glb"] = glb(gb, padded + img, [(0x12345678, b"xxxxxxxx")])
    # Strips and fans, non-indexed, with a sparse accessor and a COLOR_0.
    positions = struct.pack("<15f", 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 0, 0)
    colours = struct.pack("<20B", *([255, 0, 0, 255] * 5))
    sparse_idx = struct.pack("<2H", 1, 3)
    sparse_val = struct.pack("<6f", 1.5, 0, 0, 1.5, 1.5, 0)
    buf = positions + colours + sparse_idx + sparse_val
    strips = {
        "asset": {"version": "2.0"},
        "nodes": [{"mesh": 0}, {"mesh": 0, "translation": [3, 0, 0], "children": [2]}, {"mesh": 1}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}, "mode": 5},
                                   {"attributes": {"POSITION": 2}, "mode": 6}]},
                   {"primitives": [{"attributes": {"POSITION": 0}, "mode": 1}, {"attributes": {"POSITION": 0}, "mode": 0}]}],
        "bufferViews": [{"buffer": 0, "byteLength": 60}, {"buffer": 0, "byteOffset": 60, "byteLength": 20},
                        {"buffer": 0, "byteOffset": 80, "byteLength": 4}, {"buffer": 0, "byteOffset": 84, "byteLength": 24}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 5, "type": "VEC3", "min": [0, 0, 0], "max": [2, 1, 0]},
                      {"bufferView": 1, "componentType": 5121, "normalized": True, "count": 5, "type": "VEC4"},
                      {"componentType": 5126, "count": 5, "type": "VEC3", "min": [0, 0, 0], "max": [1.5, 1.5, 0],
                       "sparse": {"count": 2, "indices": {"bufferView": 2, "componentType": 5123},
                                  "values": {"bufferView": 3}}}],
        "buffers": [{"byteLength": len(buf), "uri": data_uri(buf)}],
    }
    seeds["strips-fans-sparse.gltf"] = json.dumps(strips).encode()
    # A scene with nothing drawn, and the smallest file that is not refused.
    seeds["empty-scene.gltf"] = b'{"asset":{"version":"2.0"},"scenes":[{"nodes":[]}],"scene":0}'
    seeds["minimal.gltf"] = b'{"asset":{"version":"2.0"}}'
    # Refused: a required extension, a GLB cut off, nesting.
    seeds["required-draco.gltf"] = (b'{"asset":{"version":"2.0"},"extensionsUsed":["KHR_draco_mesh_compression"],'
                                    b'"extensionsRequired":["KHR_draco_mesh_compression"]}')
    seeds["cut-off.glb"] = glb({"asset": {"version": "2.0"}}, b"")[:18]
    seeds["nested-extras.gltf"] = b'{"asset":{"version":"2.0","extras":{"a":[[[{"b":[1,2,{"c":null}]}]]]}}}'
    return seeds


def camera_seeds():
    seeds = {}
    for f in sorted(ASSETS.glob("*/camera*.json")):
        seeds[f"{f.parent.name}-{f.name}"] = f.read_bytes()
    hand = {
        "lecture-parallel.json": {"projection": "parallel", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0],
                                  "prp": [0.5, 0.25, 4], "window": [-2, -1, 2, 1], "near": -1, "far": 8},
        "lecture-oblique-aperture.json": {"vrp": [0, 0, -5], "vpn": [0, 0, 1], "prp": [1, 0, 5],
                                          "window": [-1, -1, 2, 1], "near": 0.1, "far": "infinity",
                                          "aperture_radius": 0.05, "image_size": [640, 480]},
        "lecture-focus-infinity.json": {"vrp": [0, 0, -5], "vpn": [0, 0, 1], "prp": [0, 0, 5],
                                        "window": [-1, -1, 1, 1], "focus_distance": "infinity",
                                        "distortion": {"alpha": 0.1, "beta": -0.02, "gamma": 0.001}},
        "physical-abbe.json": {"eye": [0, 1, 5], "target": [0, 1, 0], "up": [0, 1, 0], "focal_length_mm": 50,
                               "sensor_mm": [36, 24], "f_number": 1.4, "focus_distance": 5,
                               "near": 0.05, "far": 100, "chromatic": {"abbe_number": 55, "lateral_red": 0.001},
                               "distortion": [-0.1, 0.01, 0, 0, 0.001]},
        "intrinsics-curvature.json": {"eye": [0, 0, 3], "target": [0, 0, 0],
                                      "intrinsics": {"fx": 500, "fy": 510, "cx": 319.5, "cy": 239.5,
                                                     "width": 640, "height": 480},
                                      "focus_distance": 3, "aperture_radius": 0.01,
                                      "field_curvature": {"corner_focus_distance": 2.5}},
    }
    for name, obj in hand.items():
        seeds[name] = json.dumps(obj).encode()
    # Refused: mixed forms, vup parallel to vpn, not an object.
    seeds["mixed-forms.json"] = b'{"eye":[0,0,1],"target":[0,0,0],"vrp":[0,0,0]}'
    seeds["vup-parallel.json"] = b'{"vrp":[0,0,0],"vpn":[0,1,0],"vup":[0,2,0],"prp":[0,0,1],"window":[-1,-1,1,1]}'
    seeds["array.json"] = b"[1, 2.5e308, -0, \"\\u00e9\", true, null, {}]"
    return seeds


def write(folder, seeds):
    if folder.exists():
        shutil.rmtree(folder)
    folder.mkdir(parents=True)
    for name, data in sorted(seeds.items()):
        (folder / name).write_bytes(data)
    print(f"{folder.relative_to(ROOT)}: {len(seeds)} files, {sum(len(d) for d in seeds.values())} bytes")


def main():
    gltf_seeds = {}
    for name in ("rows", "occluder", "depth-range"):
        gltf, buffer = asset_scene(name)
        gltf_seeds[f"{name}.glb"] = glb(gltf, buffer)
        gltf_seeds[f"{name}.gltf"] = json.dumps(with_data_uri(gltf, buffer), separators=(",", ":")).encode()
    gltf_seeds.update(hand_made_gltf())
    write(OUT / "gltf", gltf_seeds)
    write(OUT / "camera", camera_seeds())


if __name__ == "__main__":
    main()
