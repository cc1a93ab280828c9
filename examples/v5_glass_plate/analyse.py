#!/usr/bin/env python3
"""Crack path, tip speed, branching time and angle of the V5 glass-plate runs.

    /usr/bin/python3 analyse.py v5_dtt_s4_m3.e ... [--maps F.png] [--speed F.png] [--csv F]
                                [--check-speed LOW HIGH]

Per file (the pre-crack tip is at x0 = 50 mm on the line y0 = 20 mm, delta = 1 mm):
* tip: the largest x of the points with damage > 0.3 (paper 001's rule), at every record;
  initiation: the first record at which the tip is more than delta beyond x0;
* speed: the tip's advance between records two apart (central difference over 1 us at the
  default output interval), over the Rayleigh speed c_R = 3180 m/s (paper 001); printed: the
  largest speed and the mean from initiation to branching;
* branching: the first record at which a point with damage > 0.3 lies farther than 2 delta from
  the line y0 (the crack has left the line); the branch point x_b is the farthest point with
  damage > 0.5 within delta/2 of the line at the last record;
* crack moves: the first record at which the tip lies beyond x0 (paper 001 reads the start off
  its speed curve, "zero until the crack starts propagating"); the initiation above comes later,
  by the time the tip takes to cover delta;
* tip at the branch point: when the tip reaches x_b (linear between records): when the crack
  branches, where the branching time above waits until a branch has left the line by 2 delta;
* angle: the slope of a line fitted to the points with damage > 0.5 more than delta above y0
  with x_b < x < x_b + 8 delta (the upper branch of the first branching), in degrees.
--check-speed LOW HIGH exits 1 unless every run's largest tip speed over c_R is in [LOW, HIGH]
and its crack has started. Needs python3-netcdf4/numpy/matplotlib (Debian)."""
import argparse
import math
import sys

import netCDF4
import numpy as np

X0, Y0, DELTA, C_R = 0.05, 0.02, 1.0e-3, 3180.0


def names(ds, var):
    return ["".join(c.decode() for c in r if c).strip() for r in ds.variables[var][:].data]


def analyse(path):
    ds = netCDF4.Dataset(path)
    x = np.asarray(ds.variables["coordx"][:])
    y = np.asarray(ds.variables["coordy"][:])
    t = np.asarray(ds.variables["time_whole"][:])
    k = names(ds, "name_elem_var").index("Damage") + 1
    dmg = np.asarray(ds.variables[f"vals_elem_var{k}eb1"][:])
    tip = np.array([x[d > 0.3].max() if (d > 0.3).any() else X0 for d in dmg])
    tip = np.maximum(tip, X0)
    started = np.nonzero(tip > X0 + DELTA)[0]
    t_init = t[started[0]] if len(started) else math.nan
    moved = np.nonzero(tip > X0)[0]
    t_move = t[moved[0]] if len(moved) else math.nan
    speed = np.full_like(tip, np.nan)
    speed[1:-1] = (tip[2:] - tip[:-2]) / (t[2:] - t[:-2])
    off = np.array([((d > 0.3) & (np.abs(y - Y0) > 2 * DELTA) & (x > X0)).any() for d in dmg])
    branched = np.nonzero(off)[0]
    r = dict(path=path, x=x, y=y, t=t, dmg=dmg, tip=tip, speed=speed, t_init=t_init,
             t_move=t_move, t_at_branch=math.nan, t_branch=math.nan, x_branch=math.nan,
             angle=math.nan)
    r["vmax"] = np.nanmax(speed) / C_R if np.isfinite(speed).any() else math.nan
    run = (t > t_init) & np.isfinite(speed)
    if len(branched):
        r["t_branch"] = t[branched[0]]
        last = dmg[-1]
        online = (last > 0.5) & (np.abs(y - Y0) < 0.5 * DELTA)
        r["x_branch"] = x[online].max() if online.any() else X0
        at = np.nonzero(tip >= r["x_branch"])[0]
        if len(at) and at[0] > 0:
            k = at[0]
            r["t_at_branch"] = t[k - 1] + (r["x_branch"] - tip[k - 1]) / (tip[k] - tip[k - 1]) * (
                t[k] - t[k - 1])
        sel = ((last > 0.5) & (y > Y0 + DELTA) & (x > r["x_branch"])
               & (x < r["x_branch"] + 8 * DELTA))
        if sel.sum() >= 3:
            r["angle"] = math.degrees(math.atan(np.polyfit(x[sel], y[sel], 1)[0]))
        run &= t < r["t_branch"]
    r["vmean"] = np.mean(speed[run]) / C_R if run.any() else math.nan
    return r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("files", nargs="+")
    ap.add_argument("--maps")
    ap.add_argument("--speed")
    ap.add_argument("--csv")
    ap.add_argument("--check-speed", nargs=2, type=float)
    a = ap.parse_args()
    rows = [analyse(p) for p in a.files]
    head = ("file, points, final t (us), initiation (us), largest tip speed / c_R, mean speed to "
            "branching / c_R, branching (us), branch x (mm), upper branch angle (deg), "
            "crack moves (us), tip at the branch point (us)")
    print(head)
    lines = []
    for r in rows:
        line = (f"{r['path']}, {len(r['x'])}, {r['t'][-1] * 1e6:.1f}, {r['t_init'] * 1e6:.1f}, "
                f"{r['vmax']:.3f}, {r['vmean']:.3f}, {r['t_branch'] * 1e6:.1f}, "
                f"{r['x_branch'] * 1e3:.1f}, {r['angle']:.1f}, {r['t_move'] * 1e6:.1f}, "
                f"{r['t_at_branch'] * 1e6:.1f}")
        print(line)
        lines.append(line)
    if a.csv:
        with open(a.csv, "w") as f:
            f.write(head.replace(", ", ",") + "\n" + "\n".join(l.replace(", ", ",") for l in lines) + "\n")
    if a.maps or a.speed:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    if a.maps:
        n = len(rows)
        cols = 2 if n > 1 else 1
        nr = (n + cols - 1) // cols
        fig, axes = plt.subplots(nr, cols, figsize=(6.2 * cols, 2.9 * nr), squeeze=False)
        for ax, r in zip(axes.flat, rows):
            h = np.sqrt(np.min(np.diff(np.unique(r["x"]))) ** 2)
            ax.scatter(r["x"] * 1e3, r["y"] * 1e3, c=r["dmg"][-1], s=max(0.05, 40 * h * 1e3 / 4), marker="s",
                       cmap="jet", vmin=0, vmax=0.5, linewidths=0)
            ax.set_aspect("equal")
            ax.set_xlim(0, 100)
            ax.set_ylim(0, 40)
            ax.set_title(f"{r['path'].rsplit('/', 1)[-1].rsplit('.', 1)[0]}, t = {r['t'][-1] * 1e6:.0f} µs",
                         fontsize=9)
            ax.tick_params(labelsize=7)
        for ax in list(axes.flat)[n:]:
            ax.axis("off")
        fig.suptitle("V5: damage index (red: > 0.5), x and y in mm", fontsize=10)
        fig.tight_layout()
        fig.savefig(a.maps, dpi=110)
        print("wrote", a.maps)
    if a.speed:
        fig, ax = plt.subplots(figsize=(7, 4))
        for r in rows:
            if r["t"][-1] > 50e-6:
                continue  # the long low-load runs would squeeze the others; their numbers are printed
            ax.plot(r["t"] * 1e6, r["speed"] / C_R, label=r["path"].rsplit("/", 1)[-1].rsplit(".", 1)[0])
        ax.axhline(2 / 3, ls="--", c="k", lw=1, label="2/3 c_R")
        ax.set_xlabel("t [µs]")
        ax.set_ylabel("crack-tip speed / c_R (3180 m/s)")
        ax.set_title("V5: tip = farthest point with damage > 0.3 (runs up to 50 µs)")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(a.speed, dpi=110)
        print("wrote", a.speed)
    if a.check_speed:
        lo, hi = a.check_speed
        bad = [r for r in rows if not (lo <= r["vmax"] <= hi) or not math.isfinite(r["t_init"])]
        for r in bad:
            print(f"FAIL: {r['path']}: largest tip speed {r['vmax']:.3f} c_R not in [{lo}, {hi}] "
                  f"(initiation {r['t_init'] * 1e6:.1f} us)")
        return 1 if bad else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
