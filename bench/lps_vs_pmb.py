#!/usr/bin/env python3
"""LPS against PMB per time step, whole Peridot runs, back to back (issue 16 item 3).

Writes run_bench.py's PMB and LPS decks (cube pulled apart, critical stretch, LPS with
omega = 1/|xi|) for each size, then runs them alternately (PMB, LPS, PMB, LPS, ...) so that a
shared machine's load hits both alike, and reports the medians of the per-step costs from
Peridot's CPU timers (model evaluation = Force + Damage + Ghost exchange, the time step loop =
those + Integration + Boundary conditions + Divergence check; the largest rank's) and their
LPS / PMB ratios, with the load average before each run. On more than one rank the CPU time of
the ghost exchange includes MPI's busy waiting: compare Force + Damage across rank counts.

    python3 bench/lps_vs_pmb.py --sizes 32 64 --steps 100 --repeats 5 --peridot build/peridot
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

EVALUATION = ["Force", "Damage", "Ghost exchange"]
LOOP = EVALUATION + ["Integration", "Boundary conditions", "Divergence check"]


def cpu_timers(log):
    """CPU timer rows of a Peridot log: name -> max over ranks [s]."""
    timers = {}
    for line in log.splitlines():
        m = re.match(r"\s+CPU (.+?)\s+([0-9.]+)\s+([0-9.]+)\s+([0-9.]+)\s*$", line)
        if m:
            timers[m.group(1)] = float(m.group(3))
    return timers


def load_average():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def run(peridot, deck_dir, ranks):
    cmd = [peridot, "peridot.xml"]
    if ranks > 1:
        cmd = ["mpirun", "--oversubscribe", "-np", str(ranks)] + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    out = subprocess.run(cmd, cwd=deck_dir, env=env, capture_output=True, text=True, check=True)
    return cpu_timers(out.stdout + out.stderr)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", nargs="+", type=int, default=[32, 64])
    ap.add_argument("--steps", type=int, default=100)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--peridot", default=os.path.join(HERE, "..", "build", "peridot"))
    ap.add_argument("--workdir", default="/tmp/lps-vs-pmb")
    ap.add_argument("--lps-influence", choices=["inverse", "one"], default="inverse")
    a = ap.parse_args()
    peridot = os.path.abspath(a.peridot)
    subprocess.run([sys.executable, os.path.join(HERE, "run_bench.py"), "--sizes"] +
                   [str(n) for n in a.sizes] + ["--models", "pmb", "lps", "--steps", str(a.steps),
                   "--codes", "peridot", "--write-only", "--workdir", a.workdir,
                   "--lps-influence", a.lps_influence], check=True, capture_output=True)
    print("peridot %s, %d rank(s), %d steps, LPS influence %s" % (peridot, a.ranks, a.steps,
                                                                  a.lps_influence))
    for n in a.sizes:
        rows = {"pmb": [], "lps": []}
        loads = []
        for rep in range(a.repeats):
            for model in ["pmb", "lps"]:
                loads.append(load_average())
                t = run(peridot, os.path.join(a.workdir, "N%d_%s" % (n, model)), a.ranks)
                ev = sum(t.get(k, 0.0) for k in EVALUATION)
                loop = sum(t.get(k, 0.0) for k in LOOP)
                rows[model].append((ev, loop))
                print("  N=%d %s rep %d: evaluation %.3f s (Force + Damage %.3f s), loop %.3f s "
                      "CPU (load %.2f)" % (n, model, rep, ev, t.get("Force", 0.0) +
                                           t.get("Damage", 0.0), loop, loads[-1]), flush=True)
        med = {m: (statistics.median(r[0] for r in rows[m]),
                   statistics.median(r[1] for r in rows[m])) for m in rows}
        pairs = statistics.median(l[1] / p[1] for p, l in zip(rows["pmb"], rows["lps"]))
        print("N=%d: LPS/PMB loop, median of the back-to-back pairs: %.2f" % (n, pairs))
        print("N=%d: median CPU per %d steps: PMB evaluation %.3f s, loop %.3f s; LPS evaluation "
              "%.3f s, loop %.3f s; LPS/PMB evaluation %.2f, loop %.2f; load %.1f-%.1f" %
              (n, a.steps, med["pmb"][0], med["pmb"][1], med["lps"][0], med["lps"][1],
               med["lps"][0] / med["pmb"][0], med["lps"][1] / med["pmb"][1], min(loads),
               max(loads)), flush=True)


if __name__ == "__main__":
    main()
