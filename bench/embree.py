#!/usr/bin/python3
"""Our traversal against Embree 3 on the same rays: the table of docs/performance.md ("Against Embree").

    cmake -S . -B build -DRAYTRACE_EMBREE=ON && cmake --build build --target raytrace_embree
    bench/embree.py [--runs 5] [--size 1280x960] [--threads 1,2] [--sphere robust] [--scenes small ...]

Scenes: small, spheres1k and spheres20k of ../shared/bench, the course's bunny (10k triangles, from
../shared/scenes), and two generated into the work directory (never committed): spheres1M (bench/scaling.py's
field of a million spheres) and triangles1M (bench/gen_triangles.py, 1,024,000 triangles). For each scene
build/raytrace_embree traces the same ray sets through our Scene and through Embree and prints one row per ray
kind and thread count: millions of rays per second for each (medians of --runs runs, on processor time) and
ours ÷ Embree (above 1: we are faster); then the agreement check. This script prints the rows as one table.
"""

import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import gen_triangles  # noqa: E402
import scaling  # noqa: E402

SCENES = ("small", "spheres1k", "spheres20k", "bunny", "spheres1M", "triangles1M")


def scene_path(name, shared, work):
    """The scene's file, generated into `work` first when it is one of ours."""
    if name in ("small", "spheres1k", "spheres20k"):
        return os.path.join(shared, "bench", name + ".pov")
    if name == "bunny":
        return os.path.join(shared, "scenes", "pov", "bunny.pov")
    path = os.path.join(work, name + ".pov")
    if not os.path.exists(path):
        os.makedirs(work, exist_ok=True)
        if name == "spheres1M":
            scaling.write_scene(path, 1000000)
        elif name == "triangles1M":
            gen_triangles.write_scene(path, 800, 3)
        else:
            sys.exit("unknown scene " + name)
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default="build/raytrace_embree")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--size", default="1280x960")
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--quality", default="high", choices=("high", "medium"))
    ap.add_argument("--sphere", choices=("robust", "textbook"), help="the sphere formula (default: the scene's)")
    ap.add_argument("--shared", default=os.path.join(HERE, "..", "..", "shared"), help="the shared directory")
    ap.add_argument("--work", default="build/bench-embree", help="directory for the generated scenes")
    ap.add_argument("--scenes", nargs="*", default=list(SCENES))
    args = ap.parse_args()
    rows, notes, failed = [], [], False
    for name in args.scenes:
        path = scene_path(name, args.shared, args.work)
        done = subprocess.run([args.bin, path, "--name", name, "--runs", str(args.runs), "--size", args.size,
                               "--threads", args.threads, "--quality", args.quality]
                              + (["--sphere", args.sphere] if args.sphere else []),
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if done.returncode == 1:
            sys.exit(done.stderr)
        failed |= done.returncode != 0
        for line in done.stdout.splitlines():
            (rows if line.startswith("|") else notes).append(line)
        print("\n".join(line for line in done.stdout.splitlines() if not line.startswith("|")), file=sys.stderr)
    kinds = []
    for r in rows:
        if r.split("|")[2] not in kinds:
            kinds.append(r.split("|")[2])
    rows.sort(key=lambda r: (args.scenes.index(r.split("|")[1].strip()), kinds.index(r.split("|")[2]),
                             int(r.split("|")[3])))
    print("| scene | rays | threads | ours Mrays/s | Embree Mrays/s | ours ÷ Embree |")
    print("|---|---|---|---:|---:|---:|")
    print("\n".join(rows))
    print()
    print("\n".join(n for n in notes if n.startswith("# agreement") or n.startswith("  disagreement")))
    sys.exit(2 if failed else 0)


if __name__ == "__main__":
    main()
