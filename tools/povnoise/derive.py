#!/usr/bin/env python3
"""Measure POV-Ray's noise table from the installed `povray` and check the model of docs/povray-noise.md.

Prints the 267 numbers of src/surface/noise.cpp's table, then the largest difference between the model and
POV-Ray's f_noise3d at random points. Needs only povray; about ten seconds.
"""
import math
import os
import random
import subprocess
import sys
import tempfile


def ask(points, expr, generator=2):
    """POV-Ray's values of `expr` (in X, Y, Z; a float or a vector) at each point."""
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "in.txt"), "w") as f:
            f.writelines(f"{x!r}, {y!r}, {z!r},\n" for x, y, z in points)
        scene = f"""#version 3.7;
global_settings {{ noise_generator {generator} }}
#include "functions.inc"
#fopen I "in.txt" read
#fopen O "out.txt" write
#while (defined(I))
  #read (I, X, Y, Z)
  #local V = {expr} + <0, 0, 0>;
  #write (O, vstr(3, V, " ", 0, 16), "\\n")
#end
#fclose O
camera {{ location -z look_at 0 }}
"""
        with open(os.path.join(d, "probe.pov"), "w") as f:
            f.write(scene)
        subprocess.run(["povray", "+Iprobe.pov", "+W1", "+H1", "-D", "-GA", "+O/dev/null"], cwd=d,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        with open(os.path.join(d, "out.txt")) as f:
            rows = [tuple(map(float, line.split())) for line in f if line.strip()]
    return rows[:len(points)]


def permutation():
    t, state = list(range(4096)), 0
    for i in range(4095, -1, -1):
        state = (state * 1812433253 + 12345) & 0xFFFFFFFF
        j = ((state >> 16) & 0x7FFF) % 4096
        t[i], t[j] = t[j], t[i]
    return t


T = permutation()


def entry(ix, iy, iz):
    return T[T[T[ix & 4095] ^ (iy & 4095)] ^ (iz & 4095)] & 255


def six_digits(v):
    return float(f"{v:.6g}")


def main():
    # One lattice point per entry; the noise there is the entry's value R[e]/2, through generator 2's stretch.
    where = {}
    for ix in range(-40, 40):
        for iy in range(-40, 40):
            where.setdefault(entry(ix + 10000, iy + 10000, 10000), (ix, iy, 0))
    if len(where) < 256:
        sys.exit("not every entry was found")
    points = [where[e] for e in range(256)]
    stretched = [row[0] for row in ask(points, "f_noise3d(X, Y, Z)")]
    table = [six_digits(2 * (v / 0.48985582 - 1.05242)) for v in stretched]
    # The vector noise's y and z components at the last entries (R[e+4]/2 and R[e+8]/2) give R[256..263];
    # the z component's gradient at entry 255 the rest.
    vector = ask(points[251:], "vturbulence(2, 0.5, 1, <X, Y, Z>)")
    table += [six_digits(2 * row[1]) for row in vector[1:4]]
    table += [six_digits(2 * row[2]) for row in vector]
    h = 1e-7
    x, y, z = points[255]
    beside = [(x + h, y, z), (x - h, y, z), (x, y + h, z), (x, y - h, z), (x, y, z + h), (x, y, z - h)]
    rows = ask(beside, "vturbulence(2, 0.5, 1, <X, Y, Z>)")
    table += [six_digits((rows[2 * a][2] - rows[2 * a + 1][2]) / (2 * h)) for a in range(3)]
    print(", ".join(f"{v:.6g}" for v in table))

    def model(p):
        q = [c + 10000.0 for c in p]
        i = [math.floor(c) for c in q]
        f = [a - b for a, b in zip(q, i)]
        s = [c * c * (3 - 2 * c) for c in f]
        total = 0.0
        for corner in range(8):
            o = [corner >> 2 & 1, corner >> 1 & 1, corner & 1]
            w = math.prod(s[a] if o[a] else 1 - s[a] for a in range(3))
            e = entry(*(i[a] + o[a] for a in range(3)))
            total += w * (table[e] / 2 + sum(table[e + 1 + a] * (f[a] - o[a]) for a in range(3)))
        return min(max((total + 1.05242) * 0.48985582, 0.0), 1.0)

    rng = random.Random(1)
    sample = [tuple(rng.uniform(-100, 100) for _ in range(3)) for _ in range(500)]
    worst = max(abs(model(p) - row[0]) for p, row in zip(sample, ask(sample, "f_noise3d(X, Y, Z)")))
    print(f"# largest difference from POV-Ray's f_noise3d at 500 random points: {worst:.3g}")


if __name__ == "__main__":
    main()
