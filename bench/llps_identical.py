#!/usr/bin/env python3
"""Linearized LPS runs of two peridot binaries compared to the bit (peridot-diff, tolerance 0).

Writes small jittered point clouds (Text File discretization; two blocks whose horizons differ,
3.015 dx and 2.6 dx, so that the bonds between them are one-sided) stretched by an initial
velocity until bonds soften and break, in 3D, plane stress and plane strain, with omega = 1 and
influence functions, without damage and with Critical Stretch, DTT and LSJ-T. Each deck runs
with --baseline on 1 rank and with --peridot on 1 and 3 ranks; every output value (displacement,
velocity, force density, damage, dilatation, neighbour count, at 11 output steps) must agree.

    python3 bench/llps_identical.py --peridot build/peridot --baseline OLD/peridot
"""
import argparse
import os
import random
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

# name: (plane mode, damage model, influence function, planar, two horizons)
DECKS = {
    "none_3d_one": ("", "", "One", False, True),
    "cs_3d_parabolic": ("", "Critical Stretch", "Parabolic Decay", False, True),
    "dtt_3d_one": ("", "DTT", "One", False, True),
    "dtt_3d_one_single": ("", "DTT", "One", False, False),
    "lsjt_3d_conical": ("", "LSJ-T", "Conical", False, True),
    "cs_ps_one": ("Plane Stress", "Critical Stretch", "One", True, True),
    "dtt_pstrain_conical": ("Plane Strain", "DTT", "Conical", True, True),
    "lsjt_pstrain_one": ("Plane Strain", "LSJ-T", "One", True, True),
}

VARIABLES_3D = ["DisplacementX", "DisplacementY", "DisplacementZ", "VelocityX", "VelocityY",
                "VelocityZ", "Force_DensityX", "Force_DensityY", "Force_DensityZ"]


def write_deck(d, mode, damage, influence, planar, two_horizons, rng):
    n = 30 if planar else 14
    dx = 1.0e-3
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "points.txt"), "w") as f:
        for k in range(1 if planar else n):
            for j in range(n):
                for i in range(n):
                    x = (i + rng.uniform(-0.1, 0.1)) * dx
                    y = (j + rng.uniform(-0.1, 0.1)) * dx
                    z = 0.0 if planar else (k + rng.uniform(-0.1, 0.1)) * dx
                    f.write("%.17g %.17g %.17g %d %.17g\n" %
                            (x, y, z, 1 if i < n // 2 else 2, dx ** (2 if planar else 3)))
    with open(os.path.join(d, "nodes.txt"), "w") as f:
        f.write("\n".join(str(i + 1) for i in range(n ** (2 if planar else 3))) + "\n")
    blocks = ""
    for b, h in ((1, 3.015 * dx), (2, (2.6 if two_horizons else 3.015) * dx)):
        blocks += "    B%d:\n      Block Names: block_%d\n      Material: M\n%s      Horizon: %r\n" % (
            b, b, "      Damage Model: D\n" if damage else "", h)
    text = "Peridigm:\n  Discretization:\n    Type: Text File\n    Input Mesh File: points.txt\n"
    if planar:
        text += "    Dimension: 2\n    Thickness: 0.001\n"
    text += "    Influence Function: %s\n" % influence
    text += "  Materials:\n    M:\n      Material Model: Linearized LPS\n"
    if mode:
        text += "      %s: true\n" % mode
    text += "      Density: 2440.0\n      Young's Modulus: 72.0e9\n      Poisson's Ratio: 0.22\n"
    if damage:
        text += ("  Damage Models:\n    D:\n      Damage Model: %s\n      Critical Stretch: 0.004\n"
                 % damage)
    text += "  Blocks:\n" + blocks
    text += """  Boundary Conditions:
    All Node Set: nodes.txt
    Stretch:
      Type: Initial Velocity
      Node Set: All Node Set
      Coordinate: x
      Value: "1200.0*(x-0.007)+20.0*sin(4000.0*y)"
  Solver:
    Initial Time: 0.0
    Final Time: 6.0e-6
    Verlet:
      Fixed dt: 3.0e-8
  Output:
    Output File Type: ExodusII
    Output Filename: out
    Output Frequency: 20
    Output Variables:
      Displacement: true
      Velocity: true
      Force_Density: true
      Damage: true
      Dilatation: true
      Number_Of_Neighbors: true
"""
    open(os.path.join(d, "deck.yaml"), "w").write(text)
    variables = VARIABLES_3D if not planar else [v for v in VARIABLES_3D if not v.endswith("Z")]
    with open(os.path.join(d, "exact.comp"), "w") as f:
        f.write("DEFAULT TOLERANCE absolute 0.0\nCOORDINATES absolute 0.0\n"
                "TIME STEPS absolute 0.0\nNODAL VARIABLES absolute 0.0\n")
        f.writelines("\t%s\tabsolute 0.0\n" % v for v in variables)
        f.write("ELEMENT VARIABLES absolute 0.0\n")
        f.writelines("\t%s\tabsolute 0.0\n" % v
                     for v in ("Damage", "Dilatation", "Number_Of_Neighbors"))


def run(binary, d, ranks, target):
    cmd = [binary, "deck.yaml"]
    if ranks > 1:
        cmd = ["mpirun", "--oversubscribe", "-np", str(ranks)] + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    subprocess.run(cmd, cwd=d, env=env, check=True, capture_output=True)
    shutil.move(os.path.join(d, "out.e"), os.path.join(d, target))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--peridot", default=os.path.join(HERE, "..", "build", "peridot"))
    ap.add_argument("--baseline", required=True, help="the peridot binary to agree with")
    ap.add_argument("--diff", default=os.path.join(HERE, "..", "build", "peridot-diff"))
    ap.add_argument("--workdir", default="/tmp/llps-identical")
    a = ap.parse_args()
    rng = random.Random(1)
    failed = 0
    for name, (mode, damage, influence, planar, two) in DECKS.items():
        d = os.path.join(a.workdir, name)
        write_deck(d, mode, damage, influence, planar, two, rng)
        run(os.path.abspath(a.baseline), d, 1, "baseline.e")
        results = []
        for ranks in (1, 3):
            target = "new_np%d.e" % ranks
            run(os.path.abspath(a.peridot), d, ranks, target)
            out = subprocess.run([a.diff, "-q", "exact.comp", target, "baseline.e"], cwd=d,
                                 capture_output=True, text=True)
            failed += out.returncode != 0
            results.append("np%d: %s" % (ranks, out.stdout.strip().splitlines()[-1]))
        print("%-20s %s" % (name, " | ".join(results)), flush=True)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
