"""Post-processing of Peridot's Exodus output (.e / .h files).

Reads the file with netCDF4 (Debian's python3-netcdf4) and numpy; plots with matplotlib. Every
point of a Peridot file is a one-node SPHERE element, so node variables (vectors such as
Displacement, written as DisplacementX/Y/Z) and element variables (scalars such as Damage) are
both returned per point, in the file's node order.
"""

import numpy as np

__all__ = ["PeridotFile"]


def _names(ds, var):
    if var not in ds.variables:
        return []
    import netCDF4

    return [str(s).strip() for s in netCDF4.chartostring(ds.variables[var][:])]


class PeridotFile:
    """One Peridot Exodus file, opened read-only."""

    def __init__(self, path):
        import netCDF4

        self.path = path
        try:
            self.ds = netCDF4.Dataset(path, "r")
        except OSError as e:
            raise SystemExit("peridot_post: cannot open %s: %s" % (path, e))
        ds = self.ds
        self.times = np.array(ds.variables["time_whole"][:], dtype=float) if "time_whole" in ds.variables else np.zeros(0)
        self.dimension = ds.dimensions["num_dim"].size if "num_dim" in ds.dimensions else 0
        self.num_nodes = ds.dimensions["num_nodes"].size if "num_nodes" in ds.dimensions else 0
        self.global_names = _names(ds, "name_glo_var")
        self.node_names = _names(ds, "name_nod_var")
        self.elem_names = _names(ds, "name_elem_var")
        self.block_names = _names(ds, "eb_names")
        self.block_ids = list(np.array(ds.variables["eb_prop1"][:])) if "eb_prop1" in ds.variables else []
        self.set_names = _names(ds, "ns_names")

    def close(self):
        self.ds.close()

    # -- what the file holds ------------------------------------------------------------------
    def blocks(self):
        """[(id, name, number of points)]"""
        out = []
        for b, bid in enumerate(self.block_ids):
            dim = "num_el_in_blk%d" % (b + 1)
            n = self.ds.dimensions[dim].size if dim in self.ds.dimensions else 0
            name = self.block_names[b] if b < len(self.block_names) else "block_%d" % bid
            out.append((int(bid), name, n))
        return out

    def node_sets(self):
        """[(name, number of points)]"""
        out = []
        for s, name in enumerate(self.set_names):
            dim = "num_nod_ns%d" % (s + 1)
            out.append((name, self.ds.dimensions[dim].size if dim in self.ds.dimensions else 0))
        return out

    def fields(self):
        """Field names: vectors once (Displacement for DisplacementX/Y/Z), then scalars."""
        out = []
        for n in self.node_names:
            base = n[:-1] if n[-1:] in "XYZ" and any(n[:-1] + c in self.node_names for c in "XYZ" if c != n[-1]) else n
            if base not in out:
                out.append(base)
        for n in self.elem_names:
            if n not in out:
                out.append(n)
        return out

    # -- values -------------------------------------------------------------------------------
    def global_values(self, name):
        if name not in self.global_names:
            raise SystemExit("peridot_post: %s has no global variable %r (it has: %s)"
                             % (self.path, name, ", ".join(self.global_names) or "none"))
        return np.array(self.ds.variables["vals_glo_var"][:, self.global_names.index(name)], dtype=float)

    def record(self, time):
        """The index of the record nearest to time."""
        if len(self.times) == 0:
            raise SystemExit("peridot_post: %s holds no record" % self.path)
        return int(np.argmin(np.abs(self.times - time)))

    def coordinates(self):
        ds = self.ds
        cols = [np.array(ds.variables[c][:], dtype=float) for c in ("coordx", "coordy", "coordz") if c in ds.variables]
        while len(cols) < 3:
            cols.append(np.zeros(self.num_nodes))
        return np.stack(cols, axis=1)

    def field(self, name, record):
        """(component names, values[num_nodes, components]) of a field at a record."""
        ds = self.ds
        if name in self.node_names:
            return [name], np.array(ds.variables["vals_nod_var%d" % (self.node_names.index(name) + 1)][record, :], dtype=float)[:, None]
        comps = [name + c for c in "XYZ" if name + c in self.node_names]
        if comps:
            vals = [np.array(ds.variables["vals_nod_var%d" % (self.node_names.index(c) + 1)][record, :], dtype=float) for c in comps]
            return comps, np.stack(vals, axis=1)
        if name in self.elem_names:
            v = self.elem_names.index(name) + 1
            out = np.full(self.num_nodes, np.nan)
            for b in range(len(self.block_ids)):
                var = "vals_elem_var%deb%d" % (v, b + 1)
                if var not in ds.variables:
                    continue
                nodes = np.array(ds.variables["connect%d" % (b + 1)][:, 0], dtype=int) - 1
                out[nodes] = np.array(ds.variables[var][record, :], dtype=float)
            return [name], out[:, None]
        raise SystemExit("peridot_post: %s has no field %r (it has: %s)"
                         % (self.path, name, ", ".join(self.fields()) or "none"))
