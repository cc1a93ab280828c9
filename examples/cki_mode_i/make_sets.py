#!/usr/bin/env python3
"""Mesh and node sets of the CKI mode-I square (cki_mode_i.yaml): a 100 x 100 grid of cell
centres (dx = 10 mm, area dx^2) as a planar text mesh, and the three bottom and three top rows
(ids are the 1-based line numbers of the points, x fastest).

With --3d, those of the 3D slab (cki_mode_i_3d.yaml, the paper's 3D setup): 60 x 60 x 3 cell
centres (dx = l/60 = 16.7 mm, volume dx^3) in slab.txt, and the three bottom and three top rows
through the thickness in slab_bottom.txt, slab_top.txt."""
import sys

if "--3d" in sys.argv[1:]:
    n, layers = 60, 3
    dx = 1.0 / n
    ids = lambda i, j, k: 1 + i + n * j + n * n * k  # noqa: E731
    with open("slab.txt", "w") as f:
        f.write("# x y z block volume\n")
        for k in range(layers):
            for j in range(n):
                for i in range(n):
                    f.write(f"{(i + 0.5) * dx!r} {(j + 0.5) * dx!r} {(k + 0.5) * dx!r} 1 "
                            f"{dx**3!r}\n")
    with open("slab_bottom.txt", "w") as f:
        f.write("\n".join(str(ids(i, j, k)) for k in range(layers) for j in range(3)
                          for i in range(n)) + "\n")
    with open("slab_top.txt", "w") as f:
        f.write("\n".join(str(ids(i, j, k)) for k in range(layers) for j in range(n - 3, n)
                          for i in range(n)) + "\n")
    sys.exit(0)
n, dx = 100, 0.01
with open("square.txt", "w") as f:
    f.write("# x y z block area\n")
    for j in range(n):
        for i in range(n):
            f.write(f"{(i + 0.5) * dx:.6f} {(j + 0.5) * dx:.6f} 0 1 {dx * dx:.6e}\n")
with open("bottom.txt", "w") as f:
    f.write("\n".join(str(1 + i + n * j) for j in range(3) for i in range(n)) + "\n")
with open("top.txt", "w") as f:
    f.write("\n".join(str(1 + i + n * j) for j in range(n - 3, n) for i in range(n)) + "\n")
