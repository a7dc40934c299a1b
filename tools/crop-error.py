#!/usr/bin/env python3
"""RMS difference of images from a reference over one crop, relative to the reference's peak there.

The measure docs/depth-of-field.md gives for an isolated defocused lamp of the bokeh scene: where
plain accumulation draws a cluster of copies and the reference a filled disc, the difference shows
as a share of the lamp's brightness. Green channel; needs oiiotool (OpenImageIO's tools).

usage: tools/crop-error.py REFERENCE.exr WIDTHxHEIGHT+X+Y IMAGE.exr [IMAGE.exr ...]
e.g.   tools/crop-error.py ref.exr 60x40+100+105 plain-16.exr filtered-16.exr
"""
import re
import subprocess
import sys
import tempfile


def crop(path, box, scratch):
    subprocess.run(["oiiotool", path, "--ch", "G", "--cut", box, "-o", scratch], check=True)
    dump = subprocess.run(["oiiotool", "--dumpdata", scratch], check=True, capture_output=True, text=True).stdout
    return [float(m.group(1)) for m in re.finditer(r"Pixel \(\d+, \d+\): ([-0-9.e+]+)", dump)]


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    reference, box, images = sys.argv[1], sys.argv[2], sys.argv[3:]
    with tempfile.NamedTemporaryFile(suffix=".exr") as scratch:
        ref = crop(reference, box, scratch.name)
        peak = max(ref)
        for path in images:
            img = crop(path, box, scratch.name)
            if len(img) != len(ref):
                sys.exit(f"{path}: the crop {box} has {len(img)} pixels, the reference's {len(ref)}")
            rms = (sum((a - b) ** 2 for a, b in zip(img, ref)) / len(ref)) ** 0.5
            print(f"{path}: {100.0 * rms / peak:.2f} % of the reference's peak {peak:.3f} in {box}")


if __name__ == "__main__":
    main()
