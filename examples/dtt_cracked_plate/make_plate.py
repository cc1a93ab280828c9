#!/usr/bin/env python3
"""Writes plate.txt (x y z block volume, one point per cell centre) and the node-set files
top.txt / bottom.txt (1-based ids of the points within one horizon of the loaded edges)."""
nx, ny, nz = 80, 32, 2          # cells along x, y, z
dx = 0.5e-3                     # cell size [m]: a 40 x 16 x 1 mm plate
horizon = 1.5e-3                # must match the deck (3 dx)
ly = ny * dx
with open("plate.txt", "w") as f, open("top.txt", "w") as top, open("bottom.txt", "w") as bottom:
    f.write("# x y z block_id volume\n")
    pid = 1
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                x, y, z = (i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx
                f.write(f"{x:.6e} {y:.6e} {z:.6e} 1 {dx**3:.6e}\n")
                if y > ly - horizon:
                    top.write(f"{pid}\n")
                if y < horizon:
                    bottom.write(f"{pid}\n")
                pid += 1
