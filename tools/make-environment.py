#!/usr/bin/env python3
"""Writes assets/environments/studio.hdr: a photographic studio as an equirectangular environment.

Three soft boxes (rectangles of uniform radiance, far brighter than 1, with soft edges) over a
dim grey gradient: a large key light front left, a fill light to the right and a strip light high
behind. Linear radiance, Radiance RGBE with run-length encoded scanlines, plain Python (no numpy).

Convention (docs/environment.md): u = 0.5 is the direction -Z, u grows towards +X (u = 0.75);
v = 0, the top row, is +Y. Azimuth below is measured from -Z towards +X, elevation from the horizon.

    python3 tools/make-environment.py [--width 1024] [--out assets/environments/studio.hdr]
"""
import argparse
import math
import os
import struct


# (name, azimuth centre, elevation centre, width, height in degrees, linear RGB radiance)
SOFT_BOXES = [
    ("key", -40.0, 30.0, 44.0, 30.0, (48.0, 46.0, 42.0)),
    ("fill", 75.0, 15.0, 30.0, 34.0, (10.0, 11.0, 12.5)),
    ("strip", 180.0, 50.0, 70.0, 9.0, (30.0, 30.0, 30.0)),
]
EDGE_DEG = 2.5  # soft edge: radiance ramps over this many degrees


def smoothstep(e0, e1, x):
    t = min(max((x - e0) / (e1 - e0), 0.0), 1.0)
    return t * t * (3.0 - 2.0 * t)


def radiance(azimuth, elevation):
    # The dim room: a warm ceiling, a darker horizon, a dark floor.
    if elevation >= 0.0:
        s = elevation / 90.0
        c = [0.06 + 0.10 * s, 0.06 + 0.09 * s, 0.065 + 0.08 * s]
    else:
        s = -elevation / 90.0
        c = [0.05 - 0.03 * s, 0.05 - 0.03 * s, 0.055 - 0.03 * s]
    for _, az0, el0, w, h, rgb in SOFT_BOXES:
        daz = (azimuth - az0 + 180.0) % 360.0 - 180.0
        # Boxes keep their angular width across the sky by scaling azimuth with cos(elevation).
        dx = abs(daz) * math.cos(math.radians(elevation))
        dy = abs(elevation - el0)
        k = (1.0 - smoothstep(w / 2 - EDGE_DEG, w / 2, dx)) * (1.0 - smoothstep(h / 2 - EDGE_DEG, h / 2, dy))
        for i in range(3):
            c[i] += k * rgb[i]
    return c


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return (0, 0, 0, 0)
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return (int(r * scale), int(g * scale), int(b * scale), exponent + 128)


def rle(channel):
    """One channel of a scanline in Radiance's run-length encoding."""
    out = bytearray()
    i, n = 0, len(channel)
    while i < n:
        # A run of at least 3 equal bytes?
        j = i
        while j < n and j - i < 127 and channel[j] == channel[i]:
            j += 1
        if j - i >= 3:
            out += bytes((128 + (j - i), channel[i]))
            i = j
            continue
        # Literals up to the next run of 3 or 128 bytes.
        j = i
        while j < n and j - i < 128:
            if j + 2 < n and channel[j] == channel[j + 1] == channel[j + 2]:
                break
            j += 1
        out += bytes((j - i,)) + bytes(channel[i:j])
        i = j
    return bytes(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--width", type=int, default=1024)
    parser.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "assets", "environments", "studio.hdr"))
    args = parser.parse_args()
    width, height = args.width, args.width // 2
    body = bytearray()
    for y in range(height):
        elevation = 90.0 - (y + 0.5) / height * 180.0
        pixels = [rgbe(*radiance((x + 0.5) / width * 360.0 - 180.0, elevation)) for x in range(width)]
        body += bytes((2, 2, width >> 8, width & 255))
        for k in range(4):
            body += rle(bytes(p[k] for p in pixels))
    header = (
        "#?RADIANCE\n# lenslab studio environment (tools/make-environment.py), linear radiance\n"
        "FORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width)
    ).encode()
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    tmp = args.out + ".tmp"
    with open(tmp, "wb") as f:
        f.write(header + bytes(body))
    os.replace(tmp, args.out)
    print("wrote %s (%d x %d, %d bytes)" % (args.out, width, height, len(header) + len(body)))


if __name__ == "__main__":
    main()
