"""ctest: runs peridot on small.yaml, then every peridot_post command on its output, and checks
the numbers against the file read directly with netCDF4 (a second reading of the file, not the
package's) and against the grid's known geometry.

usage: /usr/bin/python3 test_post.py PERIDOT PYTHON_DIR DECK
"""
import csv
import io
import os
import subprocess
import sys

import netCDF4
import numpy as np

peridot, python_dir, deck = sys.argv[1:4]
work = os.getcwd()
env = dict(os.environ, PYTHONPATH=python_dir)
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def post(*args):
    r = subprocess.run([sys.executable, "-m", "peridot_post"] + list(args), env=env,
                       capture_output=True, text=True)
    if r.returncode != 0:
        print(r.stdout, r.stderr)
    return r


subprocess.run([peridot, deck], check=True, cwd=work, stdout=subprocess.DEVNULL)
path = os.path.join(work, "small.e")
raw = netCDF4.Dataset(path)
times = np.array(raw.variables["time_whole"][:])
glo = np.array(raw.variables["vals_glo_var"][:])
gnames = [str(s) for s in netCDF4.chartostring(raw.variables["name_glo_var"][:])]
nnames = [str(s) for s in netCDF4.chartostring(raw.variables["name_nod_var"][:])]
check(len(times) == 4, "the run wrote 4 records")

r = post("info", path)
check(r.returncode == 0 and "points: 200" in r.stdout and "block 1 \"block_1\": 200 points" in r.stdout
      and "node set \"Right Node Set\": 10 points" in r.stdout
      and "Global_Kinetic_Energy, Global_Stored_Elastic_Energy" in r.stdout
      and "fields: Displacement, Model_Coordinates" in r.stdout and "records: 4" in r.stdout,
      "info lists points, block, node set, fields, globals, records")

r = post("csv", path, "--globals", "Global_Stored_Elastic_Energy", "Global_Kinetic_Energy")
rows = list(csv.reader(io.StringIO(r.stdout)))
check(rows[0] == ["time", "Global_Stored_Elastic_Energy", "Global_Kinetic_Energy"], "csv header")
values = np.array([[float(v) for v in row] for row in rows[1:]])
check(values.shape == (4, 3), "csv has one row per record")
check(np.array_equal(values[:, 0], times), "csv times are the file's, to the bit")
check(np.array_equal(values[:, 1], glo[:, gnames.index("Global_Stored_Elastic_Energy")])
      and np.array_equal(values[:, 2], glo[:, gnames.index("Global_Kinetic_Energy")]),
      "csv values are the file's, to the bit")
# Independent physics check: the initial kinetic energy is 1/2 m v^2 of the pulled column
# (10 points of 0.001 x 0.001 x 0.001 m^3 at 1190 kg/m^3, v = 1 m/s).
check(abs(values[0, 2] - 0.5 * 10 * 1190 * 1e-9) < 1e-15, "initial kinetic energy = 1/2 m v^2")

png = os.path.join(work, "energies.png")
if os.path.exists(png):
    os.remove(png)
r = post("plot", path, "--globals", "Global_Kinetic_Energy", "Global_Stored_Elastic_Energy", "-o", png)
with open(png, "rb") as f:
    head = f.read(8)
check(r.returncode == 0 and head == b"\x89PNG\r\n\x1a\n" and os.path.getsize(png) > 5000,
      "plot writes a non-empty PNG")

r = post("extract", path, "--field", "Displacement", "--time", "1.2e-6")
lines = [l for l in r.stdout.splitlines() if not l.startswith("#")]
rows = list(csv.reader(lines))
check(rows[0] == ["id", "x", "y", "z", "DisplacementX", "DisplacementY"], "extract header")
rec = int(np.argmin(np.abs(times - 1.2e-6)))
ux = np.array(raw.variables["vals_nod_var%d" % (nnames.index("DisplacementX") + 1)][rec, :])
got = np.array([float(row[4]) for row in rows[1:]])
check(len(got) == 200 and np.array_equal(got, ux), "extract at a time gives the file's record")

# Along a line: y = 0.0045 is a row of points (spacing 1 mm, centres at 0.5 mm + k mm); the
# nearest point of each sample is at most half a spacing away in x and exactly on the row.
r = post("extract", path, "--field", "Model_Coordinates", "--line", "0.0005,0.0045,0:0.0195,0.0045,0",
         "--points", "39")
rows = list(csv.reader([l for l in r.stdout.splitlines() if not l.startswith("#")]))[1:]
ok = len(rows) == 39
for row in rows:
    sx, mx, my = float(row[1]), float(row[6]), float(row[7])
    ok = ok and abs(mx - sx) <= 0.0005 + 1e-12 and abs(my - 0.0045) < 1e-12 and float(row[5]) <= 0.0005 + 1e-12
check(ok, "extract along a line takes the nearest point of each sample")

r = post("csv", path, "--globals", "Nope")
check(r.returncode != 0 and "no global variable 'Nope'" in r.stderr, "unknown names are a clear error")

sys.exit(1 if failures else 0)
