#!/usr/bin/env python3
"""Mesh and node sets of the CKI mode-I square (cki_mode_i.yaml): a 100 x 100 grid of cell
centres (dx = 10 mm, area dx^2) as a planar text mesh, and the three bottom and three top rows
(ids are the 1-based line numbers of the points, x fastest)."""
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
