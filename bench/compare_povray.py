#!/usr/bin/python3
"""End-to-end wall time of our renderer against POV-Ray 3.7 on the shared benchmark scenes.

    bench/compare_povray.py [--bin build/raytrace] [--runs 3] [--threads 2] [--size 1280x960] [--baseline OLD]

Every scene of ../shared/bench (regenerated into a work directory by its gen.py, so that the large one
need not be committed) is rendered by `raytrace render` and by `povray`, without anti-aliasing and with 3x3
supersampling (our -ss=3 against POV-Ray's +A0.0 +AM1 +R3), on the same number of threads. The runs are
interleaved (ours, POV-Ray, ours, ...) so that a change in machine load hits both alike. Wall time is what
the user waits for: process start to exit, scene loading and PNG writing included. POV-Ray gets the scene
that tools/povref/povref.py --emit-only writes, and the command line of its README. Prints a Markdown table
of medians, their ratio POV-Ray / ours, and the median of the ratios of the interleaved pairs. With
--baseline, an earlier raytrace binary runs in the same rounds too, and the table adds its time and the median
of its runs over ours.
"""

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

SHARED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared")  # beside the repo
GEN = os.path.join(SHARED, "bench", "gen.py")
POVREF = os.path.join(SHARED, "tools", "povref", "povref.py")
SCENES = ("small", "spheres1k", "spheres20k")


def wall(cmd, cwd):
    """Seconds from start to exit of `cmd`; raises if it fails."""
    start = time.perf_counter()
    done = subprocess.run(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), done.stderr.decode(errors="replace")))
    return seconds


def stolen_ms():
    """Milliseconds the hypervisor has so far kept this virtual machine's CPUs from running while they had work
    (the "steal" column of /proc/stat, summed over CPUs, in clock ticks of 10 ms as a rule); 0 where the
    kernel does not count it. Time stolen during a run is time the run waited for no fault of its own."""
    try:
        with open("/proc/stat") as f:
            ticks = sum(int(line.split()[8]) for line in f if re.match(r"cpu\d", line))
    except (OSError, IndexError, ValueError):
        return 0.0
    return ticks * 1000.0 / os.sysconf("SC_CLK_TCK")


def arguments(doc, runs, runs_help):
    """The options of the benchmark scripts on the shared scenes."""
    ap = argparse.ArgumentParser(description=doc.split("\n")[0])
    ap.add_argument("--bin", default="build/raytrace", help="our executable")
    ap.add_argument("--runs", type=int, default=runs, help=runs_help)
    ap.add_argument("--size", default="1280x960")
    ap.add_argument("--work", default="build/bench-povray", help="directory for scenes and images")
    ap.add_argument("--scenes", nargs="*", default=list(SCENES))
    return ap


def prepare(args):
    """Writes the shared benchmark scenes into the work directory with their gen.py (which writes next to
    itself, so it runs from a copy there); returns width, height, our executable and the work directory."""
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    shutil.copy(GEN, os.path.join(work, "gen.py"))
    subprocess.run([sys.executable, "gen.py"], cwd=work, check=True, stdout=subprocess.DEVNULL)
    width, height = args.size.split("x")
    return width, height, os.path.abspath(args.bin), work


def paired_ratio(times, other):
    """Median of `other` / ours over the runs made one right after the other. The load of a shared machine
    drifts over a benchmark; a pair sees nearly the same load, so this ratio is steadier than the ratio of the
    two medians."""
    return statistics.median(p / o for o, p in zip(times["ours"], times[other]))


def main():
    ap = arguments(__doc__, 3, "runs of each command (median reported)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--baseline", help="an earlier raytrace to time in the same rounds")
    args = ap.parse_args()
    width, height, binary, work = prepare(args)

    variants = (("none", [], ["-A"]), ("3x3", ["-ss=3"], ["+A0.0", "+AM1", "+R3"]))
    rows = []
    for scene in args.scenes:
        pov = scene + ".pov"
        pov37 = scene + ".pov37.pov"
        subprocess.run([POVREF, pov, width, height, "unused.png", "--emit", pov37, "--emit-only"], cwd=work,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for name, ours_aa, pov_aa in variants:
            ours = [binary, "render", pov, width, height, "--threads", str(args.threads), "--quiet"] + ours_aa
            theirs = ["povray", "+I" + pov37, "+O" + scene + ".povray.png", "+W" + width, "+H" + height,
                      "-D", "-P", "-UA", "+Q9", "+MB", "-J", "File_Gamma=1.0", "+FN8",
                      "+WT%d" % args.threads] + pov_aa
            times = {"ours": [], "pov": [], "baseline": []}
            for _ in range(args.runs):
                times["ours"].append(wall(ours, work))
                times["pov"].append(wall(theirs, work))
                if args.baseline:
                    times["baseline"].append(wall([os.path.abspath(args.baseline)] + ours[1:], work))
            ours_s, pov_s = statistics.median(times["ours"]), statistics.median(times["pov"])
            rows.append((scene, name, ours_s, pov_s, times))
            print("%s %s: ours %s, POV-Ray %s" % (scene, name, ["%.2f" % t for t in times["ours"]],
                                                   ["%.2f" % t for t in times["pov"]]), file=sys.stderr)

    extra = " baseline s | baseline / ours, per run |" if args.baseline else ""
    print("| scene | AA | ours s | POV-Ray 3.7 s | POV-Ray / ours | per-run ratio |" + extra)
    print("|---|---|---|---|---|---|" + ("---|---|" if args.baseline else ""))
    for scene, name, ours_s, pov_s, times in rows:
        line = "| %s | %s | %.3f | %.3f | %.1f× | %.1f× |" % (scene, name, ours_s, pov_s, pov_s / ours_s,
                                                             paired_ratio(times, "pov"))
        if args.baseline:
            line += " %.3f | %.2f× |" % (statistics.median(times["baseline"]), paired_ratio(times, "baseline"))
        print(line)
    print("\n%s×%s, %d threads each, wall time, median of %d interleaved runs; the per-run ratio is the median"
          " of each POV-Ray run over our run just before it." % (width, height, args.threads, args.runs))


if __name__ == "__main__":
    main()
