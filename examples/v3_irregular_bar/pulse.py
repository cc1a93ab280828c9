#!/usr/bin/env python3
"""Pulse position in the V3 bars (paper 000 Fig. 6) against c_l t.

    /usr/bin/python3 pulse.py v3_h1.6.e v3_h1.3.e ... [--png v3_pulse.png] [--csv v3_pulse.csv]
                              [--check-speed TOL]

For each Exodus file: the pulse centre at every record is the volume-weighted centroid of u_x
over the points within 30 m of the peak of the binned profile (2 m bins); the pulse speed is the
least-squares slope of the centre over t >= 10 s (after the start-up). Prints one row per file,
writes the figure (binned u_x at the last record with the exact position dashed, and the
centre's lag behind 100 m + c_l t) and, with --check-speed, exits 1 unless every speed is within
TOL (relative) of c_l. Needs python3-netcdf4, python3-numpy and python3-matplotlib (Debian)."""
import argparse
import sys

import netCDF4
import numpy as np

C_L = np.sqrt((10.0 + 4.0 / 3.0 * 6.0) / 1.0)  # K = 10, G = 3K(1-2nu)/(2(1+nu)) = 6 at nu = 1/4
X0 = 100.0


def names(ds, var):
    return ["".join(c.decode() for c in row if c).strip() for row in ds.variables[var][:].data]


def analyse(path):
    ds = netCDF4.Dataset(path)
    x = np.asarray(ds.variables["coordx"][:])
    t = np.asarray(ds.variables["time_whole"][:])
    nod = names(ds, "name_nod_var")
    ux = np.asarray(ds.variables[f"vals_nod_var{nod.index('DisplacementX') + 1}"][:])
    elem = names(ds, "name_elem_var")
    vol = np.asarray(ds.variables[f"vals_elem_var{elem.index('Volume') + 1}eb1"][0])
    nbr = np.asarray(ds.variables[f"vals_elem_var{elem.index('Number_Of_Neighbors') + 1}eb1"][0])
    edges = np.arange(0.0, x.max() + 2.0, 2.0)
    idx = np.clip(np.digitize(x, edges) - 1, 0, len(edges) - 2)
    vsum = np.bincount(idx, weights=vol, minlength=len(edges) - 1)
    centres, profiles = [], []
    for r in range(len(t)):
        prof = np.bincount(idx, weights=vol * ux[r], minlength=len(edges) - 1) / np.maximum(vsum, 1e-300)
        peak = 0.5 * (edges[np.argmax(prof)] + edges[np.argmax(prof) + 1])
        w = np.abs(x - peak) < 30.0
        centres.append(np.sum(vol[w] * ux[r][w] * x[w]) / np.sum(vol[w] * ux[r][w]))
        profiles.append(prof)
    centres = np.array(centres)
    late = t >= 10.0
    speed = np.polyfit(t[late], centres[late], 1)[0]
    return dict(path=path, n=len(x), nbr=nbr.mean(), vratio=vol.max() / vol.min(), t=t,
                centres=centres, speed=speed, xb=0.5 * (edges[:-1] + edges[1:]), prof=profiles[-1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("files", nargs="+")
    ap.add_argument("--png")
    ap.add_argument("--csv")
    ap.add_argument("--check-speed", type=float)
    a = ap.parse_args()
    rows = [analyse(p) for p in a.files]
    print(f"c_l = {C_L:.4f} m/s")
    print("file, points, mean neighbours, V_max/V_min, speed (m/s), speed/c_l - 1, "
          "centre - (100 + c_l t) at the end (m)")
    for r in rows:
        lag = r["centres"][-1] - (X0 + C_L * r["t"][-1])
        r["err"] = r["speed"] / C_L - 1.0
        r["lag"] = lag
        print(f"{r['path']}, {r['n']}, {r['nbr']:.1f}, {r['vratio']:.0f}, {r['speed']:.4f}, "
              f"{100 * r['err']:+.2f}%, {lag:+.2f}")
    if a.csv:
        with open(a.csv, "w") as f:
            f.write("file,points,mean_neighbours,vmax_over_vmin,speed,rel_error,end_lag\n")
            for r in rows:
                f.write(f"{r['path']},{r['n']},{r['nbr']:.2f},{r['vratio']:.1f},{r['speed']:.5f},"
                        f"{r['err']:.5f},{r['lag']:.3f}\n")
    if a.png:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.2))
        for r in rows:
            label = f"{r['n']} points, {r['nbr']:.0f} neighbours, {100 * r['err']:+.1f}%"
            ls = "-" if r["nbr"] < 45 else "--"
            ax1.plot(r["xb"] - (X0 + C_L * r["t"][-1]), r["prof"] * 1e3, ls, label=label)
            ax2.plot(r["t"], r["centres"] - (X0 + C_L * r["t"]), "o" + ls, ms=3, label=label)
        tend = min(r["t"][-1] for r in rows)
        ax1.axvline(0.0, ls="--", c="k", label="exact centre 100 m + c_l t")
        ax1.set_xlim(-80, 40)
        ax1.set_xlabel("x - (100 m + c_l t) [m]")
        ax1.set_ylabel("u_x [mm] (2 m bins)")
        ax1.set_title(f"pulse at the last record (t >= {tend:.1f} s)")
        ax1.legend(fontsize=8)
        ax2.axhline(0.0, ls="--", c="k")
        ax2.set_xlabel("t [s]")
        ax2.set_ylabel("pulse centre - (100 m + c_l t) [m]")
        ax2.set_title("lag behind the exact position")
        ax2.legend(fontsize=8)
        fig.suptitle("V3: irregular tetrahedral bar, normalized PMB (speed error vs c_l in the legend)")
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print("wrote", a.png)
    if a.check_speed is not None:
        bad = [r for r in rows if abs(r["err"]) > a.check_speed]
        for r in bad:
            print(f"FAIL: {r['path']}: speed {r['speed']:.4f} is {100 * r['err']:+.2f}% off c_l "
                  f"(allowed {100 * a.check_speed:.1f}%)")
        return 1 if bad else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
