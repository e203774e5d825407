#!/usr/bin/env python3
"""Runs two raytrace binaries on every scene with every command and compares, byte for byte, what each prints
(stdout, stderr), its exit status and every file it writes. A refactoring must leave all of them identical.

usage: tools/compare_outputs.py OLD_BIN NEW_BIN [--shared DIR] [--bench DIR] [--size W H] [--jobs N]
"""
import argparse
import concurrent.futures
import os
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PIXEL_COMMANDS = ["pixelray", "firsthit", "pixelcolor", "printrays", "pixeltrace"]


def scenes_under(folder):
    found = []
    for root, _, files in os.walk(folder):
        found += [os.path.join(root, f) for f in files if f.lower().endswith((".pov", ".cli"))]
    return sorted(found)


def cases(width, height):
    """Every command, as the arguments after the scene."""
    size = [str(width), str(height)]
    pixels = [(0, 0), (width // 2, height // 2), (width - 1, height // 3)]
    out = [["render"] + size, ["render"] + size + ["-ss=2"], ["raycast"] + size, ["sceneinfo"], ["printbvh"]]
    for command in PIXEL_COMMANDS:
        out += [[command] + size + [str(x), str(y)] for x, y in pixels]
    return out


def run(binary, scene, args):
    """What one run prints and writes: exit status, stdout, stderr and the files left in its working folder."""
    with tempfile.TemporaryDirectory(prefix="compare_outputs_") as work:
        done = subprocess.run([binary, args[0], scene] + args[1:], cwd=work, capture_output=True, timeout=600)
        files = {}
        for root, _, names in os.walk(work):
            for name in names:
                path = os.path.join(root, name)
                with open(path, "rb") as f:
                    files[os.path.relpath(path, work)] = f.read()
        return {"exit status": done.returncode, "stdout": done.stdout, "stderr": done.stderr, "files": files}


def compare(old, new, scene, args):
    a, b = run(old, scene, args), run(new, scene, args)
    differences = [k for k in ("exit status", "stdout", "stderr") if a[k] != b[k]]
    for name in sorted(set(a["files"]) | set(b["files"])):
        if a["files"].get(name) != b["files"].get(name):
            differences.append("file " + name)
    return scene, args, differences


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("old", help="the binary before the change")
    parser.add_argument("new", help="the binary after the change")
    parser.add_argument("--shared", default="/work/shared/scenes",
                        help="the course suites' scenes, pov/ and cli/ (default: %(default)s)")
    parser.add_argument("--bench", default="/work/shared/bench", help="the benchmark scenes (default: %(default)s)")
    parser.add_argument("--size", nargs=2, type=int, default=[40, 30], metavar=("W", "H"))
    parser.add_argument("--jobs", type=int, default=2, help="runs at once (default: %(default)s)")
    args = parser.parse_args()
    old, new = os.path.abspath(args.old), os.path.abspath(args.new)

    scenes = scenes_under(os.path.join(REPO, "scenes"))
    for folder in (os.path.join(args.shared, "pov"), os.path.join(args.shared, "cli"), args.bench):
        if not os.path.isdir(folder):
            sys.exit("compare_outputs: no folder " + folder)
        scenes += scenes_under(folder)
    work = [(scene, case) for scene in scenes for case in cases(*args.size)]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda w: compare(old, new, *w), work))
    differ = [r for r in results if r[2]]
    for scene, case, differences in differ:
        print("DIFFER %s: %s" % (" ".join(case[:1] + [scene] + case[1:]), ", ".join(differences)))
    print("%d identical, %d differ (%d scenes, %d commands each)" %
          (len(results) - len(differ), len(differ), len(scenes), len(cases(*args.size))))
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
