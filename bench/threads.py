#!/usr/bin/python3
"""Two threads against one: wall time of `raytrace render` on the shared benchmark scenes.

    bench/threads.py [--bin build/raytrace] [--runs 15] [--size 1280x960]

The scenes of ../shared/bench are regenerated as compare_povray.py does. For each scene, without AA and with
3x3 supersampling, runs on one thread and on two alternate, the order swapped every round. Printed for each:
the ratio of the fastest runs (outside load on a shared machine only ever adds time, so it disturbs these
least), of the medians, and the median of the ratios of the pairs run back to back (which follows a load that
drifts); from `--stats`, the ratio of the fastest tracing steps alone; the median time the hypervisor stole
from the machine's CPUs during a run on each thread count (a 2-core virtual machine here loses from none to
over half of it), and the ratio of the medians over the runs it stole nothing from. Last, what the machine
itself allows: each round also starts two one-thread runs at once, and twice the median one-thread time over
the median time until both have finished is the most two threads could give on this work, with nothing
shared and nothing serial (2.00× on two cores that do not slow each other down).
"""

import statistics
import subprocess
import sys
import time

from compare_povray import arguments, prepare
from phases import STEPS, STOLEN, steps

TRACE = STEPS.index("trace")  # in what steps() returns
PROCESS = len(STEPS)


def unstolen(runs):
    """The ratio of the medians over the runs from which the host stole nothing, and how many there were of
    each; a dash below 3 of either."""
    quiet = {n: [t[PROCESS] for t in runs[n] if t[STOLEN] == 0] for n in (1, 2)}
    if min(len(quiet[1]), len(quiet[2])) < 3:
        return "– (%d, %d runs)" % (len(quiet[1]), len(quiet[2]))
    return "%.2f× (%d, %d runs)" % (statistics.median(quiet[1]) / statistics.median(quiet[2]), len(quiet[1]),
                                    len(quiet[2]))


def side_by_side(command, cwd):
    """Seconds until two copies of `command`, started together, have both finished; exits if one fails.
    Each writes its image to a temporary file it renames, so the two do not spoil each other's."""
    start = time.perf_counter()
    copies = [subprocess.Popen(command, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
              for _ in range(2)]
    if any([copy.wait() for copy in copies]):  # a list, so that both are waited for
        sys.exit("failed: %s" % " ".join(command))
    return time.perf_counter() - start


def main():
    args = arguments(__doc__, 15, "rounds of one run on each thread count").parse_args()
    width, height, binary, work = prepare(args)

    print("| scene | AA | 1 thread s | 2 threads s | ratio of fastest | of medians | per pair "
          "| tracing alone, fastest | stolen, ms | of medians, nothing stolen | machine's ceiling |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for scene in args.scenes:
        for name, aa in (("none", []), ("3x3", ["-ss=3"])):
            runs, both = {1: [], 2: []}, []
            for r in range(args.runs):
                # 1 and 2 threads, and 0 for two one-thread runs at once (the machine's ceiling).
                for threads in (1, 2, 0) if r % 2 == 0 else (0, 2, 1):
                    command = [binary, "render", scene + ".pov", width, height, "--threads", str(threads or 1),
                               "--quiet", "--stats"] + aa
                    if threads:
                        runs[threads].append(steps(command, work))
                    else:
                        both.append(side_by_side(command, work))
            one, two = [t[PROCESS] / 1000 for t in runs[1]], [t[PROCESS] / 1000 for t in runs[2]]
            pairs = statistics.median(a / b for a, b in zip(one, two))
            trace = min(t[TRACE] for t in runs[1]) / min(t[TRACE] for t in runs[2])
            stolen = "%.0f / %.0f" % tuple(statistics.median(t[STOLEN] for t in runs[n]) for n in (1, 2))
            ceiling = 2 * statistics.median(one) / statistics.median(both)
            print("| %s | %s | %.3f | %.3f | %.2f× | %.2f× | %.2f× | %.2f× | %s | %s | %.2f× |" % (
                scene, name, statistics.median(one), statistics.median(two), min(one) / min(two),
                statistics.median(one) / statistics.median(two), pairs, trace, stolen, unstolen(runs), ceiling),
                flush=True)
    print("\n%s×%s, medians of %d interleaved runs on each thread count." % (width, height, args.runs))


if __name__ == "__main__":
    main()
