#!/usr/bin/env python3
"""V10 (make_impact.py's runs): did the sphere punch through the disc, is there a hole, and are
there cracks in the far field? Prints the sphere's history and the disc's damage by radius,
draws the figure, and checks (exit status 1 when a check fails):

    /usr/bin/python3 analyse.py impact.e [--png impact.png] [--times 2.6e-4 8.6e-4]
        [--check-punch] [--check-hole] [--check-far-field]

--check-punch: at the last record the sphere's centre of mass is below the disc's bottom face
  (z < -h/2) and still moving down.
--check-hole: every disc point whose reference position lies within 0.7 r of the axis (r the
  sphere's radius) has left the disc (|u_z| > h) or is damaged (> 0.5): the hole is open.
--check-far-field: no disc point farther than 3 r from the axis has damage above 0.3 (a crack
  through a point breaks about half of its bonds, so its damage is near 0.5 or above).
--stretch: per record, the largest stretch of the disc's bonds (pairs closer than the horizon,
  read from NAME.yaml) by the distance of the bond's midpoint from the axis, beside the
  critical stretch printed in NAME.log; run it on a --no-damage run (make_impact.py) to see the
  stretches the elastic waves make.

Disc and sphere are told apart by the node set file NAME_sphere.txt beside NAME.e.
Needs python3-netcdf4 and python3-matplotlib."""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import netCDF4
import numpy as np

H, R_SPHERE = 0.010, 0.010


def names(ds, var):
    return ["".join(c.decode() for c in row if c).strip() for row in ds.variables[var][:].data]


def nodal(ds, name):
    return ds.variables["vals_nod_var%d" % (names(ds, "name_nod_var").index(name) + 1)]


def element_to_nodes(ds, name):
    """An element variable (Damage is one, as in Peridigm) as a per-node array per record: each
    block's sphere elements map to their node through the block's connectivity."""
    k = names(ds, "name_elem_var").index(name) + 1
    nodes = ds.dimensions["num_nodes"].size
    steps = ds.variables["time_whole"].shape[0]
    out = np.zeros((steps, nodes))
    for b in range(1, ds.dimensions["num_el_blk"].size + 1):
        var = "vals_elem_var%deb%d" % (k, b)
        if var in ds.variables:
            out[:, np.asarray(ds.variables["connect%d" % b][:]).ravel() - 1] = ds.variables[var][:]
    return out


def print_stretch(ds, X, disc, rho, t, base, ux, uy, uz):
    with open(base + ".yaml") as f:
        horizon = float(next(l for l in f if l.strip().startswith("Horizon:")).split(":")[1])
    idx = np.flatnonzero(disc)
    P = X[idx]
    first, second = [], []
    for lo in range(0, len(P), 512):  # pairs closer than the horizon, brute force in chunks
        d = np.linalg.norm(P[lo:lo + 512, None, :] - P[None, :, :], axis=2)
        i, j = np.nonzero((d < horizon) & (d > 0))
        keep = lo + i < j
        first.append(idx[lo + i[keep]])
        second.append(idx[j[keep]])
    i, j = np.concatenate(first), np.concatenate(second)
    xi = X[j] - X[i]
    length = np.linalg.norm(xi, axis=1)
    mid = 0.5 * (rho[i] + rho[j])
    bands = [(0, 1.5), (1.5, 3), (3, 4.5), (4.5, 1e9)]
    print("  time [ms]  largest disc bond stretch, midpoint r/r_s in " +
          "  ".join("[%g, %s)" % (lo, "inf" if hi > 1e8 else "%g" % hi) for lo, hi in bands))
    for n in range(len(t)):
        U = np.c_[ux[n], uy[n], uz[n]]
        stretch = np.linalg.norm(xi + U[j] - U[i], axis=1) / length - 1
        row = []
        for lo, hi in bands:
            sel = (mid >= lo * R_SPHERE) & (mid < hi * R_SPHERE)
            row.append("%10.2e" % stretch[sel].max() if sel.any() else "%10s" % "-")
        print("  %8.3f  " % (1e3 * t[n]) + "    ".join(row))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exodus")
    ap.add_argument("--png", default=None)
    ap.add_argument("--times", type=float, nargs="*", default=[2.6e-4, 8.6e-4])
    ap.add_argument("--check-punch", action="store_true")
    ap.add_argument("--check-hole", action="store_true")
    ap.add_argument("--check-far-field", action="store_true")
    ap.add_argument("--stretch", action="store_true")
    a = ap.parse_args()
    ds = netCDF4.Dataset(a.exodus)
    X = np.c_[ds.variables["coordx"][:], ds.variables["coordy"][:], ds.variables["coordz"][:]]
    t = np.array(ds.variables["time_whole"][:])
    base = a.exodus[:-2]
    sphere_ids = np.loadtxt(base + "_sphere.txt", dtype=int) - 1
    sphere = np.zeros(len(X), bool)
    sphere[sphere_ids] = True
    disc = ~sphere
    ux, uy, uz = (nodal(ds, "Displacement" + c) for c in "XYZ")
    vz = nodal(ds, "VelocityZ")
    rho = np.hypot(X[:, 0], X[:, 1])
    if a.stretch:
        print_stretch(ds, X, disc, rho, t, base, ux, uy, uz)
    if "name_elem_var" not in ds.variables:
        return 0  # no damage output (a --no-damage run)
    damage = element_to_nodes(ds, "Damage")
    print("  time [ms]  sphere z_c [mm]  v_z [m/s]  disc points damaged > 0.5   max damage r > 3r_s")
    for n in range(len(t)):
        zc = np.mean(X[sphere, 2] + uz[n, sphere])
        d = np.asarray(damage[n])
        print("  %8.3f  %14.2f  %9.2f  %26d  %18.3f" % (
            1e3 * t[n], 1e3 * zc, np.mean(vz[n, sphere]), np.sum(d[disc] > 0.5),
            d[disc & (rho > 3 * R_SPHERE)].max()))
    last = len(t) - 1
    d = np.asarray(damage[last])
    UZ = np.asarray(uz[last])
    print("\nLast record, t = %.3f ms: disc damage by radius (reference), mean and max:" % (1e3 * t[last]))
    edges = np.array([0, 0.5, 1, 1.5, 2, 3, 4, 6]) * R_SPHERE
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = disc & (rho >= lo) & (rho < hi)
        if sel.any():
            gone = np.sum(np.abs(UZ[sel]) > H)
            print("  r/r_s in [%.1f, %.1f): %5d points, damage mean %.3f max %.3f, %d left the disc"
                  % (lo / R_SPHERE, hi / R_SPHERE, sel.sum(), d[sel].mean(), d[sel].max(), gone))
    sel = disc & (rho >= edges[-1])
    if sel.any():
        print("  r/r_s >= %.1f: %5d points, damage mean %.3f max %.3f" % (
            edges[-1] / R_SPHERE, sel.sum(), d[sel].mean(), d[sel].max()))
    status = 0
    if a.check_punch:
        zc = np.mean(X[sphere, 2] + UZ[sphere])
        v = np.mean(vz[last, sphere])
        ok = zc < -0.5 * H and v < 0
        print("check punch: sphere centre z = %.2f mm (disc bottom %.1f mm), v_z = %.2f m/s: %s"
              % (1e3 * zc, -0.5e3 * H, v, "ok" if ok else "FAILED"))
        status |= not ok
    if a.check_hole:
        sel = disc & (rho < 0.7 * R_SPHERE)
        open_ = (np.abs(UZ[sel]) > H) | (d[sel] > 0.5)
        ok = sel.any() and open_.all()
        print("check hole: %d of %d disc points within 0.7 r of the axis gone or damaged > 0.5: %s"
              % (open_.sum(), sel.sum(), "ok" if ok else "FAILED"))
        status |= not ok
    if a.check_far_field:
        far = d[disc & (rho > 3 * R_SPHERE)].max()
        ok = far <= 0.3
        print("check far field: largest damage beyond 3 r = %.3f (bound 0.3): %s"
              % (far, "ok" if ok else "FAILED"))
        status |= not ok
    if a.png:
        times = [min(range(len(t)), key=lambda n: abs(t[n] - s)) for s in a.times]
        fig, ax = plt.subplots(2, len(times), figsize=(5.2 * len(times), 9.0), squeeze=False)
        for col, n in enumerate(times):
            dn = np.asarray(damage[n])
            # Top view: each column of the disc coloured by its largest damage through the thickness.
            key = np.round(X[:, :2] / 1e-5).astype(np.int64)
            cols = {}
            for k in np.flatnonzero(disc):
                kk = (key[k, 0], key[k, 1])
                cols[kk] = max(cols.get(kk, 0.0), dn[k])
            xy = np.array([(kx * 1e-5, ky * 1e-5) for kx, ky in cols]) * 1e3
            sc = ax[0, col].scatter(xy[:, 0], xy[:, 1], c=list(cols.values()), s=3, cmap="inferno_r",
                                    vmin=0, vmax=1)
            ax[0, col].set_aspect("equal")
            ax[0, col].set_title("disc from above, t = %.2f ms (max damage through h)" % (1e3 * t[n]))
            ax[0, col].set_xlabel("x [mm]")
            ax[0, col].set_ylabel("y [mm]")
            fig.colorbar(sc, ax=ax[0, col], shrink=0.8, label="damage")
            # Side view: the slice |y| < dx/2 of both bodies in the current configuration.
            sl = np.abs(X[:, 1]) < 0.5 * H / 4 + 1e-9
            cur = X + np.c_[ux[n], uy[n], uz[n]]
            ax[1, col].scatter(1e3 * cur[sl & disc, 0], 1e3 * cur[sl & disc, 2], c=dn[sl & disc], s=6,
                               cmap="inferno_r", vmin=0, vmax=1)
            ax[1, col].scatter(1e3 * cur[sl & sphere, 0], 1e3 * cur[sl & sphere, 2], c="tab:blue", s=6)
            ax[1, col].set_aspect("equal")
            ax[1, col].set_xlim(-4e3 * R_SPHERE, 4e3 * R_SPHERE)
            ax[1, col].set_ylim(-3e3 * R_SPHERE, 3e3 * R_SPHERE)
            ax[1, col].set_title("slice y = 0 (sphere blue), t = %.2f ms" % (1e3 * t[n]))
            ax[1, col].set_xlabel("x [mm]")
            ax[1, col].set_ylabel("z [mm]")
        fig.suptitle("V10 scaled: CKI sphere (50 m/s) through a CKI disc, short-range contact")
        fig.tight_layout()
        fig.savefig(a.png, dpi=100)
        print("figure:", os.path.abspath(a.png))
    return status


if __name__ == "__main__":
    sys.exit(main())
