#!/usr/bin/env python3
"""Large meshes against POV-Ray 3.7: one mesh2 of a million triangles, and 10,000 instances of a 100k-triangle
mesh (`object { M }` shares the declared mesh). Prints wall time and peak memory of each renderer, medians of
--runs, for the table in docs/performance.md ("Large meshes")."""
import argparse
import math
import os
import re
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def grid_mesh(f, n):
    """A wavy n×n grid over the unit square: 2(n−1)² triangles."""
    f.write('mesh2 { vertex_vectors { %d\n' % (n * n))
    for j in range(n):
        f.write(''.join('<%.5f,%.5f,%.5f>,' % (i / (n - 1) - 0.5,
                                               0.1 * math.sin(6 * i / (n - 1)) * math.cos(6 * j / (n - 1)),
                                               j / (n - 1) - 0.5) for i in range(n)))
        f.write('\n')
    f.write('}\nface_indices { %d\n' % (2 * (n - 1) * (n - 1)))
    for j in range(n - 1):
        f.write(''.join('<%d,%d,%d>,<%d,%d,%d>,' % (a, a + 1, a + n, a + 1, a + n + 1, a + n)
                        for a in range(j * n, j * n + n - 1)))
        f.write('\n')
    f.write('}\npigment { rgb <0.8,0.6,0.4> } }\n')


HEAD = ('#version 3.7;\nglobal_settings { assumed_gamma 1 }\n'
        'camera { location %s look_at %s angle 60 }\nlight_source { <0,200,-100> rgb 1 }\n')


def write_scenes(folder):
    os.makedirs(folder, exist_ok=True)
    one = os.path.join(folder, 'mesh1m.pov')
    with open(one, 'w') as f:
        f.write(HEAD % ('<0,1.2,-1>', '<0,0,0>'))
        grid_mesh(f, 708)  # 2·707² = 999,698 triangles
    many = os.path.join(folder, 'instances10k.pov')
    with open(many, 'w') as f:
        f.write(HEAD % ('<50,80,-60>', '<50,0,50>'))
        f.write('#declare M = ')
        grid_mesh(f, 224)  # 2·223² = 99,458 triangles
        f.write('#for (J, 0, 99) #for (I, 0, 99)\n  object { M rotate y*(I*7+J*13) translate <I,0,J> }\n#end #end\n')
    return [one, many]


def measure(cmd, cwd):
    """Wall seconds and peak resident MiB of one run, from GNU time."""
    run = subprocess.run(['/usr/bin/time', '-f', 'TIME %e %M'] + cmd, cwd=cwd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit('failed: %s\n%s' % (' '.join(cmd), run.stderr[-2000:]))
    seconds, kib = re.findall(r'TIME ([0-9.]+) ([0-9]+)', run.stderr)[-1]
    return float(seconds), int(kib) / 1024


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument('--bin', default=os.path.join(ROOT, 'build', 'raytrace'))
    ap.add_argument('--runs', type=int, default=3)
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--size', default='640x480')
    args = ap.parse_args()
    width, height = args.size.split('x')
    folder = os.path.join(ROOT, 'build', 'bench-meshes')
    print('| scene | triangles drawn | raytrace s | POV-Ray s | ratio | raytrace MiB | POV-Ray MiB |')
    print('|---|---|---|---|---|---|---|')
    for scene in write_scenes(folder):
        name = os.path.basename(scene)
        ours = [measure([args.bin, 'render', name, width, height, '-o', 'ours.png', '--threads', str(args.threads)],
                        folder) for _ in range(args.runs)]
        theirs = [measure(['povray', '+I' + name, '+W' + width, '+H' + height, '-A', '+Oref.png', '-D', '-V',
                           '+WT%d' % args.threads], folder) for _ in range(args.runs)]
        t0, t1 = statistics.median(r[0] for r in ours), statistics.median(r[0] for r in theirs)
        m0, m1 = statistics.median(r[1] for r in ours), statistics.median(r[1] for r in theirs)
        drawn = '999,698' if name == 'mesh1m.pov' else '10,000 × 99,458'
        print('| %s | %s | %.2f | %.2f | %.1f× | %.0f | %.0f |' % (name, drawn, t0, t1, t1 / t0, m0, m1))


if __name__ == '__main__':
    main()
