#!/usr/bin/python3
"""Two threads against one: wall time of `raytrace render` on the shared benchmark scenes.

    bench/threads.py [--bin build/raytrace] [--runs 15] [--size 1280x960]

The scenes of ../shared/bench are regenerated as compare_povray.py does. For each scene, without AA and with
3x3 supersampling, runs on one thread and on two alternate, the order swapped every round. Printed for each:
the ratio of the fastest runs (outside load on a shared machine only ever adds time, so it disturbs these
least), of the medians, and the median of the ratios of the pairs run back to back (which follows a load that
drifts).
"""

import statistics

from compare_povray import arguments, prepare, wall


def main():
    args = arguments(__doc__, 15, "rounds of one run on each thread count").parse_args()
    width, height, binary, work = prepare(args)

    print("| scene | AA | 1 thread s | 2 threads s | ratio of fastest | of medians | per pair |")
    print("|---|---|---|---|---|---|---|")
    for scene in args.scenes:
        for name, aa in (("none", []), ("3x3", ["-ss=3"])):
            times = {1: [], 2: []}
            for r in range(args.runs):
                for threads in (1, 2) if r % 2 == 0 else (2, 1):
                    command = [binary, "render", scene + ".pov", width, height, "--threads", str(threads), "--quiet"]
                    times[threads].append(wall(command + aa, work))
            one, two = times[1], times[2]
            pairs = statistics.median(a / b for a, b in zip(one, two))
            print("| %s | %s | %.3f | %.3f | %.2f× | %.2f× | %.2f× |" % (
                scene, name, statistics.median(one), statistics.median(two), min(one) / min(two),
                statistics.median(one) / statistics.median(two), pairs), flush=True)
    print("\n%s×%s, medians of %d interleaved runs on each thread count." % (width, height, args.runs))


if __name__ == "__main__":
    main()
