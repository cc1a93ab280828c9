#!/usr/bin/env python3
"""Point cloud, node sets and deck of the CKI curved bar (paper 004, section 5: V9, 2D).

The bar follows f(x) = cos(pi x / 2) for x in [-L_B/2, L_B/2], L_B = 1 m (arc length
S = 1.1934 m), W_B = 62.5 mm wide, dx = W_B / N_n (paper: N_n = 20, dx = 3.125 mm, horizon
9.42 mm = 3.0144 dx, kept at any N_n). Two clouds:

* --cloud paper: the paper's. Root points evenly in arc length (spacing S/round(S/dx) ~ dx)
  from x = -L_B/2 to L_B/2; through each, N_n points on the curve's normal at offsets
  (k + 1/2 - N_n/2) dx. The paper's eq. (5.1) prints the normal's slope as 1/f'(x_i); the
  normal's is -1/f'(x_i) (the printed line is not perpendicular to the curve). Area of a point:
  ds dx (1 + kappa o), kappa the curvature, o the offset away from the centre of curvature.
  Its triangles of three neighbours on one offset curve are nearly degenerate (area ~4e-4
  horizon^2): with the paper's C2 < 0 (nu = 0.3, plane stress) they make the model unstable
  (README.md).
* --cloud grid (default): a square lattice of spacing dx (cell centres, symmetric about x = 0,
  N_n points across the crown) cut to the bar: the points whose foot on the curve lies in
  [-L_B/2, L_B/2] and whose offset is within W_B/2; area dx^2.

Coordinates are written to full precision: rounded, points on one normal are no longer
collinear and form triangles of area ~1e-9 m^2 that the model does not skip (its cut is
1e-10 horizon^2), with stiffnesses that blow the run up within a few steps.

Loading (eqs. 5.2-5.5): p(t) = p0 (1 - ((t - t1/2)/(t1/2))^2) for t <= t1, 0 after,
p0 = 4e5 N/m (2D), t1 = 300 us, along n_l = (sin a, cos a) at the left end, n_r = (-sin a, cos a)
at the right end, a = arctan(-1/f'(L_B/2)): the unit tangents into the bar (a push along the
axis). The paper applies the body force density p(t)/dx n to one layer of points; here it is a
Traction on the end face W_B x 1 m over the layer (the first normal's N_n points, or on the
lattice the points within dx of the end in arc length), b = p W_B n / V_layer: the paper's
p/dx on N_n points of area dx^2, and the total force p W_B exactly when the lattice's layer holds
N_n +- 1 points.

Usage: make_bar.py [--cloud grid|paper] [--nn 20] [--p0 4e5] [--final 6e-3] [--output-dt 5e-5]
                   [--name NAME]
writes NAME.txt (x y 0 block area), NAME_left.txt, NAME_right.txt (1-based ids), NAME_so.txt
(arc length and offset of each point, for analyse.py) and NAME.yaml, and prints a summary."""
import argparse
import math

L_B = 1.0  # bar length along x [m]
W_B = 0.0625  # bar width [m]
RHO, E, NU = 7580.0, 210.0e9, 0.3  # steel; thickness 1 m, so rho is also the paper's kg/m^2
G_C = 1.0  # Griffith's parameter [N/m]
P0, T1 = 4.0e5, 300.0e-6  # pulse peak [N/m] and duration [s]
DELTA_OVER_DX = 9.42 / 3.125  # the paper's horizon 9.42 mm at dx = 3.125 mm (3.0144 dx)
# Fixed time step per metre of dx: 0.9 x the Verlet limit that Peridot measures on these clouds
# (Lanczos; 3.84e-4 dx/(m/s) at N_n = 5 and 10, 3.79e-4 at N_n = 20).
DT_PER_DX = 3.4e-4


def f(x):
    return math.cos(0.5 * math.pi * x)


def fp(x):
    return -0.5 * math.pi * math.sin(0.5 * math.pi * x)


def fpp(x):
    return -0.25 * math.pi**2 * math.cos(0.5 * math.pi * x)


def arc_length(x, n=20000):
    """Arc length of f from -L_B/2 to x (Simpson)."""
    a = -0.5 * L_B
    h = (x - a) / n
    g = lambda u: math.sqrt(1.0 + fp(u) ** 2)  # noqa: E731
    s = g(a) + g(x) + sum((4 if i % 2 else 2) * g(a + i * h) for i in range(1, n))
    return s * h / 3.0


def x_at_arc(s, total):
    """The x whose arc length from -L_B/2 is s (bisection)."""
    lo, hi = -0.5 * L_B, 0.5 * L_B
    if s <= 0.0:
        return lo
    if s >= total:
        return hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if arc_length(mid, 400) < s:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def build_paper(nn):
    """The paper's cloud: N_n points on the normal through each root point."""
    dx = W_B / nn
    total = arc_length(0.5 * L_B)
    nroot = round(total / dx) + 1
    ds = total / (nroot - 1)
    points = []  # (x, y, area, s, offset)
    for i in range(nroot):
        s = i * ds
        xr = x_at_arc(s, total)
        t = 1.0 / math.sqrt(1.0 + fp(xr) ** 2)
        nx, ny = -fp(xr) * t, t  # unit normal, away from the centre of curvature (f'' < 0)
        kappa = -fpp(xr) * t**3
        for k in range(nn):
            o = (k + 0.5 - 0.5 * nn) * dx
            points.append((xr + o * nx, f(xr) + o * ny, ds * dx * (1.0 + kappa * o), s, o))
    left = list(range(nn))
    right = list(range((nroot - 1) * nn, nroot * nn))
    return dx, total, points, left, right, f"{nroot} root points {ds:.6g} m apart"


def foot(px, py):
    """The root x of the curve's normal through (px, py), its arc length s and the signed
    offset o (outward positive): Newton on (P - c(x)) . c'(x) = 0 from the vertical foot."""
    x = min(max(px, -0.6), 0.6)
    for _ in range(50):
        g = (px - x) + (py - f(x)) * fp(x)
        dg = -1.0 - fp(x) ** 2 + (py - f(x)) * fpp(x)
        step = g / dg
        x -= step
        if abs(step) < 1e-15:
            break
    t = 1.0 / math.sqrt(1.0 + fp(x) ** 2)
    return x, (-fp(x) * t) * (px - x) + t * (py - f(x))


def build_grid(nn):
    """A square lattice (spacing dx, cell centres, symmetric about x = 0 and centred on the
    crown's width) cut to the bar: the points whose normal foot on the curve lies in
    [-L_B/2, L_B/2] and whose offset is within W_B/2. Triangles are then exactly collinear or
    at least dx^2/2 in area (no near-degenerate ones, see the README). Loaded layers: the points
    within dx (in arc length) of either end."""
    dx = W_B / nn
    total = arc_length(0.5 * L_B)
    xs = [(i + 0.5) * dx for i in range(-round(0.6 / dx), round(0.6 / dx))]
    ys = [1.0 - (j + 0.5 - 0.5 * nn) * dx for j in range(round(0.45 / dx) + nn)]
    points, left, right = [], [], []
    for py in ys:
        for px in xs:
            xr, o = foot(px, py)
            if abs(xr) > 0.5 * L_B or abs(o) >= 0.5 * W_B:
                continue
            s = arc_length(xr, 200)
            if s < dx:
                left.append(len(points))
            if s > total - dx:
                right.append(len(points))
            points.append((px, py, dx * dx, s, o))
    return dx, total, points, left, right, "square lattice cut to the bar"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--nn", type=int, default=20, help="points across the width (paper: 20)")
    ap.add_argument("--final", type=float, default=6.0e-3, help="final time [s]")
    ap.add_argument("--p0", type=float, default=P0, help="pulse peak [N/m] (paper: 4e5)")
    ap.add_argument("--output-dt", type=float, default=5.0e-5, help="time between outputs [s]")
    ap.add_argument("--dt-per-dx", type=float, default=DT_PER_DX,
                    help="time step per metre of dx [s/m]")
    ap.add_argument("--cloud", choices=("grid", "paper"), default="grid",
                    help="grid: square lattice cut to the bar; paper: points on the normals")
    ap.add_argument("--name", default=None)
    a = ap.parse_args()
    name = a.name or f"curved_bar_{a.cloud}_n{a.nn}"
    build = build_grid if a.cloud == "grid" else build_paper
    dx, total, points, left, right, layout = build(a.nn)
    delta = DELTA_OVER_DX * dx
    dt = a.dt_per_dx * dx
    every = max(1, math.ceil(a.output_dt / dt - 1e-9))
    dt = a.output_dt / every  # outputs fall on multiples of output_dt
    with open(f"{name}.txt", "w") as out:
        out.write(f"# curved bar, paper 004 sec. 5: N_n = {a.nn}, dx = {dx:.6g} m, {layout}, "
                  f"S = {total:.6f} m\n")
        out.write("# x y z block area\n")
        for x, y, area, s, o in points:
            out.write(f"{x!r} {y!r} 0 1 {area!r}\n")
    with open(f"{name}_so.txt", "w") as out:  # for analyse.py: where each point sits on the bar
        out.write(f"# arc length s [m] and offset o [m] (outward) per point; S = {total:.9f} "
                  f"W_B = {W_B} horizon = {delta:.9g}\n")
        for x, y, area, s, o in points:
            out.write(f"{s:.9f} {o:.9f}\n")
    with open(f"{name}_left.txt", "w") as out:
        out.write("\n".join(str(1 + k) for k in left) + "\n")
    with open(f"{name}_right.txt", "w") as out:
        out.write("\n".join(str(1 + k) for k in right) + "\n")
    # The pulse along the inward tangent (paper eqs. 5.2-5.5) as a Traction on the end layer:
    # b = p(t) W_B / V_layer, i.e. the paper's p(t)/dx on its layer of N_n points of area
    # dx^2, and the total force p(t) W_B exactly also when the lattice's end layer holds
    # N_n +- 1 points.
    alpha = math.atan(-1.0 / fp(0.5 * L_B))
    half = 0.5 * T1

    def pulse(component):
        return (f'"if (t <= {T1:.6g}) {{ value = {a.p0 * component:.12g} * '
                f'(1 - ((t - {half:.6g}) / {half:.6g})^2); }} else {{ value = 0; }}"')

    deck = f"""# Paper 004, section 5 (V9), 2D: the steel curved bar f(x) = cos(pi x/2), x in [-0.5, 0.5] m,
# W_B = 62.5 mm, under a pressure pulse p(t) = p0 (1 - ((t - t1/2)/(t1/2))^2), p0 = {a.p0:g} N/m
# (paper: 4e5), t1 = 300 us, on one layer of points at each end along the inward tangent
# (eqs. 5.2-5.5), as a traction on the end face W_B x 1 m (the paper's body force p(t)/dx). Continuum-kinematics material, plane stress, nu = 0.3 (triangles
# on), critical stretch from G_c = 1 N/m (paper eq. 3.3). N_n = {a.nn} points across the width
# (paper: 20), dx = {dx:.6g} m, horizon {delta:.6g} m = 3.0144 dx as the paper's 9.42 mm at 3.125 mm.
# Written by make_bar.py --cloud {a.cloud} --nn {a.nn} --p0 {a.p0:g} --final {a.final:g} --output-dt {a.output_dt:g} --dt-per-dx {a.dt_per_dx:g}
Peridigm:
  Discretization:
    Type: Text File
    Input Mesh File: {name}.txt
    Dimension: 2
    Thickness: 1.0
  Materials:
    Steel:
      Material Model: Continuum Kinematics
      Density: {RHO}
      Young's Modulus: {E:.6g}
      Poisson's Ratio: {NU}
      Plane Stress: true
  Damage Models:
    Griffith:
      Damage Model: Critical Stretch
      Fracture Energy: {G_C}
  Blocks:
    Bar:
      Block Names: block_1
      Material: Steel
      Damage Model: Griffith
      Horizon: {delta:.9g}
  Boundary Conditions:
    Left End Node Set: {name}_left.txt
    Right End Node Set: {name}_right.txt
    Left Pulse X:
      Type: Traction
      Surface Area: {W_B}
      Node Set: Left End Node Set
      Coordinate: x
      Value: {pulse(math.sin(alpha))}
    Left Pulse Y:
      Type: Traction
      Surface Area: {W_B}
      Node Set: Left End Node Set
      Coordinate: y
      Value: {pulse(math.cos(alpha))}
    Right Pulse X:
      Type: Traction
      Surface Area: {W_B}
      Node Set: Right End Node Set
      Coordinate: x
      Value: {pulse(-math.sin(alpha))}
    Right Pulse Y:
      Type: Traction
      Surface Area: {W_B}
      Node Set: Right End Node Set
      Coordinate: y
      Value: {pulse(math.cos(alpha))}
  Solver:
    Initial Time: 0.0
    Final Time: {a.final:.9g}
    Verlet:
      Fixed dt: {dt:.9g}
      Stable Time Step Estimate: "Verlet Limit"
  Output:
    Output Filename: {name}
    Output Frequency: {every}
    Output Variables:
      Displacement: true
      Damage: true
"""
    with open(f"{name}.yaml", "w") as out:
        out.write(deck)
    print(f"{name}.yaml: {len(points)} points, N_n = {a.nn}, dx = {dx:.6g} m, "
          f"horizon = {delta:.6g} m, {layout}, {len(left)} + {len(right)} loaded points, "
          f"S = {total:.6f} m, dt = {dt:.6g} s")


if __name__ == "__main__":
    main()
