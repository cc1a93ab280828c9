#!/usr/bin/env python3
"""V4 (paper 000 section 3.2): the plane-strain edge-cracked patch as a Peridot deck.

    /usr/bin/python3 make_patch.py DX [--model paper|consistent] [--rate R] [--final T]
                                      [--horizon-ratio M]

writes v4_<model>_dx<DX>.yaml and its point and node-set files (prefix v4_dx<DX>_): a square
lattice of cell centres, width L = 1 m (x) by height 2L (y) (1250 points at DX = 0.04, as the
paper's coarsest), an edge crack along y = L from x = 0 to a = L/8 (a bond filter), and the
layers within one horizon of the top and bottom edges, pulled apart by a traction sigma = R t
(paper 002's nonlocal Neumann load: Peridot's `Traction`).

Material: normalized PMB, plane strain, G_I = 1 J/m^2 (Critical Stretch with Fracture Energy),
density 1 kg/m^3 (the paper gives none: it only sets the time scale).
  --model paper       the paper's constant c_i = 9K / sum V_j with K = E/(3(1-2nu)) = 1e4 Pa
                      (E = 1e4, nu = 1/3): Peridot's `Bulk Modulus: 9375` (= 15K/16,
                      doc/theory/planar-and-fracture-energy.md). The material this is has
                      nu = 1/4 and plane-strain modulus E/(1-nu^2) = 15000 Pa.
  --model consistent  `Young's Modulus: 1e4` in plane strain: nu = 1/4, E/(1-nu^2) = 10667 Pa.
Outputs (globals only, every 5 steps): the largest damage anywhere, within two horizons of the
crack tip, in the band x in [a + 0.1, a + 0.15] along the crack line (the crack has grown by
0.1 m) and in the band x in [0.45, 0.55] (it has run past mid-width); critical.py reads them."""
import argparse

ap = argparse.ArgumentParser()
ap.add_argument("dx", type=float)
ap.add_argument("--model", choices=["paper", "consistent"], default="paper")
ap.add_argument("--rate", type=float, default=400.0, help="traction rate, Pa/s")
ap.add_argument("--final", type=float, default=0.55, help="final time, s")
ap.add_argument("--horizon-ratio", type=float, default=3.015)
ap.add_argument("--material", choices=["normalized-pmb", "pmb", "lps"], default="normalized-pmb",
                help="with --model consistent: the model of the speed/accuracy map "
                     "(bench/tradeoff/fracture_map.py); the same material, E = 1e4, nu = 1/4")
ap.add_argument("--influence", choices=["One", "Conical", "Conical Over Zeta"], default="One",
                help="the influence function (Discretization -> Influence Function); the "
                     "critical stretch follows it (fracture-energy formula with J_k)")
a = ap.parse_args()
if a.influence != "One" and a.material == "normalized-pmb":
    ap.error("--influence: Normalized PMB is defined for the influence function One only")
if a.material != "normalized-pmb" and a.model != "consistent":
    ap.error("--material needs --model consistent (the paper's constant is normalized PMB's)")

L, H, A = 1.0, 2.0, 0.125
nx, ny = round(L / a.dx), round(H / a.dx)
dx = L / nx
delta = a.horizon_ratio * dx
tag = f"dx{a.dx:g}".replace(".", "p") + ("" if a.horizon_ratio == 3.015 else f"_m{a.horizon_ratio:g}".replace(".", "p"))
if a.material != "normalized-pmb":
    tag += "_" + a.material
if a.influence != "One":
    tag += "_" + a.influence.lower().replace(" ", "")
prefix = f"v4_{tag}_"
with open(prefix + "points.txt", "w") as f:
    f.write("# x y z block area\n")
    for j in range(ny):
        for i in range(nx):
            f.write(f"{(i + 0.5) * dx:.9f} {(j + 0.5) * dx:.9f} 0 1 {dx * dx:.9e}\n")
top, bottom, ahead, tip, grown = [], [], [], [], []
for j in range(ny):
    y = (j + 0.5) * dx
    for i in range(nx):
        x = (i + 0.5) * dx
        pid = 1 + i + nx * j
        if y > H - delta:
            top.append(pid)
        if y < delta:
            bottom.append(pid)
        if 0.45 <= x <= 0.55 and abs(y - H / 2) < delta:
            ahead.append(pid)
        if abs(x - A) < 2 * delta and abs(y - H / 2) < 2 * delta:
            tip.append(pid)
        if A + 0.1 <= x <= A + 0.15 and abs(y - H / 2) < delta:
            grown.append(pid)
for name, ids in (("top", top), ("bottom", bottom), ("ahead", ahead), ("tip", tip), ("grown", grown)):
    with open(prefix + name + ".txt", "w") as f:
        f.write("\n".join(map(str, ids)) + "\n")
if a.model == "paper":
    modulus = "Bulk Modulus: 9375.0"
else:
    modulus = "Young's Modulus: 1.0e4"
model_name = {"normalized-pmb": "Normalized PMB", "pmb": "Elastic Bond Based", "lps": "Elastic"}[a.material]
if a.material == "lps":
    modulus += "\n      Poisson's Ratio: 0.25"
deck = f"""# V4, paper 000 section 3.2, made by make_patch.py {a.dx:g} --model {a.model}: a 1 m x 2 m
# plane-strain patch, {nx} x {ny} points (dx = {dx:g} m), edge crack y = 1 m, 0 <= x <= 0.125 m,
# traction sigma = {a.rate:g} t Pa on the layers within delta = {delta:g} m of the top and bottom.
Peridigm:
  Discretization:
    Type: Text File
    Input Mesh File: {prefix}points.txt
    Dimension: 2
    Thickness: 1.0
    Influence Function: "{a.influence}"
    Bond Filters:
      Edge Crack:
        Type: Rectangular_Plane
        Normal_X: 0.0
        Normal_Y: 1.0
        Normal_Z: 0.0
        Lower_Left_Corner_X: -0.5
        Lower_Left_Corner_Y: {H / 2:.9f}
        Lower_Left_Corner_Z: 1.0
        Bottom_Unit_Vector_X: 1.0
        Bottom_Unit_Vector_Y: 0.0
        Bottom_Unit_Vector_Z: 0.0
        Bottom_Length: {0.5 + A:.9f}
        Side_Length: 2.0
  Materials:
    Patch:
      Material Model: "{model_name}"
      Plane Strain: true
      Density: 1.0
      {modulus}
  Damage Models:
    Griffith:
      Damage Model: "Critical Stretch"
      Fracture Energy: 1.0
  Blocks:
    Patch:
      Block Names: block_1
      Material: Patch
      Damage Model: Griffith
      Horizon: {delta:.9f}
  Boundary Conditions:
    Top Node Set: {prefix}top.txt
    Bottom Node Set: {prefix}bottom.txt
    Ahead Node Set: {prefix}ahead.txt
    Tip Node Set: {prefix}tip.txt
    Grown Node Set: {prefix}grown.txt
    Pull Up:
      Type: Traction
      Node Set: Top Node Set
      Coordinate: y
      Surface Area: 1.0
      Value: "{a.rate:g}*t"
    Pull Down:
      Type: Traction
      Node Set: Bottom Node Set
      Coordinate: y
      Surface Area: 1.0
      Value: "-{a.rate:g}*t"
  Compute Class Parameters:
    Max Damage:
      Compute Class: Block_Data
      Calculation Type: Maximum
      Block: block_1
      Variable: Damage
      Output Label: Max_Damage
    Ahead Damage:
      Compute Class: Node_Set_Data
      Calculation Type: Maximum
      Node Set: Ahead Node Set
      Variable: Damage
      Output Label: Ahead_Damage
    Tip Damage:
      Compute Class: Node_Set_Data
      Calculation Type: Maximum
      Node Set: Tip Node Set
      Variable: Damage
      Output Label: Tip_Damage
    Grown Damage:
      Compute Class: Node_Set_Data
      Calculation Type: Maximum
      Node Set: Grown Node Set
      Variable: Damage
      Output Label: Grown_Damage
  Solver:
    Final Time: {a.final:g}
    Verlet:
      Safety Factor: 0.9
  Output:
    Output File Type: ExodusII
    Output Filename: v4_{a.model}_{tag}
    Output Frequency: 5
    Output Variables:
      Max_Damage: true
      Ahead_Damage: true
      Tip_Damage: true
      Grown_Damage: true
"""
with open(f"v4_{a.model}_{tag}.yaml", "w") as f:
    f.write(deck)
print(f"v4_{a.model}_{tag}.yaml: {nx * ny} points, dx {dx:g}, horizon {delta:g}, rate {a.rate:g} Pa/s")
