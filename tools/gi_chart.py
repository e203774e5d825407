#!/usr/bin/python3
"""Speed against error for -gi: uniform sampling against --gi-cache, on the course's GI scenes.

    tools/gi_chart.py [--bin build/raytrace] [--size 160x120] [--threads 2] [--scenes A.pov B.pov] [--replot]

For each scene it renders a reference of its own (the mean of --ref-seeds renders at --ref-samples, seeds 1…),
then every setting of the sweep with seed 0, and measures each image's RMS pixel error against the reference
(8-bit units) and the CPU time the render took (user + system of the child: steadier than wall time on a shared
machine). The reference's own noise is taken out of the error: the squared error of a render against a mean of
K renders is its squared error against the converged image plus the mean's variance, which the spread of the K
renders gives (their per-pixel variance / K); the square root of that variance is printed as the reference's
standard error. Uniform runs go from 8,2 to 256,64; cached runs sweep the accuracy at three sample counts.
Writes resources/gi-speed-vs-error.csv and .png, and prints the table in Markdown: for each run but the uniform
ones, the uniform error at the same CPU time (interpolated in log-log) beside its own. --replot redraws the
chart and table from the CSV (which may hold modes since removed, such as the adaptive runs, docs/gi.md).
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
CACHE_SAMPLES = ["64,16", "256,16", "256,64"]
CACHE = ["0.3", "0.2", "0.15", "0.1", "0.07", "0.05"]
MODES = ["uniform", "cache", "adaptive"]  # the order of the table; "adaptive" only in an old CSV


def render(binary, scene, size, threads, samples, seed, flag=None):
    """The image as float RGB and the CPU seconds the render took."""
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [binary, "render", os.path.abspath(scene), *size.split("x"), "-gi", "-gi_samples=" + samples,
               "--seed", str(seed), "--threads", str(threads), "--quiet"]
        if flag:
            cmd.append(flag)
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
    parser.add_argument("--size", default="160x120")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--ref-samples", default="128,32")
    parser.add_argument("--ref-seeds", type=int, default=16)
    parser.add_argument("--scenes", nargs="+", default=[os.path.join(ROOT, "..", "shared", "scenes", "pov", s)
                                                         for s in ("cornell.pov", "simple-gi.pov")])
    parser.add_argument("--out", default=os.path.join(ROOT, "resources", "gi-speed-vs-error"))
    parser.add_argument("--replot", action="store_true", help="redraw from the CSV instead of rendering")
    args = parser.parse_args()
    rows = read(args.out + ".csv") if args.replot else measure(args)
    plot(rows, args)


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["cpu_s"], r["rms_error"] = float(r["cpu_s"]), float(r["rms_error"])
    return rows


def measure(args):
    rows = []
    for scene in args.scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        refs = np.array([render(args.bin, scene, args.size, args.threads, args.ref_samples, seed)[0]
                         for seed in range(1, args.ref_seeds + 1)])
        reference = refs.mean(axis=0)
        ref_variance = float(np.mean(refs.var(axis=0, ddof=1) / len(refs)))
        print("%-10s reference: %d renders at %s, standard error %.3f/255 (RMS over pixels)"
              % (name, len(refs), args.ref_samples, math.sqrt(ref_variance)), file=sys.stderr)
        runs = ([("uniform", s, "", None) for s in UNIFORM] +
                [("cache", s, a, "--gi-cache=" + a) for s in CACHE_SAMPLES for a in CACHE])
        for mode, samples, setting, flag in runs:
            image, cpu = render(args.bin, scene, args.size, args.threads, samples, 0, flag)
            mse = float(np.mean((image - reference) ** 2))
            rms = math.sqrt(max(0.0, mse - ref_variance))
            rows.append({"scene": name, "mode": mode, "samples": samples, "setting": setting,
                         "cpu_s": round(cpu, 2), "rms_error": round(rms, 3),
                         "reference_se": round(math.sqrt(ref_variance), 3)})
            print("%-10s %-8s %-7s %-6s %7.2f s  RMS %.3f/255" % (name, mode, samples, setting, cpu, rms),
                  file=sys.stderr)
    with open(args.out + ".csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    return rows


def plot(rows, args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes = sorted({r["scene"] for r in rows})
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.5), squeeze=False)
    print("| scene | mode | -gi_samples | accuracy / threshold | CPU s | RMS error (/255) | uniform at the same CPU time |")
    print("|---|---|---|---|---|---|---|")
    for ax, scene in zip(axes[0], scenes):
        uniform = [(r["cpu_s"], r["rms_error"]) for r in rows if r["scene"] == scene and r["mode"] == "uniform"]
        # One line for uniform sampling, one per sample count for the others, in the order of the runs.
        line = lambda r: (r["mode"], "" if r["mode"] == "uniform" else r["samples"])
        series = []
        for r in sorted((r for r in rows if r["scene"] == scene), key=lambda r: MODES.index(r["mode"])):
            if line(r) not in series:
                series.append(line(r))
        for mode, samples in series:
            mine = [r for r in rows if r["scene"] == scene and line(r) == (mode, samples)]
            style = {"uniform": "o-", "cache": "^-", "adaptive": "s--"}[mode]
            label = mode if mode == "uniform" else "%s %s" % (mode, samples)
            ax.loglog([r["cpu_s"] for r in mine], [r["rms_error"] for r in mine], style, label=label)
            for r in mine:
                ax.annotate(r["setting"] or r["samples"], (r["cpu_s"], r["rms_error"]), fontsize=7)
                same = interpolate(uniform, r["cpu_s"]) if mode != "uniform" else None
                print("| %s | %s | %s | %s | %.2f | %.3f | %s |" % (scene, mode, r["samples"], r["setting"],
                                                                  r["cpu_s"], r["rms_error"],
                                                                  "%.3f" % same if same else ""))
        ax.set_title("%s, %s" % (scene, args.size))
        ax.set_xlabel("CPU seconds (%d threads)" % args.threads)
        ax.set_ylabel("RMS pixel error against the converged reference (/255)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out + ".png", dpi=100)


if __name__ == "__main__":
    main()
