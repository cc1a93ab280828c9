#!/usr/bin/env python3
"""Memory and set-up/output time of one deck at several rank counts (the cluster study).

Runs `mpirun -np P peridot DECK` for each P (oversubscribed on a small machine), and reads
from Peridot's log the largest rank's peak resident memory, the summed peak, the set-up and
output wall-clock times (max over ranks) and the point and bond counts. Standard library only.

    python3 bench/cluster_scaling.py --deck /tmp/box/box.yaml --ranks 1 2 4 8 16

`--box N` first writes an N^3 HEX8 Exodus box and a deck for it (Elastic Bond Based, horizon
1.5 dx, one step, one output record of Displacement, Velocity, Damage) with
`build/bench_make_box_mesh`.
"""

import argparse
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)

DECK = """Peridigm:
  Discretization:
    Type: "Exodus"
    Input Mesh File: "{mesh}"
  Materials:
    Glass:
      Material Model: "Elastic Bond Based"
      Density: 2200.0
      Bulk Modulus: 14.9e9
  Blocks:
    All:
      Block Names: "block_1"
      Material: "Glass"
      Horizon: {horizon}
  Solver:
    Initial Time: 0.0
    Final Time: {final}
    Verlet:
      Fixed dt: {dt}
  Output:
    Output File Type: "ExodusII"
    Output Filename: "box_out"
    Output Frequency: 1
    Output Variables:
      Displacement: true
      Velocity: true
      Damage: true
"""


def write_box(n, workdir, tool):
    os.makedirs(workdir, exist_ok=True)
    mesh = os.path.join(workdir, "box%d.g" % n)
    dx = 1.0  # bench_make_box_mesh writes unit-spacing elements
    if not os.path.exists(mesh):
        subprocess.run([tool, str(n), mesh], check=True)
    deck = os.path.join(workdir, "box%d.yaml" % n)
    with open(deck, "w") as f:
        f.write(DECK.format(mesh=mesh, horizon=1.5 * dx, dt=1.0e-4, final=1.0e-4))
    return deck


def parse(out):
    r = {}
    m = re.search(r"largest rank's peak resident ([\d.]+) MB", out)
    r["largest_rank_mb"] = float(m.group(1)) if m else None
    m = re.search(r"peak resident ([\d.]+) MB = ", out)
    r["sum_mb"] = float(m.group(1)) if m else None
    m = re.search(r"Points: (\d+), bonds \(one-sided\): (\d+)", out)
    if m:
        r["points"], r["bonds"] = int(m.group(1)), int(m.group(2))
    for name in ("Setup", "Setup: read mesh", "Setup: partition + search", "Output"):
        m = re.search(r"^  " + re.escape(name) + r"\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)", out, re.M)
        r[name] = float(m.group(2)) if m else None  # max over ranks
    return r


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--deck")
    p.add_argument("--box", type=int, help="write an N^3 HEX8 box and its deck first")
    p.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4, 8, 16])
    p.add_argument("--peridot", default=os.path.join(REPO, "build", "peridot"))
    p.add_argument("--tool", default=os.path.join(REPO, "build", "bench_make_box_mesh"))
    p.add_argument("--workdir", default="/tmp/peridot-cluster")
    p.add_argument("--json")
    a = p.parse_args()
    deck = write_box(a.box, a.workdir, a.tool) if a.box else a.deck
    if not deck:
        sys.exit("give --deck or --box")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    rows = []
    for np_ in a.ranks:
        cmd = ["mpirun", "--oversubscribe", "-np", str(np_), a.peridot, os.path.abspath(deck)]
        run = subprocess.run(cmd, cwd=os.path.dirname(os.path.abspath(deck)), env=env,
                             capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit("peridot failed at %d ranks:\n%s%s" % (np_, run.stdout, run.stderr))
        r = parse(run.stdout)
        r["ranks"] = np_
        rows.append(r)
        print("%3d ranks: largest rank %8.1f MB, all ranks %8.1f MB, set-up %7.2f s (read %6.2f, "
              "partition+search %6.2f), output %6.2f s" %
              (np_, r["largest_rank_mb"], r["sum_mb"], r["Setup"], r["Setup: read mesh"],
               r["Setup: partition + search"], r["Output"]), flush=True)
    base = rows[0]["largest_rank_mb"]
    for r in rows:
        print("%3d ranks: largest rank / 1-rank peak = %.3f" % (r["ranks"], r["largest_rank_mb"] / base))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
