#!/usr/bin/python3
"""Speed against error for -gi: uniform sampling against --gi-adaptive, on the course's two GI scenes.

    tools/gi_chart.py [--bin build/raytrace] [--size 128x96] [--threads 2] [--scenes A.pov B.pov]

For each scene it renders a reference of its own (the mean of --ref-seeds renders at --ref-samples, seeds 1…),
then every setting of the sweep with seed 0, and measures each image's RMS pixel error against the reference
(8-bit units) and the CPU time the render took (user + system of the child: steadier than wall time on a shared
machine). Uniform runs go from 8,2 to 256,64; adaptive runs cap at 256,64 and sweep the threshold. Writes
resources/gi-speed-vs-error.csv and .png, and prints the table in Markdown with the verdict: for each adaptive
run, the uniform error at the same CPU time (interpolated in log-log) beside its own.
"""
import argparse
import csv
import math
import os
import resource
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UNIFORM = ["8,2", "16,4", "32,8", "64,16", "128,32", "256,64"]
ADAPTIVE = ["0.04", "0.02", "0.01", "0.005"]
ADAPTIVE_CAP = "256,64"


def render(binary, scene, size, threads, samples, seed, adaptive=None):
    """The image as float RGB and the CPU seconds the render took."""
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [binary, "render", os.path.abspath(scene), *size.split("x"), "-gi", "-gi_samples=" + samples,
               "--seed", str(seed), "--threads", str(threads), "--quiet"]
        if adaptive:
            cmd.append("--gi-adaptive=" + adaptive)
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run(cmd, cwd=tmp, check=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        image = np.asarray(Image.open(os.path.join(tmp, "output.png")).convert("RGB"), dtype=np.float64)
    return image, cpu


def interpolate(points, t):
    """The uniform error at CPU time t, from (time, error) points, linear in log-log; None outside them."""
    points = sorted(points)
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if t0 <= t <= t1:
            f = (math.log(t) - math.log(t0)) / (math.log(t1) - math.log(t0))
            return math.exp(math.log(e0) + f * (math.log(e1) - math.log(e0)))
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "raytrace"))
    parser.add_argument("--size", default="128x96")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--ref-samples", default="128,32")
    parser.add_argument("--ref-seeds", type=int, default=4)
    parser.add_argument("--scenes", nargs="+", default=[os.path.join(ROOT, "..", "shared", "scenes", "pov", s)
                                                         for s in ("cornell.pov", "simple-gi.pov")])
    parser.add_argument("--out", default=os.path.join(ROOT, "resources", "gi-speed-vs-error"))
    args = parser.parse_args()

    rows = []
    for scene in args.scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        refs = [render(args.bin, scene, args.size, args.threads, args.ref_samples, seed)[0]
                for seed in range(1, args.ref_seeds + 1)]
        reference = np.mean(refs, axis=0)
        runs = [("uniform", s, None) for s in UNIFORM] + [("adaptive", ADAPTIVE_CAP, e) for e in ADAPTIVE]
        for mode, samples, threshold in runs:
            image, cpu = render(args.bin, scene, args.size, args.threads, samples, 0, threshold)
            rms = float(np.sqrt(np.mean((image - reference) ** 2)))
            rows.append({"scene": name, "mode": mode, "samples": samples, "threshold": threshold or "",
                         "cpu_s": round(cpu, 2), "rms_error": round(rms, 3)})
            print("%-10s %-8s %-7s %-6s %7.2f s  RMS %.3f/255" % (name, mode, samples, threshold or "", cpu, rms),
                  file=sys.stderr)

    with open(args.out + ".csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes = sorted({r["scene"] for r in rows})
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.5), squeeze=False)
    print("| scene | mode | -gi_samples | threshold | CPU s | RMS error (/255) | uniform at the same CPU time |")
    print("|---|---|---|---|---|---|---|")
    for ax, scene in zip(axes[0], scenes):
        uniform = [(r["cpu_s"], r["rms_error"]) for r in rows if r["scene"] == scene and r["mode"] == "uniform"]
        for mode, marker in (("uniform", "o-"), ("adaptive", "s--")):
            mine = [r for r in rows if r["scene"] == scene and r["mode"] == mode]
            ax.loglog([r["cpu_s"] for r in mine], [r["rms_error"] for r in mine], marker, label=mode)
            for r in mine:
                ax.annotate(r["threshold"] or r["samples"], (r["cpu_s"], r["rms_error"]), fontsize=7)
                same = interpolate(uniform, r["cpu_s"]) if mode == "adaptive" else None
                print("| %s | %s | %s | %s | %.2f | %.3f | %s |" % (scene, mode, r["samples"], r["threshold"],
                                                                  r["cpu_s"], r["rms_error"],
                                                                  "%.3f" % same if same else ""))
        ax.set_title("%s, %s" % (scene, args.size))
        ax.set_xlabel("CPU seconds (%d threads)" % args.threads)
        ax.set_ylabel("RMS pixel error against the reference (/255)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(args.out + ".png", dpi=100)


if __name__ == "__main__":
    main()
