#!/usr/bin/env python3
"""Peridot vs LAMMPS PERI on the same scene: a stretching cube with bond breaking.

Writes a Peridot deck and a LAMMPS input for each (N, model), runs both codes alternately
(`mpirun -np P`, several repeats), and reports medians of the time-stepping loop, bond updates
per second per core, the Peridot/LAMMPS ratio, Peridot's parallel efficiency and the peak
resident memory per bond. Standard library only. See bench/README.md.

    python3 bench/run_bench.py --sizes 32 64 --models pmb lps --repeats 3
"""

import argparse
import json
import math
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)

# ----------------------------------------------------------------------------------------------
# Scene (SI units). Glass-like constants, as in Peridigm's and LAMMPS's PERI examples.
# ----------------------------------------------------------------------------------------------
DENSITY = 2200.0
BULK = 14.9e9
SHEAR = 8.94e9
YOUNG = 9.0 * BULK * SHEAR / (3.0 * BULK + SHEAR)  # the 2D plate's E (plane stress PMB: nu = 1/3)
HORIZON_FACTOR = 3.015  # delta = 3.015 dx


class Scene:
    def __init__(self, n, model, a):
        self.n = n
        self.model = model
        self.dx = a.dx
        self.delta = HORIZON_FACTOR * a.dx
        self.length = n * a.dx
        self.center = 0.5 * self.length
        self.sc = a.critical_stretch
        self.rate = a.strain_rate          # v_x = rate * (x - xc), i.e. v0 = rate * L
        self.dt = a.dt
        self.steps = a.steps
        self.skin = a.skin * a.dx
        self.influence = a.lps_influence   # "inverse" (1/|xi|, as LAMMPS) or "one"
        self.micromodulus = 18.0 * BULK / (math.pi * self.delta ** 4)
        self.planar = model == "plate2d"  # N x N points, plane stress, thickness dx

    @property
    def num_points(self):
        return self.n ** 2 if self.planar else self.n ** 3

    @property
    def name(self):
        return "N%d_%s" % (self.n, self.model)

    # Peridot's own stable time-step estimate for an interior point (Silling & Askari, PMB
    # micromodulus from K), reproduced here so the harness can warn before running.
    def stable_dt(self):
        if self.planar:
            return float("inf")  # Peridot prints its own estimate; the 3D sum does not apply
        s = 0.0
        r = int(math.ceil(HORIZON_FACTOR))
        for i in range(-r, r + 1):
            for j in range(-r, r + 1):
                for k in range(-r, r + 1):
                    d2 = i * i + j * j + k * k
                    if d2 and d2 < HORIZON_FACTOR ** 2:
                        s += self.dx ** 3 * self.micromodulus / (math.sqrt(d2) * self.dx)
        return math.sqrt(2.0 * DENSITY / s)

    def write_peridot(self, d):
        nodes = os.path.join(d, "all_nodes.txt")
        if not os.path.exists(nodes):
            with open(nodes, "w") as f:
                total = self.num_points
                for start in range(1, total + 1, 16):
                    f.write(" ".join(str(k) for k in range(start, min(start + 16, total + 1))))
                    f.write("\n")
        if self.model == "plate2d":
            material = """    <ParameterList name="Glass">
      <Parameter name="Material Model" type="string" value="Elastic Bond Based"/>
      <Parameter name="Plane Stress" type="bool" value="true"/>
      <Parameter name="Density" type="double" value="%r"/>
      <Parameter name="Young's Modulus" type="double" value="%r"/>
    </ParameterList>""" % (DENSITY, YOUNG)
            influence = ""
        elif self.model == "pmb":
            material = """    <ParameterList name="Glass">
      <Parameter name="Material Model" type="string" value="Elastic Bond Based"/>
      <Parameter name="Density" type="double" value="%r"/>
      <Parameter name="Bulk Modulus" type="double" value="%r"/>
    </ParameterList>""" % (DENSITY, BULK)
            influence = ""
        else:
            material = """    <ParameterList name="Glass">
      <Parameter name="Material Model" type="string" value="Elastic"/>
      <Parameter name="Density" type="double" value="%r"/>
      <Parameter name="Bulk Modulus" type="double" value="%r"/>
      <Parameter name="Shear Modulus" type="double" value="%r"/>
    </ParameterList>""" % (DENSITY, BULK, SHEAR)
            influence = ('    <Parameter name="Influence Function" type="string" value="1.0/zeta"/>\n'
                         if self.influence == "inverse" else "")
        deck = """<ParameterList>
  <!-- bench/run_bench.py: %(name)s. %(what)s, delta = %(hf)s dx, critical
       stretch, initial velocity v_x = rate (x - xc) that stretches it until bonds break. -->
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="PdQuickGrid"/>
%(generator)s
    <Parameter name="NeighborhoodType" type="string" value="Spherical"/>
%(influence)s  </ParameterList>
  <ParameterList name="Materials">
%(material)s
  </ParameterList>
  <ParameterList name="Damage Models">
    <ParameterList name="Stretch">
      <Parameter name="Damage Model" type="string" value="Critical Stretch"/>
      <Parameter name="Critical Stretch" type="double" value="%(sc)r"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="Cube">
      <Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="Glass"/>
      <Parameter name="Damage Model" type="string" value="Stretch"/>
      <Parameter name="Horizon" type="double" value="%(delta)r"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
    <Parameter name="All Node Set" type="string" value="all_nodes.txt"/>
    <ParameterList name="Stretching Velocity">
      <Parameter name="Type" type="string" value="Initial Velocity"/>
      <Parameter name="Node Set" type="string" value="All Node Set"/>
      <Parameter name="Coordinate" type="string" value="x"/>
      <Parameter name="Value" type="string" value="%(rate)r*(x-%(xc)r)"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value="0.0"/>
    <Parameter name="Final Time" type="double" value="%(tfinal)r"/>
    <ParameterList name="Verlet">
      <Parameter name="Fixed dt" type="double" value="%(dt)r"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Compute Class Parameters">
    <ParameterList name="Damage Sum">
      <Parameter name="Compute Class" type="string" value="Block_Data"/>
      <Parameter name="Calculation Type" type="string" value="Sum"/>
      <Parameter name="Block" type="string" value="block_1"/>
      <Parameter name="Variable" type="string" value="Damage"/>
      <Parameter name="Output Label" type="string" value="Damage_Sum"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output File Type" type="string" value="ExodusII"/>
    <Parameter name="Output Filename" type="string" value="peridot_out"/>
    <Parameter name="Output Frequency" type="int" value="%(steps)d"/>
    <ParameterList name="Output Variables">
      <Parameter name="Damage_Sum" type="bool" value="true"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
""" % dict(name=self.name, hf=HORIZON_FACTOR, generator=self.generator(), influence=influence,
           what=("plane-stress PMB plate, N^2 points" if self.planar else "PMB/LPS cube, N^3 points"),
           material=material, sc=self.sc, delta=self.delta, rate=self.rate, xc=self.center,
           tfinal=self.steps * self.dt, dt=self.dt, steps=self.steps)
        path = os.path.join(d, "peridot.xml")
        with open(path, "w") as f:
            f.write(deck)
        return path

    def generator(self):
        axes = "XY" if self.planar else "XYZ"
        lines = ['    <ParameterList name="TensorProduct%dDMeshGenerator">' % len(axes)]
        lines += ['      <Parameter name="%s Origin" type="double" value="0.0"/>' % a for a in axes]
        lines += ['      <Parameter name="%s Length" type="double" value="%r"/>' % (a, self.length)
                  for a in axes]
        lines += ['      <Parameter name="Number Points %s" type="int" value="%d"/>' % (a, self.n)
                  for a in axes]
        lines.append("    </ParameterList>")
        if self.planar:
            lines.append('    <Parameter name="Thickness" type="double" value="%r"/>' % self.dx)
        return "\n".join(lines)

    def write_lammps(self, d):
        if self.planar:
            return None  # LAMMPS PERI has no 2D (plane stress / strain) model
        if self.model == "pmb":
            pair = "pair_style      peri/pmb\npair_coeff      * * %r %r %r 0.0" % (
                self.micromodulus, self.delta, self.sc)
        else:
            pair = "pair_style      peri/lps\npair_coeff      * * %r %r %r %r 0.0" % (
                BULK, SHEAR, self.delta, self.sc)
        text = """# bench/run_bench.py: %(name)s (LAMMPS PERI twin of peridot.xml)
units           si
boundary        s s s
atom_style      peri
atom_modify     map array
# points at (i + 1/2) dx, i = 0..N-1, as PdQuickGrid's TensorProduct3DMeshGenerator
lattice         sc %(dx)r origin 0.5 0.5 0.5
region          cube block 0 %(n)d 0 %(n)d 0 %(n)d units lattice
create_box      1 cube
create_atoms    1 region cube
%(pair)s
set             group all density %(rho)r
set             group all volume %(vol)r
neighbor        %(skin)r bin
neigh_modify    every 1 delay 0 check yes
variable        vx atom %(rate)r*(x-%(xc)r)
velocity        all set v_vx 0.0 0.0 sum no units box
fix             1 all nve
compute         dmg all damage/atom
compute         avgdmg all reduce ave c_dmg
thermo_style    custom step c_avgdmg ke
thermo          0
timestep        %(dt)r
# peri/lps in LAMMPS 29Sep2021 leaves s0 uninitialised in the very first force call (made
# before fix PERI_NEIGH has built the bond lists), which breaks every stretched bond on step
# 1. A zero-step run first sets s0 = s00 at the reference configuration (see README).
run             0 post no
run             %(steps)d
""" % dict(name=self.name, dx=self.dx, n=self.n, pair=pair, rho=DENSITY, vol=self.dx ** 3,
           skin=self.skin, rate=self.rate, xc=self.center, dt=self.dt, steps=self.steps)
        path = os.path.join(d, "in.lammps")
        with open(path, "w") as f:
            f.write(text)
        return path


# ----------------------------------------------------------------------------------------------
# Running
# ----------------------------------------------------------------------------------------------
# Extra mpirun options for the binding of the ranks (--bind none: ranks may use every core, as
# a process started without mpirun does; mpirun's default binds each of up to two ranks to a
# core, which leaves Peridot's rank no processor to spare).
BIND = []
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_NUM_THREADS="1")


CLK_TCK = os.sysconf("SC_CLK_TCK")


def machine_busy_seconds():
    """CPU seconds spent busy by the whole machine so far (all cores), from /proc/stat."""
    with open("/proc/stat") as f:
        v = [int(x) for x in f.readline().split()[1:]]
    # user nice system idle iowait irq softirq steal ...
    return (v[0] + v[1] + v[2] + v[5] + v[6] + (v[7] if len(v) > 7 else 0)) / CLK_TCK


def wait_until_quiet(max_wait, threshold=0.15):
    """Wait (up to max_wait s) until the other processes on the box use < threshold of a core.

    Other people's builds and tests share this machine; a benchmark run started while they
    compute is slowed down. Returns the busy fraction seen last (in cores)."""
    t_end = time.monotonic() + max_wait
    quiet = 0
    while True:
        b0, t0 = machine_busy_seconds(), time.monotonic()
        time.sleep(1.0)
        busy = (machine_busy_seconds() - b0) / (time.monotonic() - t0)
        quiet = quiet + 1 if busy < threshold else 0
        if quiet >= 2 or time.monotonic() > t_end:
            return busy


def run_timed(cmd, ranks, cwd, tag, timeout):
    """mpirun -np ranks, each rank under /usr/bin/time -v.

    Returns (stdout, wall, [rss_kb], [user+sys s], foreign_cpu_s) where foreign_cpu_s is the CPU
    time the rest of the machine used while the run was going (a contamination measure)."""
    prefix = os.path.join(cwd, "time_" + tag)
    for f in os.listdir(cwd):
        if f.startswith("time_" + tag + "."):
            os.remove(os.path.join(cwd, f))
    wrapped = ["mpirun", "-np", str(ranks)] + BIND + ["sh", "-c",
               'exec /usr/bin/time -v -o "$0.${OMPI_COMM_WORLD_RANK:-0}" "$@"', prefix] + cmd
    busy0 = machine_busy_seconds()
    t0 = time.monotonic()
    p = subprocess.Popen(wrapped, cwd=cwd, env=ENV, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, start_new_session=True)
    try:
        out, _ = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)  # our own mpirun's process group only
        p.communicate()
        raise RuntimeError("%s timed out after %d s" % (tag, timeout))
    wall = time.monotonic() - t0
    busy = machine_busy_seconds() - busy0
    if p.returncode != 0:
        raise RuntimeError("%s failed (exit %d):\n%s" % (tag, p.returncode, out[-3000:]))
    rss, cpu = [], []
    for r in range(ranks):
        with open("%s.%d" % (prefix, r)) as f:
            t = f.read()
        rss.append(int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", t).group(1)))
        cpu.append(float(re.search(r"User time \(seconds\): ([\d.]+)", t).group(1)) +
                   float(re.search(r"System time \(seconds\): ([\d.]+)", t).group(1)))
    # mpirun itself polls a little; count everything not in our ranks as foreign.
    return out, wall, rss, cpu, max(0.0, busy - sum(cpu))


def parse_peridot(out, cwd):
    r = {}
    m = re.search(r"Points: (\d+), bonds \(one-sided\): (\d+), ranks: (\d+)", out)
    r["points"], r["bonds"], r["ranks"] = int(m.group(1)), int(m.group(2)), int(m.group(3))
    m = re.search(r"Stable time step estimate: (\S+)", out)
    r["stable_dt"] = float(m.group(1))
    m = re.search(r"Time step: (\S+).*steps: (\d+)", out)
    r["dt"], r["steps"] = float(m.group(1)), int(m.group(2))
    rows = {}
    for m in re.finditer(r"^\s+(\S.*?)\s{2,}([\d.]+)\s+([\d.]+)\s+([\d.]+)\s*$", out, re.M):
        rows[m.group(1).strip()] = {"min": float(m.group(2)), "max": float(m.group(3)),
                                    "ave": float(m.group(4))}
    r["timers"] = rows
    loop_rows = ["Force", "Damage", "Integration", "Ghost exchange"]
    # Loop time: the loop's timer rows, each at its slowest rank (an upper bound that includes
    # the waiting in the ghost exchange). Peridot has no single loop timer; see README.
    r["loop"] = sum(rows[k]["max"] for k in loop_rows if k in rows)
    r["loop_ave"] = sum(rows[k]["ave"] for k in loop_rows if k in rows)
    # "elapsed 12.3 s" or "elapsed 1 min 50 s"; printed only for loops longer than 5 s
    m = re.findall(r"step (\d+)/(\d+) .*?elapsed (?:(\d+) min )?([\d.]+) s", out)
    if m and m[-1][0] == m[-1][1]:
        r["elapsed"] = 60.0 * float(m[-1][2] or 0) + float(m[-1][3])
    r["damage"] = None
    h = os.path.join(cwd, "peridot_out.h")
    if shutil.which("ncdump") and os.path.exists(h):
        txt = subprocess.run(["ncdump", "-v", "vals_glo_var", h], capture_output=True,
                             text=True).stdout
        vals = re.findall(r"[-+]?\d[\d.eE+-]*", txt.split("vals_glo_var =")[-1])
        if vals:
            r["damage"] = float(vals[-1]) / r["points"]
    return r


def parse_lammps(log):
    with open(log) as f:
        txt = f.read()
    r = {}
    # the last run (the first is the zero-step "run 0")
    txt_all = txt
    txt = txt[txt.rfind("Step c_avgdmg"):]
    m = re.search(r"Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms", txt)
    r["loop"], r["ranks"], r["steps"], r["points"] = (float(m.group(1)), int(m.group(2)),
                                                      int(m.group(3)), int(m.group(4)))
    r["bonds"] = int(re.search(r"total # of bonds = (\d+)", txt_all).group(1))
    r["sections"] = {}
    for m in re.finditer(r"^(Pair|Neigh|Comm|Output|Modify|Other)\s*\|([^\n]*)", txt, re.M):
        nums = [float(x) for x in re.findall(r"[\d.]+(?:e[-+]?\d+)?", m.group(2))]
        # columns: min avg max %varavg %total ("Other" has only avg and %total)
        r["sections"][m.group(1)] = nums[1] if len(nums) >= 5 else nums[0]
    m = re.search(r"Neighbor list builds = (\d+)", txt)
    r["neigh_builds"] = int(m.group(1)) if m else None
    m = re.search(r"Per MPI rank memory allocation \(min/avg/max\) = \S+ \| \S+ \| (\S+) Mbytes", txt)
    r["lammps_mem_mb"] = float(m.group(1)) if m else None
    thermo = re.search(r"Step\s+c_avgdmg\s+KinEng\s*\n((?:\s*\d+\s+\S+\s+\S+\s*\n)+)", txt)
    r["damage"] = float(thermo.group(1).strip().splitlines()[-1].split()[1]) if thermo else None
    return r


def one_run(code, scene, ranks, d, a, tag):
    if a.settle > 0:
        time.sleep(a.settle)
    if a.wait_quiet > 0:
        wait_until_quiet(a.wait_quiet)
    if code == "peridot":
        out, wall, rss, cpu, foreign = run_timed([a.peridot, "peridot.xml"], ranks, d, tag,
                                                 a.timeout)
        with open(os.path.join(d, "%s.out" % tag), "w") as f:
            f.write(out)
        r = parse_peridot(out, d)
    else:
        log = "log_%s.lammps" % tag
        out, wall, rss, cpu, foreign = run_timed(
            [a.lmp, "-in", "in.lammps", "-log", log, "-screen", "none", "-nocite"], ranks, d, tag,
            a.timeout)
        r = parse_lammps(os.path.join(d, log))
    r["wall"] = wall
    r["cpu"] = cpu
    r["foreign_cpu"] = foreign
    r["foreign_frac"] = foreign / wall  # in cores: 0 = the box was ours, 1 = one core stolen
    r["rss_kb"] = rss
    r["rss_total_kb"] = sum(rss)
    return r


# ----------------------------------------------------------------------------------------------
# Report
# ----------------------------------------------------------------------------------------------
def med(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def fmt(x, spec):
    return "n/a" if x is None else format(x, spec)


def summarize(results):
    """results: list of run dicts -> {(n, model, code, ranks): summary}."""
    groups = {}
    for r in results:
        groups.setdefault((r["n"], r["model"], r["code"], r["np"]), []).append(r)
    s = {}
    for key, runs in groups.items():
        loop = med([x["loop"] for x in runs])
        bonds = runs[0]["bonds"]
        steps = runs[0]["steps"]
        s[key] = {
            "runs": len(runs), "loop": loop, "bonds": bonds, "steps": steps,
            "points": runs[0]["points"],
            "rate": bonds * steps / (loop * key[3]),
            "rss_mb": med([x["rss_total_kb"] for x in runs]) / 1024.0,
            "rss_per_bond": med([x["rss_total_kb"] for x in runs]) * 1024.0 / bonds,
            "damage": med([x.get("damage") for x in runs]),
            "wall": med([x["wall"] for x in runs]),
            "spread": (max(x["loop"] for x in runs) - min(x["loop"] for x in runs)) / loop,
            "foreign": max(x.get("foreign_frac", 0.0) for x in runs),
            "cpu": med([sum(x["cpu"]) for x in runs if "cpu" in x]),
            "raw": runs,
        }
        if key[2] == "peridot":
            s[key]["rows"] = {k: med([x["timers"].get(k, {}).get("max") for x in runs])
                              for k in ["Force", "Damage", "Integration", "Ghost exchange",
                                        "Setup", "Output"]}
            s[key]["elapsed"] = med([x.get("elapsed") for x in runs])
        else:
            s[key]["rows"] = {k: med([x["sections"].get(k) for x in runs])
                              for k in ["Pair", "Neigh", "Comm", "Modify", "Output", "Other"]}
            s[key]["neigh_builds"] = runs[0].get("neigh_builds")
    return s


def report(results, baselines=None):
    s = summarize(results)
    keys = sorted({(k[0], k[1]) for k in s})
    ranks_all = sorted({k[3] for k in s})
    lines = []
    lines.append("### Throughput (medians of %s runs; loop time = time-stepping loop only)\n" %
                 "/".join(sorted({str(v["runs"]) for v in s.values()})))
    lines.append("| N | model | ranks | bonds Peridot | bonds LAMMPS | steps | Peridot loop [s] "
                 "| LAMMPS loop [s] | Peridot bond-upd/s/core | LAMMPS bond-upd/s/core "
                 "| Peridot/LAMMPS | Peridot eff. 1→2 | LAMMPS eff. 1→2 |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n, model in keys:
        for p in ranks_all:
            P, L = s.get((n, model, "peridot", p)), s.get((n, model, "lammps", p))
            ratio = P["rate"] / L["rate"] if P and L else None
            effP = effL = None
            if p > 1:
                P1, L1 = s.get((n, model, "peridot", 1)), s.get((n, model, "lammps", 1))
                if P and P1:
                    effP = P1["loop"] / (p * P["loop"])
                if L and L1:
                    effL = L1["loop"] / (p * L["loop"])
            lines.append("| %d | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                n, model, p, fmt(P and P["bonds"], ",d"), fmt(L and L["bonds"], ",d"),
                fmt((P or L)["steps"], "d"),
                fmt(P and P["loop"], ".2f"), fmt(L and L["loop"], ".2f"),
                fmt(P and P["rate"] / 1e6, ".1f") + ("M" if P else ""),
                fmt(L and L["rate"] / 1e6, ".1f") + ("M" if L else ""),
                fmt(ratio, ".2f"), "—" if p == 1 else fmt(effP, ".0%"),
                "—" if p == 1 else fmt(effL, ".0%")))
    lines.append("")
    lines.append("### Memory and physics check (peak RSS summed over ranks)\n")
    lines.append("| N | model | ranks | Peridot RSS [MB] | LAMMPS RSS [MB] | Peridot B/bond "
                 "| LAMMPS B/bond | Peridot B/bond above baseline | LAMMPS B/bond above baseline "
                 "| bond ratio P/L | mean damage P | mean damage L |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n, model in keys:
        for p in ranks_all:
            P, L = s.get((n, model, "peridot", p)), s.get((n, model, "lammps", p))
            def above(x, code):
                if not x or not baselines or (code, p) not in baselines:
                    return None
                return (x["rss_mb"] - baselines[(code, p)]) * 1024 * 1024 / x["bonds"]
            lines.append("| %d | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                n, model, p, fmt(P and P["rss_mb"], ".0f"), fmt(L and L["rss_mb"], ".0f"),
                fmt(P and P["rss_per_bond"], ".1f"), fmt(L and L["rss_per_bond"], ".1f"),
                fmt(above(P, "peridot"), ".1f"), fmt(above(L, "lammps"), ".1f"),
                fmt(P["bonds"] / L["bonds"] if P and L else None, ".4f"),
                fmt(P and P["damage"], ".3f"), fmt(L and L["damage"], ".3f")))
    if baselines:
        lines.append("")
        lines.append("Baseline RSS (tiny %s^3 run, MB, summed over ranks): " % BASELINE_N +
                     ", ".join("%s np%d %.0f" % (c, p, v) for (c, p), v in sorted(baselines.items())))
    lines.append("")
    lines.append("### Where the loop time goes (medians, seconds; Peridot rows are slowest-rank "
                 "timers, LAMMPS rows are rank-averaged sections)\n")
    lines.append("| N | model | ranks | Peridot Force | Damage | Integration | Ghost exchange "
                 "| (Setup) | LAMMPS Pair | Neigh | Comm | Modify | Other | neigh builds "
                 "| run-to-run spread P / L | max foreign load P / L [cores] |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n, model in keys:
        for p in ranks_all:
            P, L = s.get((n, model, "peridot", p)), s.get((n, model, "lammps", p))
            pr = P["rows"] if P else {}
            lr = L["rows"] if L else {}
            lines.append("| %d | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s / %s | %s / %s |" % (
                n, model, p, fmt(pr.get("Force"), ".2f"), fmt(pr.get("Damage"), ".2f"),
                fmt(pr.get("Integration"), ".2f"), fmt(pr.get("Ghost exchange"), ".2f"),
                fmt(pr.get("Setup"), ".2f"), fmt(lr.get("Pair"), ".2f"),
                fmt(lr.get("Neigh"), ".2f"), fmt(lr.get("Comm"), ".2f"),
                fmt(lr.get("Modify"), ".2f"), fmt(lr.get("Other"), ".2f"),
                fmt(L and L.get("neigh_builds"), "d"),
                fmt(P and P["spread"], ".0%"), fmt(L and L["spread"], ".0%"),
                fmt(P and P["foreign"], ".2f"), fmt(L and L["foreign"], ".2f")))
    return "\n".join(lines) + "\n"


BASELINE_N = 6


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", type=int, nargs="+", default=[32, 64])
    ap.add_argument("--models", nargs="+", choices=["pmb", "lps", "plate2d"], default=["pmb", "lps"],
                    help="plate2d: an N x N glass plate, plane-stress PMB + critical stretch, "
                    "Peridot only (LAMMPS PERI has no 2D model)")
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--codes", nargs="+", choices=["peridot", "lammps"], default=["peridot", "lammps"])
    ap.add_argument("--dx", type=float, default=5.0e-4, help="lattice spacing [m]")
    ap.add_argument("--dt", type=float, default=5.0e-8,
                    help="time step [s], the same in both codes (about 0.37 x the stable estimate)")
    ap.add_argument("--critical-stretch", type=float, default=0.002)
    ap.add_argument("--strain-rate", type=float, default=4000.0,
                    help="v_x = rate * (x - xc) [1/s]")
    ap.add_argument("--skin", type=float, default=0.3,
                    help="LAMMPS neighbor skin in units of dx (its contact-force list)")
    ap.add_argument("--lps-influence", choices=["inverse", "one"], default="inverse",
                    help="Peridot's LPS influence function: 1/|xi| (LAMMPS's, default) or 1")
    ap.add_argument("--peridot", default=None, help="peridot binary (default: /tmp/build-bench/peridot)")
    ap.add_argument("--lmp", default=shutil.which("lmp") or "lmp")
    ap.add_argument("--bind", choices=["default", "none"], default="default",
                    help="mpirun's binding of the ranks (none: --bind-to none, for both codes)")
    ap.add_argument("--workdir", default="/tmp/peridot-bench")
    ap.add_argument("--timeout", type=int, default=900, help="per run, seconds")
    ap.add_argument("--wait-quiet", type=int, default=120,
                    help="before each run wait up to this many seconds for the box to be idle "
                         "(other users' jobs); 0 = do not wait")
    ap.add_argument("--settle", type=float, default=0,
                    help="sleep this many seconds before each run. On a VM whose host takes back "
                         "freed guest memory within seconds (bench/RESULTS.md), a run started "
                         "right after another gets part of its fresh pages several times cheaper: "
                         "30 s makes every run start alike (cold)")
    ap.add_argument("--max-foreign", type=float, default=0.25,
                    help="rerun (once) a run during which other processes used more than this "
                         "fraction of a core")
    ap.add_argument("--no-baseline", action="store_true", help="skip the tiny-run RSS baseline")
    ap.add_argument("--json", default=None,
                    help="results file, saved after every run (default WORKDIR/results.json); "
                         "runs already in it with the same settings are skipped (resume)")
    ap.add_argument("--fresh", action="store_true", help="ignore an existing results file")
    ap.add_argument("--write-only", action="store_true",
                    help="only write the decks/inputs under --workdir (e.g. for profiling)")
    ap.add_argument("--retries", type=int, default=2,
                    help="how many times to rerun a run disturbed by other processes")
    ap.add_argument("--report", nargs="+", default=None, metavar="JSON",
                    help="only print the tables from saved JSON result files")
    a = ap.parse_args()
    if a.bind == "none":
        BIND[:] = ["--bind-to", "none"]

    if a.report:
        results, baselines = [], {}
        for fn in a.report:
            with open(fn) as f:
                data = json.load(f)
            results += data["results"]
            for k, v in data.get("baselines", {}).items():
                c, p = k.split(":")
                baselines[(c, int(p))] = v
        print(report(results, baselines or None))
        return

    if a.peridot is None:
        for cand in ["/tmp/build-bench/peridot", os.path.join(REPO, "build", "peridot")]:
            if os.path.exists(cand):
                a.peridot = cand
                break
    a.peridot = os.path.abspath(a.peridot) if a.peridot else "peridot"
    os.makedirs(a.workdir, exist_ok=True)
    print("peridot: %s\nlammps:  %s\nworkdir: %s" % (a.peridot, a.lmp, a.workdir), flush=True)

    # Results are saved after every run and a rerun resumes: runs already in the JSON file with
    # the same settings are not repeated (this box is shared; runs can get killed).
    if a.json is None:
        a.json = os.path.join(a.workdir, "results.json")
    store = {"results": [], "baselines": {}, "settings": []}
    if os.path.exists(a.json) and not a.fresh and not a.write_only:
        with open(a.json) as f:
            store = json.load(f)
        print("resuming from %s (%d runs saved)" % (a.json, len(store["results"])), flush=True)

    def save():
        tmp = a.json + ".tmp"
        with open(tmp, "w") as f:
            json.dump(store, f, indent=1)
        os.replace(tmp, a.json)

    def setting_key(r):
        return (r["code"], r["n"], r["model"], r["np"], r["rep"], r["steps_requested"], r["dt"],
                r["strain_rate"], r["critical_stretch"], r["skin_dx"], r["lps_influence"])

    done = {setting_key(r) for r in store["results"] if "steps_requested" in r}

    if not a.no_baseline and not a.write_only:
        b = argparse.Namespace(**vars(a))
        b.steps = 10
        for code in a.codes:
            for p in a.ranks:
                if "%s:%d" % (code, p) in store["baselines"]:
                    continue
                sc = Scene(BASELINE_N, "pmb", b)
                d = os.path.join(a.workdir, "baseline")
                os.makedirs(d, exist_ok=True)
                sc.write_peridot(d)
                sc.write_lammps(d)
                r = one_run(code, sc, p, d, b, "%s_np%d" % (code, p))
                store["baselines"]["%s:%d" % (code, p)] = r["rss_total_kb"] / 1024.0
                save()
                print("baseline %s np%d: %.0f MB" % (code, p, r["rss_total_kb"] / 1024.0),
                      flush=True)
    if not a.write_only:
        store["settings"].append({k: v for k, v in vars(a).items()})
        save()

    for n in a.sizes:
        for model in a.models:
            sc = Scene(n, model, a)
            d = os.path.join(a.workdir, sc.name)
            os.makedirs(d, exist_ok=True)
            sc.write_peridot(d)
            lammps_input = sc.write_lammps(d)
            if a.write_only:
                print("wrote %s/peridot.xml" % d + (" and %s/in.lammps" % d if lammps_input else
                                                   " (no LAMMPS twin: LAMMPS PERI is 3D only)"))
                continue
            est = sc.stable_dt()
            if a.dt > est:
                print("warning: dt %g exceeds the stable estimate %g" % (a.dt, est))
            for rep in range(a.repeats):
                for p in a.ranks:
                    for code in a.codes:  # alternate the codes within each repeat
                        if code == "lammps" and sc.planar:
                            continue
                        meta = dict(code=code, n=n, model=model, np=p, rep=rep,
                                    steps_requested=a.steps, dt=a.dt, strain_rate=a.strain_rate,
                                    critical_stretch=a.critical_stretch, skin_dx=a.skin,
                                    lps_influence=a.lps_influence)
                        if setting_key(meta) in done:
                            continue
                        tag = "%s_np%d_r%d" % (code, p, rep)
                        r = one_run(code, sc, p, d, a, tag + "_a0")
                        r["tag"] = tag + "_a0"
                        for attempt in range(1, a.retries + 1):
                            if r["foreign_frac"] <= a.max_foreign:
                                break
                            print("  (%s: other processes used %.2f cores during the run; "
                                  "running it again)" % (r["tag"], r["foreign_frac"]), flush=True)
                            r2 = one_run(code, sc, p, d, a, "%s_a%d" % (tag, attempt))
                            r2["tag"] = "%s_a%d" % (tag, attempt)
                            r = r2 if r2["foreign_frac"] < r["foreign_frac"] else r
                        r.update(meta)
                        if r.get("stable_dt") and r["stable_dt"] < a.dt:
                            print("warning: dt %g exceeds Peridot's stable estimate %g" %
                                  (a.dt, r["stable_dt"]), flush=True)
                        r["date"] = time.strftime("%Y-%m-%d %H:%M:%S")
                        store["results"].append(r)
                        save()
                        print("%-8s N=%-4d %s np=%d rep=%d  loop %.3f s  bonds %d  RSS %.0f MB  "
                              "damage %s  foreign %.2f cores" % (
                                  code, n, model, p, rep, r["loop"], r["bonds"],
                                  r["rss_total_kb"] / 1024.0, fmt(r.get("damage"), ".3f"),
                                  r["foreign_frac"]), flush=True)
    if a.write_only:
        return
    wanted = [r for r in store["results"] if r["n"] in a.sizes and r["model"] in a.models]
    baselines = {(k.split(":")[0], int(k.split(":")[1])): v for k, v in store["baselines"].items()}
    print()
    print(report(wanted, baselines or None))


if __name__ == "__main__":
    main()
