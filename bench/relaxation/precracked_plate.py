#!/usr/bin/python3
"""A pre-cracked plate pulled to failure three ways (issue 11, item 5): adaptive dynamic
relaxation, QuasiStatic (Newton on the tangent) and an explicit Verlet run with a slow ramp.

The plate: 40 x 40 points of unit spacing in the plane (2D, plane stress, bond-based PMB,
K = 1, rho = 1, horizon 3.015, critical stretch 0.005), an edge crack from x = 0 to x = 16
along y = 20 (a bond filter), the three top rows pulled up and the three bottom rows down by
d(t) = 0.15 t each (the bottom rows also held in x), t from 0 to 1 in 60 load steps. The load
is the sum of the top rows' internal force (the reaction), from a Node_Set_Data compute in a
globals-only output stream. Explicit: the same ramp over T = 3000 time units (about 100 wave
transits of the plate) with Peridigm's stable step, output 60 times.

Usage: bench/relaxation/precracked_plate.py --peridot build/peridot [--workdir DIR]
       [--figure doc/figures/precracked_plate.png] [--csv bench/relaxation/precracked_plate.csv]
Prints a Markdown summary (peak load, displacement at peak, iterations, CPU time).
"""
import argparse
import csv
import os
import re
import subprocess
import time

import netCDF4
import numpy as np

N, DELTA, PULL, STEPS, T_RAMP = 40, 3.015, 0.15, 60, 3000.0


def write_mesh(path):
    top, bottom = [], []
    with open(path, "w") as f:
        gid = 0
        for j in range(N):
            for i in range(N):
                gid += 1
                y = j + 0.5
                f.write("%r %r 0.0 1 1.0\n" % (i + 0.5, y))
                if y > N - 3:
                    top.append(gid)
                if y < 3:
                    bottom.append(gid)
    return top, bottom


def deck(solver, ramp_time):
    scale = "t" if ramp_time == 1.0 else "t/%r" % ramp_time
    return f"""Peridigm:
  Discretization:
    Type: Text File
    Input Mesh File: plate.txt
    Dimension: 2
    Thickness: 1.0
    Bond Filters:
      Crack:
        Type: Rectangular_Plane
        Normal_X: 0.0
        Normal_Y: 1.0
        Normal_Z: 0.0
        Lower_Left_Corner_X: -1.0
        Lower_Left_Corner_Y: 20.0
        Lower_Left_Corner_Z: 1.0
        Bottom_Unit_Vector_X: 1.0
        Bottom_Unit_Vector_Y: 0.0
        Bottom_Unit_Vector_Z: 0.0
        Bottom_Length: 17.0
        Side_Length: 2.0
  Materials:
    PMB:
      Material Model: Elastic Bond Based
      Plane Stress: true
      Density: 1.0
      Bulk Modulus: 1.0
  Damage Models:
    Stretch:
      Damage Model: Critical Stretch
      Critical Stretch: 0.005
  Blocks:
    Plate:
      Block Names: block_1
      Material: PMB
      Damage Model: Stretch
      Horizon: {DELTA}
  Boundary Conditions:
    Top Node Set: top.txt
    Bottom Node Set: bottom.txt
    Pull Up:
      Type: Prescribed Displacement
      Node Set: Top Node Set
      Coordinate: y
      Value: "{PULL}*{scale}"
    Pull Down:
      Type: Prescribed Displacement
      Node Set: Bottom Node Set
      Coordinate: y
      Value: "-{PULL}*{scale}"
    Hold:
      Type: Prescribed Displacement
      Node Set: Bottom Node Set
      Coordinate: x
      Value: "0.0"
  Compute Class Parameters:
    Reaction:
      Compute Class: Node_Set_Data
      Calculation Type: Sum
      Node Set: Top Node Set
      Variable: Force
      Output Label: Reaction
    Broken:
      Compute Class: Block_Data
      Calculation Type: Maximum
      Block: block_1
      Variable: Damage
      Output Label: MaxDamage
  Solver:
    Final Time: {ramp_time!r}
{solver}  Output History:
    Output Filename: history
    Output Frequency: {1 if ramp_time == 1.0 else "FREQ"}
    Output Variables:
      Reaction: true
      MaxDamage: true
"""


def run(peridot, workdir, name, text):
    os.makedirs(os.path.join(workdir, name), exist_ok=True)
    here = os.path.join(workdir, name)
    top, bottom = write_mesh(os.path.join(here, "plate.txt"))
    open(os.path.join(here, "top.txt"), "w").write("\n".join(map(str, top)) + "\n")
    open(os.path.join(here, "bottom.txt"), "w").write("\n".join(map(str, bottom)) + "\n")
    open(os.path.join(here, "plate.yaml"), "w").write(text)
    start = time.process_time()
    wall = time.time()
    p = subprocess.run([peridot, "plate.yaml"], cwd=here, capture_output=True, text=True)
    cpu = time.process_time() - start  # children are not counted here; see resource below
    wall = time.time() - wall
    log = p.stdout + p.stderr
    open(os.path.join(here, "log.txt"), "w").write(log)
    h = netCDF4.Dataset(os.path.join(here, "history.h"))
    names = [netCDF4.chartostring(n).item() for n in h.variables["name_glo_var"][:]]
    values = np.array(h.variables["vals_glo_var"][:])
    times = np.array(h.variables["time_whole"][:])
    h.close()
    load = values[:, names.index("ReactionY")]
    damage = values[:, names.index("MaxDamage")]
    return {"times": times, "load": -load, "damage": damage, "log": log, "status": p.returncode,
            "wall": wall}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--peridot", required=True)
    ap.add_argument("--workdir", default="/tmp/precracked_plate")
    ap.add_argument("--figure", default="doc/figures/precracked_plate.png")
    ap.add_argument("--csv", default="bench/relaxation/precracked_plate.csv")
    a = ap.parse_args()
    peridot = os.path.abspath(a.peridot)
    adr = f"""    Adaptive Dynamic Relaxation:
      Number of Load Steps: {STEPS}
      Relative Tolerance: 1.0e-4
"""
    qs = f"""    QuasiStatic:
      Number of Load Steps: {STEPS}
      Relative Tolerance: 1.0e-4
      Maximum Solver Iterations: 30
"""
    verlet = "    Verlet:\n      Safety Factor: 0.9\n"
    explicit = deck(verlet, T_RAMP)
    # Peridigm's estimate for this plate, read from a --check run, gives the output frequency.
    here = os.path.join(a.workdir, "probe")
    os.makedirs(here, exist_ok=True)
    write_mesh(os.path.join(here, "plate.txt"))
    top, bottom = write_mesh(os.path.join(here, "plate.txt"))
    open(os.path.join(here, "top.txt"), "w").write("\n".join(map(str, top)) + "\n")
    open(os.path.join(here, "bottom.txt"), "w").write("\n".join(map(str, bottom)) + "\n")
    open(os.path.join(here, "plate.yaml"), "w").write(explicit.replace("FREQ", "1"))
    probe = subprocess.run([peridot, "--check", "plate.yaml"], cwd=here, capture_output=True,
                           text=True)
    steps = int(re.search(r"steps: (\d+)", probe.stdout + probe.stderr).group(1))
    explicit = explicit.replace("FREQ", str(max(1, steps // STEPS)))
    results = {}
    for name, text in (("ADR", deck(adr, 1.0)), ("QuasiStatic", deck(qs, 1.0)),
                       ("Verlet slow ramp", explicit)):
        results[name] = run(peridot, a.workdir, name.split()[0], text)
    rows = []
    print("| Method | Steps done | Peak load | d at peak | Iterations | Wall s | Ended |")
    print("|---|---|---|---|---|---|---|")
    for name, r in results.items():
        scale = 1.0 if name != "Verlet slow ramp" else 1.0 / T_RAMP
        d = PULL * r["times"] * scale * 2  # opening of the grips
        k = int(np.argmax(r["load"]))
        iterations = "-"
        m = re.search(r"Adaptive Dynamic Relaxation: (\d+) iterations", r["log"])
        if m:
            iterations = m.group(1)
        m = re.search(r"QuasiStatic: (\d+) Newton iterations", r["log"])
        if m:
            iterations = m.group(1) + " Newton"
        if name == "Verlet slow ramp":
            iterations = "%d steps" % steps
        ended = "completed" if r["status"] == 0 else "stopped (exit %d)" % r["status"]
        if r["status"] != 0:
            m = re.search(r"load step (\d+)", r["log"])
            if m:
                ended += " at load step " + m.group(1)
        print("| %s | %d | %.4g | %.4g | %s | %.1f | %s |" % (
            name, len(d) - 1, r["load"][k], d[k], iterations, r["wall"], ended))
        for di, li, dmg in zip(d, r["load"], r["damage"]):
            rows.append((name, di, li, dmg))
    with open(a.csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["method", "grip_opening", "load", "max_damage"])
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for name, style in (("Verlet slow ramp", "-"), ("QuasiStatic", "s"), ("ADR", "o-")):
        d = [r[1] for r in rows if r[0] == name]
        load = [r[2] for r in rows if r[0] == name]
        ax.plot(d, load, style, label=name, markersize=3)
    ax.set_xlabel("grip opening")
    ax.set_ylabel("load (reaction of the top rows)")
    ax.set_title("Pre-cracked PMB plate pulled to failure")
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.figure, dpi=120)


if __name__ == "__main__":
    main()
