#!/usr/bin/env python3
"""Weak scaling of Peridot: set-up, step and output costs and the ghost traffic per rank.

Each rank gets the same block of the bench cube (bench/README.md: PMB + critical stretch,
delta = 3.015 dx, stretched until bonds break): P ranks run an (a n) x (b n) x (c n) lattice with
a b c = P, as cubic as it goes. On a machine with fewer cores than ranks the runs are
oversubscribed, so wall-clock times measure the machine, not the code: the table gives the CPU
seconds of each phase (Peridot's "CPU <phase>" timer rows, the ranks' main threads), as the
average and the largest over the ranks, and the bytes a rank sends per ghost exchange of the
positions (one per step for PMB; from the ghost Import's export list, printed by Peridot). With
perfect weak scaling every column but the totals stays constant. Standard library only.

    python3 bench/weak_scaling.py --peridot build/peridot --ranks 1 2 4 8 16 --per-rank 32
"""

import argparse
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)

DECK = """Peridigm:
  Discretization:
    Type: "PdQuickGrid"
    NeighborhoodType: "Spherical"
    TensorProduct3DMeshGenerator:
      X Origin: 0.0
      Y Origin: 0.0
      Z Origin: 0.0
      X Length: {lx!r}
      Y Length: {ly!r}
      Z Length: {lz!r}
      Number Points X: {nx}
      Number Points Y: {ny}
      Number Points Z: {nz}
  Materials:
    Glass:
      Material Model: "Elastic Bond Based"
      Density: 2200.0
      Bulk Modulus: 14.9e9
  Damage Models:
    Stretch:
      Damage Model: "Critical Stretch"
      Critical Stretch: 0.002
  Blocks:
    Cube:
      Block Names: "block_1"
      Material: "Glass"
      Damage Model: "Stretch"
      Horizon: {horizon!r}
  Boundary Conditions:
    Stretching Velocity:
      Type: "Initial Velocity"
      Node Set: "FULL_DOMAIN"
      Coordinate: "x"
      Value: "4000.0*(x-{xc!r})"
  Solver:
    Initial Time: 0.0
    Final Time: {final!r}
    Verlet:
      Fixed dt: {dt!r}
  Output:
    Output File Type: "ExodusII"
    Output Filename: "weak_out"
    Output Frequency: {every}
    Output Variables:
      Displacement: true
      Velocity: true
      Damage: true
"""


def factors(p):
    """a, b, c with a b c = p, a >= b >= c, as close to a cube as possible."""
    best = None
    for a in range(1, p + 1):
        for b in range(1, a + 1):
            if p % (a * b):
                continue
            c = p // (a * b)
            if c > b:
                continue
            score = a - c
            if best is None or score < best[0]:
                best = (score, (a, b, c))
    return best[1]


def loadavg():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def parse(log):
    rows = {}
    for m in re.finditer(r"^\s+(\S.*?)\s{2,}([\d.]+)\s+([\d.]+)\s+([\d.]+)\s*$", log, re.M):
        rows[m.group(1).strip()] = (float(m.group(2)), float(m.group(3)), float(m.group(4)))
    r = {"rows": rows}
    m = re.search(r"Points: (\d+), bonds \(one-sided\): (\d+)", log)
    r["points"], r["bonds"] = int(m.group(1)), int(m.group(2))
    m = re.search(r"bond imbalance \(max/avg\): ([\d.]+)", log)
    r["imbalance"] = float(m.group(1)) if m else 1.0
    m = re.search(r"Ghost points per rank \(max/avg\): (\d+) / (\d+); bytes sent per ghost "
                  r"exchange of a 3-vector field, per rank \(max/avg\): (\d+) / (\d+)", log)
    r["ghosts_max"], r["ghosts_avg"], r["bytes_max"], r["bytes_avg"] = (
        [int(m.group(k)) for k in range(1, 5)] if m else [0, 0, 0, 0])
    m = re.search(r"steps: (\d+)", log)
    r["steps"] = int(m.group(1))
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--peridot", default=os.path.join(REPO, "build", "peridot"))
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4, 8, 16])
    ap.add_argument("--per-rank", type=int, default=32, help="points per rank = this^3")
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--output-every", type=int, default=10)
    ap.add_argument("--workdir", default="/tmp/peridot-weak")
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    args.peridot = os.path.abspath(args.peridot)  # the runs start in their own directories
    dx, dt = 0.5e-3, 5e-8
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    results = []
    for p in args.ranks:
        a, b, c = factors(p)
        nx, ny, nz = a * args.per_rank, b * args.per_rank, c * args.per_rank
        work = os.path.join(args.workdir, "np%d" % p)
        os.makedirs(work, exist_ok=True)
        deck = os.path.join(work, "weak.yaml")
        with open(deck, "w") as f:
            f.write(DECK.format(lx=nx * dx, ly=ny * dx, lz=nz * dx, nx=nx, ny=ny, nz=nz,
                                horizon=3.015 * dx, xc=0.5 * nx * dx, final=args.steps * dt,
                                dt=dt, every=args.output_every))
        load0 = loadavg()
        t0 = time.time()
        proc = subprocess.run(["mpirun", "--oversubscribe", "-np", str(p), args.peridot, deck],
                              cwd=work, env=env, capture_output=True, text=True)
        wall = time.time() - t0
        if proc.returncode != 0:
            sys.exit("np %d failed:\n%s\n%s" % (p, proc.stdout[-3000:], proc.stderr[-3000:]))
        r = parse(proc.stdout)
        r.update(ranks=p, grid=[nx, ny, nz], wall=wall, load=[load0, loadavg()])
        results.append(r)
        rows = r["rows"]
        cpu = lambda name, k: rows.get("CPU " + name, (0, 0, 0))[k]
        step_names = ["Force", "Damage", "Integration", "Ghost exchange", "Boundary conditions",
                      "Divergence check"]
        records = args.steps // args.output_every + 1
        print("np %2d %4dx%4dx%4d: %d points, %d bonds, imbalance %.3f, wall %.1f s, load %.1f-%.1f"
              % (p, nx, ny, nz, r["points"], r["bonds"], r["imbalance"], wall, load0,
                 r["load"][1]), flush=True)
        r["summary"] = {
            "setup_avg": cpu("Setup", 2), "setup_max": cpu("Setup", 1),
            "search_avg": cpu("Setup: partition + search", 2),
            "search_max": cpu("Setup: partition + search", 1),
            "step_avg": sum(cpu(n, 2) for n in step_names) / r["steps"],
            "step_max": sum(cpu(n, 1) for n in step_names) / r["steps"],
            "ghost_avg": cpu("Ghost exchange", 2) / r["steps"],
            "output_avg": cpu("Output", 2) / records, "output_max": cpu("Output", 1) / records,
        }
    print()
    print("| ranks | lattice | points/rank | bonds/rank | set-up CPU avg / max [s] | "
          "partition + search avg / max [s] | step CPU avg / max [ms] | ghost exchange avg [ms] | "
          "output per record avg / max [ms] | ghost points/rank max / avg | "
          "bytes sent/step/rank max / avg | bond imbalance | load avg |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in results:
        s = r["summary"]
        print("| %d | %s | %d | %.2fM | %.2f / %.2f | %.2f / %.2f | %.1f / %.1f | %.2f | %.1f / %.1f "
              "| %d / %d | %d / %d | %.3f | %.1f |"
              % (r["ranks"], "x".join(map(str, r["grid"])), r["points"] // r["ranks"],
                 r["bonds"] / r["ranks"] / 1e6, s["setup_avg"], s["setup_max"], s["search_avg"],
                 s["search_max"], 1e3 * s["step_avg"], 1e3 * s["step_max"], 1e3 * s["ghost_avg"],
                 1e3 * s["output_avg"], 1e3 * s["output_max"], r["ghosts_max"], r["ghosts_avg"],
                 r["bytes_max"], r["bytes_avg"], r["imbalance"], sum(r["load"]) / 2))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
