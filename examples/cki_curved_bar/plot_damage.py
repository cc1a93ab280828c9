#!/usr/bin/env python3
"""doc/figures/cki_curved_bar_damage.png: damage of the CKI curved bar at a few times (a run with
damage) and, below, the largest bond stretch away from the loaded ends against time in a run at
the paper's load, against the critical stretch. Usage:
    /usr/bin/python3 plot_damage.py DAMAGED.e PAPER_LOAD.e [--times 0.4e-3 2.9e-3 5.8e-3]
        [--png cki_curved_bar_damage.png]
Needs python3-netcdf4, python3-matplotlib and python3-scipy (Debian)."""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import netCDF4
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from analyse import critical_stretch, names, read_so, stretch_history  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("damaged")
    ap.add_argument("paper_load")
    ap.add_argument("--times", type=float, nargs="*", default=[0.4e-3, 2.9e-3, 5.8e-3])
    ap.add_argument("--png", default="cki_curved_bar_damage.png")
    a = ap.parse_args()
    fig = plt.figure(figsize=(9, 2.3 * len(a.times) + 2.8))
    grid = fig.add_gridspec(len(a.times) + 1, 1, height_ratios=[1] * len(a.times) + [1.2])
    ds = netCDF4.Dataset(a.damaged)
    x, y = np.asarray(ds.variables["coordx"][:]), np.asarray(ds.variables["coordy"][:])
    times = np.asarray(ds.variables["time_whole"][:])
    k = names(ds, "name_elem_var").index("Damage") + 1
    damage = ds.variables[f"vals_elem_var{k}eb1"]
    label = os.path.basename(a.damaged).rsplit(".", 1)[0]
    for n, t in enumerate(a.times):
        r = int(np.argmin(abs(times - t)))
        ax = fig.add_subplot(grid[n])
        sc = ax.scatter(x, y, c=damage[r], s=0.5, cmap="inferno", vmin=0, vmax=1, linewidths=0)
        ax.set_aspect("equal")
        ax.set_xlim(-0.56, 0.56)
        ax.set_ylim(0.64, 1.06)
        ax.set_title(f"damage, {label}, t = {times[r] * 1e3:.2f} ms", fontsize=9)
        ax.set_ylabel("y [m]", fontsize=8)
        ax.tick_params(labelsize=7)
    fig.colorbar(sc, ax=fig.axes, shrink=0.5, label="damage", location="right")
    base = a.paper_load.rsplit(".", 1)[0]
    s, o, S, W, delta = read_so(base + "_so.txt")
    ds2 = netCDF4.Dataset(a.paper_load)
    t2 = np.asarray(ds2.variables["time_whole"][:])
    hist = stretch_history(ds2, s, S, delta)
    st = np.array([h[0] for h in hist])
    mid = np.array([S / 3 <= h[1] <= 2 * S / 3 for h in hist])
    sc_ = critical_stretch(delta)
    ax = fig.add_subplot(grid[-1])
    ax.plot(t2 * 1e3, st / sc_, lw=0.8, color="0.4", label="largest stretch away from the ends")
    ax.plot(t2[mid] * 1e3, st[mid] / sc_, ".", ms=2, color="C3", label="... when in the middle third")
    ax.axvline(1.5 * S / 5517.65 * 1e3, color="C0", lw=0.8, ls="--",
               label="pulse front back at mid-bar, 1.5 S/c")
    ax.axvline(2.9, color="C2", lw=0.8, ls=":", label="paper's Fig. 9 (2.9 ms)")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("stretch / s_c")
    ax.set_title(f"paper's load p0 = 4e5 N/m, no damage: s_c = {sc_:.3g}", fontsize=9)
    ax.legend(fontsize=7, loc="upper right")
    ax.set_ylim(0, None)
    fig.savefig(a.png, dpi=130, bbox_inches="tight")
    print("wrote", a.png)


if __name__ == "__main__":
    main()
