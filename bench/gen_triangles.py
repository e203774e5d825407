#!/usr/bin/python3
"""A scene of about a million triangles: a jittered field of geodesic spheres on a plane, one light.

    bench/gen_triangles.py OUT.pov [--spheres 800] [--subdivisions 3]

Each sphere is an icosahedron whose faces are split in four `subdivisions` times (20·4^s triangles: 1280 for
s = 3), lifted onto the sphere; 800 of them make 1,024,000 triangles. The field and camera are bench/scaling.py's
(write_field), so the picture resembles its sphere scenes. Deterministic (fixed seed); the file is about
120 MB and never committed.
"""

import argparse
import math

from scaling import write_field


def icosphere(subdivisions):
    """Unit-sphere vertices and triangles (index triples) of a subdivided icosahedron."""
    g = (1 + 5 ** 0.5) / 2
    verts = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g), (0, -1, -g), (0, 1, -g),
             (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    verts = [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in verts]
    for _ in range(subdivisions):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                m = [(verts[a][i] + verts[b][i]) / 2 for i in range(3)]
                n = math.sqrt(sum(x * x for x in m))
                verts.append(tuple(x / n for x in m))
                middle[key] = len(verts) - 1
            return middle[key]

        split = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = split
    return verts, faces


def write_scene(path, spheres, subdivisions):
    verts, faces = icosphere(subdivisions)
    describe = lambda cols, rows: ("%d geodesic spheres of %d triangles (%d in all) on a plane, 1 light "
                                   "(bench/gen_triangles.py)" % (spheres, len(faces), spheres * len(faces)))
    with open(path, "w") as f:
        for x, y, z, r, rng in write_field(f, spheres, 1024, describe):
            colour = "pigment { color rgb <%.3f, %.3f, %.3f> }" % (rng.uniform(0.1, 1), rng.uniform(0.1, 1),
                                                                   rng.uniform(0.1, 1))
            p = ["<%.5f, %.5f, %.5f>" % (x + r * v[0], y + r * v[1], z + r * v[2]) for v in verts]
            f.writelines("triangle { %s, %s, %s %s }\n" % (p[a], p[b], p[c], colour) for a, b, c in faces)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--spheres", type=int, default=800)
    ap.add_argument("--subdivisions", type=int, default=3)
    args = ap.parse_args()
    write_scene(args.out, args.spheres, args.subdivisions)


if __name__ == "__main__":
    main()
