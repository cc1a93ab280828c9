#!/usr/bin/python3
"""Speed/accuracy map for fracture (issue 14, item 5): V4's critical traction (the plane-strain
edge-cracked patch, examples/v4_edge_crack) by model and horizon ratio, against LEFM.

One material for all models, E = 1e4 Pa, nu = 1/4, plane strain, G_I = 1 J/m^2 (each model's
critical stretch from the fracture energy): LEFM gives 134.9 Pa (paper 000 eqs. 23-24). For each
model (normalized PMB, PMB, LPS; PMB and LPS also with the Conical influence function, whose
critical stretch comes from the same fracture energy through J_k) and delta/dx (3.015, 4.015, 5.015) the patch is run at dx = a/3 ... a/8
and the critical traction (the crack has grown by 0.1 m, critical.py's measure) is fitted
linearly in dx and extrapolated to dx -> 0. Cost: the CPU time of the finest run.

Usage: bench/tradeoff/fracture_map.py --peridot build/peridot [--workdir DIR]
       [--figure doc/figures/fracture_map.png] [--csv bench/tradeoff/fracture_map.csv]
Prints the table as Markdown.
"""
import argparse
import csv
import math
import os
import resource
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
V4 = os.path.join(HERE, "..", "..", "examples", "v4_edge_crack")
sys.path.insert(0, V4)
import critical  # noqa: E402  (examples/v4_edge_crack/critical.py)

A = 0.125
SPACINGS = [A / 3, A / 4, A / 5, A / 6, A / 8]
# label -> (make_patch.py --material, --influence)
MATERIALS = {"normalized PMB": ("normalized-pmb", "One"), "PMB": ("pmb", "One"),
             "LPS": ("lps", "One"), "PMB, Conical": ("pmb", "Conical"),
             "LPS, Conical": ("lps", "Conical")}
RATIOS = [3.015, 4.015, 5.015]
RATE = 400.0


def run(args, material, influence, ratio, dx):
    made = subprocess.run(["/usr/bin/python3", os.path.join(V4, "make_patch.py"), "%.7f" % dx,
                           "--model", "consistent", "--material", material, "--influence", influence,
                           "--horizon-ratio", repr(ratio), "--rate", repr(RATE)],
                          cwd=args.workdir, capture_output=True, text=True, check=True)
    deck = made.stdout.split(":")[0]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run([args.peridot, deck], cwd=args.workdir, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if out.returncode != 0:
        sys.exit("run %s failed:\n%s%s" % (deck, out.stdout, out.stderr))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    _, grown, init, runaway = critical.read(os.path.join(args.workdir, deck[:-5] + ".h"), RATE)
    print("  %-15s %-8s d/dx %.3f dx %.5f  critical %.2f Pa  cpu %.1f s" %
          (material, influence, ratio, dx, grown, cpu), flush=True)
    return dict(material=material, influence=influence, ratio=ratio, dx=dx, critical=grown, first_tip_bond=init,
                runaway=runaway, cpu=cpu)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--peridot", required=True)
    ap.add_argument("--workdir", default="/tmp/fracture_map")
    ap.add_argument("--figure", default="doc/figures/fracture_map.png")
    ap.add_argument("--csv", default="bench/tradeoff/fracture_map.csv")
    a = ap.parse_args()
    a.peridot = os.path.abspath(a.peridot)
    os.makedirs(a.workdir, exist_ok=True)
    lefm = critical.lefm(1e4 / (1 - 0.25 ** 2))
    rows, fits = [], []
    for label, (material, influence) in MATERIALS.items():
        for ratio in RATIOS:
            series = [run(a, material, influence, ratio, dx) for dx in SPACINGS]
            for r in series:
                r["label"] = label
            rows += series
            x = np.array([r["dx"] for r in series])
            y = np.array([r["critical"] for r in series])
            M = np.vstack([np.ones(len(x)), x]).T
            coef, *_ = np.linalg.lstsq(M, y, rcond=None)
            resid = y - M @ coef
            err = math.sqrt(resid @ resid / (len(x) - 2) * np.linalg.inv(M.T @ M)[0, 0])
            fits.append(dict(label=label, ratio=ratio, sigma0=coef[0], error=err,
                             finest=y[-1], cpu_finest=series[-1]["cpu"]))
    print("\nLEFM (E = 1e4, nu = 1/4, plane strain): %.1f Pa\n" % lefm)
    print("| model | δ/Δx | at dx = a/3 | at dx = a/8 | extrapolated to dx → 0 | vs LEFM | CPU at a/8 [s] |")
    print("|---|---|---|---|---|---|---|")
    for f in fits:
        first = [r["critical"] for r in rows if r["label"] == f["label"] and r["ratio"] == f["ratio"]]
        print("| %s | %.3f | %.1f | %.1f | %.1f ± %.1f | %+.1f%% | %.1f |" % (
            f["label"], f["ratio"], first[0], f["finest"], f["sigma0"], f["error"],
            100 * (f["sigma0"] / lefm - 1), f["cpu_finest"]))
    with open(a.csv, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=["label", "material", "influence", "ratio", "dx", "critical",
                                           "first_tip_bond", "runaway", "cpu"])
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for n, f in enumerate(fits):
        rs = [r for r in rows if r["label"] == f["label"] and r["ratio"] == f["ratio"]]
        style = ["-", "--", ":"][RATIOS.index(f["ratio"])]
        colour = "C%d" % list(MATERIALS).index(f["label"])
        name = "%s, δ = %g dx" % (f["label"], f["ratio"])
        ax[0].plot([r["dx"] for r in rs], [r["critical"] for r in rs], "o" + style, c=colour,
                   label=name)
        ax[0].plot([0], [f["sigma0"]], "D", c=colour, mfc="none")
        ax[1].plot([r["cpu"] for r in rs], [abs(r["critical"] / lefm - 1) for r in rs],
                   "o" + style, c=colour, label=name)
    ax[0].axhline(lefm, c="k", lw=0.8, label="LEFM %.1f Pa" % lefm)
    ax[0].set_xlabel("lattice spacing dx [m] (diamonds: linear extrapolation)")
    ax[0].set_ylabel("critical traction [Pa]")
    ax[0].legend(fontsize=7)
    ax[1].set_xscale("log")
    ax[1].set_yscale("log")
    ax[1].set_xlabel("CPU time of the run [s]")
    ax[1].set_ylabel("|critical / LEFM - 1|")
    fig.suptitle("V4 edge-cracked patch: critical traction by model and horizon ratio")
    fig.tight_layout()
    fig.savefig(a.figure, dpi=110)


if __name__ == "__main__":
    main()
