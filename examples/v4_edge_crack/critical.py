#!/usr/bin/env python3
"""Critical traction of the V4 runs (make_patch.py decks) against resolution, extrapolated to
dx -> 0, beside LEFM (paper 000 eqs. 23-24) and the paper's 144.4 +- 1.5 Pa.

    /usr/bin/python3 critical.py RATE v4_paper_dx0p04.h ... [--png F] [--csv F]
                                 [--check LOW HIGH]

The traction is sigma = RATE t, read at the outputs (every 5 steps).
Critical traction: the first output at which a point within delta of the crack line with
a + 0.1 m <= x <= a + 0.15 m has damage > 0.3 (the crack has grown by 0.1 m). Printed beside it:
the first broken bond within two horizons of the tip (Tip_Damage > 0; on a lattice the bonds cut
at the tip often fail at a lower load and the crack then arrests) and the run-away (a point with
damage > 0.3 in x in [0.45, 0.55]: the crack has run past mid-width; later by its travel time).
A bond broken elsewhere before the tip's is reported. Linear fits sigma(dx) = sigma_0 + b dx of
each series give sigma_0 and its standard error; the figure shows the fit of the critical
traction. --check LOW HIGH exits 1 unless every critical traction lies in [LOW, HIGH].
Needs python3-netcdf4/numpy/matplotlib (Debian)."""
import argparse
import math
import re
import sys

import netCDF4
import numpy as np


def lefm(e_plane_strain, g=1.0, a=0.125, width=1.0):
    """Eqs. (23)-(24): sigma_F = K_I / sqrt(pi a) / Y(a/L), K_I = sqrt(G E/(1-nu^2))."""
    r = a / width
    y = 1.12 - 0.23 * r + 10.6 * r**2 - 21.7 * r**3 + 30.4 * r**4
    return math.sqrt(g * e_plane_strain) / math.sqrt(math.pi * a) / y


def read(path, rate):
    ds = netCDF4.Dataset(path)
    t = np.asarray(ds.variables["time_whole"][:])
    names = ["".join(c.decode() for c in r if c).strip() for r in ds.variables["name_glo_var"][:].data]
    g = np.asarray(ds.variables["vals_glo_var"][:])
    dmax, dahead = g[:, names.index("Max_Damage")], g[:, names.index("Ahead_Damage")]
    m = re.search(r"dx(\d+p?\d*)", path)
    dx = float(m.group(1).replace("p", "."))
    dtip = g[:, names.index("Tip_Damage")]
    init = rate * t[np.argmax(dtip > 0)] if (dtip > 0).any() else float("nan")
    dgrown = g[:, names.index("Grown_Damage")]
    grown = rate * t[np.argmax(dgrown > 0.3)] if (dgrown > 0.3).any() else float("nan")
    first = rate * t[np.argmax(dmax > 0)] if (dmax > 0).any() else float("nan")
    if first < init:
        print(f"{path}: a bond away from the tip broke first, at {first:.2f} Pa")
    run = rate * t[np.argmax(dahead > 0.3)] if (dahead > 0.3).any() else float("nan")
    return dx, grown, init, run


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("rate", type=float)
    ap.add_argument("files", nargs="+")
    ap.add_argument("--png")
    ap.add_argument("--csv")
    ap.add_argument("--check", nargs=2, type=float)
    a = ap.parse_args()
    rows = sorted((read(p, a.rate) + (p,) for p in a.files), reverse=True)
    paper_const = lefm(1e4 / (1 - (1 / 3) ** 2))  # the paper's E, nu = 1/3: 138.5 Pa
    sim_paper = lefm(15000.0)  # the material Bulk Modulus 9375 is: nu = 1/4, E/(1-nu^2) = 15000
    sim_consistent = lefm(1e4 / (1 - 0.25**2))  # Young's Modulus 1e4 in plane strain, nu = 1/4
    print(f"LEFM, eqs. 23-24: E = 1e4, nu = 1/3 (the paper's values): {paper_const:.1f} Pa; "
          f"E/(1-nu^2) = 15000 (the paper's constant, nu = 1/4): {sim_paper:.1f} Pa; "
          f"E = 1e4, nu = 1/4: {sim_consistent:.1f} Pa; paper: 146.9 printed, 144.4 +- 1.5 simulated")
    groups = {}
    for r in rows:
        m = re.search(r"_m(\d+p\d+)", r[-1])
        groups.setdefault(m.group(1).replace("p", ".") if m else "3.015", []).append(r)
    fits = {}
    for ratio, grp in groups.items():
        print(f"horizon = {ratio} dx")
        print("dx (m), growth by 0.1 m (Pa), first broken tip bond (Pa), run-away (Pa), file")
        for dx, grown, init, run, p in grp:
            print(f"{dx:.5f}, {grown:.2f}, {init:.2f}, {run:.2f}, {p}")
        cols = np.array([r[:4] for r in grp])
        for k, label in ((1, "growth by 0.1 m"), (2, "first broken tip bond"), (3, "run-away")):
            if len(grp) < 3:
                break
            A = np.vstack([np.ones(len(grp)), cols[:, 0]]).T
            coef, *_ = np.linalg.lstsq(A, cols[:, k], rcond=None)
            resid = cols[:, k] - A @ coef
            cov = resid @ resid / (len(grp) - 2) * np.linalg.inv(A.T @ A)
            print(f"linear fit, {label}: sigma(dx) = {coef[0]:.2f} (+- {math.sqrt(cov[0, 0]):.2f}) "
                  f"+ {coef[1]:.1f} dx")
            if k == 1:
                fits[ratio] = (coef[0], math.sqrt(cov[0, 0]), coef[1])
    dxs = np.array([r[0] for r in rows])
    grown = np.array([r[1] for r in rows])
    if a.csv:
        with open(a.csv, "w") as f:
            f.write("dx,growth,first_tip_bond,runaway,file\n")
            for dx, gr, i, r, p in rows:
                f.write(f"{dx:.6f},{gr:.3f},{i:.3f},{r:.3f},{p}\n")
    if a.png:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(10.5, 4.8))
        for n, (ratio, grp) in enumerate(groups.items()):
            cols = np.array([r[:4] for r in grp])
            col = f"C{n}"
            ax.plot(cols[:, 0], cols[:, 1], "o", c=col, label=f"δ = {ratio} dx: growth by 0.1 m")
            ax.plot(cols[:, 0], cols[:, 2], "x", c=col, label=f"δ = {ratio} dx: first broken tip bond")
            ax.plot(cols[:, 0], cols[:, 3], "s", c=col, mfc="none", ms=4,
                    label=f"δ = {ratio} dx: run-away (past x = L/2)")
            if ratio in fits:
                f0, e0, slope = fits[ratio]
                xx = np.linspace(0, cols[:, 0].max() * 1.05, 50)
                ax.plot(xx, f0 + slope * xx, "-", c=col, lw=1,
                        label=f"δ = {ratio} dx: linear fit, {f0:.1f} ± {e0:.1f} Pa at dx = 0")
        ax.axhline(sim_paper, ls="--", c="k", lw=1, label=f"LEFM, the model's E' = 15000 Pa: {sim_paper:.1f}")
        ax.axhline(paper_const, ls=":", c="k", lw=1, label=f"LEFM, E = 1e4, ν = 1/3: {paper_const:.1f}")
        ax.errorbar([0], [144.4], yerr=[1.5], fmt="D", c="C3", label="paper 000: 144.4 ± 1.5 (extrapolated)")
        ax.set_xlim(left=-0.002)
        ax.set_xlabel("lattice spacing dx [m]")
        ax.set_ylabel("traction [Pa]")
        ax.set_title("V4: plane-strain edge-cracked patch, normalized PMB, G_I = 1 J/m²")
        ax.legend(fontsize=7, bbox_to_anchor=(1.02, 1.0), loc="upper left")
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print("wrote", a.png)
    if a.check:
        lo, hi = a.check
        bad = [(dx, i) for dx, i in zip(dxs, grown) if not (lo <= i <= hi)]
        for dx, i in bad:
            print(f"FAIL: dx = {dx:g}: critical traction {i:.2f} Pa outside [{lo:g}, {hi:g}]")
        return 1 if bad else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
