#!/usr/bin/python3
"""Render time against scene size: 1k, 10k, 100k and 1M spheres.

    bench/scaling.py [--bin build/raytrace] [--runs 3] [--threads 2] [--size 1280x960]

Each scene is a jittered field of n spheres on a plane under one light, like ../shared/bench/spheres20k.pov,
with radii ∝ 1/√n so that the spheres cover about the same share of the picture whatever n; the files are
generated into the work directory (the largest is about 150 MB) and never committed. For each n the script
times, as medians of interleaved runs, the whole render and the same command at 1×1 pixel: the fixed cost
of loading the file and building the hierarchy. Writes resources/scaling.csv and resources/scaling.png.
"""

import argparse
import csv
import os
import random
import statistics
import subprocess
import sys
import time

COUNTS = (1000, 10000, 100000, 1000000)


def write_field(f, n, seed, describe):
    """Writes the comment describe(cols, rows), camera, light and plane to `f`, then yields (x, y, z, r, rng) for each of its
    n spheres; the caller draws what else a sphere needs from rng before asking for the next."""
    rng = random.Random(seed)
    side = int(round((2 * n) ** 0.5))  # a 2:1 grid, as in spheres20k.pov
    cols, rows = side, (n + side - 1) // side
    scale = (20000 / n) ** 0.5          # spheres20k's sizes at n = 20000
    f.write("// %s\n" % describe(cols, rows))
    # up exactly perpendicular to the view direction (0, -9, -33), as gen.py makes it
    d = (0.0, -9.0, -33.0)
    norm = (d[1] ** 2 + d[2] ** 2) ** 0.5
    up = (0.0, -d[2] / norm, d[1] / norm)
    f.write("camera {\n  location <0, 9, 8>\n  up <0, %.6f, %.6f>\n  right <1.33333, 0, 0>\n"
            "  look_at <0, 0, -25>\n}\n" % (up[1], up[2]))
    f.write("light_source { <-60, 80, 60> color rgb <1.2, 1.2, 1.2> }\n")
    f.write("plane { <0, 1, 0>, 0\n  pigment { color rgb <0.6, 0.6, 0.65> }\n"
            "  finish { ambient 0.15 diffuse 0.7 }\n}\n")
    for k in range(n):
        i, j = k % cols, k // cols
        r = rng.uniform(0.08, 0.2) * scale
        x = -40 + (i + 0.5) * 80 / cols + rng.uniform(-0.25, 0.25) * 80 / cols
        z = -60 + (j + 0.5) * 60 / rows + rng.uniform(-0.25, 0.25) * 60 / rows
        y = r + rng.uniform(0, 0.5) * scale
        yield x, y, z, r, rng


def write_scene(path, n):
    with open(path, "w") as f:
        for x, y, z, r, rng in write_field(f, n, n, lambda cols, rows: "%d spheres in a jittered %d x %d field on a "
                                           "plane, 1 light (bench/scaling.py)" % (n, cols, rows)):
            f.write("sphere { <%.5f, %.5f, %.5f>, %.5f\n  pigment { color rgb <%.3f, %.3f, %.3f> }\n"
                    "  finish { ambient 0.15 diffuse 0.7 specular 0.3 roughness 0.05 }\n}\n"
                    % (x, y, z, r, rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1)))


def wall(cmd, cwd):
    start = time.perf_counter()
    done = subprocess.run(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if done.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), done.stderr.decode(errors="replace")))
    return time.perf_counter() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default="build/raytrace")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--size", default="1280x960")
    ap.add_argument("--work", default="build/bench-scaling")
    ap.add_argument("--out", default="resources/scaling")
    args = ap.parse_args()
    width, height = args.size.split("x")
    binary = os.path.abspath(args.bin)
    os.makedirs(args.work, exist_ok=True)

    rows = []
    for n in COUNTS:
        scene = "spheres%d.pov" % n
        if not os.path.exists(os.path.join(args.work, scene)):
            write_scene(os.path.join(args.work, scene), n)
        base = [binary, "render", scene, "--threads", str(args.threads), "--quiet"]
        full, setup = [], []
        for _ in range(args.runs):
            full.append(wall(base + [width, height], args.work))
            setup.append(wall(base + ["1", "1"], args.work))
        rows.append((n, statistics.median(full), statistics.median(setup)))
        # Two medians of separate runs: at 1M spheres their noise exceeds the tracing time, so no difference
        # of them is reported.
        print("%8d spheres: render %.3f s; loading and building alone %.3f s" % rows[-1], file=sys.stderr)

    with open(args.out + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["spheres", "render_s", "load_and_build_s"])
        for n, total, setup in rows:
            w.writerow([n, "%.4f" % total, "%.4f" % setup])

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ns = [r[0] for r in rows]
    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=120)
    ax.plot(ns, [r[1] for r in rows], "o-", label="whole render (%s×%s, %d threads)" % (width, height, args.threads))
    ax.plot(ns, [r[2] for r in rows], "s--", label="the same at 1×1 pixel: loading the file + building the BVH")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("spheres in the scene")
    ax.set_ylabel("wall time, s (median of %d)" % args.runs)
    ax.set_title("raytrace render: time against scene size")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out + ".png")
    print("wrote %s.csv and %s.png" % (args.out, args.out), file=sys.stderr)


if __name__ == "__main__":
    main()
