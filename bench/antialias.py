#!/usr/bin/python3
"""Adaptive anti-aliasing: wall time against image error, ours against POV-Ray 3.7, on the shared bench scenes.

    bench/antialias.py [--bin build/raytrace] [--runs 3] [--threads 2] [--size 320x240] [--scenes small ...]
                       [--svg resources/antialias.svg]

Each scene (../shared/bench, regenerated and converted for POV-Ray as bench/compare_povray.py does) is rendered
by each setting below; a setting's error is the RMS over every channel of every pixel, in 8-bit units scaled to
[0, 1], of its PNG against its renderer's own reference: ours with 16 x 16 stratified samples (-ss=16), POV-Ray's
with the most its non-recursive method takes (+A0.0 +AM1 +R9: the pixel's own ray and 81 more), so that the
two renderers' small differences of shading do not count as aliasing. Wall time is the median of interleaved
runs (process start to exit, loading and writing included), and so is the CPU time (user and system, of all
its threads), which a machine shared with other work changes less; rays per pixel come from --stats=json and
POV-Ray's statistics. Prints a Markdown table per scene and, for POV-Ray's +A0.3, the fastest of our settings
whose error is no larger, with the ratio of the wall times and of the CPU times. --svg also draws every scene's
settings as error against wall time.
"""

import json
import math
import os
import re
import resource
import statistics
import subprocess
import sys
import time

import numpy
from PIL import Image

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_povray  # noqa: E402  (the shared scenes and their POV-Ray form)

OURS = [
    ("none", []),
    ("-ss=3", ["-ss=3"]),
    ("--aa=1 0.3", ["--aa=1", "--aa-threshold=0.3"]),
    ("--aa=1 0.1", ["--aa=1", "--aa-threshold=0.1"]),
    ("--aa=1 0.03", ["--aa=1", "--aa-threshold=0.03"]),
    ("--aa=2 0.3", ["--aa=2", "--aa-threshold=0.3"]),
    ("--aa=2 0.1", ["--aa=2", "--aa-threshold=0.1"]),
]
POVRAY = [
    ("-A", ["-A"]),
    ("+A0.3", ["+A0.3", "+AM1", "+R3"]),
    ("+A0.1", ["+A0.1", "+AM1", "+R3"]),
    ("+A0.03", ["+A0.03", "+AM1", "+R3"]),
    ("+A0.0 (3x3)", ["+A0.0", "+AM1", "+R3"]),
    ("+AM2 +A0.3", ["+A0.3", "+AM2", "+R3"]),
]


def cpu_seconds():
    """User and system time of the children waited for so far."""
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    return used.ru_utime + used.ru_stime


def run(cmd, cwd):
    """Wall seconds from start to exit of `cmd`, its CPU seconds and its stderr; stops the script if it fails."""
    cpu = cpu_seconds()
    start = time.perf_counter()
    done = subprocess.run(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), done.stderr.decode(errors="replace")))
    return seconds, cpu_seconds() - cpu, done.stderr.decode(errors="replace")


def pixels(path):
    return numpy.asarray(Image.open(path).convert("RGB"), dtype=numpy.float64) / 255.0


def rms(path, reference):
    return float(numpy.sqrt(numpy.mean((pixels(path) - reference) ** 2)))


def ours_rays(stderr, width, height):
    stats = json.loads(stderr.strip().splitlines()[-1])
    return stats["rays"]["eye"] / (width * height)


def povray_rays(stderr, width, height):
    """POV-Ray's "Pixels" (first rays) and "Samples" (supersamples) of its statistics."""
    m = re.search(r"Pixels:\s+(\d+)\s+Samples:\s+(\d+)", stderr)
    return (int(m.group(1)) + int(m.group(2))) / (width * height) if m else float("nan")


def svg(results, path):
    """Error against time, both on log scales, a panel per scene."""
    panel_w, panel_h, pad = 420, 300, 50
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">'
           % (panel_w * len(results), panel_h + 40), '<rect width="100%" height="100%" fill="white"/>']
    for k, (scene, rows) in enumerate(results):
        good = [r for r in rows if r[3] > 0]
        ts = [math.log10(r[2]) for r in good]
        es = [math.log10(r[3]) for r in good]
        t0, t1 = min(ts) - 0.1, max(ts) + 0.1
        e0, e1 = min(es) - 0.1, max(es) + 0.1
        x0 = k * panel_w

        def px(t):
            return x0 + pad + (t - t0) / (t1 - t0) * (panel_w - 2 * pad)

        def py(e):
            return 20 + (e1 - e) / (e1 - e0) * (panel_h - 2 * 20)

        out.append('<text x="%d" y="14">%s: RMS error (log) against wall time in s (log)</text>' % (x0 + pad, scene))
        out.append('<rect x="%d" y="20" width="%d" height="%d" fill="none" stroke="#888"/>'
                   % (x0 + pad, panel_w - 2 * pad, panel_h - 40))
        for t in range(math.floor(t0), math.ceil(t1) + 1):
            for m in (1, 2, 5):
                v = math.log10(m) + t
                if t0 <= v <= t1:
                    out.append('<text x="%.1f" y="%d" text-anchor="middle">%g</text>' % (px(v), panel_h - 5, m * 10 ** t))
        for e in range(math.floor(e0), math.ceil(e1) + 1):
            for m in (1, 2, 5):
                v = math.log10(m) + e
                if e0 <= v <= e1:
                    out.append('<text x="%d" y="%.1f" text-anchor="end">%g</text>' % (x0 + pad - 4, py(v) + 4, m * 10 ** e))
        for who, name, seconds, error, _, _ in good:
            colour = "#c0392b" if who == "POV-Ray" else "#2471a3"
            x, y = px(math.log10(seconds)), py(math.log10(error))
            out.append('<circle cx="%.1f" cy="%.1f" r="4" fill="%s"/>' % (x, y, colour))
            out.append('<text x="%.1f" y="%.1f" fill="%s">%s</text>' % (x + 6, y - 4, colour, name))
    out.append('<text x="%d" y="%d" fill="#2471a3">raytrace</text>' % (pad, panel_h + 30))
    out.append('<text x="%d" y="%d" fill="#c0392b">POV-Ray 3.7</text>' % (pad + 80, panel_h + 30))
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    ap = compare_povray.arguments(__doc__, 3, "timed runs of each setting (median reported)")
    ap.set_defaults(size="320x240", work="build/bench-antialias", scenes=["small", "spheres1k"])
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--svg", help="write the chart here")
    args = ap.parse_args()
    width, height, binary, work = compare_povray.prepare(args)
    w, h = int(width), int(height)
    results = []
    for scene in args.scenes:
        pov, pov37 = scene + ".pov", scene + ".pov37.pov"
        subprocess.run([compare_povray.POVREF, pov, width, height, "unused.png", "--emit", pov37, "--emit-only"],
                       cwd=work, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

        def ours(flags, out):
            return [binary, "render", pov, width, height, "--threads", str(args.threads), "--quiet",
                    "--stats=json", "-o", out] + flags

        def theirs(flags, out):
            return ["povray", "+I" + pov37, "+O" + out, "+W" + width, "+H" + height, "-D", "-P", "-UA", "+Q9", "+MB",
                    "-J", "File_Gamma=1.0", "+FN8", "+WT%d" % args.threads] + flags

        run(ours(["-ss=16"], scene + ".ours-ref.png"), work)
        run(theirs(["+A0.0", "+AM1", "+R9"], scene + ".pov-ref.png"), work)
        ref_ours = pixels(os.path.join(work, scene + ".ours-ref.png"))
        ref_pov = pixels(os.path.join(work, scene + ".pov-ref.png"))
        settings = [("raytrace", n, ours(f, "%s.ours.%d.png" % (scene, i))) for i, (n, f) in enumerate(OURS)]
        settings += [("POV-Ray", n, theirs(f, "%s.pov.%d.png" % (scene, i))) for i, (n, f) in enumerate(POVRAY)]
        times = {n: [] for _, n, _ in settings}
        cpus = {n: [] for _, n, _ in settings}
        stderrs = {}
        for _ in range(args.runs):
            for who, name, cmd in settings:
                seconds, cpu, stderrs[name] = run(cmd, work)
                times[name].append(seconds)
                cpus[name].append(cpu)
        rows = []
        for who, name, cmd in settings:
            out = os.path.join(work, cmd[cmd.index("-o") + 1] if who == "raytrace" else cmd[2][2:])
            error = rms(out, ref_ours if who == "raytrace" else ref_pov)
            rays = (ours_rays if who == "raytrace" else povray_rays)(stderrs[name], w, h)
            rows.append((who, name, statistics.median(times[name]), error, rays, statistics.median(cpus[name])))
        results.append((scene, rows))
        print("\n### %s, %s×%s, %d threads\n" % (scene, width, height, args.threads))
        print("| renderer | setting | rays/pixel | wall s | CPU s | RMS error |")
        print("|---|---|---|---|---|---|")
        for who, name, seconds, error, rays, cpu in rows:
            print("| %s | %s | %.2f | %.3f | %.3f | %.5f |" % (who, name, rays, seconds, cpu, error))
        pov03 = next(r for r in rows if r[1] == "+A0.3")
        match = [r for r in rows if r[0] == "raytrace" and r[3] <= pov03[3]]
        if match:
            best = min(match, key=lambda r: r[2])
            print("\nAt POV-Ray +A0.3's error (%.5f, %.3f s): raytrace %s, error %.5f, %.3f s: %.1f× faster."
                  % (pov03[3], pov03[2], best[1], best[3], best[2], pov03[2] / best[2]))
            cheapest = min(match, key=lambda r: r[5])
            print("In CPU time (%.3f s): raytrace %s, %.3f s: %.1f× less."
                  % (pov03[5], cheapest[1], cheapest[5], pov03[5] / cheapest[5]))
        else:
            print("\nNo raytrace setting reaches POV-Ray +A0.3's error (%.5f)." % pov03[3])
    if args.svg:
        svg(results, args.svg)
    print("\nError: RMS of the 8-bit PNG against the renderer's own reference (ours -ss=16, POV-Ray +A0.0 +AM1 +R9);"
          " time: median of %d interleaved runs, wall and CPU." % args.runs)


if __name__ == "__main__":
    main()
