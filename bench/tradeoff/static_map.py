#!/usr/bin/python3
"""Speed/accuracy map for a static field (issue 14, item 5): a plate with a hole under tension
against Kirsch's solution.

A square plate [-L, L]^2 (2D, plane stress, E = 1, nu = 1/3 so that the bond-based models take
part) with a hole of radius a = 6 at its centre, spacing 1. Kirsch's displacement field for a
remote stress sigma = 1e-3 along x is prescribed on the band of points within one horizon of
the outer edge (x and y), and QuasiStatic solves for the rest in one load step (a linear
problem at this strain). Errors, at the points at least two horizons inside the band:
  u_error   relative L2 difference of u from Kirsch's u;
  hole      the strain e_xx at the point of the first row above the hole's top (x = 0.5,
            y = a + 0.5), as the Deformation_Gradient compute gives it (F - I), and as the
            central difference of u_x along x there, each divided by Kirsch's e_xx at that point.
Cost: CPU time of the run and the peak resident memory Peridot reports.

Studies: PMB, normalized PMB, LPS at delta/dx = 2.015, 3.015, 4.015, 5.015; LPS with partial
volumes; LPS with the Conical influence function. (Linearized LPS has no tangent: QuasiStatic
refuses it, so it is not in this map.)

Usage: bench/tradeoff/static_map.py --peridot build/peridot [--workdir DIR]
       [--figure doc/figures/static_map.png] [--csv bench/tradeoff/static_map.csv] [--quick]
Prints the table as Markdown.
"""
import argparse
import csv
import math
import os
import re
import resource
import subprocess
import sys
import time

import numpy as np

E, NU, SIGMA, A, L = 1.0, 1.0 / 3.0, 1.0e-3, 6.0, 20
MU = E / (2 * (1 + NU))
KAPPA = (3 - NU) / (1 + NU)  # plane stress
MODELS = {"PMB": "Elastic Bond Based", "normalized PMB": "Normalized PMB", "LPS": "Elastic"}


def kirsch(x, y):
    """Kirsch's displacement (plane stress) for remote sigma along x, hole radius A."""
    r = np.hypot(x, y)
    th = np.arctan2(y, x)
    c2, s2 = np.cos(2 * th), np.sin(2 * th)
    ur = SIGMA / (8 * MU * r) * ((KAPPA - 1) * r * r + 2 * A * A +
                                 2 * (r * r + (KAPPA + 1) * A * A - A ** 4 / (r * r)) * c2)
    ut = -SIGMA / (8 * MU * r) * 2 * (r * r + (KAPPA - 1) * A * A + A ** 4 / (r * r)) * s2
    return ur * np.cos(th) - ut * np.sin(th), ur * np.sin(th) + ut * np.cos(th)


def kirsch_strain_xx(x, y, h=1e-4):
    return (kirsch(x + h, y)[0] - kirsch(x - h, y)[0]) / (2 * h)


def self_check():
    """The field's own stresses: traction-free hole, sigma_xx -> sigma far away, 3 sigma at
    the top of the hole. A wrong formula stops the study."""
    def stress(x, y, h=1e-5):
        exx = kirsch_strain_xx(x, y, h)
        eyy = (kirsch(x, y + h)[1] - kirsch(x, y - h)[1]) / (2 * h)
        exy = 0.5 * ((kirsch(x, y + h)[0] - kirsch(x, y - h)[0]) / (2 * h) +
                     (kirsch(x + h, y)[1] - kirsch(x - h, y)[1]) / (2 * h))
        c = E / (1 - NU * NU)
        return c * (exx + NU * eyy), c * (eyy + NU * exx), 2 * MU * exy
    sxx, syy, sxy = stress(0.0, A)
    assert abs(sxx / SIGMA - 3) < 1e-4 and abs(syy / SIGMA) < 1e-4, (sxx, syy)
    sxx, syy, sxy = stress(A, 0.0)  # the hole's side: sigma_rr = sigma_xx = 0
    assert abs(sxx / SIGMA) < 1e-4 and abs(syy / SIGMA + 1) < 1e-4, (sxx, syy)
    sxx, syy, sxy = stress(1e4, 3e3)
    assert abs(sxx / SIGMA - 1) < 1e-4 and abs(syy / SIGMA) < 1e-4 and abs(sxy) < 1e-7


def cloud():
    pts = []
    for j in range(2 * L):
        for i in range(2 * L):
            x, y = -L + i + 0.5, -L + j + 0.5
            if math.hypot(x, y) > A:
                pts.append((x, y))
    return pts


def deck(model, horizon, pv, influence="One"):
    shear = ""
    if model == "Elastic":
        shear = "      Young's Modulus: %r\n      Poisson's Ratio: %r\n" % (E, NU)
    else:
        shear = "      Young's Modulus: %r\n" % E
    pvkey = "    Partial Volumes: true\n" if pv else ""
    if influence != "One":
        pvkey += "    Influence Function: %s\n" % influence
    return f"""Peridigm:
  Discretization:
    Type: Text File
    Input Mesh File: plate.txt
    Dimension: 2
    Thickness: 1.0
{pvkey}  Materials:
    M:
      Material Model: {model}
      Plane Stress: true
      Density: 1.0
{shear}  Blocks:
    B:
      Block Names: block_1
      Material: M
      Horizon: {horizon!r}
  Boundary Conditions:
    Band Node Set: band.txt
    Ux:
      Type: Prescribed Displacement
      Node Set: Band Node Set
      Coordinate: x
      Value: "{{UX}}"
    Uy:
      Type: Prescribed Displacement
      Node Set: Band Node Set
      Coordinate: y
      Value: "{{UY}}"
  Solver:
    Final Time: 1.0
    QuasiStatic:
      Number of Load Steps: 1
      Relative Tolerance: 1.0e-10
      Maximum Solver Iterations: 5
      Belos Relative Tolerance: 1.0e-12
  Output:
    Output Filename: plate
    Output Frequency: 1
    Output Variables:
      Displacement: true
      Deformation_Gradient: true
"""


def kirsch_expression():
    """Kirsch's u_x and u_y as deck expressions in x, y (t scales the load: 1 at the end)."""
    s, mu, k, a2, a4 = SIGMA, MU, KAPPA, A * A, A ** 4
    r2 = "(x*x + y*y)"
    c2 = f"((x*x - y*y)/{r2})"
    s2 = f"(2*x*y/{r2})"
    ur_r = f"({s!r}/(8*{mu!r}*{r2}))*(({k - 1!r})*{r2} + {2 * a2!r} + 2*({r2} + {(k + 1) * a2!r} - {a4!r}/{r2})*{c2})"
    ut_r = f"(-{s!r}/(8*{mu!r}*{r2}))*2*({r2} + {(k - 1) * a2!r} + {a4!r}/{r2})*{s2}"
    # u_r / r times (x, y) and u_theta / r times (-y, x)
    ux = f"t*({ur_r}*x - {ut_r}*y)"
    uy = f"t*({ur_r}*y + {ut_r}*x)"
    return ux, uy


def run(args, label, model, ratio, pv, influence="One"):
    horizon = ratio + 0.015
    here = os.path.join(args.workdir, "%s_%g%s%s" % (model.replace(" ", "_"), ratio,
                                                      "_pv" if pv else "",
                                                      "" if influence == "One" else "_" + influence))
    os.makedirs(here, exist_ok=True)
    pts = cloud()
    band = [k + 1 for k, (x, y) in enumerate(pts) if max(abs(x), abs(y)) > L - horizon]
    with open(os.path.join(here, "plate.txt"), "w") as f:
        for x, y in pts:
            f.write("%r %r 0.0 1 1.0\n" % (x, y))
    with open(os.path.join(here, "band.txt"), "w") as f:
        f.write("\n".join(map(str, band)) + "\n")
    ux, uy = kirsch_expression()
    text = deck(model, horizon, pv, influence).replace("{UX}", ux).replace("{UY}", uy)
    with open(os.path.join(here, "plate.yaml"), "w") as f:
        f.write(text)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run([args.peridot, "plate.yaml"], cwd=here, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if out.returncode != 0:
        sys.exit("run %s failed:\n%s%s" % (here, out.stdout, out.stderr))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    peak = float(re.search(r"peak resident ([0-9.]+) MB", out.stdout).group(1))
    import netCDF4
    d = netCDF4.Dataset(os.path.join(here, "plate.e"))
    names = [netCDF4.chartostring(n).item() for n in d.variables["name_nod_var"][:]]
    enames = [netCDF4.chartostring(n).item() for n in d.variables["name_elem_var"][:]]
    x = np.array(d.variables["coordx"][:])
    y = np.array(d.variables["coordy"][:])
    ux_n = np.array(d.variables["vals_nod_var%d" % (names.index("DisplacementX") + 1)][-1])
    uy_n = np.array(d.variables["vals_nod_var%d" % (names.index("DisplacementY") + 1)][-1])
    fxx = np.array(d.variables["vals_elem_var%deb1" % (enames.index("Deformation_GradientXX") + 1)][-1])
    d.close()
    kx, ky = kirsch(x, y)
    inner = np.maximum(np.abs(x), np.abs(y)) < L - 3 * horizon
    u_error = math.sqrt(np.sum((ux_n - kx)[inner] ** 2 + (uy_n - ky)[inner] ** 2) /
                        np.sum(kx[inner] ** 2 + ky[inner] ** 2))
    # The point above the hole's top, x = 0.5, y = first row outside the hole.
    top = min((k for k in range(len(x)) if abs(x[k] - 0.5) < 1e-9 and y[k] > 0),
              key=lambda k: y[k])
    exact = kirsch_strain_xx(x[top], y[top])
    right = [k for k in range(len(x)) if abs(x[k] - 1.5) < 1e-9 and abs(y[k] - y[top]) < 1e-9][0]
    left = [k for k in range(len(x)) if abs(x[k] + 0.5) < 1e-9 and abs(y[k] - y[top]) < 1e-9][0]
    difference = (ux_n[right] - ux_n[left]) / 2.0
    row = dict(label=label, model=model, ratio=ratio, pv=int(pv), points=len(pts), cpu=cpu,
               peak_mb=peak, u_error=u_error, hole_F=(fxx[top] - 1.0) / exact,
               hole_difference=difference / exact)
    print("  %-22s d/dx %.3f  u error %.4f  e_xx(F)/Kirsch %.3f  e_xx(du)/Kirsch %.3f  cpu %.2f s"
          % (label, horizon, u_error, row["hole_F"], row["hole_difference"], cpu), flush=True)
    return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--peridot", required=True)
    ap.add_argument("--workdir", default="/tmp/static_map")
    ap.add_argument("--figure", default="doc/figures/static_map.png")
    ap.add_argument("--csv", default="bench/tradeoff/static_map.csv")
    ap.add_argument("--quick", action="store_true", help="LPS at 3.015 only, no files")
    a = ap.parse_args()
    a.peridot = os.path.abspath(a.peridot)
    self_check()
    ratios = [3.0] if a.quick else [2.0, 3.0, 4.0, 5.0]
    models = {"LPS": "Elastic"} if a.quick else MODELS
    rows = []
    for label, model in models.items():
        for ratio in ratios:
            rows.append(run(a, label, model, ratio, False))
    if not a.quick:
        for ratio in ratios:
            rows.append(run(a, "LPS, partial volumes", "Elastic", ratio, True))
        for ratio in ratios:
            rows.append(run(a, "LPS, Conical influence", "Elastic", ratio, False, "Conical"))
    if a.quick:
        r = rows[0]
        # The quick run is a smoke test with a real bound: LPS at 3 spacings is within 3% of
        # Kirsch's field (measured ~1%); a wrong field, load or solver misses it by far.
        if not r["u_error"] < 0.03:
            sys.exit("LPS u error %.4f above 0.03" % r["u_error"])
        return
    print("\n| model | δ/Δx | u L2 error | e_xx at hole via F / Kirsch | via u differences / Kirsch | CPU [s] | peak [MB] |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %.3f | %.4f | %.3f | %.3f | %.2f | %.0f |" % (
            r["label"], r["ratio"] + 0.015, r["u_error"], r["hole_F"], r["hole_difference"],
            r["cpu"], r["peak_mb"]))
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for index, label in enumerate(dict.fromkeys(r["label"] for r in rows)):
        rs = [r for r in rows if r["label"] == label]
        colour = "C%d" % index
        ax[0].loglog([r["cpu"] for r in rs], [r["u_error"] for r in rs], "o-", color=colour,
                     label=label)
        for r in rs:
            ax[0].annotate("%g" % (r["ratio"] + 0.015), (r["cpu"], r["u_error"]), fontsize=7)
        ax[1].plot([r["ratio"] + 0.015 for r in rs], [r["hole_F"] for r in rs], "o-",
                   color=colour, label=label + " (F)")
        ax[1].plot([r["ratio"] + 0.015 for r in rs], [r["hole_difference"] for r in rs], "x--",
                   color=colour, label=label + " (Δu)")
    ax[0].set_xlabel("CPU time [s]")
    ax[0].set_ylabel("relative L2 error of u vs Kirsch")
    ax[0].legend(fontsize=7)
    ax[1].axhline(1.0, color="k", lw=0.5)
    ax[1].set_xlabel("δ/Δx")
    ax[1].set_ylabel("e_xx at the hole / Kirsch")
    ax[1].legend(fontsize=6)
    fig.suptitle("Plate with a hole under tension (QuasiStatic) against Kirsch")
    fig.tight_layout()
    fig.savefig(a.figure, dpi=120)


if __name__ == "__main__":
    main()
