#!/usr/bin/env python3
"""Error against the ray-cast reference of every aperture pattern at 8 … 256 views, on three
scenes, over several seeds: the table and the convergence slopes of docs/sampling.md.

    tools/sampling-sweep.py [--build build] [--out sampling-sweep] [--seeds 4] [--reference-spp 2048]

Per scene, `lenslab sweep` ray casts the reference (cached in OUT/SCENE/, two independent halves
whose difference gives the reference's own noise); every pattern, count and seed is then rendered
with `lenslab render` to .exr and compared with the halves' mean by `oiiotool --diff` over R, G, B
(what the sweep's own rows report). The reference's noise is independent of a frame's error, so
its mean square is subtracted from each frame's before the PSNR and the slope ("corrected").

Writes OUT/sampling.csv (one row per image) and OUT/sampling.md (the tables). Needs oiiotool.
Run again with --build OTHER --label NAME to compare another build against the same references.
"""
import argparse
import math
import os
import re
import subprocess
import sys

SCENES = [
    ("rows-dof", "assets/rows/rows.gltf", "assets/rows/camera-dof.json"),
    ("occluder-dof", "assets/occluder/occluder.gltf", "assets/occluder/camera-dof.json"),
    ("rows-lens", "assets/rows/rows.gltf", "assets/rows/camera-lens.json"),
]
PATTERNS = ["sobol", "concentric", "r2", "random"]
COUNTS = [8, 16, 32, 64, 128, 256]


def run(cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def rmse_of(image, reference):
    # oiiotool exits non-zero when the images differ at all; its report is what we want.
    p = subprocess.run(["oiiotool", image, "--ch", "R,G,B", reference, "--ch", "R,G,B", "--diff"],
                       capture_output=True, text=True)
    m = re.search(r"RMS error = ([0-9.eE+-]+)", p.stdout)
    if not m:
        sys.exit(f"oiiotool --diff {image} {reference}: no RMS error in its output:\n{p.stdout}{p.stderr}")
    return float(m.group(1))


def slope(counts, rmses):
    """Least squares of log RMSE on log N: −0.5 is independent samples' rate."""
    xs = [math.log(n) for n in counts]
    ys = [math.log(r) for r in rmses]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def psnr(mse):
    return -10.0 * math.log10(mse) if mse > 0 else float("inf")


def main():
    top = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=os.path.join(top, "build"))
    ap.add_argument("--out", default="sampling-sweep")
    ap.add_argument("--seeds", type=int, default=4, help="seeds 1..N per pattern and count")
    ap.add_argument("--reference-spp", type=int, default=2048)
    ap.add_argument("--width", type=int, default=512)
    ap.add_argument("--patterns", default=",".join(PATTERNS))
    ap.add_argument("--scenes", default=",".join(s[0] for s in SCENES))
    ap.add_argument("--label", default="", help="names the outputs sampling-LABEL.csv/.md (runs of other builds share the references)")
    a = ap.parse_args()
    lenslab = os.path.join(a.build, "lenslab")
    patterns = a.patterns.split(",")
    suffix = f"-{a.label}" if a.label else ""
    os.makedirs(a.out, exist_ok=True)
    rows = []  # (scene, pattern, count, seed, rmse)
    noise = {}
    for name, scene, camera in SCENES:
        if name not in a.scenes.split(","):
            continue
        folder = os.path.join(a.out, name)
        print(f"{name}: reference ({a.reference_spp} spp, cached in {folder})", flush=True)
        run([lenslab, "sweep", os.path.join(top, scene), "--camera", os.path.join(top, camera), "-o", folder,
             "--width", str(a.width), "--reference-spp", str(a.reference_spp), "--methods", "concentric",
             "--max-views", "1", "-q"])
        with open(os.path.join(folder, "sweep.md")) as f:
            noise[name] = float(re.search(r"its own noise, from its two halves: RMSE ([0-9.eE+-]+)", f.read()).group(1))
        halves = sorted(p for p in os.listdir(folder) if p.startswith("reference-") and p.endswith(".exr"))
        reference = os.path.join(folder, "reference-mean.exr")
        run(["oiiotool", os.path.join(folder, halves[0]), os.path.join(folder, halves[1]), "--add", "--mulc", "0.5",
             "-o", reference])
        frame = os.path.join(folder, f"frame{suffix}.exr")
        for pattern in patterns:
            for n in COUNTS:
                for seed in range(1, a.seeds + 1):
                    run([lenslab, "render", os.path.join(top, scene), "--camera", os.path.join(top, camera),
                         "--width", str(a.width), "--pattern", pattern, "--aperture-samples", str(n),
                         "--seed", str(seed), "-o", frame, "-q"])
                    rows.append((name, pattern, n, seed, rmse_of(frame, reference)))
            print(f"{name}: {pattern} done", flush=True)

    with open(os.path.join(a.out, f"sampling{suffix}.csv"), "w") as f:
        f.write("scene,pattern,views,seed,rmse\n")
        for r in rows:
            f.write(f"{r[0]},{r[1]},{r[2]},{r[3]},{r[4]:.7g}\n")

    out = [f"Width {a.width}, reference {a.reference_spp} spp, seeds 1–{a.seeds}. PSNR of the mean squared "
           "error over the seeds, less the reference's own noise; in brackets the seeds' range (uncorrected). "
           "Slope: least squares of log RMSE (corrected) on log N.\n"]
    for name in noise:
        out.append(f"\n### {name} (reference noise RMSE {noise[name]:.5f}: {psnr(noise[name] ** 2):.1f} dB)\n")
        out.append("| pattern | " + " | ".join(str(n) for n in COUNTS) + " | slope |")
        out.append("|---|" + "---|" * (len(COUNTS) + 1))
        for pattern in patterns:
            cells, corrected = [], []
            for n in COUNTS:
                e = [r[4] for r in rows if r[0] == name and r[1] == pattern and r[2] == n]
                mse = sum(x * x for x in e) / len(e)
                c = max(mse - noise[name] ** 2, 1e-12)
                corrected.append(math.sqrt(c))
                cells.append(f"{psnr(c):.1f} ({psnr(max(e) ** 2):.1f}–{psnr(min(e) ** 2):.1f})")
            out.append(f"| {pattern} | " + " | ".join(cells) + f" | {slope(COUNTS, corrected):.2f} |")
    with open(os.path.join(a.out, f"sampling{suffix}.md"), "w") as f:
        f.write("\n".join(out) + "\n")
    print("\n".join(out))


if __name__ == "__main__":
    main()
