#!/usr/bin/python3
"""A contact sheet of a capture: evenly spaced frames from its manifest, each labelled with its
frame number, time and lens, in a grid (Pillow; Debian's python3-pil).

usage: tools/contact_sheet.py MANIFEST.jsonl OUT.png [--count 8] [--columns 4] [--gif OUT.gif (240 px wide)]
The manifest's "file" entries are read relative to the manifest's folder (PNG frames)."""
import argparse
import json
import os

from PIL import Image, ImageDraw, ImageFont


def label(line):
    focus = line["focus_distance"]
    focus = "∞" if focus == "infinity" else f"{focus:.2f} m"
    n = line["f_number"]
    stop = "pinhole" if n == "infinity" else f"f/{n:.1f}"
    return f'{line["frame"]:>3}  {line["time"]:.2f} s   {line["focal_length_mm"]:.0f} mm  {stop}  focus {focus}'


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("manifest")
    parser.add_argument("out")
    parser.add_argument("--count", type=int, default=8)
    parser.add_argument("--columns", type=int, default=4)
    parser.add_argument("--gif", help="also every frame as an animated GIF")
    args = parser.parse_args()

    folder = os.path.dirname(os.path.abspath(args.manifest))
    lines = sorted((json.loads(l) for l in open(args.manifest) if l.strip()), key=lambda l: l["frame"])
    if not lines:
        raise SystemExit(f"{args.manifest}: no frames")
    count = min(args.count, len(lines))
    picked = [lines[round(i * (len(lines) - 1) / max(count - 1, 1))] for i in range(count)]
    frames = [Image.open(os.path.join(folder, l["file"])).convert("RGB") for l in picked]
    w, h = frames[0].size
    font = ImageFont.truetype("/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf", max(10, w // 28))
    band = font.size + 8
    rows = (count + args.columns - 1) // args.columns
    sheet = Image.new("RGB", (args.columns * w, rows * (h + band)), (20, 20, 20))
    draw = ImageDraw.Draw(sheet)
    for i, (frame, line) in enumerate(zip(frames, picked)):
        x, y = (i % args.columns) * w, (i // args.columns) * (h + band)
        sheet.paste(frame, (x, y))
        draw.text((x + 4, y + h + 4), label(line), fill=(230, 230, 230), font=font)
    sheet.save(args.out, optimize=True)
    if args.gif:
        # Small enough for a README: 240 px wide, one shared palette, no dithering (which would flicker).
        every = []
        for l in lines:
            f = Image.open(os.path.join(folder, l["file"])).convert("RGB")
            every.append(f.resize((240, round(240 * f.height / f.width)), Image.Resampling.LANCZOS))
        fps = 1.0 / (lines[1]["time"] - lines[0]["time"]) if len(lines) > 1 else 24.0
        palette = every[len(every) // 2].quantize(colors=96)
        quantized = [f.quantize(palette=palette, dither=Image.Dither.NONE) for f in every]
        quantized[0].save(args.gif, save_all=True, append_images=quantized[1:], duration=round(1000 / fps), loop=0,
                          optimize=True)


if __name__ == "__main__":
    main()
