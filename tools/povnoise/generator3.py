#!/usr/bin/env python3
"""Check the model of noise_generator 3 (docs/povray-noise.md, "Generator 3") against the installed `povray`.

Measures the gradient at a few lattice corners from POV-Ray's values along the lattice's edges, shows each is
an entry of the table drawn from rand() seeded with 1, then prints the largest difference between the model and
POV-Ray's f_noise3d at random points. Needs only povray; a few seconds.
"""
import math
import random

from derive import ask

SHIFT = 10000000 + 12432434 * 2.0 ** -29  # the double nearest 10000000.023157213
FRACTION = SHIFT - 10000000


def tables():
    state = 1

    def rand():
        nonlocal state
        state = (state * 1812433253 + 12345) & 0xFFFFFFFF
        return (state >> 16) & 0x7FFF

    gradients = []
    while len(gradients) < 2048:
        v = [rand() % 4096 - 2048 for _ in range(3)]
        length2 = sum(c * c for c in v)
        if length2 <= 2048 * 2048:
            gradients.append([c / math.sqrt(length2) for c in v])
    p = list(range(2048)) + [0]
    for i in range(2048, 0, -2):
        j = rand() % 2048
        p[i], p[j] = p[j], p[i]
    return gradients, p[:2048] * 2


GRADIENTS, P = tables()


def s_curve(t):
    return t * t * (3 - 2 * t)


def entry(ix, iy, iz):
    return (P[P[ix & 2047] + (iy & 2047)] + (iz & 2047)) & 2047


def model(point):
    q = [c + SHIFT for c in point]
    i = [math.floor(c) for c in q]
    f = [a - b for a, b in zip(q, i)]
    s = [s_curve(t) for t in f]
    total = 0.0
    for corner in range(8):
        o = [corner >> 2 & 1, corner >> 1 & 1, corner & 1]
        w = math.prod(s[a] if o[a] else 1 - s[a] for a in range(3))
        g = GRADIENTS[entry(*(int(i[a]) + o[a] for a in range(3)))]
        total += w * sum(g[a] * (f[a] - o[a]) for a in range(3))
    return min(max(0.4925 + 0.795 * total, 0.0), 1.0)


def slope_at_corner(corner, axis):
    """0.795 times the corner's gradient along axis, from POV-Ray's values on the edge leaving it: there only the
    edge's two corners count, so four values fit their two slopes exactly."""
    points, rows = [], []
    for n in range(1, 5):
        p = [c - FRACTION for c in corner]
        p[axis] += n / 5
        points.append(tuple(p))
        t = p[axis] + SHIFT - math.floor(p[axis] + SHIFT)
        rows.append(((1 - s_curve(t)) * t, s_curve(t) * (t - 1)))
    values = [row[0] - 0.4925 for row in ask(points, "f_noise3d(X, Y, Z)", generator=3)]
    # least squares for two unknowns: the normal equations
    aa = sum(r[0] * r[0] for r in rows)
    ab = sum(r[0] * r[1] for r in rows)
    bb = sum(r[1] * r[1] for r in rows)
    av = sum(r[0] * v for r, v in zip(rows, values))
    bv = sum(r[1] * v for r, v in zip(rows, values))
    return (av * bb - bv * ab) / (aa * bb - ab * ab)


def main():
    base = int(math.floor(SHIFT))
    for corner in [(0, 0, 0), (1, 2, 3), (-5, 7, 2)]:
        measured = [slope_at_corner(corner, axis) / 0.795 for axis in range(3)]
        expected = GRADIENTS[entry(*(base + c for c in corner))]
        print(corner, " ".join(f"{v:.15f}" for v in measured), "table:",
              f"{max(abs(a - b) for a, b in zip(measured, expected)):.2g}")
    rng = random.Random(1)
    sample = [tuple(rng.uniform(-100, 100) for _ in range(3)) for _ in range(2000)]
    worst = max(abs(model(p) - row[0]) for p, row in zip(sample, ask(sample, "f_noise3d(X, Y, Z)", generator=3)))
    print(f"# largest difference from POV-Ray's f_noise3d (noise_generator 3) at 2000 random points: {worst:.3g}")


if __name__ == "__main__":
    main()
