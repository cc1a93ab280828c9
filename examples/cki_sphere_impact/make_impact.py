#!/usr/bin/env python3
"""Point clouds, node set and deck of V10 (paper 004, section 6): a steel sphere shot at 50 m/s
through a brittle disc that is free in space, both continuum-kinematics (CKI) bodies in 3D, in
contact through the short-range force.

The paper (Table 3): sphere r = 10 mm, rho 7850, E 210 GPa, nu 0.25, G_c 1500 N/m, dx 4 mm,
horizon 12.06 mm; disc R = 250 mm, h = 10 mm, rho 2000, E 50 GPa, nu 0.2, G_c 1 N/m, dx 5 mm,
horizon 40.075 mm (8 dx); contact l_c = 2.5 mm, C_con = 1000 GPa. Scaled to this machine (say
so wherever it is reported):

* one spacing for both bodies, dx = h / --layers (default 4 layers: 2.5 mm; the paper's disc has
  2 layers), cell centres of a cubic lattice cut to the disc and to the sphere;
* horizon --ratio dx in both bodies (default 2.015): a 3D CKI point at 8 dx would have ~10^8
  tetrahedra (three-neighbour interactions grow as N1^3, bench/RESULTS.md), and 3.015 dx costs
  ~1,700 PMB evaluations per step;
* disc radius --radius (default 60 mm, the paper 250 mm): the far field starts at 3 sphere radii;
* contact radius l_c = dx / 2 (the paper's rule l_c ~ max(dx_I, dx_II) / 2), search radius 2 l_c
  every 5 steps, C_con = 1000 GPa (paper 004 eq. 2.34, Peridot's `Short Range Force`).

The sphere starts 1.5 dx (point to point) above the disc's top layer, centred on its axis,
moving along -z. Time step --dt (default 0.1 us, below the contact spring's bound).

Usage: make_impact.py [--layers 4] [--ratio 2.015] [--radius 0.06] [--final 6e-4]
                      [--output-dt 2e-5] [--dt 1e-7] [--name NAME]
writes NAME.txt (x y z block volume; block 1 the disc, block 2 the sphere), NAME_sphere.txt
(1-based ids), NAME.yaml, and prints a summary."""
import argparse
import math

H = 0.010  # disc thickness [m]
R_SPHERE = 0.010
V0 = 50.0
DISC = dict(rho=2000.0, E=50.0e9, nu=0.2, gc=1.0)
SPHERE = dict(rho=7850.0, E=210.0e9, nu=0.25, gc=1500.0)
C_CON = 1000.0e9


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--layers", type=int, default=4, help="points through the disc thickness")
    ap.add_argument("--ratio", type=float, default=2.015, help="horizon / dx")
    ap.add_argument("--radius", type=float, default=0.06, help="disc radius [m] (paper 0.25)")
    ap.add_argument("--final", type=float, default=6.0e-4, help="final time [s]")
    ap.add_argument("--output-dt", type=float, default=2.0e-5, help="time between outputs [s]")
    ap.add_argument("--dt", type=float, default=1.0e-7, help="time step [s]")
    ap.add_argument("--disc-gc", type=float, default=DISC["gc"],
                    help="the disc's Griffith parameter G_c [N/m] (paper: 1)")
    ap.add_argument("--no-damage", action="store_true",
                    help="no damage model: the elastic response (the stretches the waves make)")
    ap.add_argument("--name", default=None)
    a = ap.parse_args()
    DISC["gc"] = a.disc_gc
    dx = H / a.layers
    name = a.name or f"impact_l{a.layers}_r{round(a.radius * 1000)}"
    delta = a.ratio * dx
    l_c = 0.5 * dx
    n = math.ceil(a.radius / dx)
    disc = []
    for k in range(a.layers):
        z = (k + 0.5) * dx - 0.5 * H
        for j in range(-n, n):
            y = (j + 0.5) * dx
            for i in range(-n, n):
                x = (i + 0.5) * dx
                if x * x + y * y <= a.radius**2:
                    disc.append((x, y, z))
    m = math.ceil(R_SPHERE / dx)
    zc = 0.5 * H + R_SPHERE + 0.5 * dx
    sphere = []
    for k in range(-m, m):
        for j in range(-m, m):
            for i in range(-m, m):
                p = ((i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx)
                if p[0] ** 2 + p[1] ** 2 + p[2] ** 2 <= R_SPHERE**2:
                    sphere.append((p[0], p[1], zc + p[2]))
    gap = min(z for _, _, z in sphere) - (0.5 * H - 0.5 * dx)
    volume = dx**3
    with open(f"{name}.txt", "w") as out:
        out.write(f"# V10 scaled: disc R = {a.radius} m, h = {H} m, sphere r = {R_SPHERE} m, "
                  f"dx = {dx} m\n# x y z block volume\n")
        for x, y, z in disc:
            out.write(f"{x!r} {y!r} {z!r} 1 {volume!r}\n")
        for x, y, z in sphere:
            out.write(f"{x!r} {y!r} {z!r} 2 {volume!r}\n")
    with open(f"{name}_sphere.txt", "w") as out:
        out.write("\n".join(str(len(disc) + 1 + k) for k in range(len(sphere))) + "\n")
    every = max(1, round(a.output_dt / a.dt))

    def material(p):
        return (f"      Material Model: Continuum Kinematics\n      Density: {p['rho']}\n"
                f"      Young's Modulus: {p['E']:.6g}\n      Poisson's Ratio: {p['nu']}\n")

    damage = "" if a.no_damage else f"""  Damage Models:
    Disc Griffith:
      Damage Model: Critical Stretch
      Fracture Energy: {DISC['gc']}
    Sphere Griffith:
      Damage Model: Critical Stretch
      Fracture Energy: {SPHERE['gc']}
"""
    disc_damage = "" if a.no_damage else "      Damage Model: Disc Griffith\n"
    sphere_damage = "" if a.no_damage else "      Damage Model: Sphere Griffith\n"
    deck = f"""# Paper 004, section 6 (V10), scaled by make_impact.py (see its docstring): a steel sphere
# (r = {R_SPHERE} m, {len(sphere)} points) shot at {V0} m/s through a brittle disc (R = {a.radius} m,
# h = {H} m, {len(disc)} points) free in space; dx = {dx} m, horizon {a.ratio} dx in both bodies.
Peridigm:
  Discretization:
    Type: Text File
    Input Mesh File: {name}.txt
    Omit Bonds Between Blocks: All
  Materials:
    Disc:
{material(DISC)}    Sphere:
{material(SPHERE)}{damage}  Blocks:
    Disc:
      Block Names: block_1
      Material: Disc
{disc_damage}      Horizon: {delta:.9g}
    Sphere:
      Block Names: block_2
      Material: Sphere
{sphere_damage}      Horizon: {delta:.9g}
  Contact:
    Search Radius: {2 * l_c:.9g}
    Search Frequency: 5
    Models:
      Paper Contact:
        Contact Model: Short Range Force
        Contact Radius: {l_c:.9g}
        Spring Constant: {C_CON:.6g}
    Interactions:
      Sphere On Disc:
        First Block: block_1
        Second Block: block_2
        Contact Model: Paper Contact
  Boundary Conditions:
    Sphere Node Set: {name}_sphere.txt
    Shot:
      Type: Initial Velocity
      Node Set: Sphere Node Set
      Coordinate: z
      Value: {-V0}
  Solver:
    Final Time: {a.final:.9g}
    Verlet:
      Fixed dt: {a.dt:.9g}
  Output:
    Output Filename: {name}
    Output Frequency: {every}
    Output Variables:
      Displacement: true
      Velocity: true
{"" if a.no_damage else "      Damage: true"}
"""
    with open(f"{name}.yaml", "w") as out:
        out.write(deck)
    print(f"{name}.yaml: disc {len(disc)} points, sphere {len(sphere)} points, dx = {dx:.6g} m, "
          f"horizon = {delta:.6g} m, contact radius {l_c:.6g} m, gap {gap:.6g} m, "
          f"{round(a.final / a.dt)} steps of {a.dt:.3g} s")


if __name__ == "__main__":
    main()
