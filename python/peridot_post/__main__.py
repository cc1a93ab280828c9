"""Command line: python3 -m peridot_post {info,csv,plot,extract} FILE ...

  info FILE                         what the file holds
  csv FILE [--globals A B ...] [-o out.csv]
  plot FILE [--globals A B ...] -o out.png
  extract FILE --field NAME [--time T] [--line x0,y0,z0:x1,y1,z1 --points N] [-o out.csv]
"""

import argparse
import csv
import sys

import numpy as np

from peridot_post import PeridotFile


def cmd_info(args):
    f = PeridotFile(args.file)
    out = sys.stdout
    out.write("file: %s\n" % args.file)
    out.write("dimension: %d, points: %d\n" % (f.dimension, f.num_nodes))
    for bid, name, n in f.blocks():
        out.write("block %d \"%s\": %d points\n" % (bid, name, n))
    for name, n in f.node_sets():
        out.write("node set \"%s\": %d points\n" % (name, n))
    out.write("fields: %s\n" % (", ".join(f.fields()) or "none"))
    out.write("global variables: %s\n" % (", ".join(f.global_names) or "none"))
    if len(f.times):
        out.write("records: %d, times %.9g .. %.9g\n" % (len(f.times), f.times[0], f.times[-1]))
    else:
        out.write("records: 0\n")
    return 0


def chosen_globals(f, names):
    names = names or f.global_names
    if not names:
        raise SystemExit("peridot_post: %s has no global variables" % f.path)
    return names, [f.global_values(n) for n in names]


def open_out(path):
    return open(path, "w", newline="") if path and path != "-" else sys.stdout


def cmd_csv(args):
    f = PeridotFile(args.file)
    names, cols = chosen_globals(f, args.globals)
    out = open_out(args.output)
    w = csv.writer(out)
    w.writerow(["time"] + names)
    for r, t in enumerate(f.times):
        w.writerow([repr(float(t))] + [repr(float(c[r])) for c in cols])
    if out is not sys.stdout:
        out.close()
    return 0


def cmd_plot(args):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    f = PeridotFile(args.file)
    names, cols = chosen_globals(f, args.globals)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for n, c in zip(names, cols):
        ax.plot(f.times, c, marker="." if len(f.times) < 30 else None, label=n)
    ax.set_xlabel("time")
    ax.set_title(args.title or args.file)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print("wrote %s" % args.output)
    return 0


def parse_line(text):
    try:
        a, b = text.split(":")
        p0 = np.array([float(v) for v in a.split(",")])
        p1 = np.array([float(v) for v in b.split(",")])
    except ValueError:
        raise SystemExit("peridot_post: --line expects x0,y0,z0:x1,y1,z1, got %r" % text)
    if p0.size != 3 or p1.size != 3:
        raise SystemExit("peridot_post: --line expects 3 coordinates at each end, got %r" % text)
    return p0, p1


def cmd_extract(args):
    f = PeridotFile(args.file)
    record = f.record(args.time if args.time is not None else (f.times[-1] if len(f.times) else 0.0))
    comps, values = f.field(args.field, record)
    x = f.coordinates()
    out = open_out(args.output)
    w = csv.writer(out)
    out.write("# %s at record %d, time %.9g\n" % (args.field, record + 1, f.times[record]))
    if args.line is None:
        w.writerow(["id", "x", "y", "z"] + comps)
        for i in range(f.num_nodes):
            w.writerow([i + 1] + [repr(float(v)) for v in x[i]] + [repr(float(v)) for v in values[i]])
    else:
        # Samples along the segment; each takes the value of the nearest point (the points are
        # the discretization: there is no interpolation between them).
        if args.points < 2:
            raise SystemExit("peridot_post: --points must be at least 2")
        p0, p1 = parse_line(args.line)
        w.writerow(["s", "x", "y", "z", "id", "distance"] + comps)
        for k in range(args.points):
            s = k / (args.points - 1)
            p = p0 + s * (p1 - p0)
            d2 = np.sum((x - p) ** 2, axis=1)
            i = int(np.argmin(d2))
            w.writerow([repr(s * float(np.linalg.norm(p1 - p0)))] + [repr(float(v)) for v in p] +
                       [i + 1, repr(float(np.sqrt(d2[i])))] + [repr(float(v)) for v in values[i]])
    if out is not sys.stdout:
        out.close()
    return 0


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m peridot_post", description="Peridot output post-processing")
    sub = p.add_subparsers(dest="command", required=True)
    s = sub.add_parser("info", help="list blocks, node sets, fields, global variables, times")
    s.add_argument("file")
    s = sub.add_parser("csv", help="global variables over time as CSV")
    s.add_argument("file")
    s.add_argument("--globals", nargs="+", help="names (default: all)")
    s.add_argument("-o", "--output", help="CSV file (default: standard output)")
    s = sub.add_parser("plot", help="global variables over time as a PNG")
    s.add_argument("file")
    s.add_argument("--globals", nargs="+", help="names (default: all)")
    s.add_argument("-o", "--output", required=True, help="PNG file")
    s.add_argument("--title")
    s = sub.add_parser("extract", help="a field at a time, at every point or along a line")
    s.add_argument("file")
    s.add_argument("--field", required=True, help="e.g. Displacement, Damage")
    s.add_argument("--time", type=float, help="the record nearest this time (default: the last)")
    s.add_argument("--line", help="x0,y0,z0:x1,y1,z1: sample along this segment")
    s.add_argument("--points", type=int, default=50, help="samples along the line (default 50)")
    s.add_argument("-o", "--output", help="CSV file (default: standard output)")
    args = p.parse_args(argv)
    return {"info": cmd_info, "csv": cmd_csv, "plot": cmd_plot, "extract": cmd_extract}[args.command](args)


if __name__ == "__main__":
    sys.exit(main())
