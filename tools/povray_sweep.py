#!/usr/bin/python3
"""Random scenes rendered by raytrace and by real POV-Ray 3.7, compared pixel by pixel.

    tools/povray_sweep.py [--bin build/raytrace] [--seeds 1-30] [--size 320x240] [--work DIR] [--limit 0.5]

Needs POV-Ray (`apt-get install -y povray`) and ../shared/tools/povref, which makes POV-Ray compute the course's
shading model (its README says what it reproduces exactly). Each seed gives a course-format scene that neither
suite has: a camera aimed near the origin from 12–18 units, 1–3 lights, 4–10 objects of every kind with random
materials (a third reflective, a third glass with an rgbf filter and an ior of 1.3–1.8, specular highlights of
any roughness) and 1–4 random transforms each (non-uniform scales, rotations about several axes, and planes
turned and moved too). For each scene, `raycast` is compared with povref's flat colours (the geometry), and
`render` with povref's course model, in turn plain, with `-beers` and with `-ss=3`. Printed: the
percentage of pixels whose largest channel differs by more than 8/255; the exit status is 1 when any exceeds
--limit.

Objects are placed apart from one another. Where a glass object overlaps another, the two models differ on
purpose: the course bends a ray entering glass by 1/ior whatever it leaves, while POV-Ray keeps a stack of the
media it is inside.
"""

import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
POVREF = os.path.join(ROOT, "..", "shared", "tools", "povref")
# Our flags for `render`, and povref's for the same model; seed s uses entry s mod 3. Not `-fresnel`: povref's
# emulation of it lets POV-Ray add an unweighted mirror ray wherever a ray reflects totally inside glass (its
# README: 1.3 % of the official checkerbox image off by more than 8/255).
VARIANTS = [([], []), (["-beers"], ["--beers"]), (["-ss=3"], ["--aa", "3"])]


def vector(values):
    return "<%s>" % ", ".join("%.3f" % (v + 0.0) for v in values)  # + 0.0 turns -0.0 into 0.0


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    n = math.sqrt(sum(x * x for x in a))
    return [x / n for x in a]


def shape(kind, rng):
    """The statement's opening and the radius of a sphere about the origin that holds the shape."""
    if kind == "sphere":
        centre, radius = [rng.uniform(-1, 1) for _ in range(3)], rng.uniform(0.6, 1.6)
        return "sphere { %s, %.3f" % (vector(centre), radius), math.dist(centre, [0, 0, 0]) + radius
    if kind == "box":
        low, high = [rng.uniform(-1.5, -0.3) for _ in range(3)], [rng.uniform(0.3, 1.5) for _ in range(3)]
        corner = [max(-a, b) for a, b in zip(low, high)]
        return "box { %s, %s" % (vector(low), vector(high)), math.dist(corner, [0] * 3)
    if kind in ("cone", "cylinder"):
        half = rng.uniform(0.5, 1.5)
        axis = [half * x for x in unit([rng.uniform(-1, 1) for _ in range(3)])]
        base = [-x for x in axis]
        if kind == "cylinder":
            radius = rng.uniform(0.3, 1.0)
            return "cylinder { %s, %s, %.3f" % (vector(base), vector(axis), radius), math.hypot(half, radius)
        radii = [rng.uniform(0.5, 1.5), rng.choice([0.0, rng.uniform(0.1, 0.8)])]  # a point at either end, or none
        rng.shuffle(radii)
        opening = "cone { %s, %.3f, %s, %.3f" % (vector(base), radii[0], vector(axis), radii[1])
        return opening, math.hypot(half, max(radii))
    corners = [[rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-1, 1)] for _ in range(3)]
    return "triangle { %s, %s, %s" % tuple(vector(c) for c in corners), max(math.dist(c, [0] * 3) for c in corners)


def material(kind, rng):
    glass = kind not in ("plane", "triangle") and rng.random() < 0.3
    colour = [rng.uniform(0.5 if glass else 0.1, 1.0) for _ in range(3)]
    pigment = ("rgbf %s" % vector(colour + [rng.uniform(0.4, 0.95)])) if glass else "rgb %s" % vector(colour)
    finish = "ambient %.3f diffuse %.3f" % (rng.uniform(0.05, 0.3), rng.uniform(0.3, 0.9))
    if rng.random() < 0.6:
        finish += " specular %.3f roughness %.3f" % (rng.uniform(0.1, 1.0), rng.choice([0.01, 0.05, 0.1, 0.5, 0.9]))
    if rng.random() < 0.3:
        finish += " reflection %.3f" % rng.uniform(0.1, 0.7)
    if glass:
        finish += " refraction 1 ior %.3f" % rng.uniform(1.3, 1.8)
    return "  pigment { color %s }\n  finish { %s }" % (pigment, finish)


def transforms(rng):
    """1-4 random steps, the most they can grow a shape's radius by, and the farthest they can move it."""
    steps, grow, moved = [], 1.0, 0.0
    for _ in range(rng.randint(1, 4)):
        kind = rng.choice(["scale", "rotate", "rotate", "translate"])
        if kind == "scale":
            factors = [rng.uniform(0.4, 1.8) for _ in range(3)]
            grow, moved = grow * max(factors), moved * max(factors)
            steps.append("scale " + vector(factors))
        elif kind == "rotate":
            angles = [0.0] * 3
            for axis in rng.sample(range(3), rng.randint(1, 3)):
                angles[axis] = rng.uniform(-90, 90)
            steps.append("rotate " + vector(angles))
        else:
            offset = [rng.uniform(-1, 1) for _ in range(3)]
            moved += math.dist(offset, [0] * 3)
            steps.append("translate " + vector(offset))
    return steps, grow, moved


def scene(seed):
    rng = random.Random(seed)
    distance = rng.uniform(12, 18)
    azimuth, elevation = math.radians(rng.uniform(-40, 40)), math.radians(rng.uniform(-5, 30))
    location = [distance * math.cos(elevation) * math.sin(azimuth), distance * math.sin(elevation),
                distance * math.cos(elevation) * math.cos(azimuth)]
    look_at = [rng.uniform(-1, 1) for _ in range(3)]
    ahead = unit([a - b for a, b in zip(look_at, location)])
    right = unit(cross(ahead, [0, 1, 0]))
    up = cross(right, ahead) if rng.random() < 0.7 else [0, 1, 0]  # `up` need not be at right angles
    text = ["// tools/povray_sweep.py, seed %d" % seed,
            "camera {\n  location %s\n  up %s\n  right %s\n  look_at %s\n}" % (
                vector(location), vector(up), vector([1.33333 * x for x in right]), vector(look_at))]
    for _ in range(rng.randint(1, 3)):
        position = [rng.uniform(-20, 20), rng.uniform(5, 25), rng.uniform(-5, 25)]
        text.append("light_source { %s color rgb %s }" % (vector(position), vector([rng.uniform(0.5, 1.3)] * 3)))

    solids = ["sphere", "box", "cone", "cylinder", "triangle"]
    count = rng.randint(4, 10)
    kinds = rng.sample(solids, min(count, len(solids)))
    kinds += [rng.choice(solids) for _ in range(count - len(kinds))]
    if rng.random() < 0.8:
        kinds[rng.randrange(count)] = "plane"
    placed = []  # (centre, radius) of the objects so far
    for kind in kinds:
        if kind == "plane":
            floor = rng.random() < 0.6
            opening = "plane { %s, %.3f" % ("<0, 1, 0>" if floor else "<0, 0, 1>", rng.uniform(-4, -2) if floor
                                            else rng.uniform(-12, -6))
            steps = ["rotate " + vector([rng.uniform(-15, 15), rng.uniform(-30, 30), rng.uniform(-15, 15)]),
                     "translate " + vector([rng.uniform(-1, 1) for _ in range(3)]),
                     "scale " + vector([rng.uniform(0.5, 2), rng.uniform(0.7, 1.5), rng.uniform(0.5, 2)])]
            steps = [s for s in steps if rng.random() < 0.6]
            rng.shuffle(steps)
        else:
            opening, radius = shape(kind, rng)
            steps, grow, moved = transforms(rng)
            radius = radius * grow + moved
            for _ in range(200):
                centre = [rng.uniform(-4.5, 4.5), rng.uniform(-2.5, 2.5), rng.uniform(-3, 2)]
                if all(math.dist(centre, c) > radius + r for c, r in placed):
                    break
            placed.append((centre, radius))
            steps.append("translate " + vector(centre))
        text.append("%s\n%s\n%s\n}" % (opening, material(kind, rng), "\n".join("  " + s for s in steps)))
    return "\n".join(text) + "\n"


def run(command, cwd):
    done = subprocess.run(command, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(command), done.stderr))


def differing(ours, theirs, cwd):
    """Percentage of pixels whose largest channel differs by more than 8/255."""
    done = subprocess.run([sys.executable, os.path.join(POVREF, "imgdiff.py"), ours, theirs, "--json"], cwd=cwd,
                          capture_output=True, text=True, check=True)
    return 100 * json.loads(done.stdout)["frac_gt8"]


def seeds(text):
    first, _, last = text.partition("-")
    return range(int(first), int(last or first) + 1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default="build/raytrace", help="our executable")
    ap.add_argument("--seeds", default="1-30", type=seeds, help="a seed or a range, as 1-30")
    ap.add_argument("--size", default="320x240")
    ap.add_argument("--work", default="build/povray-sweep", help="directory for scenes and images")
    ap.add_argument("--limit", type=float, default=0.5, help="the most differing pixels allowed, in percent")
    args = ap.parse_args()
    binary, work = os.path.abspath(args.bin), os.path.abspath(args.work)
    width, height = args.size.split("x")
    povref = [sys.executable, os.path.join(POVREF, "povref.py")]

    print("| seed | geometry, % | render, % | flags |\n|---|---|---|---|")
    worst = 0.0
    for seed in args.seeds:
        folder = os.path.join(work, "seed%d" % seed)
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, "scene.pov"), "w") as f:
            f.write(scene(seed))
        ours, theirs = VARIANTS[seed % len(VARIANTS)]
        run([binary, "raycast", "scene.pov", width, height], folder)
        shutil.move(os.path.join(folder, "output.png"), os.path.join(folder, "ours_flat.png"))
        run(povref + ["scene.pov", width, height, "povray_flat.png", "--model", "course", "--mode", "flat"], folder)
        run([binary, "render", "scene.pov", width, height, "--quiet"] + ours, folder)
        shutil.move(os.path.join(folder, "output.png"), os.path.join(folder, "ours.png"))
        run(povref + ["scene.pov", width, height, "povray.png", "--model", "course"] + theirs, folder)
        flat = differing("ours_flat.png", "povray_flat.png", folder)
        full = differing("ours.png", "povray.png", folder)
        worst = max(worst, flat, full)
        print("| %d | %.3f | %.3f | %s |" % (seed, flat, full, " ".join(ours) or "–"), flush=True)
    print("\nWorst: %.3f %% of pixels off by more than 8/255 (limit %.3f %%)." % (worst, args.limit))
    return 1 if worst > args.limit else 0


if __name__ == "__main__":
    sys.exit(main())
