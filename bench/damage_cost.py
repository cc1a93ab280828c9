#!/usr/bin/env python3
"""Cost of the damage models per time step against PMB + critical stretch, whole Peridot runs.

Writes run_bench.py's PMB cube (pulled apart until bonds break, delta = 3.015 dx), derives one
deck per damage model from it (the same scene, `Damage Model` replaced), and runs them
alternately so that a shared machine's load hits all alike. Reports the medians of the CPU of
Force + Damage (the largest rank's timers) and their ratio to PMB + critical stretch. With
--baseline, an older binary runs each deck too, back to back with --peridot. With --material
"Linearized LPS" the damage models run with that material instead of PMB (K as PMB's, nu 1/4,
influence function One) and PMB + critical stretch stays the reference.

    python3 bench/damage_cost.py --size 32 --steps 100 --repeats 3 --peridot build/peridot
    python3 bench/damage_cost.py --material "Linearized LPS" ... --baseline OLD/peridot
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from lps_vs_pmb import load_average, run  # noqa: E402

DAMAGE = {"critical_stretch": "Critical Stretch", "dtt": "DTT", "lsjt": "LSJ-T"}


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--size", type=int, default=32)
    ap.add_argument("--steps", type=int, default=100)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--peridot", default=os.path.join(HERE, "..", "build", "peridot"))
    ap.add_argument("--baseline", help="an older peridot binary, run back to back with --peridot")
    ap.add_argument("--workdir", default="/tmp/damage-cost")
    ap.add_argument("--material", choices=["Elastic Bond Based", "Linearized LPS"],
                    default="Elastic Bond Based", help="the material of the damage models' decks")
    a = ap.parse_args()
    subprocess.run([sys.executable, os.path.join(HERE, "run_bench.py"), "--sizes", str(a.size),
                    "--models", "pmb", "--steps", str(a.steps), "--codes", "peridot",
                    "--write-only", "--workdir", a.workdir], check=True, capture_output=True)
    source = os.path.join(a.workdir, "N%d_pmb" % a.size)
    deck = open(os.path.join(source, "peridot.xml")).read()
    damage = dict(DAMAGE)
    material = deck
    if a.material != "Elastic Bond Based":
        material, n = re.subn(
            r'(<Parameter name="Material Model" type="string" value=")Elastic Bond Based("/>)',
            r"\g<1>%s\g<2>" % a.material +
            "\n      <Parameter name=\"Poisson's Ratio\" type=\"double\" value=\"0.25\"/>", deck)
        assert n == 1, "run_bench.py's deck changed"
        damage = {"pmb_critical_stretch": "Critical Stretch"}
        damage.update(DAMAGE)
    dirs = {}
    for key, name in damage.items():
        tag = "" if key.startswith("pmb_") or material is deck else "llps_"
        d = os.path.join(a.workdir, "N%d_%s%s" % (a.size, tag, key))
        os.makedirs(d, exist_ok=True)
        shutil.copy(os.path.join(source, "all_nodes.txt"), d)
        text, n = re.subn(r'(name="Damage Model" type="string" value=")Critical Stretch"',
                          r'\g<1>%s"' % name, deck if key.startswith("pmb_") else material)
        assert n == 1, "run_bench.py's deck changed"
        open(os.path.join(d, "peridot.xml"), "w").write(text)
        dirs[key] = d
    binaries = {"new": os.path.abspath(a.peridot)}
    if a.baseline:
        binaries["baseline"] = os.path.abspath(a.baseline)
    cost = {(b, k): [] for b in binaries for k in damage}
    loads = []
    for rep in range(a.repeats):
        for key in damage:
            for b, path in binaries.items():
                loads.append(load_average())
                t = run(path, dirs[key], 1)
                cost[(b, key)].append(t.get("Force", 0.0) + t.get("Damage", 0.0))
                print("  rep %d %-16s %-8s Force %.3f s + Damage %.3f s CPU (load %.1f)" %
                      (rep, key, b, t.get("Force", 0.0), t.get("Damage", 0.0), loads[-1]),
                      flush=True)
    print("%d^3, %d steps, %s, medians of %d, load %.1f-%.1f (CPU of Force + Damage):" %
          (a.size, a.steps, a.material, a.repeats, min(loads), max(loads)))
    reference_key = "pmb_critical_stretch" if "pmb_critical_stretch" in damage else \
        "critical_stretch"
    for b in binaries:
        reference = statistics.median(cost[(b, reference_key)])
        for key in damage:
            m = statistics.median(cost[(b, key)])
            print("  %-8s %-16s %.3f s  %.2f x PMB + critical stretch" % (b, key, m,
                                                                         m / reference))
    if a.baseline:
        for key in damage:
            new = statistics.median(cost[("new", key)])
            old = statistics.median(cost[("baseline", key)])
            print("  %-24s new / baseline %.3f" % (key, new / old))


if __name__ == "__main__":
    main()
