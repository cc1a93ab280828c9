#!/usr/bin/env python3
"""Paper 002's mesh-convergence study of the glass plate (its section 4.3, Table 3 and Figs. 9
and 11): DTT at 4 MPa with delta = 1 mm and m = delta/h = 2, 3, 6 against the finest run, m = 12.

    /usr/bin/python3 convergence.py v5_dtt_s4_m2.e v5_dtt_s4_m3.e v5_dtt_s4_m6.e v5_dtt_s4_m12.e \
        [--dir DIR] [--plot F.png] [--check]

The finest m given is the reference. The node-set files of make_plate.py (v5_m<M>_top.txt,
v5_m<M>_bottom.txt) are read from DIR (default: the directory of each Exodus file).

* Displacements (Table 3): each coarse run's displacement at the last record is interpolated to
  the reference points (bilinear on the coarse lattice of cell centres, extended linearly over
  the half cell at the edges), and the difference from the reference is measured in three norms,
  because the paper does not say which L2 norm it prints: the continuum norm
  (integral over the plate of |du|^2 dA)^(1/2) [m^2], the root mean square over the reference
  points [m], and that RMS over the RMS of the reference displacement (relative).
* Energies (Figs. 9 and 11): the potential energy Ep (Global_Stored_Elastic_Energy), the kinetic
  energy Ek (Global_Kinetic_Energy), the work of the load W = sum_i b_i V_i . u_i (the traction
  is a constant body force on the two loaded layers, total sigma * A each, so W = sigma A times
  the mean opening of the two layers), and paper 002's total energy, eq. 14, E = Ep + Ek - W,
  at every record; the differences from the reference at the same times.
* Theorem 4: E(t) never increases; printed: the largest increase between records over the
  largest |W|.
--check exits 1 unless the energy and displacement differences shrink from the coarsest to the
finest coarse run and E(t) never increases by more than 1e-3 of the largest |W| in any run.
Needs python3-netcdf4/numpy/scipy/matplotlib (Debian)."""
import argparse
import os
import re
import sys

import netCDF4
import numpy as np
from scipy.interpolate import RegularGridInterpolator

W_PLATE, H_PLATE, DELTA, SIGMA, AREA = 0.1, 0.04, 1.0e-3, 4.0e6, 1.0e-4


def names(ds, var):
    return ["".join(c.decode() for c in r if c).strip() for r in ds.variables[var][:].data]


def node_set(path):
    with open(path) as f:
        return np.array([int(s) - 1 for s in f.read().split()])


def load(path, directory):
    m = int(re.search(r"_m(\d+)", os.path.basename(path)).group(1))
    ds = netCDF4.Dataset(path)
    r = dict(path=path, m=m, h=DELTA / m)
    r["x"] = np.asarray(ds.variables["coordx"][:])
    r["y"] = np.asarray(ds.variables["coordy"][:])
    r["t"] = np.asarray(ds.variables["time_whole"][:])
    evars = names(ds, "name_elem_var")
    nvars = names(ds, "name_nod_var")
    ux = np.asarray(ds.variables[f"vals_nod_var{nvars.index('DisplacementX') + 1}"][:])
    uy = np.asarray(ds.variables[f"vals_nod_var{nvars.index('DisplacementY') + 1}"][:])
    r["ux"], r["uy"] = ux, uy
    r["damage"] = np.asarray(ds.variables[f"vals_elem_var{evars.index('Damage') + 1}eb1"][-1])
    gvars = names(ds, "name_glo_var")
    glo = np.asarray(ds.variables["vals_glo_var"][:])
    r["Ek"] = glo[:, gvars.index("Global_Kinetic_Energy")]
    r["Ep"] = glo[:, gvars.index("Global_Stored_Elastic_Energy")]
    # The node sets number the points as the input file does (row by row); the Exodus file
    # may order them otherwise, so find each set member by its lattice position.
    d = directory or os.path.dirname(os.path.abspath(path))
    nx = round(W_PLATE / r["h"])
    ij = np.rint(r["x"] / r["h"] - 0.5).astype(int) + nx * np.rint(r["y"] / r["h"] - 0.5).astype(int)
    where = np.empty(ij.size, dtype=int)
    where[ij] = np.arange(ij.size)
    top = where[node_set(os.path.join(d, f"v5_m{m}_top.txt"))]
    bottom = where[node_set(os.path.join(d, f"v5_m{m}_bottom.txt"))]
    r["W"] = SIGMA * AREA * (uy[:, top].mean(axis=1) - uy[:, bottom].mean(axis=1))
    r["E"] = r["Ep"] + r["Ek"] - r["W"]
    return r


def interpolate(coarse, fine, field):
    h = coarse["h"]
    nx, ny = round(W_PLATE / h), round(H_PLATE / h)
    grid = np.zeros((nx, ny))
    i = np.rint(coarse["x"] / h - 0.5).astype(int)
    j = np.rint(coarse["y"] / h - 0.5).astype(int)
    grid[i, j] = coarse[field][-1]
    f = RegularGridInterpolator(((np.arange(nx) + 0.5) * h, (np.arange(ny) + 0.5) * h), grid,
                                bounds_error=False, fill_value=None)
    return f(np.column_stack([fine["x"], fine["y"]]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("files", nargs="+")
    ap.add_argument("--dir")
    ap.add_argument("--plot")
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    runs = sorted((load(p, a.dir) for p in a.files), key=lambda r: r["m"])
    ref, coarse = runs[-1], runs[:-1]
    area = ref["h"] ** 2
    ok = True
    print(f"reference m = {ref['m']}: {ref['x'].size} points, t = {ref['t'][-1] * 1e6:.2f} us")
    print("Displacement differences at the last record (paper 002 Table 3):")
    print("m, component, continuum L2 [m^2], RMS [m], RMS / RMS of the reference")
    disp = {}
    for r in coarse:
        if not np.isclose(r["t"][-1], ref["t"][-1]):
            sys.exit(f"{r['path']}: last record at {r['t'][-1]} s, the reference at {ref['t'][-1]} s")
        for c in ("x", "y"):
            diff = interpolate(r, ref, "u" + c) - ref["u" + c][-1]
            l2 = np.sqrt(np.sum(diff**2) * area)
            rms = np.sqrt(np.mean(diff**2))
            rel = rms / np.sqrt(np.mean(ref["u" + c][-1] ** 2))
            disp[(r["m"], c)] = l2
            print(f"{r['m']}, {c}, {l2:.3e}, {rms:.3e}, {rel:.3f}")
    print("Energies (paper 002 Figs. 9 and 11), at the last record and the largest difference "
          "from the reference over the records:")
    print("m, Ep [J], Ek [J], W [J], E = Ep + Ek - W [J], max|dEp|, max|dEk|, max|dE|, "
          "largest rise of E / max|W|")
    diffs = {}
    for r in runs:
        n = min(r["t"].size, ref["t"].size)
        same = np.allclose(r["t"][:n], ref["t"][:n], rtol=1e-9, atol=1e-12)
        d = [np.max(np.abs(r[k][:n] - ref[k][:n])) if same else np.nan for k in ("Ep", "Ek", "E")]
        rise = max(0.0, np.max(np.diff(r["E"]))) / np.max(np.abs(r["W"]))
        diffs[r["m"]] = d
        print(f"{r['m']}, {r['Ep'][-1]:.4e}, {r['Ek'][-1]:.4e}, {r['W'][-1]:.4e}, {r['E'][-1]:.4e}, "
              f"{d[0]:.3e}, {d[1]:.3e}, {d[2]:.3e}, {rise:.2e}")
        if rise > 1e-3:
            ok = False
            print(f"  E rises in m = {r['m']}")
    ms = [r["m"] for r in coarse]
    for c in ("x", "y"):
        if len(ms) > 1 and not disp[(ms[0], c)] > disp[(ms[-1], c)]:
            ok = False
            print(f"  u_{c} difference does not shrink from m = {ms[0]} to m = {ms[-1]}")
    for k, name in enumerate(("Ep", "Ek", "E")):
        if len(ms) > 1 and not diffs[ms[0]][k] > diffs[ms[-1]][k]:
            ok = False
            print(f"  {name} difference does not shrink from m = {ms[0]} to m = {ms[-1]}")
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig = plt.figure(figsize=(17, 7.6))
        for k, r in enumerate(runs[:4]):
            axm = fig.add_subplot(2, 4, k + 1)
            h = r["h"]
            img = np.zeros((round(H_PLATE / h), round(W_PLATE / h)))
            img[np.rint(r["y"] / h - 0.5).astype(int), np.rint(r["x"] / h - 0.5).astype(int)] = r["damage"]
            axm.imshow(img, origin="lower", extent=(0, 100, 0, 40), cmap="jet", vmin=0, vmax=1,
                       interpolation="nearest")
            axm.set(aspect="equal", xlim=(0, 100), ylim=(0, 40), xlabel="x [mm]",
                    title=f"damage, m = {r['m']}, t = {r['t'][-1] * 1e6:.0f} µs")
        ax = [fig.add_subplot(2, 4, 5 + k) for k in range(4)]
        for r in runs:
            ax[0].plot(r["t"] * 1e6, r["Ep"] * 1e3, label=f"Ep, m = {r['m']}")
            ax[0].plot(r["t"] * 1e6, r["Ek"] * 1e3, "--", label=f"Ek, m = {r['m']}")
            ax[0].plot(r["t"] * 1e6, r["E"] * 1e3, ":", label=f"E, m = {r['m']}")
        ax[0].set(xlabel="t [µs]", ylabel="energy [mJ]", title="Energies (Ep, Ek, E = Ep + Ek − W)")
        ax[0].legend(fontsize=6, ncol=2)
        for k, (name, key) in enumerate((("potential", "Ep"), ("kinetic", "Ek"),
                                         ("total E (eq. 14)", "E"))):
            for r in coarse:
                n = min(r["t"].size, ref["t"].size)
                ax[k + 1].plot(r["t"][:n] * 1e6, np.abs(r[key][:n] - ref[key][:n]) * 1e3,
                               label=f"m = {r['m']}")
            ax[k + 1].set(xlabel="t [µs]", ylabel=f"|difference from m = {ref['m']}| [mJ]",
                          title=f"{name} energy")
            ax[k + 1].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=110)
    if a.check and not ok:
        sys.exit(1)


if __name__ == "__main__":
    main()
