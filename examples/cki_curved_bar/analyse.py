#!/usr/bin/env python3
"""Crack initiation in the CKI curved bar (make_bar.py's runs) and the damage figure.

    /usr/bin/python3 analyse.py curved_bar_n20.e [--threshold 0.5] [--png out.png]
        [--times 0.5e-3 2.9e-3 5.8e-3] [--check-middle-third] [--check-after-reflection]

Reads NAME.e and NAME_so.txt (each point's arc length s from the left end and its offset o across
the width, outward = away from the centre of curvature). Initiation: the first output record at
which a point farther than 3 horizons (in arc length) from both loaded ends has Damage above the
threshold; printed with the time, s/S, the offset o and the position. The first record with any
broken bond there (Damage > 0) is printed too. Cracks at the last record: the damaged points
(> threshold) grouped by s (a gap of more than two horizons starts a new group).

Checks (exit status 1 when they fail): --check-middle-third: every point of the
initiation lies in s in [S/3, 2S/3]; --check-after-reflection: it comes after 1.5 S/c, the time the pulse front from
one end needs to reach the far end and, reflected there, the middle of the bar
(c = sqrt(E/(rho(1-nu^2))), plane stress); --check-during-reflected-pulse: it comes no later than
1.5 S/c + t1, when the reflected pulse (t1 = 300 us long) has passed the middle; --check-no-crack:
there is none. Needs python3-netcdf4 and python3-matplotlib."""
import argparse
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import netCDF4
import numpy as np

E, NU, RHO = 210.0e9, 0.3, 7580.0
T1 = 300.0e-6  # pulse duration
C_PLATE = math.sqrt(E / (RHO * (1.0 - NU**2)))  # plane-stress longitudinal wave speed


def names(ds, var):
    return ["".join(c.decode() for c in row if c).strip() for row in ds.variables[var][:].data]


def read_so(path):
    with open(path) as f:
        head = f.readline().split()
    meta = {head[i]: float(head[i + 2]) for i in range(len(head) - 2) if head[i + 1] == "="}
    so = np.loadtxt(path)
    return so[:, 0], so[:, 1], meta["S"], meta["W_B"], meta["horizon"]


def critical_stretch(delta, g_c=1.0):
    """Paper 004 eq. (3.3), 2D, with the plane-stress in-plane bulk modulus (as Peridot)."""
    k, g = E / (2.0 * (1.0 - NU)), E / (2.0 * (1.0 + NU))
    return math.sqrt(g_c / (delta * (6.0 * g / math.pi + 16.0 / (9.0 * math.pi**2) * (k - 2.0 * g))))


def stretch_history(ds, s, S, delta):
    """Per record: the largest bond stretch among bonds (pairs within the horizon) whose
    midpoint lies farther than 3 horizons from both ends, its bond's s (midpoint) and offset."""
    from scipy.spatial import cKDTree

    nodal = names(ds, "name_nod_var")
    X = np.c_[ds.variables["coordx"][:], ds.variables["coordy"][:]]
    ux = ds.variables[f"vals_nod_var{nodal.index('DisplacementX') + 1}"]
    uy = ds.variables[f"vals_nod_var{nodal.index('DisplacementY') + 1}"]
    pairs = np.array(sorted(cKDTree(X).query_pairs(delta)))
    L = np.linalg.norm(X[pairs[:, 1]] - X[pairs[:, 0]], axis=1)
    sm = 0.5 * (s[pairs[:, 0]] + s[pairs[:, 1]])
    inner = (sm > 3 * delta) & (sm < S - 3 * delta)
    pairs, L, sm = pairs[inner], L[inner], sm[inner]
    out = []
    for r in range(len(ds.variables["time_whole"])):
        Y = X + np.c_[ux[r], uy[r]]
        st = (np.linalg.norm(Y[pairs[:, 1]] - Y[pairs[:, 0]], axis=1) - L) / L
        k = int(np.argmax(st))
        out.append((st[k], sm[k], pairs[k, 0]))
    return out


def groups(s_values, gap):
    """Runs of sorted s values separated by more than gap: (s_min, s_max, count)."""
    out = []
    for v in np.sort(s_values):
        if out and v - out[-1][1] <= gap:
            out[-1][1] = v
            out[-1][2] += 1
        else:
            out.append([v, v, 1])
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exodus")
    ap.add_argument("--threshold", type=float, default=0.5)
    ap.add_argument("--png", default=None)
    ap.add_argument("--times", type=float, nargs="*", default=None,
                    help="times to plot [s] (default: initiation, 2.9 ms, 5.8 ms, last)")
    ap.add_argument("--check-middle-third", action="store_true")
    ap.add_argument("--check-after-reflection", action="store_true")
    ap.add_argument("--check-during-reflected-pulse", action="store_true")
    ap.add_argument("--check-no-crack", action="store_true")
    ap.add_argument("--stretch", action="store_true",
                    help="print the running maximum of the bond stretch away from the ends and "
                    "the load factor s_c / max that a crack needs, up to the first broken bond")
    a = ap.parse_args()
    base = a.exodus.rsplit(".", 1)[0]
    s, o, S, W, delta = read_so(base + "_so.txt")
    ds = netCDF4.Dataset(a.exodus)
    x = np.asarray(ds.variables["coordx"][:])
    y = np.asarray(ds.variables["coordy"][:])
    times = np.asarray(ds.variables["time_whole"][:])
    k = names(ds, "name_elem_var").index("Damage") + 1
    damage = np.asarray(ds.variables[f"vals_elem_var{k}eb1"][:])  # one block, node order
    inner = (s > 3 * delta) & (s < S - 3 * delta)
    t_reflect = 1.5 * S / C_PLATE
    print(f"{len(s)} points, S = {S:.4f} m, horizon = {delta:.5g} m, {len(times)} records to "
          f"t = {times[-1] * 1e3:.3f} ms; c = {C_PLATE:.1f} m/s, front back at mid-bar after "
          f"1.5 S/c = {t_reflect * 1e3:.3f} ms")
    if a.stretch:
        sc = critical_stretch(delta)
        print(f"critical stretch s_c = {sc:.5g} (eq. 3.3, G_c = 1 N/m); running maximum of the "
              "bond stretch away from the ends:")
        top = 0.0
        for r, (st, sm, j) in enumerate(stretch_history(ds, s, S, delta)):
            if (damage[r][inner] > 0).any():
                print(f"  (bonds break from t = {times[r] * 1e3:.3f} ms on: history ends)")
                break
            if st > top * 1.02 and st > 0:
                top = st
                print(f"  t = {times[r] * 1e3:.3f} ms: {st:.4g} at s/S = {sm / S:.3f}, "
                      f"o/W_B = {o[j] / W:+.2f}; load factor for a break s_c/max = {sc / st:.2f}")
    first_any = next((r for r in range(len(times)) if (damage[r][inner] > 0).any()), None)
    if first_any is not None:
        i = np.flatnonzero(inner & (damage[first_any] > 0))
        print(f"first broken bond away from the ends: t = {times[first_any] * 1e3:.3f} ms, "
              f"s/S in [{s[i].min() / S:.3f}, {s[i].max() / S:.3f}], o/W_B in "
              f"[{o[i].min() / W:+.2f}, {o[i].max() / W:+.2f}]")
    init = next((r for r in range(len(times)) if (damage[r][inner] > a.threshold).any()), None)
    ok = True
    if init is None:
        print(f"no damage above {a.threshold} away from the ends by {times[-1] * 1e3:.3f} ms")
        ok = not (a.check_middle_third or a.check_after_reflection
                  or a.check_during_reflected_pulse)
    else:
        i = np.flatnonzero(inner & (damage[init] > a.threshold))
        print(f"initiation (damage > {a.threshold}): t = {times[init] * 1e3:.3f} ms (previous "
              f"record {times[init - 1] * 1e3:.3f} ms), {len(i)} points at s/S in "
              f"[{s[i].min() / S:.3f}, {s[i].max() / S:.3f}], o/W_B in "
              f"[{o[i].min() / W:+.2f}, {o[i].max() / W:+.2f}], x in "
              f"[{x[i].min():+.4f}, {x[i].max():+.4f}] m")
        for j in i:
            print(f"    point {j + 1}: s/S = {s[j] / S:.3f}, o/W_B = {o[j] / W:+.2f}, "
                  f"damage {damage[init][j]:.2f}")
        if a.check_middle_third and not ((s[i] >= S / 3) & (s[i] <= 2 * S / 3)).all():
            print("FAIL: the crack initiates outside the middle third")
            ok = False
        if a.check_after_reflection and not times[init] > t_reflect:
            print(f"FAIL: initiation at {times[init] * 1e3:.3f} ms, before 1.5 S/c")
            ok = False
        if a.check_during_reflected_pulse and not times[init] <= t_reflect + T1:
            print(f"FAIL: initiation at {times[init] * 1e3:.3f} ms, after 1.5 S/c + t1 = "
                  f"{(t_reflect + T1) * 1e3:.3f} ms")
            ok = False
        if a.check_no_crack:
            print("FAIL: a crack initiates")
            ok = False
    last = damage[-1]
    cracked = last > a.threshold
    for g in groups(s[cracked], 2 * delta):
        print(f"damaged (> {a.threshold}) at t = {times[-1] * 1e3:.3f} ms: s/S in "
              f"[{g[0] / S:.3f}, {g[1] / S:.3f}], {g[2]} points")
    for r in range(len(times)):
        if (damage[r] > a.threshold).any() and r % max(1, len(times) // 30) == 0:
            n = int((damage[r] > a.threshold).sum())
            print(f"  t = {times[r] * 1e3:.3f} ms: {n} points above {a.threshold}, "
                  f"{int((damage[r] > 0).sum())} with a broken bond")
    if a.png:
        want = a.times
        if want is None:
            want = [times[init]] if init is not None else []
            want += [t for t in (2.9e-3, 5.8e-3) if t <= times[-1] + 1e-9] + [times[-1]]
        records = sorted({int(np.argmin(abs(times - t))) for t in want})
        fig, axes = plt.subplots(len(records), 1, figsize=(9, 2.6 * len(records)), squeeze=False)
        for ax, r in zip(axes[:, 0], records):
            sc = ax.scatter(x, y, c=damage[r], s=0.6 if len(x) > 3000 else 4, cmap="inferno",
                            vmin=0, vmax=1, linewidths=0)
            ax.set_aspect("equal")
            ax.set_xlim(-0.56, 0.56)
            ax.set_ylim(0.62, 1.07)
            ax.set_title(f"t = {times[r] * 1e3:.3f} ms", fontsize=10)
            ax.set_ylabel("y [m]")
        axes[-1, 0].set_xlabel("x [m]")
        fig.colorbar(sc, ax=axes[:, 0].tolist(), label="damage", shrink=0.8)
        fig.savefig(a.png, dpi=130)
        print("wrote", a.png)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
