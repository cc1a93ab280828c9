#!/usr/bin/python3
"""Speed/accuracy map for wave propagation (issue 14, item 5), on the V2 geometry.

A right-going Gaussian pulse u = A g(x - x0 - c t) in a bar periodic in y and z (a plane wave:
the classical solution travels undistorted at c_l = sqrt(1.8 K / rho) for every model here,
nu = 1/4). Each run's error is the relative L2 difference of u_x along one line of points at
the final time from that classical solution; its cost is the process CPU time (not wall time:
the machine may be shared) and its peak resident memory, as Peridot's log reports it.

Studies (one PNG each, written to --figures):
  models   PMB, normalized PMB, LPS, linearized LPS at delta/dx = 2..6 (+0.015), dt = estimate
  timestep normalized PMB and LPS at delta = 3.015 dx: Safety Factor 0.25/0.5/1 of Peridigm's
           estimate and 0.9 of the "Verlet Limit"
  options  LPS and normalized PMB at delta/dx = 3.015: partial volumes, influence functions

Usage: bench/tradeoff/wave_map.py --peridot build/peridot [--workdir DIR] [--figures doc/figures]
       [--quick]   (delta/dx 2 and 3 only, for a smoke run)
Writes DIR/wave_map.csv and the PNGs; prints the table as Markdown.
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

K, RHO, A, WIDTH, X0, T_END, LENGTH = 10.0, 1.0, 1e-3, 15.0, 75.0, 40.0, 300
CL = math.sqrt(1.8 * K / RHO)
MODELS = {"PMB": "Elastic Bond Based", "normalized PMB": "Normalized PMB", "LPS": "Elastic",
          "linearized LPS": "Linearized LPS"}


def deck_text(name, model, horizon, n_yz, dt, steps, options):
    shear = "      Shear Modulus: %r\n" % (0.6 * K) if model in ("Elastic", "Linearized LPS") else ""
    extra = "".join("    %s: %s\n" % kv for kv in options.get("discretization", {}).items())
    solver = ("      Fixed dt: %r\n" % dt) if dt else ("      Safety Factor: 1.0\n")
    if options.get("estimate"):
        solver += '      Stable Time Step Estimate: "%s"\n' % options["estimate"]
    # Half a step past the last one: Peridot, as Peridigm, takes floor((t_f - t_0) / dt) steps,
    # and the quotient of steps * dt by dt may round to just below `steps`.
    final = (steps + 0.5) * dt if dt else T_END
    return f"""Peridigm:
  Discretization:
    Type: PdQuickGrid
    NeighborhoodType: Spherical
    Periodic Y: true
    Periodic Z: true
{extra}    TensorProduct3DMeshGenerator:
      X Origin: 0.0
      Y Origin: 0.0
      Z Origin: 0.0
      X Length: {float(LENGTH)}
      Y Length: {float(n_yz)}
      Z Length: {float(n_yz)}
      Number Points X: {LENGTH}
      Number Points Y: {n_yz}
      Number Points Z: {n_yz}
  Materials:
    M:
      Material Model: "{model}"
      Density: {RHO}
      Bulk Modulus: {K}
{shear}  Blocks:
    B:
      Block Names: block_1
      Material: M
      Horizon: {horizon}
  Boundary Conditions:
    All Node Set: all_{n_yz}.txt
    U:
      Type: Initial Displacement
      Node Set: All Node Set
      Coordinate: x
      Value: "{A}*exp(-((x - {X0})/{WIDTH})^2)"
    V:
      Type: Initial Velocity
      Node Set: All Node Set
      Coordinate: x
      Value: "{CL!r}*{A}*2*(x - {X0})/{WIDTH**2}*exp(-((x - {X0})/{WIDTH})^2)"
  Solver:
    Final Time: {final!r}
    Verlet:
{solver}  Output:
    Output File Type: ExodusII
    Output Filename: {name}
    Output Frequency: {steps if steps else 1000000}
    Output Variables:
      Displacement: true
"""


def run(args, name, label, model, ratio, options, safety=1.0):
    horizon = ratio + 0.015
    n_yz = max(4, int(math.ceil(2 * horizon)) + 1)  # no point bonded to two images of one
    ids = os.path.join(args.workdir, "all_%d.txt" % n_yz)
    if not os.path.exists(ids):
        with open(ids, "w") as f:
            f.write("\n".join(str(i) for i in range(1, LENGTH * n_yz * n_yz + 1)) + "\n")
    path = os.path.join(args.workdir, name + ".yaml")
    # The estimate first (--check), then Fixed dt = safety x estimate and a whole number of
    # steps, so that the last record is at the final time.
    with open(path, "w") as f:
        f.write(deck_text(name, model, horizon, n_yz, None, None, options))
    check = subprocess.run([args.peridot, "--check", name + ".yaml"], cwd=args.workdir,
                           capture_output=True, text=True)
    m = re.search(r"Stable time step estimate: ([0-9.eE+-]+)", check.stdout)
    if check.returncode != 0 or not m:
        sys.exit("--check failed for %s:\n%s%s" % (name, check.stdout, check.stderr))
    dt = safety * float(m.group(1))
    steps = int(math.ceil(T_END / dt))
    dt = T_END / steps
    with open(path, "w") as f:
        f.write(deck_text(name, model, horizon, n_yz, dt, steps, options))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    wall = time.time()
    out = subprocess.run([args.peridot, name + ".yaml"], cwd=args.workdir, capture_output=True,
                         text=True)
    wall = time.time() - wall
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if out.returncode != 0:
        sys.exit("run %s failed:\n%s%s" % (name, out.stdout, out.stderr))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    peak = float(re.search(r"peak resident ([0-9.]+) MB", out.stdout).group(1))
    bonds = int(re.search(r"bonds \(one-sided\): (\d+)", out.stdout).group(1).replace(",", ""))
    error = pulse_error(os.path.join(args.workdir, name + ".e"), steps * dt)
    row = dict(study=label[0], label=label[1], model=model, ratio=ratio, safety=safety,
               dt=dt, steps=steps, points=LENGTH * n_yz * n_yz, bonds=bonds, cpu=cpu,
               wall=wall, peak_mb=peak, error=error)
    print("  %-10s %-28s dt %.4g x%d  error %.4f  cpu %.2f s  peak %.0f MB" %
          (label[0], label[1], dt, steps, error, cpu, peak), flush=True)
    return row


def pulse_error(exodus, t):
    import netCDF4
    with netCDF4.Dataset(exodus) as d:
        names = [b"".join(n).decode().strip("\x00").strip()
                 for n in d.variables["name_nod_var"][:].filled(b"")]
        ux = d.variables["vals_nod_var%d" % (names.index("DisplacementX") + 1)][-1, :]
        time_last = float(d.variables["time_whole"][-1])
        x = d.variables["coordx"][:]
        y = d.variables["coordy"][:]
        z = d.variables["coordz"][:]
    if abs(time_last - t) > 1e-9 * t:
        sys.exit("%s: last record at t = %g, expected %g" % (exodus, time_last, t))
    line = (np.abs(y - y.min()) < 1e-9) & (np.abs(z - z.min()) < 1e-9)
    exact = A * np.exp(-((x[line] - X0 - CL * t) / WIDTH) ** 2)
    return float(np.linalg.norm(ux[line] - exact) / np.linalg.norm(exact))


def plot(rows, study, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4.2))
    groups = {}
    for r in rows:
        if r["study"] == study:
            groups.setdefault(r["model"] if study == "models" else r["label"], []).append(r)
    for key, rs in groups.items():
        cpu = [r["cpu"] for r in rs]
        mem = [r["peak_mb"] for r in rs]
        err = [r["error"] for r in rs]
        style = "o-" if study == "models" else "o"
        ax[0].loglog(cpu, err, style, label=key)
        ax[1].semilogy(mem, err, style, label=key)
        if study == "models":
            for r in rs:
                ax[0].annotate("%g" % r["ratio"], (r["cpu"], r["error"]), fontsize=7,
                               xytext=(3, 3), textcoords="offset points")
    ax[0].set_xlabel("CPU time [s]")
    ax[1].set_xlabel("peak resident memory [MB]")
    for a in ax:
        a.set_ylabel("relative L2 error of u_x")
        a.grid(True, which="both", alpha=0.3)
    ax[0].legend(fontsize=7)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--peridot", required=True)
    p.add_argument("--workdir", default="/tmp/peridot-wave-map")
    p.add_argument("--figures", default=None, help="directory for the PNGs (none: no plots)")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--replot", metavar="CSV", help="only redraw the PNGs from a wave_map.csv")
    args = p.parse_args()
    if args.replot:
        with open(args.replot) as f:
            rows = [dict(r, cpu=float(r["cpu"]), peak_mb=float(r["peak_mb"]),
                         error=float(r["error"]), ratio=float(r["ratio"]))
                    for r in csv.DictReader(f)]
        figures(rows, args.figures or ".")
        return
    args.peridot = os.path.abspath(args.peridot)
    os.makedirs(args.workdir, exist_ok=True)
    ratios = [2, 3] if args.quick else [2, 3, 4, 5, 6]
    rows = []
    for short, model in MODELS.items():
        for m in ratios:
            rows.append(run(args, "m_%s_%d" % (model.replace(" ", "_"), m), ("models", short),
                            model, m, {}))
    for short in ("normalized PMB", "LPS"):
        model = MODELS[short]
        for s in (0.25, 0.5, 1.0):
            rows.append(run(args, "t_%s_%s" % (model.replace(" ", "_"), str(s).replace(".", "p")),
                            ("timestep", "%s, %g x Peridigm" % (short, s)), model, 3, {}, s))
        rows.append(run(args, "t_%s_vl" % model.replace(" ", "_"),
                        ("timestep", "%s, 0.9 x Verlet Limit" % short), model, 3,
                        {"estimate": "Verlet Limit"}, 0.9))
    for short in ("normalized PMB", "LPS"):
        model = MODELS[short]
        variants = [("centre rule, One", {})]
        variants.append(("partial volumes", {"discretization": {"Partial Volumes": "true"}}))
        if model == "Elastic":
            for f in ("Parabolic Decay", "Gaussian", "Conical"):
                variants.append(("influence %s" % f,
                                 {"discretization": {"Influence Function": '"%s"' % f}}))
        for label, opts in variants:
            rows.append(run(args, "o_%s_%s" % (model.replace(" ", "_"),
                                               re.sub(r"\W+", "_", label)),
                            ("options", "%s, %s" % (short, label)), model, 3, opts))
    with open(os.path.join(args.workdir, "wave_map.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("\n| study | case | δ/Δx | Δt | steps | bonds | CPU [s] | peak [MB] | error |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print("| %s | %s | %g | %.4g | %d | %d | %.2f | %.0f | %.4f |" %
              (r["study"], r["label"], r["ratio"] + 0.015, r["dt"], r["steps"], r["bonds"],
               r["cpu"], r["peak_mb"], r["error"]))
    if args.figures:
        figures(rows, args.figures)


def figures(rows, directory):
    os.makedirs(directory, exist_ok=True)
    plot(rows, "models", os.path.join(directory, "map_wave_models.png"),
         "Gaussian pulse, 40 s of travel: error vs cost, per model, labels = δ/Δx "
         "(Δx = 1, Δt = Peridigm's estimate)")
    plot(rows, "timestep", os.path.join(directory, "map_wave_timestep.png"),
         "Gaussian pulse, δ = 3.015Δx: time step choices")
    plot(rows, "options", os.path.join(directory, "map_wave_options.png"),
         "Gaussian pulse, δ = 3.015Δx: quadrature and influence function")


if __name__ == "__main__":
    main()
