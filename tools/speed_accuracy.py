#!/usr/bin/python3
"""Speed-vs-accuracy chart of the real renderer (docs/reference/stability.md §3, chart B).

    python3 tools/speed_accuracy.py build/raytrace

renders the stability scenes (scenes/stability/S1-S4) at 160x120 with one knob at a time changed from a
baseline (double, robust sphere, relative offset, -ss=4, --depth=8), and writes
resources/speed-vs-accuracy.csv and resources/speed-vs-accuracy.png. For every configuration:

- time: the median wall-clock time of --runs renders (the whole process, parsing included);
- error against the reference (double, robust, relative offset, -ss=8, --depth=32): RMSE of the 8-bit
  images in units of full scale, and the share of pixels with a channel off by more than 1/255;
- the same two numbers against the baseline arithmetic at the SAME samples and depth, so that precision,
  sphere-formula and offset knobs show their numerical error alone (docs/reference/stability.md §3, last paragraph).
"""
import argparse
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = [
    ("S1 grazing light, mirrors", "scenes/stability/s1_grazing.pov"),
    ("S2 r=1e-2 spheres at 1e3-1e4", "scenes/stability/s2_tiny_far.pov"),
    ("S3 glass between mirrors", "scenes/stability/s3_glass_mirrors.pov"),
    ("S4 = S1 moved by 1e4", "scenes/stability/s4_far.pov"),
]
BASE = {"precision": "double", "sphere": "robust", "offset": "relative", "ss": "4", "depth": "8",
        "hierarchy": "auto"}
REFERENCE = dict(BASE, ss="8", depth="32")
# One knob at a time (docs/reference/stability.md §3). Float is paired with each sphere formula and with the offsets
# whose failure float exposes first.
KNOBS = [
    ("baseline", {}),
    # What a user gets without flags: chooseArithmetic()'s tier, sphere test and offset for the scene.
    ("default", {"precision": "auto", "sphere": "auto", "offset": "auto"}),
    ("precision", {"precision": "float"}),
    ("precision", {"precision": "float", "sphere": "textbook"}),
    ("sphere", {"sphere": "textbook"}),
    # The course tier: the course reference's float arithmetic with its 0.001 offsets (scene/arithmetic.hpp).
    ("precision", {"precision": "course", "offset": "course"}),
    ("offset", {"offset": "course"}),
    ("offset", {"offset": "normal"}),
    ("offset", {"offset": "wb"}),
    ("offset", {"precision": "float", "offset": "course"}),
    ("offset", {"precision": "float", "offset": "normal"}),
    ("samples", {"ss": "1"}),
    ("samples", {"ss": "2"}),
    ("samples", {"ss": "8"}),
    ("depth", {"depth": "1"}),
    ("depth", {"depth": "2"}),
    ("depth", {"depth": "3"}),
    ("depth", {"depth": "5"}),
    ("depth", {"depth": "16"}),
    # These scenes are below the hierarchy's crossover, so auto means none: forcing one must only move time.
    ("hierarchy", {"hierarchy": "always"}),
]
COLOURS = {"baseline": "black", "default": "tab:pink", "precision": "tab:red", "sphere": "tab:purple", "offset": "tab:orange",
           "samples": "tab:blue", "depth": "tab:green", "hierarchy": "tab:brown"}


def flags(config):
    offset = [] if config["offset"] == "auto" else [f"--offset={config['offset']}"]  # auto: the tier's own
    return [f"--precision={config['precision']}", f"--sphere={config['sphere']}"] + offset + [
        f"-ss={config['ss']}", f"--depth={config['depth']}", f"--hierarchy={config['hierarchy']}"]


def label(config):
    """The knobs that differ from the baseline, e.g. 'float textbook'."""
    changed = [f"{k}={v}" for k, v in config.items() if BASE[k] != v]
    return " ".join(changed) or "baseline"


def render(binary, scene, config, size, runs):
    """Median seconds over `runs` renders, and the image as floats in [0, 1]."""
    times = []
    with tempfile.TemporaryDirectory() as work:
        for _ in range(runs):
            start = time.perf_counter()
            subprocess.run([binary, "render", os.path.join(ROOT, scene), str(size[0]), str(size[1])] + flags(config),
                           cwd=work, check=True, stdout=subprocess.DEVNULL)
            times.append(time.perf_counter() - start)
        image = np.asarray(Image.open(os.path.join(work, "output.png")).convert("RGB"), dtype=np.float64) / 255
    return statistics.median(times), image


def errors(image, reference):
    diff = np.abs(image - reference)
    # 8-bit values differ by whole steps: "more than 1/255" is 2 steps or more.
    return float(np.sqrt(np.mean(diff ** 2))), float(np.mean(np.any(diff > 1.5 / 255, axis=2)))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("binary", help="the raytrace executable, e.g. build/raytrace")
    parser.add_argument("--runs", type=int, default=3, help="renders per configuration (median time)")
    parser.add_argument("--size", default="160x120", help="image size WxH")
    parser.add_argument("--out", default=os.path.join(ROOT, "resources", "speed-vs-accuracy"),
                        help="output path without extension (.csv and .png are written)")
    args = parser.parse_args()
    size = tuple(int(v) for v in args.size.split("x"))
    binary = os.path.abspath(args.binary)

    rows = []
    for title, scene in SCENES:
        _, reference = render(binary, scene, REFERENCE, size, 1)
        same_sampling = {}
        for knob, change in KNOBS:
            config = dict(BASE, **change)
            seconds, image = render(binary, scene, config, size, args.runs)
            key = (config["ss"], config["depth"])
            if key not in same_sampling:
                arithmetic = dict(BASE, ss=config["ss"], depth=config["depth"])
                same_sampling[key] = image if arithmetic == config else render(binary, scene, arithmetic, size, 1)[1]
            rmse, off = errors(image, reference)
            rmse_same, off_same = errors(image, same_sampling[key])
            rows.append({"scene": title, "knob": knob, "config": label(config), "args": " ".join(flags(config)),
                         "seconds": f"{seconds:.4f}", "rmse": f"{rmse:.6f}", "share_off": f"{off:.5f}",
                         "rmse_same_sampling": f"{rmse_same:.6f}", "share_off_same_sampling": f"{off_same:.5f}"})
            print(f"{title:32s} {label(config):28s} {seconds:7.3f}s rmse {rmse:.5f} off {off:.4f} "
                  f"(numerical: rmse {rmse_same:.5f} off {off_same:.4f})", file=sys.stderr)

    with open(args.out + ".csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    plot(rows, args.out + ".png", size)


def plot(rows, path, size):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 2, figsize=(13, 9.5))
    floor = 1e-5  # an exact match, drawn on the axis floor of the log scale
    for ax, (title, _) in zip(axes.flat, SCENES):
        points = [r for r in rows if r["scene"] == title]
        base = next(float(r["rmse"]) for r in points if r["knob"] == "baseline")
        unlabelled = 0
        for r in points:
            x, y, off = float(r["seconds"]), max(float(r["rmse"]), floor), float(r["share_off"])
            ax.scatter(x, y, s=20 + 600 * off, color=COLOURS[r["knob"]], alpha=0.7, edgecolors="k", linewidths=0.5)
            # Knobs that change nothing visible pile up on the baseline: count them, don't label them.
            if r["knob"] not in ("baseline", "samples") and abs(float(r["rmse"]) - base) <= 0.02 * base:
                unlabelled += 1
                continue
            ax.annotate(r["config"], (x, y), fontsize=7, xytext=(4, 3), textcoords="offset points")
        if unlabelled:
            ax.text(0.02, 0.03, f"{unlabelled} settings within 2% of the baseline's RMSE (unlabelled)", transform=ax.transAxes, fontsize=7)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(bottom=floor / 2)
        ax.set_title(title)
        ax.set_xlabel("median render time, s (whole process)")
        ax.set_ylabel("RMSE vs reference (full scale = 1)")
        ax.grid(True, which="both", alpha=0.3)
    handles = [plt.Line2D([], [], marker="o", ls="", color=c, label=k) for k, c in COLOURS.items()]
    fig.legend(handles=handles, loc="lower center", ncol=len(handles))
    fig.suptitle(f"raytrace speed vs accuracy at {size[0]}x{size[1]}: one knob changed from the baseline "
                 f"double/robust/relative/ss=4/depth=8\nreference: ss=8, depth=32; "
                 f"marker area ~ share of pixels off by more than 1/255")
    fig.tight_layout(rect=(0, 0.04, 1, 0.96))
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
