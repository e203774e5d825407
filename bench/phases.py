#!/usr/bin/python3
"""Where the time of a render goes, on one thread and on two: the steps `raytrace render --stats` reports.

    bench/phases.py [--bin build/raytrace] [--runs 11] [--size 1280x960] [--scenes spheres20k] [--ss 1]

The scenes of ../shared/bench are regenerated as compare_povray.py does. For each scene, runs on one thread
and on two alternate, the order swapped every round. Printed for each step (loading the file, building the
scene and its hierarchy, tracing, encoding and writing the PNG, their sum, and the whole process from start
to exit as the shell sees it): the median and, in brackets, the fastest run on each thread count, and the
ratio of the medians. Last, the median time the hypervisor stole from the machine's CPUs during a run.
"""

import re
import statistics
import subprocess
import sys
import time

from compare_povray import arguments, prepare, stolen_ms

STEPS = ("load", "build", "trace", "write", "total")
STOLEN = len(STEPS) + 1  # in what steps() returns, after the whole process
LINE = re.compile(r"raytrace: " + ", ".join(r"%s ([0-9.]+) ms" % s for s in STEPS))


def steps(command, cwd):
    """The milliseconds of each step, of the whole process, and stolen from the machine meanwhile
    (stolen_ms); exits if the command fails."""
    steal = stolen_ms()
    start = time.perf_counter()
    done = subprocess.run(command, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    process = (time.perf_counter() - start) * 1000
    steal = stolen_ms() - steal
    match = LINE.search(done.stderr)
    if done.returncode != 0 or not match:
        sys.exit("failed: %s\n%s" % (" ".join(command), done.stderr))
    return [float(v) for v in match.groups()] + [process, steal]


def main():
    ap = arguments(__doc__, 11, "rounds of one run on each thread count")
    ap.set_defaults(scenes=["spheres20k"])
    ap.add_argument("--ss", type=int, default=1, help="N for -ss=N")
    args = ap.parse_args()
    width, height, binary, work = prepare(args)

    for scene in args.scenes:
        times = {1: [], 2: []}
        for r in range(args.runs):
            for threads in (1, 2) if r % 2 == 0 else (2, 1):
                command = [binary, "render", scene + ".pov", width, height, "-ss=%d" % args.ss, "--threads",
                           str(threads), "--quiet", "--stats"]
                times[threads].append(steps(command, work))
        print("\n%s, -ss=%d: milliseconds, median (fastest) of %d runs\n" % (scene, args.ss, args.runs))
        print("| step | 1 thread | 2 threads | ratio of medians |")
        print("|---|---|---|---|")
        for i, name in enumerate(STEPS + ("process",)):
            one = [t[i] for t in times[1]]
            two = [t[i] for t in times[2]]
            a, b = statistics.median(one), statistics.median(two)
            ratio = "%.2f×" % (a / b) if a and b else "–"  # a step under 0.05 ms shows as 0.0
            print("| %s | %.1f (%.1f) | %.1f (%.1f) | %s |" % (name, a, min(one), b, min(two), ratio), flush=True)
        print("| stolen by the host | %.0f | %.0f | |" % tuple(statistics.median(t[STOLEN] for t in times[n])
                                                          for n in (1, 2)))


if __name__ == "__main__":
    main()
