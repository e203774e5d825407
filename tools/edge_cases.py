#!/usr/bin/python3
"""The accuracy edge cases (scenes/stability/edge_*.pov) against real POV-Ray 3.7, pixel by pixel.

    tools/edge_cases.py [--bin build/raytrace] [--before OTHER_BINARY] [--size 640x480] [--work DIR]
                         [--povref DIR]

Needs POV-Ray (`apt-get install -y povray`) and ../shared/tools/povref (see tools/povray_sweep.py). Each scene
is drawn by `raycast` (compared with povref's flat colours: the geometry) and by `render` (compared with
povref's course model: the shading), at default settings, then with --precision=double; with --before, also
by another build at default settings. Printed: a Markdown table of the pixels whose largest channel differs
from POV-Ray's by more than 8/255 (docs/accuracy.md keeps the latest one).
"""

import argparse
import glob
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
POVREF = os.path.join(ROOT, "..", "shared", "tools", "povref")


def differing(a, b):
    """Pixels whose largest channel differs by more than 8/255."""
    import numpy as np
    from PIL import Image
    x = np.asarray(Image.open(a).convert("RGB")).astype(int)
    y = np.asarray(Image.open(b).convert("RGB")).astype(int)
    return int((np.abs(x - y).max(axis=2) > 8).sum())


def ours(binary, command, scene, size, flags, out):
    subprocess.run([os.path.abspath(binary), command, scene, *size] + flags, cwd=os.path.dirname(out), check=True,
                   stdout=subprocess.DEVNULL)
    os.replace(os.path.join(os.path.dirname(out), "output.png"), out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "raytrace"))
    ap.add_argument("--before", help="another build to compare at default settings")
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--work", default="/tmp/raytrace-edge-cases")
    ap.add_argument("--povref", default=POVREF, help="the povref folder (default ../shared/tools/povref)")
    args = ap.parse_args()
    size = args.size.split("x")
    os.makedirs(args.work, exist_ok=True)
    runs = ([("before", args.before, [])] if args.before else []) + [("after", args.bin, []),
                                                                     ("double", args.bin, ["--precision=double"])]
    names = [r[0] for r in runs]
    print("| scene | raycast: " + " / ".join(names) + " | render: " + " / ".join(names) + " |")
    print("|---|---|---|")
    for scene in sorted(glob.glob(os.path.join(ROOT, "scenes", "stability", "edge_*.pov"))):
        name = os.path.basename(scene)[:-4]
        row = []
        for command, mode in (("raycast", ["--mode", "flat"]), ("render", ["--model", "course"])):
            reference = os.path.join(args.work, "%s.%s.pov.png" % (name, command))
            if not os.path.exists(reference):
                subprocess.run([os.path.join(args.povref, "povref.py"), scene, *size, reference, *mode, "--threads", "2"],
                               check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            counts = []
            for label, binary, flags in runs:
                out = os.path.join(args.work, "%s.%s.%s.png" % (name, command, label))
                ours(binary, command, scene, size, flags, out)
                counts.append(str(differing(out, reference)))
            row.append(" / ".join(counts))
        print("| %s | %s |" % (name, " | ".join(row)))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
