#!/usr/bin/env python3
"""V5 (paper 001 section 3, paper 002 section 4.3): the soda-lime glass plate with a pre-crack,
planar (plane stress), as a Peridot deck.

    /usr/bin/python3 make_plate.py MODEL SIGMA_MPA M [--final US] [--every US] [--partial-volumes]

MODEL: pmb (PMB: bond-based, critical stretch), dtt (bond-based with paper 002's DTT law),
lpst (LPS-T: `Elastic` LPS with the DTT law), lsjt (LSJ-T: `Linearized LPS` with `LSJ-T`).
Writes v5_<model>_s<SIGMA>_m<M>.yaml and the point and node-set files (prefix v5_m<M>_):
a 100 mm x 40 mm plate, a square lattice of cell centres with spacing h = delta/M (delta = 1 mm),
the pre-crack along y = 20 mm from the left edge to x = 50 mm (a bond filter, as Ha and Bobaru
and paper 002), and the layers within one horizon of the top and bottom edges, pulled apart by a
constant traction SIGMA from t = 0 (paper 002's nonlocal Neumann load, Peridot's `Traction`).
Glass: E = 72 GPa, rho = 2440 kg/m^3, G0 = 3.8 J/m^2 (S_c derived from it), nu = 0.22 for the
state-based models (bond-based: nu = 1/3 in plane stress, fixed); conical influence function
(bond-based), (1 - zeta/delta)/zeta (state-based, paper 001 eq. 24); S0+/S1+ = 0.95/1.05 S_c.
The horizon is (M + 0.015) h, i.e. 1.005 mm at M = 3, so that the lattice points at exactly
delta are not left to round-off. Time step 0.02 us (the papers')."""
import argparse

ap = argparse.ArgumentParser()
ap.add_argument("model", choices=["pmb", "dtt", "lpst", "lsjt"])
ap.add_argument("sigma", type=float, help="traction, MPa")
ap.add_argument("m", type=int, help="delta / h")
ap.add_argument("--final", type=float, default=None, help="final time, us")
ap.add_argument("--every", type=float, default=0.5, help="output interval, us")
ap.add_argument("--dt", type=float, default=0.02, help="time step, us")
ap.add_argument("--partial-volumes", action="store_true",
                help="partial-volume quadrature (the papers' partial areas) instead of the centre rule")
a = ap.parse_args()

W, H, A, DELTA = 0.1, 0.04, 0.05, 1.0e-3
h = DELTA / a.m
nx, ny = round(W / h), round(H / h)
horizon = DELTA if a.partial_volumes else (a.m + 0.015) * h  # partial volumes: the cells cut by the circle count in part
final = a.final if a.final is not None else {0.2: 150.0, 2.0: 43.0, 4.0: 20.0}.get(a.sigma, 30.0)
prefix = f"v5_m{a.m}_"
with open(prefix + "points.txt", "w") as f:
    f.write("# x y z block area\n")
    for j in range(ny):
        for i in range(nx):
            f.write(f"{(i + 0.5) * h:.9e} {(j + 0.5) * h:.9e} 0 1 {h * h:.9e}\n")
top = [1 + i + nx * j for j in range(ny) for i in range(nx) if (j + 0.5) * h > H - horizon]
bottom = [1 + i + nx * j for j in range(ny) for i in range(nx) if (j + 0.5) * h < horizon]
for name, ids in (("top", top), ("bottom", bottom)):
    with open(prefix + name + ".txt", "w") as f:
        f.write("\n".join(map(str, ids)) + "\n")

if a.model in ("pmb", "dtt"):
    material = '      Material Model: "Elastic Bond Based"'
    influence = "Conical"
else:
    name = "Elastic" if a.model == "lpst" else "Linearized LPS"
    material = f"""      Material Model: "{name}"
      Poisson's Ratio: 0.22"""
    influence = "Conical Over Zeta"
damage = {"pmb": "Critical Stretch", "dtt": "DTT", "lpst": "DTT", "lsjt": "LSJ-T"}[a.model]
tag = f"v5_{a.model}_s{a.sigma:g}_m{a.m}".replace(".", "p") + ("_pv" if a.partial_volumes else "")
every = max(1, round(a.every / a.dt))
deck = f"""# V5 glass plate, made by make_plate.py {a.model} {a.sigma:g} {a.m}: {nx} x {ny} points,
# h = {h * 1e3:.4f} mm, horizon {horizon * 1e3:.4f} mm, traction {a.sigma:g} MPa, {final:g} us.
Peridigm:
  Discretization:
    Type: Text File
    Input Mesh File: {prefix}points.txt
    Dimension: 2
    Thickness: 1.0e-3
    Influence Function: {influence}
{"    Partial Volumes: true" + chr(10) if a.partial_volumes else ""}    Bond Filters:
      Pre Crack:
        Type: Rectangular_Plane
        Normal_X: 0.0
        Normal_Y: 1.0
        Normal_Z: 0.0
        Lower_Left_Corner_X: -0.01
        Lower_Left_Corner_Y: {H / 2:.9e}
        Lower_Left_Corner_Z: 1.0
        Bottom_Unit_Vector_X: 1.0
        Bottom_Unit_Vector_Y: 0.0
        Bottom_Unit_Vector_Z: 0.0
        Bottom_Length: {A + 0.01:.9e}
        Side_Length: 2.0
  Materials:
    Glass:
{material}
      Plane Stress: true
      Density: 2440.0
      Young's Modulus: 72.0e9
  Damage Models:
    Fracture:
      Damage Model: "{damage}"
      Fracture Energy: 3.8
  Blocks:
    Plate:
      Block Names: block_1
      Material: Glass
      Damage Model: Fracture
      Horizon: {horizon:.9e}
  Boundary Conditions:
    Top Node Set: {prefix}top.txt
    Bottom Node Set: {prefix}bottom.txt
    Pull Up:
      Type: Traction
      Node Set: Top Node Set
      Coordinate: y
      Surface Area: 1.0e-4
      Value: "{a.sigma * 1e6:.6e}"
    Pull Down:
      Type: Traction
      Node Set: Bottom Node Set
      Coordinate: y
      Surface Area: 1.0e-4
      Value: "{-a.sigma * 1e6:.6e}"
  Solver:
    Final Time: {final * 1e-6:.6e}
    Verlet:
      Fixed dt: {a.dt * 1e-6:.6e}
  Output:
    Output File Type: ExodusII
    Output Filename: {tag}
    Output Frequency: {every}
    Output Variables:
      Displacement: true
      Damage: true
      Global_Kinetic_Energy: true
      Global_Stored_Elastic_Energy: true
"""
with open(tag + ".yaml", "w") as f:
    f.write(deck)
print(f"{tag}.yaml: {nx * ny} points, h {h * 1e3:g} mm, horizon {horizon * 1e3:.4f} mm, "
      f"{round(final / a.dt)} steps")
