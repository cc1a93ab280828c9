#!/usr/bin/python3
"""Fuzzer for peridot's input handling (issue 15; results in doc/robustness.md).

Runs peridot on mutated decks (XML and YAML), corrupt meshes (text and Exodus) and runs
interrupted by signals, each in a fresh directory with a timeout, and sorts every outcome:

  ok      exit 0
  slow    still printing progress at the timeout (a long run, e.g. Final Time left at 1 s)
  error   exit 1, 2, 3 or 5 with one "peridot: error: " line on stderr (a clear message)
  CRASH   a signal, an abort, a stack trace, "internal error" (an uncaught exception), exit 4,
          an error without the "peridot: error: " line, or an error line over 4,000 characters
  HANG    still running at the timeout

Every CRASH and HANG is kept (deck, meshes, stdout, stderr) under <work>/findings/<id>/.
Only the Python standard library is used (/usr/bin/python3). Runs are reproducible from the
seed: the case number k of a run with --seed S is always the same input.

Usage:
  tools/fuzz/fuzz.py --peridot build/peridot --decks 4500 --decks-np2 500 \\
      --meshes 350 --meshes-np2 150 --signals 20 --jobs 2 --seed 1 --work /tmp/peridot-fuzz
"""
import argparse
import concurrent.futures
import json
import math
import os
import random
import shutil
import signal
import subprocess
import sys
import time

# ---------------------------------------------------------------------------------------------
# Seed decks, as nested lists of (key, value); a value is a str, int, float, bool or a list.
# All are tiny (8 to 64 points, 10 steps) so that thousands run in minutes.


def output_list(name="run", freq=5, variables=("Displacement", "Velocity", "Damage")):
    return [("Output File Type", "ExodusII"), ("Output Filename", name),
            ("Output Frequency", freq),
            ("Output Variables", [(v, True) for v in variables])]


def seed_quickgrid():
    return [
        ("Discretization", [
            ("Type", "PdQuickGrid"),
            ("TensorProduct3DMeshGenerator", [
                ("X Origin", 0.0), ("Y Origin", 0.0), ("Z Origin", 0.0),
                ("X Length", 3.0), ("Y Length", 2.0), ("Z Length", 2.0),
                ("Number Points X", 3), ("Number Points Y", 2), ("Number Points Z", 2)])]),
        ("Materials", [("My Material", [
            ("Material Model", "Elastic"), ("Density", 7800.0),
            ("Bulk Modulus", 130.0e9), ("Shear Modulus", 78.0e9)])]),
        ("Damage Models", [("My Damage", [
            ("Damage Model", "Critical Stretch"), ("Critical Stretch", 0.01)])]),
        ("Blocks", [("My Blocks", [
            ("Block Names", "block_1"), ("Material", "My Material"),
            ("Damage Model", "My Damage"), ("Horizon", 1.5)])]),
        ("Boundary Conditions", [
            ("Left Node Set", "1 4 7 10"),
            ("Left Velocity", [("Type", "Initial Velocity"), ("Node Set", "Left Node Set"),
                               ("Coordinate", "x"), ("Value", "-1.0*(z+1)")])]),
        ("Solver", [("Initial Time", 0.0), ("Final Time", 1.0e-6),
                    ("Verlet", [("Fixed dt", 1.0e-7)])]),
        ("Compute Class Parameters", [("Left Force", [
            ("Compute Class", "Block_Data"), ("Calculation Type", "Sum"), ("Block", "block_1"),
            ("Variable", "Force"), ("Output Label", "Left_Force")])]),
        ("Output", output_list("run", 5, ("Displacement", "Velocity", "Damage", "Left_Force"))),
    ]


def seed_text(mesh="cube.txt"):
    return [
        ("Discretization", [("Type", "Text File"), ("Input Mesh File", mesh),
                            ("Bond Filters", [("My Filter", [
                ("Type", "Rectangular_Plane"), ("Normal_X", 1.0), ("Normal_Y", 0.0),
                ("Normal_Z", 0.0), ("Lower_Left_Corner_X", 1.5), ("Lower_Left_Corner_Y", -1.0),
                ("Lower_Left_Corner_Z", -1.0), ("Bottom_Unit_Vector_X", 0.0),
                ("Bottom_Unit_Vector_Y", 1.0), ("Bottom_Unit_Vector_Z", 0.0),
                ("Bottom_Length", 4.0), ("Side_Length", 4.0)])])]),
        ("Materials", [("My Material", [
            ("Material Model", "Elastic Bond Based"), ("Density", 7800.0),
            ("Bulk Modulus", 130.0e9)])]),
        ("Blocks", [("My Blocks", [
            ("Block Names", "block_1"), ("Material", "My Material"), ("Horizon", 1.5)])]),
        ("Boundary Conditions", [
            ("Bottom Node Set", "1 2 3 4"),
            ("Bottom Velocity", [("Type", "Prescribed Displacement"),
                                 ("Node Set", "Bottom Node Set"), ("Coordinate", "z"),
                                 ("Value", "-1.0e-3*t")])]),
        ("Solver", [("Initial Time", 0.0), ("Final Time", 5.0e-4),
                    ("Verlet", [("Safety Factor", 0.5)])]),
        ("Output", output_list("run", 3, ("Displacement", "Force", "Global_Kinetic_Energy"))),
        ("Output2", output_list("hist", 2, ("Global_Kinetic_Energy",))),
    ]


def seed_exodus(mesh="hex.g"):
    return [
        ("Discretization", [("Type", "Exodus"), ("Input Mesh File", mesh)]),
        ("Materials", [("My Material", [
            ("Material Model", "Elastic"), ("Density", 2200.0),
            ("Bulk Modulus", 14.9e9), ("Shear Modulus", 8.94e9)])]),
        ("Blocks", [("My Blocks", [
            ("Block Names", "block_1"), ("Material", "My Material"), ("Horizon", 0.75)])]),
        ("Boundary Conditions", [
            ("Initial Velocity X", [("Type", "Initial Velocity"), ("Node Set", "nodelist_1"),
                                    ("Coordinate", "x"), ("Value", "1.0")])]),
        ("Solver", [("Initial Time", 0.0), ("Final Time", 2.0e-6),
                    ("Verlet", [("Fixed dt", 2.0e-7)])]),
        ("Output", output_list("run", 5, ("Displacement", "Element_Id"))),
    ]


def seed_contact():
    d = seed_text("two.txt")
    d[2] = ("Blocks", [("Block One", [("Block Names", "block_1"), ("Material", "My Material"),
                                      ("Horizon", 1.5)]),
                       ("Block Two", [("Block Names", "block_2"), ("Material", "My Material"),
                                      ("Horizon", 1.5)])])
    d.append(("Contact", [
        ("Search Radius", 2.0), ("Search Frequency", 2),
        ("Models", [("My Contact", [("Contact Model", "Short Range Force"),
                                    ("Contact Radius", 0.9), ("Spring Constant", 1.0e12)])]),
        ("Interactions", [("One With Two", [("First Block", "block_1"),
                                            ("Second Block", "block_2"),
                                            ("Contact Model", "My Contact")])])]))
    return d


SEEDS = [seed_quickgrid, seed_text, seed_exodus, seed_contact]

# The second seed set (--seed-set solvers): the implicit solvers, the correspondence families,
# ductile damage and the planar LPS-T/LSJ-T laws, which came after the first campaign. Each is a
# small PdQuickGrid bar or plate (node sets inline), a few load or time steps.


def quickgrid_bar(nx=6, ny=3, nz=3):
    return ("Discretization", [
        ("Type", "PdQuickGrid"),
        ("TensorProduct3DMeshGenerator", [
            ("X Origin", 0.0), ("Y Origin", 0.0), ("Z Origin", 0.0),
            ("X Length", float(nx)), ("Y Length", float(ny)), ("Z Length", float(nz)),
            ("Number Points X", nx), ("Number Points Y", ny), ("Number Points Z", nz)])])


def end_sets(nx=6, ny=3, nz=3):
    left = " ".join(str(1 + nx * k) for k in range(ny * nz))
    right = " ".join(str(nx + nx * k) for k in range(ny * nz))
    return [("Left Node Set", left), ("Right Node Set", right)]


def stretched_ends(rate="1.0e-3*t*x"):
    bcs = end_sets()
    for side in ("Left", "Right"):
        for c, v in (("x", rate), ("y", "0.0"), ("z", "0.0")):
            bcs.append(("%s %s" % (side, c.upper()), [
                ("Type", "Prescribed Displacement"), ("Node Set", side + " Node Set"),
                ("Coordinate", c), ("Value", v)]))
    return ("Boundary Conditions", bcs)


def lps_bar(solver):
    return [
        quickgrid_bar(),
        ("Materials", [("Steel", [
            ("Material Model", "Elastic"), ("Density", 7800.0),
            ("Young's Modulus", 200.0e9), ("Poisson's Ratio", 0.25)])]),
        ("Damage Models", [("Brittle", [
            ("Damage Model", "Critical Stretch"), ("Critical Stretch", 0.02)])]),
        ("Blocks", [("Bar", [("Block Names", "block_1"), ("Material", "Steel"),
                             ("Damage Model", "Brittle"), ("Horizon", 1.51)])]),
        stretched_ends(),
        solver,
        ("Output", output_list("run", 1, ("Displacement", "Force_Density", "Damage"))),
    ]


def seed_quasistatic():
    return lps_bar(("Solver", [("Initial Time", 0.0), ("Final Time", 1.0), ("QuasiStatic", [
        ("Number of Load Steps", 2), ("Relative Tolerance", 1.0e-8),
        ("Maximum Solver Iterations", 10), ("Belos Relative Tolerance", 1.0e-10),
        ("Adaptive Load-Stepping", [("Maximum load step reductions in one step", 3),
                                    ("Maximum total load step reductions", 6)])])]))


def seed_nox():
    return lps_bar(("Solver", [("Initial Time", 0.0), ("Final Time", 1.0), ("NOXQuasiStatic", [
        ("Nonlinear Solver", "Line Search Based"), ("Number of Load Steps", 2),
        ("Max Solver Iterations", 20), ("Relative Tolerance", 1.0e-8),
        ("Direction", [("Method", "Newton"), ("Newton", [("Linear Solver", [
            ("Jacobian Operator", "Matrix-Free"), ("Preconditioner", "None"),
            ("Tolerance", 1.0e-6)])])]),
        ("Line Search", [("Method", "Polynomial")])])]))


def seed_implicit():
    return lps_bar(("Solver", [("Initial Time", 0.0), ("Final Time", 4.0e-4), ("Implicit", [
        ("Fixed dt", 1.0e-4), ("Beta", 0.25), ("Gamma", 0.5), ("Absolute Tolerance", 1.0e-6),
        ("Maximum Solver Iterations", 10)])]))


def seed_relaxation():
    return lps_bar(("Solver", [("Initial Time", 0.0), ("Final Time", 1.0),
                               ("Adaptive Dynamic Relaxation", [
                                   ("Number of Load Steps", 2), ("Relative Tolerance", 1.0e-6)])]))


def metal_bar(material, damage=None, nx=8, ny=4, nz=4, horizon=2.015):
    blocks = [("Block Names", "block_1"), ("Material", "Metal"), ("Horizon", horizon)]
    deck = [
        quickgrid_bar(nx, ny, nz),
        ("Materials", [("Metal", [("Material Model", material), ("Density", 1.0),
                                  ("Young's Modulus", 1.0), ("Poisson's Ratio", 0.3),
                                  ("Yield Stress", 2.0e-3)] + extra_keys(material))]),
    ]
    if damage:
        deck.append(("Damage Models", [("Ductile", damage)]))
        blocks.append(("Damage Model", "Ductile"))
    left = " ".join(str(1 + nx * k) for k in range(ny * nz))
    right = " ".join(str(nx + nx * k) for k in range(ny * nz))
    deck += [
        ("Blocks", [("Bar", blocks)]),
        ("Boundary Conditions", [
            ("Left Node Set", left), ("Right Node Set", right),
            ("Pull Left", [("Type", "Prescribed Displacement"), ("Node Set", "Left Node Set"),
                           ("Coordinate", "x"), ("Value", "-0.004*t")]),
            ("Pull Right", [("Type", "Prescribed Displacement"), ("Node Set", "Right Node Set"),
                            ("Coordinate", "x"), ("Value", "0.004*t")])]),
        ("Solver", [("Initial Time", 0.0), ("Final Time", 4.0),
                    ("Verlet", [("Safety Factor", 0.5)])]),
        ("Output", output_list("run", 4, ("Displacement", "Damage", "Cauchy_Stress",
                                          "Equivalent_Plastic_Strain"))),
    ]
    return deck


def extra_keys(material):
    if "Hypoelastic" in material:
        return [("Actual Horizon", 2.015), ("Gradient Order Of Accuracy", 2)]
    if "Bond Associated" in material:
        return []
    return [("Hourglass Coefficient", 0.05), ("Hardening Modulus", 0.02)]


def seed_ductile():
    return metal_bar("Isotropic Hardening Correspondence", [
        ("Damage Model", "Johnson Cook"), ("Damage Parameter 1", 0.001),
        ("Damage Parameter 2", 0.004), ("Damage Parameter 3", 1.5),
        ("Threshold Damage", 0.4), ("Critical Damage", 0.7)])


def seed_hypoelastic():
    return metal_bar("Elastic Plastic Hypoelastic Correspondence")


def seed_bond_associated():
    return metal_bar("Elastic Plastic Bond Associated Correspondence")


def seed_planar():
    return [
        ("Discretization", [("Type", "PdQuickGrid"), ("Thickness", 0.001),
                            ("Influence Function", "Conical Over Zeta"),
                            ("TensorProduct2DMeshGenerator", [
                                ("X Origin", 0.0), ("Y Origin", 0.0), ("X Length", 0.012),
                                ("Y Length", 0.008), ("Number Points X", 12),
                                ("Number Points Y", 8)])]),
        ("Materials", [("Glass", [("Material Model", "Linearized LPS"), ("Plane Stress", True),
                                  ("Density", 2440.0), ("Young's Modulus", 72.0e9),
                                  ("Poisson's Ratio", 0.22)])]),
        ("Damage Models", [("Brittle", [("Damage Model", "LSJ-T"), ("Fracture Energy", 3.8)])]),
        ("Blocks", [("Plate", [("Block Names", "block_1"), ("Material", "Glass"),
                               ("Damage Model", "Brittle"), ("Horizon", 0.003015)])]),
        ("Boundary Conditions", [
            ("All Node Set", " ".join(str(k) for k in range(1, 97))),
            ("Pull", [("Type", "Initial Velocity"), ("Node Set", "All Node Set"),
                      ("Coordinate", "y"), ("Value", "50.0*(y - 0.004)/0.004")])]),
        ("Solver", [("Initial Time", 0.0), ("Final Time", 1.0e-6),
                    ("Verlet", [("Safety Factor", 0.7)])]),
        ("Output", output_list("run", 5, ("Displacement", "Damage", "Dilatation"))),
    ]


SOLVER_SEEDS = [seed_quasistatic, seed_nox, seed_implicit, seed_relaxation, seed_ductile,
                seed_hypoelastic, seed_bond_associated, seed_planar]
SEED_SETS = {"classic": SEEDS, "solvers": SOLVER_SEEDS}

# ---------------------------------------------------------------------------------------------
# Serialization (what a user would write).


def scalar_type(v):
    if isinstance(v, bool):
        return "bool"
    if isinstance(v, int):
        return "int"
    if isinstance(v, float):
        return "double"
    return "string"


def scalar_text(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    return str(v)


def xml_escape(s):
    return (s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
            .replace('"', "&quot;"))


def to_xml(tree, indent=1):
    out = []
    pad = "  " * min(indent, 8)  # capped: a 12,000-deep deck stays linear in size
    for k, v in tree:
        if isinstance(v, list):
            out.append('%s<ParameterList name="%s">' % (pad, xml_escape(k)))
            out.extend(to_xml(v, indent + 1))
            out.append("%s</ParameterList>" % pad)
        else:
            out.append('%s<Parameter name="%s" type="%s" value="%s"/>' % (
                pad, xml_escape(k), scalar_type(v), xml_escape(scalar_text(v))))
    return out if indent > 1 else "<ParameterList>\n" + "\n".join(out) + "\n</ParameterList>\n"


def yaml_key(k):
    plain = k and all(c.isalnum() or c in " _-." for c in k) and k[0].isalpha()
    return k if plain else json.dumps(k)


def yaml_scalar(v):
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, float) and (math.isnan(v) or math.isinf(v)):
        return ".nan" if math.isnan(v) else (".inf" if v > 0 else "-.inf")
    return scalar_text(v)


def to_yaml(tree, indent=1):
    out = []
    pad = "  " * indent
    for k, v in tree:
        if isinstance(v, list):
            if v:
                out.append("%s%s:" % (pad, yaml_key(k)))
                out.extend(to_yaml(v, indent + 1))
            else:
                out.append("%s%s: {}" % (pad, yaml_key(k)))
        else:
            out.append("%s%s: %s" % (pad, yaml_key(k), yaml_scalar(v)))
    return out if indent > 1 else "Peridigm:\n" + "\n".join(out) + "\n"


# ---------------------------------------------------------------------------------------------
# Deck mutations.

EXTREMES = [0, -1, 1, 0.0, -0.0, -1.0, 1e300, -1e300, 1e-300, 5e-324, float("nan"),
            float("inf"), float("-inf"), 2 ** 31 - 1, 2 ** 31, 2 ** 32 + 1, 2 ** 63 - 1, 2 ** 63,
            -2 ** 63, 10 ** 30, "", " ", "abc", "1e999", "0x10", "1,5", "-", "nan", "inf",
            "true", "x" * 1000, "1\x002", "/", "..", "\u00e9\u00e8", "$(rm)", "%s%n%s",
            "1 2 3 4 5 6 7 8 9 10 11 12 13", "-1.0*(x+", "sin(x)/0", "block_1", "Default",
            "1e308*10", "t*1e308"]

NAMES = ["Elastic", "elastic", "ELASTIC", "Elastik", "Elastic Bond Based", "PMB",
         "Linear LPS Partial Volume", "Critical Stretch", "critical stretch",
         "Interface Aware", "Time Dependent Critical Stretch", "Verlet", "QuasiStatic",
         "Implicit", "ExodusII", "Exodus", "Text File", "PdQuickGrid", "Gmsh", "VTK"]


def nodes(tree, path=()):
    """Every (parent list, index, path) of the tree."""
    for i, (k, v) in enumerate(tree):
        yield tree, i, path + (k,)
        if isinstance(v, list):
            yield from nodes(v, path + (k,))


def pick(rng, tree, want=None):
    cands = [n for n in nodes(tree)
             if want is None or (want == "scalar") == (not isinstance(n[0][n[1]][1], list))]
    return rng.choice(cands) if cands else None


def nest(v, depth, key="a"):
    for _ in range(depth):
        v = [(key, v)]
    return v


def mutate_tree(rng, tree, fmt="xml"):
    """One structural mutation; returns its name. Block YAML nested d deep holds d^2 blanks of
    indentation, so YAML nests at most 1,000 deep here (deeper YAML comes from "deepflow")."""
    op = rng.choice(["delete", "delete", "duplicate", "retype", "extreme", "extreme", "extreme",
                     "name", "rename", "hugekey", "nest", "unknown", "swap", "emptylist",
                     "scalar2list"])
    n = pick(rng, tree, "scalar" if op in ("retype", "extreme", "name", "swap") else None)
    if n is None:
        return "none"
    parent, i, _ = n
    k, v = parent[i]
    if op == "delete":
        del parent[i]
    elif op == "duplicate":
        parent.insert(i + 1, (k, v if not isinstance(v, list) else json.loads(json.dumps(v))))
    elif op == "retype":
        if isinstance(v, bool):
            parent[i] = (k, rng.choice([2, "maybe", 1.5]))
        elif isinstance(v, (int, float)):
            parent[i] = (k, rng.choice([str(v), "abc", True, [("x", v)], int(v) if
                                        isinstance(v, float) and math.isfinite(v) else 1]))
        else:
            parent[i] = (k, rng.choice([1, 2.5, True, -1, [("x", v)]]))
    elif op == "extreme":
        parent[i] = (k, rng.choice(EXTREMES))
    elif op == "name":
        parent[i] = (k, rng.choice(NAMES))
    elif op == "rename":
        parent[i] = (rng.choice([k.lower(), k.upper(), k + " ", k[:-1], k.replace(" ", "_"),
                                 "", "a\x00b", k + "\u00e9"]), v)
    elif op == "hugekey":
        parent[i] = (rng.choice(["K" * 300, "K" * 70000, "K" * rng.choice([10 ** 5, 10 ** 6])]),
                     v)
    elif op == "nest":
        depths = [2, 10, 70, 300, 3000, 12000] if fmt == "xml" else [2, 10, 70, 300, 1000]
        parent[i] = (k, nest(v, rng.choice(depths)))
    elif op == "unknown":
        parent.insert(i, (rng.choice(["Unknown", "Verbose", "Horizon", "Output Frequency"]),
                          rng.choice(EXTREMES)))
    elif op == "swap":
        m = pick(rng, tree, "scalar")
        p2, j, _ = m
        parent[i], p2[j] = (k, p2[j][1]), (p2[j][0], v)
    elif op == "emptylist":
        parent[i] = (k, [])
    elif op == "scalar2list":
        parent[i] = (k, v if isinstance(v, list) else [(k, v)])
    return op


def mutate_text(rng, text):
    """One byte-level mutation of a serialized deck."""
    op = rng.choice(["truncate", "dropline", "dupline", "flip", "nul", "tab", "junk",
                     "deepflow", "swaplines"])
    lines = text.split("\n")
    if op == "truncate":
        return op, text[:rng.randrange(len(text))]
    if op == "dropline":
        del lines[rng.randrange(len(lines))]
    elif op == "dupline":
        j = rng.randrange(len(lines))
        lines.insert(j, lines[j])
    elif op == "swaplines":
        a, b = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[a], lines[b] = lines[b], lines[a]
    elif op == "flip":
        b = bytearray(text.encode("utf-8", "surrogatepass"))
        for _ in range(rng.choice([1, 2, 8])):
            j = rng.randrange(len(b))
            b[j] ^= 1 << rng.randrange(8)
        return op, b.decode("latin-1")
    elif op == "nul":
        j = rng.randrange(len(text))
        return op, text[:j] + "\x00" + text[j:]
    elif op == "tab":
        j = rng.randrange(len(lines))
        lines[j] = lines[j].replace("  ", "\t", 1)
    elif op == "junk":
        j = rng.randrange(len(text))
        junk = "".join(chr(rng.randrange(1, 256)) for _ in range(rng.choice([1, 16, 200])))
        return op, text[:j] + junk + text[j:]
    elif op == "deepflow":
        j = rng.randrange(len(lines))
        d = rng.choice([50, 500, 6000])
        lines[j] = lines[j] + " " + "[" * d + "1" + "]" * d
    return op, "\n".join(lines)


# ---------------------------------------------------------------------------------------------
# Meshes.


def grid_text(n=4, spacing=1.0, blocks=1):
    rows = ["# x y z block volume"]
    for k in range(n):
        for j in range(n):
            for i in range(n):
                b = 1 if blocks == 1 or i < n // 2 else 2
                rows.append("%r %r %r %d %r" % ((i + 0.5) * spacing, (j + 0.5) * spacing,
                                                (k + 0.5) * spacing, b, spacing ** 3))
    return "\n".join(rows) + "\n"


def two_blocks_text():
    rows = ["# two 2x2x2 cubes, 0.5 apart"]
    for b, x0 in ((1, 0.0), (2, 2.5)):
        for k in range(2):
            for j in range(2):
                for i in range(2):
                    rows.append("%r %r %r %d 1.0" % (x0 + i, float(j), float(k), b))
    return "\n".join(rows) + "\n"


def hex_cdl(n=2):
    """A cube of n^3 HEX8 elements (edge 0.5) with node set 1 on x = 0, as CDL for ncgen."""
    m = n + 1
    xs, ys, zs = [], [], []
    for k in range(m):
        for j in range(m):
            for i in range(m):
                xs.append(i * 0.5)
                ys.append(j * 0.5)
                zs.append(k * 0.5)
    node = lambda i, j, k: 1 + i + m * (j + m * k)
    conn = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                conn.append([node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k),
                             node(i, j + 1, k), node(i, j, k + 1), node(i + 1, j, k + 1),
                             node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)])
    ns = [node(0, j, k) for k in range(m) for j in range(m)]
    f = lambda v: ", ".join(str(x) for x in v)
    return """netcdf hex {
dimensions:
	len_string = 33 ; len_line = 81 ; four = 4 ; time_step = UNLIMITED ; num_dim = 3 ;
	num_nodes = %d ; num_elem = %d ; num_el_blk = 1 ; num_node_sets = 1 ;
	num_nod_ns1 = %d ; num_el_in_blk1 = %d ; num_nod_per_el1 = 8 ;
variables:
	double time_whole(time_step) ; char coor_names(num_dim, len_string) ;
	char eb_names(num_el_blk, len_string) ; char ns_names(num_node_sets, len_string) ;
	int elem_map(num_elem) ; int eb_status(num_el_blk) ;
	int eb_prop1(num_el_blk) ; eb_prop1:name = "ID" ;
	int ns_status(num_node_sets) ; int ns_prop1(num_node_sets) ; ns_prop1:name = "ID" ;
	int node_ns1(num_nod_ns1) ;
	int connect1(num_el_in_blk1, num_nod_per_el1) ; connect1:elem_type = "HEX8" ;
	double coordx(num_nodes) ; double coordy(num_nodes) ; double coordz(num_nodes) ;
	:api_version = 8.03f ; :version = 8.03f ; :floating_point_word_size = 8 ; :file_size = 1 ;
	:title = "fuzz seed" ;
data:
 coor_names = "x", "y", "z" ; eb_names = "" ; ns_names = "" ;
 elem_map = %s ; eb_status = 1 ; eb_prop1 = 1 ; ns_status = 1 ; ns_prop1 = 1 ;
 node_ns1 = %s ;
 connect1 = %s ;
 coordx = %s ; coordy = %s ; coordz = %s ;
}
""" % (m ** 3, n ** 3, len(ns), n ** 3, f(range(1, n ** 3 + 1)), f(ns),
       ", ".join(f(c) for c in conn), f(xs), f(ys), f(zs))


def mutate_text_mesh(rng, text):
    lines = text.rstrip("\n").split("\n")
    op = rng.choice(["farpoint", "farpoint", "nanpoint", "dropcol", "addcol", "negvol",
                     "zerovol", "hugevol", "dupline", "truncate", "flip", "empty", "junk",
                     "scale", "coincident", "bigid", "negblock", "onepoint", "longline"])
    body = [l for l in lines if l and not l.startswith("#")]
    if op == "farpoint":
        x = rng.choice([1e4, 1e10, 3e16, 1e19, 1e300, -1e300, 1.7e308])
        body.append("%r 0.5 0.5 1 1.0" % x)
    elif op == "nanpoint":
        body.append(rng.choice(["nan 0 0 1 1.0", "inf 0 0 1 1.0", "0 0 0 1 nan"]))
    elif op == "dropcol":
        j = rng.randrange(len(body))
        body[j] = " ".join(body[j].split()[:-1])
    elif op == "addcol":
        j = rng.randrange(len(body))
        body[j] += " 7"
    elif op in ("negvol", "zerovol", "hugevol"):
        j = rng.randrange(len(body))
        p = body[j].split()
        p[4] = {"negvol": "-1.0", "zerovol": "0", "hugevol": "1e308"}[op]
        body[j] = " ".join(p)
    elif op == "dupline":
        body += body[:rng.choice([1, len(body)])]
    elif op == "truncate":
        t = "\n".join(body)
        return op, t[:rng.randrange(len(t))]
    elif op == "flip":
        b = bytearray("\n".join(body).encode())
        for _ in range(rng.choice([1, 4, 32])):
            b[rng.randrange(len(b))] ^= 1 << rng.randrange(8)
        return op, b.decode("latin-1")
    elif op == "empty":
        return op, rng.choice(["", "\n", "# only a comment\n"])
    elif op == "junk":
        return op, "".join(chr(rng.randrange(0, 256)) for _ in range(rng.choice([10, 1000])))
    elif op == "scale":
        s = rng.choice([1e-300, 1e-12, 1e10, 1e200])
        body = ["%r %r %r %s %r" % (float(p[0]) * s, float(p[1]) * s, float(p[2]) * s, p[3],
                                     float(p[4]) * min(s, 1e100) ** 3)
                for p in (l.split() for l in body)]
    elif op == "coincident":
        body.append(body[0])
    elif op == "bigid":
        j = rng.randrange(len(body))
        p = body[j].split()
        p[3] = rng.choice(["2147483648", "99999999999999999999", "0", "-1", "1.5"])
        body[j] = " ".join(p)
    elif op == "negblock":
        body = [" ".join(l.split()[:3] + ["-3"] + l.split()[4:]) for l in body]
    elif op == "onepoint":
        body = body[:1]
    elif op == "longline":
        body.append("1 " * 100000)
    return op, "\n".join(body) + "\n"


def mutate_binary(rng, data):
    op = rng.choice(["truncate", "truncate", "flip", "flip", "flipheader", "zero", "append",
                     "scalecoords"])
    b = bytearray(data)
    if op == "truncate":
        return op, bytes(b[:rng.randrange(len(b))])
    if op == "flip":
        for _ in range(rng.choice([1, 4, 64])):
            b[rng.randrange(len(b))] ^= 1 << rng.randrange(8)
    elif op == "flipheader":
        for _ in range(rng.choice([1, 2, 8])):
            b[rng.randrange(min(len(b), 2048))] ^= 1 << rng.randrange(8)
    elif op == "zero":
        j = rng.randrange(len(b))
        n = rng.choice([4, 64, 1024])
        b[j:j + n] = bytes(len(b[j:j + n]))
    elif op == "append":
        b += bytes(rng.randrange(256) for _ in range(rng.choice([1, 100, 10000])))
    elif op == "scalecoords":
        # Overwrite 8-byte words near the end (the coordinates) with huge doubles.
        import struct
        for _ in range(rng.choice([1, 8])):
            j = len(b) - 8 * rng.randrange(1, max(2, len(b) // 64))
            if j > 0:
                b[j:j + 8] = struct.pack(">d", rng.choice([1e10, 1e300, float("nan")]))
    return op, bytes(b)


# ---------------------------------------------------------------------------------------------
# Running and judging.

STACK_MARKERS = ["Process received signal", "*** Error", "Segmentation fault", "terminate called",
                 "stack smashing", "buffer overflow detected", "free(): ", "malloc(): ",
                 "double free", "Aborted", "core dumped", "internal error", "[ 0]", "backtrace",
                 "AddressSanitizer", "std::bad_alloc", "what():"]


def judge(rc, out, err):
    if rc is None:
        # A run that still reports steps at the timeout is slow, not stuck (a deleted Final
        # Time means Peridigm's default of 1 s: millions of steps).
        if "  step " in out and "remaining ~" in out:
            return "slow", "still stepping at the timeout"
        return "HANG", "timeout"
    for m in STACK_MARKERS:
        if m in err:
            return "CRASH", "stderr has %r" % m
    if rc == 0:
        return "ok", ""
    if rc < 0 or rc > 128:
        return "CRASH", "killed by signal %d" % (-rc if rc < 0 else rc - 128)
    if rc == 4:
        return "CRASH", "exit 4 (internal error)"
    errors = [l for l in err.splitlines() if l.startswith("peridot: error: ")]
    if rc in (1, 2, 3, 5):
        if not errors:
            return "CRASH", "exit %d without a \"peridot: error: \" line" % rc
        if max(len(l) for l in errors) > 4000:
            return "CRASH", "error line of %d characters" % max(len(l) for l in errors)
        return "error", errors[0][16:]
    return "CRASH", "exit status %d" % rc


def ranks_of(session, name):
    pids = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/comm" % entry) as f:
                comm = f.read().strip()
            if comm == name[:15] and os.getsid(int(entry)) == session:
                pids.append(int(entry))
        except (OSError, ProcessLookupError):
            pass
    return pids


# Open MPI failing to start (before peridot runs any code): two singletons started in the same
# instant can race for one session directory. Such a run is repeated, not judged.
MPI_START_FAILURES = ["orte_init failed", "ORTE_ERROR_LOG", "orte_ess_init failed"]


def run_case(args, case):
    for attempt in range(3):
        r = run_case_once(args, case, attempt)
        if r["verdict"] != "retry":
            return r
        time.sleep(0.5)
    return r


def run_case_once(args, case, attempt):
    """case: dict(id, files={name: bytes|None(fifo)|'DIR'}, deck, np, signal)."""
    d = os.path.join(args.work, "runs", case["id"])
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    for name, data in case["files"].items():
        p = os.path.join(d, name)
        if data is None:
            os.mkfifo(p)
        elif data == "DIR":
            os.makedirs(p)
        elif isinstance(data, tuple) and data[0] == "LINK":
            os.symlink(data[1], p)
        else:
            with open(p, "wb") as f:
                f.write(data)
    env = dict(os.environ)
    os.makedirs(os.path.join(d, ".ompi"), exist_ok=True)
    env.update(OMPI_MCA_orte_tmpdir_base=os.path.join(d, ".ompi"))  # a session dir per run
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_ess_singleton_isolated="1", OMPI_MCA_btl="self,vader",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    cmd = [args.peridot, case["deck"]]
    if case["np"] > 1:
        cmd = [args.mpirun, "--oversubscribe", "-np", str(case["np"])] + cmd
    t0 = time.time()
    p = subprocess.Popen(cmd, cwd=d, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                         start_new_session=True)
    rc = None
    try:
        if case.get("signal"):
            try:
                out, err = p.communicate(timeout=case["signal_after"])
                rc = p.returncode
            except subprocess.TimeoutExpired:
                if case["np"] == 1:
                    os.kill(p.pid, case["signal"])
                else:
                    # To the ranks, as a batch system does (doc/restart.md: mpirun answers
                    # SIGTERM by killing the job).
                    for rank in ranks_of(p.pid, os.path.basename(args.peridot)):
                        os.kill(rank, case["signal"])
                out, err = p.communicate(timeout=args.timeout)
                rc = p.returncode
        else:
            out, err = p.communicate(timeout=args.timeout)
            rc = p.returncode
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, err = p.communicate()
        rc = None
    out = out.decode("utf-8", "replace")
    err = err.decode("utf-8", "replace")
    verdict, why = judge(rc, out, err)
    if verdict == "CRASH" and any(m in err for m in MPI_START_FAILURES) and attempt < 2:
        shutil.rmtree(d, ignore_errors=True)
        return dict(verdict="retry")
    if verdict in ("CRASH", "HANG"):
        keep = os.path.join(args.work, "findings", case["id"])
        shutil.rmtree(keep, ignore_errors=True)
        shutil.copytree(d, keep, symlinks=True,
                        ignore=lambda s, names: [n for n in names
                                                 if not os.path.isfile(os.path.join(s, n))])
        with open(os.path.join(keep, "report.txt"), "w") as f:
            f.write("cmd: %s\nrc: %s\nverdict: %s (%s)\nmutation: %s\n--- stderr ---\n%s\n"
                    "--- stdout ---\n%s\n" % (" ".join(cmd), rc, verdict, why,
                                              case.get("what"), err[:20000], out[:20000]))
    shutil.rmtree(d, ignore_errors=True)
    return dict(id=case["id"], kind=case["kind"], np=case["np"], what=case.get("what"),
                verdict=verdict, why=why[:300], seconds=round(time.time() - t0, 2))


def base_files(args):
    files = {"cube.txt": grid_text(2).encode(), "two.txt": two_blocks_text().encode(),
             "grid.txt": grid_text(4).encode()}
    hexg = os.path.join(args.work, "hex.g")
    if not os.path.exists(hexg):
        cdl = os.path.join(args.work, "hex.cdl")
        with open(cdl, "w") as f:
            f.write(hex_cdl(2))
        subprocess.run(["ncgen", "-o", hexg, cdl], check=True)
    with open(hexg, "rb") as f:
        files["hex.g"] = f.read()
    return files


def deck_case(args, k, np, base):
    rng = random.Random("deck-%d-%d" % (args.seed, k))
    tree = rng.choice(SEED_SETS[args.seed_set])()
    fmt = rng.choice(["xml", "yaml"])
    whats = [mutate_tree(rng, tree, fmt) for _ in range(rng.choice([1, 1, 2, 3]))]
    text = to_xml(tree) if fmt == "xml" else to_yaml(tree)
    if rng.random() < 0.3:
        op, text = mutate_text(rng, text)
        whats.append("text:" + op)
    files = dict(base)
    files["deck." + fmt] = text.encode("utf-8", "surrogatepass")
    return dict(id="d%05d-np%d" % (k, np), kind="deck", np=np, deck="deck." + fmt,
                files=files, what=fmt + ":" + ",".join(whats))


def mesh_case(args, k, np, base):
    rng = random.Random("mesh-%d-%d" % (args.seed, k))
    files = dict(base)
    kind = rng.choice(["text", "text", "exodus", "exodus", "special"])
    if kind == "text":
        op, text = mutate_text_mesh(rng, base["grid.txt"].decode())
        files["grid.txt"] = text.encode("latin-1", "replace")
        tree, what = seed_text("grid.txt"), "text:" + op
    elif kind == "exodus":
        op, data = mutate_binary(rng, base["hex.g"])
        files["hex.g"] = data
        tree, what = seed_exodus("hex.g"), "exodus:" + op
    else:
        op = rng.choice(["fifo", "dir", "dangling", "loop", "devnull", "deckfifo", "nodeset"])
        tree = rng.choice([seed_text("m.txt"), seed_exodus("m.g")])
        name = tree[0][1][1][1]
        if op == "fifo":
            files[name] = None
        elif op == "dir":
            files[name] = "DIR"
        elif op == "dangling":
            files[name] = ("LINK", "nowhere")
        elif op == "loop":
            files[name] = ("LINK", name)
        elif op == "devnull":
            files[name] = ("LINK", "/dev/null")
        elif op == "nodeset":
            tree = seed_text("grid.txt")
            tree[3][1][0] = ("Bottom Node Set", "ns.txt")
            files["ns.txt"] = rng.choice([None, "DIR", b"1 2 x", b"\x00\x01", b"99999999999"])
        elif op == "deckfifo":
            files["deck.xml"] = None
        what = "special:" + op
    fmt = rng.choice(["xml", "yaml"])
    deck = "deck." + fmt
    if deck not in files:
        files[deck] = (to_xml(tree) if fmt == "xml" else to_yaml(tree)).encode()
    return dict(id="m%05d-np%d" % (k, np), kind="mesh", np=np, deck=deck, files=files,
                what=what)


def signal_case(args, k, base):
    rng = random.Random("signal-%d-%d" % (args.seed, k))
    tree = seed_text("grid.txt")
    tree[4] = ("Solver", [("Initial Time", 0.0), ("Final Time", 1.0),
                          ("Verlet", [("Fixed dt", 1.0e-7)])])
    if rng.random() < 0.5:
        tree.append(("Restart", [("Checkpoint Frequency", 1000)]))
    files = dict(base)
    files["deck.yaml"] = to_yaml(tree).encode()
    sig = rng.choice([signal.SIGINT, signal.SIGTERM, signal.SIGUSR1, signal.SIGHUP])
    np = rng.choice([1, 2])
    return dict(id="s%05d-np%d" % (k, np), kind="signal", np=np, deck="deck.yaml", files=files,
                signal=sig, signal_after=rng.uniform(0.5, 3.0),
                what="signal %s" % signal.Signals(sig).name)


def main():
    sys.setrecursionlimit(100000)  # deeply nested decks are serialized recursively
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--peridot", required=True)
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--decks", type=int, default=100, help="mutated decks at 1 rank")
    ap.add_argument("--decks-np2", type=int, default=0, help="mutated decks at 2 ranks")
    ap.add_argument("--meshes", type=int, default=0, help="corrupt meshes at 1 rank")
    ap.add_argument("--meshes-np2", type=int, default=0, help="corrupt meshes at 2 ranks")
    ap.add_argument("--signals", type=int, default=0, help="runs stopped by a signal")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--seed-set", choices=sorted(SEED_SETS), default="classic",
                    help="the decks that mutated decks start from (a case id names the same "
                         "input only with the same --seed-set)")
    ap.add_argument("--work", default="/tmp/peridot-fuzz")
    ap.add_argument("--only", default="", help="comma-separated case ids to run again")
    args = ap.parse_args()
    args.peridot = os.path.abspath(args.peridot)
    os.makedirs(args.work, exist_ok=True)
    base = base_files(args)
    # The seeds themselves must run: a mutation is then the only difference.
    for seed in SEED_SETS[args.seed_set]:
        for fmt in ("xml", "yaml"):
            files = dict(base)
            files["deck." + fmt] = (to_xml(seed()) if fmt == "xml" else to_yaml(seed())).encode()
            r = run_case(args, dict(id="seed-%s-%s" % (seed.__name__, fmt), kind="seed", np=1,
                                    deck="deck." + fmt, files=files, what="seed"))
            if r["verdict"] != "ok":
                print("seed %s (%s) does not run: %s" % (seed.__name__, fmt, r["why"]))
                return 2
    # Each case is made by the worker that runs it (some decks are 100 MB).
    cases = [lambda k=k: deck_case(args, k, 1, base) for k in range(args.decks)]
    cases += [lambda k=k: deck_case(args, 100000 + k, 2, base) for k in range(args.decks_np2)]
    cases += [lambda k=k: mesh_case(args, k, 1, base) for k in range(args.meshes)]
    cases += [lambda k=k: mesh_case(args, 100000 + k, 2, base) for k in range(args.meshes_np2)]
    cases += [lambda k=k: signal_case(args, k, base) for k in range(args.signals)]
    if args.only:
        # Case ids: d|m|s, number, -np1|-np2 (e.g. d00755-np1); the same input as in the run.
        wanted = args.only.split(",")
        makers = {"d": deck_case, "m": mesh_case}
        cases = []
        for cid in wanted:
            k, np = int(cid[1:].split("-")[0]), int(cid.split("np")[1])
            if cid[0] == "s":
                cases.append(lambda k=k: signal_case(args, k, base))
            else:
                cases.append(lambda k=k, np=np, f=makers[cid[0]]: f(args, k, np, base))
    results = []
    log = open(os.path.join(args.work, "results-only.jsonl" if args.only else "results.jsonl"),
               "w")
    t0 = time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for r in pool.map(lambda make: run_case(args, make()), cases):
            results.append(r)
            log.write(json.dumps(r) + "\n")
            log.flush()
            if r["verdict"] in ("CRASH", "HANG"):
                print("%s %s (%s): %s" % (r["verdict"], r["id"], r["what"], r["why"]),
                      flush=True)
            if len(results) % 250 == 0:
                print("... %d/%d cases, %.0f s" % (len(results), len(cases), time.time() - t0),
                      flush=True)
    table = {}
    for r in results:
        key = (r["kind"], r["np"])
        table.setdefault(key, {"ok": 0, "error": 0, "slow": 0, "CRASH": 0, "HANG": 0})
        table[key][r["verdict"]] += 1
    print("\nkind    ranks   cases      ok   error    slow   CRASH    HANG")
    for (kind, np), c in sorted(table.items()):
        print("%-7s %5d %7d %7d %7d %7d %7d %7d" % (kind, np, sum(c.values()), c["ok"],
                                                    c["error"], c["slow"], c["CRASH"], c["HANG"]))
    print("total %d cases in %.0f s; findings in %s" % (len(results), time.time() - t0,
                                                       os.path.join(args.work, "findings")))
    bad = sum(c["CRASH"] + c["HANG"] for c in table.values())
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
