#!/usr/bin/env python3
"""Damage of the CKI mode-I square at its output records: a PNG of the last record (and of the
record nearest the middle of the run), points coloured by Damage; a 3D slab (cki_mode_i_3d.e) is
drawn from above, each column of points coloured by its largest damage through the thickness.
Usage:
    /usr/bin/python3 plot_damage.py cki_mode_i.e [--check]  -> cki_mode_i_damage.png
--check (exit status 1 when it fails): at the last record the crack (points damaged > 0.3 right
of the pre-crack tip) has reached x >= 0.9 m, and no point farther than 0.06 m from the crack
line y = 0.5 m is damaged > 0.3 (one clean crack, no diffuse damage: the paper's Fig. 5).
Needs python3-netcdf4 and python3-matplotlib (Debian)."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import netCDF4
import numpy as np


def names(ds, var):
    return ["".join(c.decode() for c in row if c).strip() for row in ds.variables[var][:].data]


def main(path):
    ds = netCDF4.Dataset(path)
    x = ds.variables["coordx"][:]
    y = ds.variables["coordy"][:]
    times = ds.variables["time_whole"][:]
    k = names(ds, "name_elem_var").index("Damage") + 1
    # One block of one-node elements, in node order (Peridot's layout).
    damage = np.asarray(ds.variables[f"vals_elem_var{k}eb1"][:])
    if "coordz" in ds.variables:  # 3D: one column per (x, y), its largest damage
        key = np.round(np.c_[x, y] / 1e-9).astype(np.int64)
        columns, inverse = np.unique(key, axis=0, return_inverse=True)
        inverse = inverse.ravel()
        column_damage = np.zeros((damage.shape[0], len(columns)))
        for r in range(damage.shape[0]):
            np.maximum.at(column_damage[r], inverse, damage[r])
        x, y, damage = columns[:, 0] * 1e-9, columns[:, 1] * 1e-9, column_damage
    records = sorted({len(times) // 2, len(times) - 1})
    fig, axes = plt.subplots(1, len(records), figsize=(5.5 * len(records), 5), squeeze=False)
    for ax, r in zip(axes[0], records):
        sc = ax.scatter(x, y, c=damage[r], s=3, cmap="inferno", vmin=0, vmax=0.6)
        ax.set_aspect("equal")
        ax.set_title(f"t = {times[r] * 1e3:.3f} ms")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
    fig.colorbar(sc, ax=axes[0].tolist(), label="damage")
    out = path.rsplit(".", 1)[0] + "_damage.png"
    fig.savefig(out, dpi=120)
    print("wrote", out)
    # The crack path: the damaged points (> 0.3) right of the pre-crack tip, their y spread.
    last = damage[-1]
    ahead = (last > 0.3) & (x > 0.5)
    if ahead.any():
        print(f"damaged points ahead of the tip: {ahead.sum()}, x up to {x[ahead].max():.3f} m, "
              f"y in [{y[ahead].min():.3f}, {y[ahead].max():.3f}] m")
    else:
        print("no damage ahead of the pre-crack tip")
    off = (last > 0.3) & (np.abs(y - 0.5) > 0.06)
    print(f"points damaged > 0.3 farther than 0.06 m from the crack line: {off.sum()}")
    return bool(ahead.any() and x[ahead].max() >= 0.9 and not off.any())


if __name__ == "__main__":
    files = [a for a in sys.argv[1:] if not a.startswith("--")]
    ok = main(files[0] if files else "cki_mode_i.e")
    if "--check" in sys.argv[1:]:
        print("check one clean crack through:", "ok" if ok else "FAILED")
        sys.exit(0 if ok else 1)
