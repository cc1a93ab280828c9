#!/usr/bin/python3
"""Run a directory of Peridigm's test decks through Peridot and print a survey table.

Usage: peridigm_deck_survey.py [--peridot BUILD/peridot] [--timeout 60] [--markdown]
                               [--no-run] [--work DIR] DECKDIR

DECKDIR holds one folder per case with Peridigm's deck(s) (.xml, .yaml) and whatever meshes
could be fetched (.txt text meshes, .g Exodus meshes). The tool cannot fetch anything itself.
For every deck:
  1. the deck is copied with its folder into a scratch work directory (DECKDIR is not touched);
  2. an Exodus mesh the deck names but that is missing is replaced by a *substitute*: a small hex
     bar with one element block per block name and one node set per node set name the deck
     refers to, spaced so that the deck's horizon holds a few neighbours. It only lets the
     deck's vocabulary be exercised; results on it mean nothing;
  3. `peridot --check DECK` runs; if it passes, a real run follows, capped at --timeout seconds;
  4. the deck is classified: runs / check only (passes --check, but its run on a substitute mesh
     stops with a clear error: the substitute's node sets are guesses) / refused (a clear
     message naming what is missing) / bad (crash, hang, a run that fails on the deck's own
     mesh, or a warning that a key was ignored).
The first line printed is the count: "N of M run; K refused naming the feature; B bad".
Standard library and numpy + netCDF4 (Debian's python3-netcdf4) only.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

# ---------------------------------------------------------------- deck reading


def read_deck(path):
    """The deck as nested dicts {name: value or dict}; values stay strings."""
    if path.endswith('.xml'):
        def walk(el):
            d = {}
            for c in el:
                if c.tag == 'ParameterList':
                    d[c.get('name')] = walk(c)
                elif c.tag == 'Parameter':
                    d[c.get('name')] = c.get('value')
            return d
        return walk(ET.parse(path).getroot())
    # Peridigm's YAML decks: a small indentation reader is enough (no flow style in them).
    root = {}
    stack = [(-1, root)]
    for raw in open(path, encoding='utf-8', errors='replace'):
        line = raw.split(' #')[0].rstrip() if not raw.lstrip().startswith('#') else ''
        if not line.strip() or ':' not in line:
            continue
        ind = len(line) - len(line.lstrip())
        key, _, val = line.strip().partition(':')
        key = key.strip().strip('"\'')
        val = val.strip().strip('"\'')
        while stack[-1][0] >= ind:
            stack.pop()
        if val == '':
            d = {}
            stack[-1][1][key] = d
            stack.append((ind, d))
        else:
            stack[-1][1][key] = val
    if len(root) == 1 and isinstance(next(iter(root.values())), dict) and 'Peridigm' in root:
        root = root['Peridigm']
    return root


def flat(d, prefix=''):
    for k, v in d.items():
        if isinstance(v, dict):
            yield from flat(v, prefix + k + '/')
        else:
            yield prefix + k, v


def summary(deck):
    """Solver, material models, damage models and notable features the deck uses."""
    solver = [k for k, v in deck.get('Solver', {}).items() if isinstance(v, dict)]
    mats = sorted({v.get('Material Model', '?') for v in deck.get('Materials', {}).values()
                   if isinstance(v, dict)})
    dmg = sorted({v.get('Damage Model', '?') for v in deck.get('Damage Models', {}).values()
                  if isinstance(v, dict)})
    feats = []
    disc = deck.get('Discretization', {})
    feats.append(disc.get('Type', '?'))
    for k in ('Contact', 'Compute Class Parameters', 'Block Data', 'Multiphysics'):
        if k in deck:
            feats.append(k)
    bcs = deck.get('Boundary Conditions', {})
    types = sorted({v.get('Type') for v in bcs.values() if isinstance(v, dict) and v.get('Type')})
    feats += types
    if any(not isinstance(v, dict) for v in bcs.values()):
        feats.append('node sets in the deck')
    return ', '.join(solver) or '-', ', '.join(mats) or '-', ', '.join(dmg) or '-', feats


# ---------------------------------------------------------------- substitute meshes


def mesh_names(deck):
    """Block names and node set names the deck refers to."""
    blocks = []
    for g in deck.get('Blocks', {}).values():
        if isinstance(g, dict):
            blocks += g.get('Block Names', '').split()
    if 'default' in blocks:  # 'default' takes every block no other group names: add one such
        blocks.remove('default')
        n = 1
        while 'block_%d' % n in blocks:
            n += 1
        blocks.append('block_%d' % n)
    sets = []
    bcs = deck.get('Boundary Conditions', {})
    for k, v in bcs.items():
        if isinstance(v, dict):
            ns = v.get('Node Set')
            if ns and ns not in sets and ns not in bcs and not re.fullmatch(r'[\d\s,]+', ns):
                sets.append(ns)
    for v in flat(deck):
        if v[0].endswith('Node Set') and '/' in v[0] and v[0].split('/')[0] != 'Boundary Conditions':
            if v[1] not in sets and not re.fullmatch(r'[\d\s,]+', v[1]):
                sets.append(v[1])
    return blocks, sets


def write_substitute_text(path, blocks, spacing):
    """A 'x y z block_id volume' point cloud: a 4 x 3 x 3 lattice per block along x."""
    ids = []
    for b in blocks or ['block_1']:
        m = re.fullmatch(r'block_(\d+)', b)
        ids.append(int(m.group(1)) if m else len(ids) + 1)
    with open(path, 'w') as f:
        for n, bid in enumerate(ids):
            for k in range(3):
                for j in range(3):
                    for i in range(4):
                        f.write('%.6g %.6g %.6g %d %.6g\n' % ((4 * n + i) * spacing, j * spacing,
                                                              k * spacing, bid, spacing ** 3))


def write_substitute_shell(path, spacing):
    """One SHELL4 facet, the plane x = 2 spacings across the substitute bar (an `Exodus Mesh`
    bond filter cuts the bonds that cross it)."""
    import numpy as np
    from netCDF4 import Dataset
    ds = Dataset(path, 'w', format='NETCDF3_64BIT_OFFSET')
    ds.api_version = np.float32(8.0)
    ds.version = np.float32(8.0)
    ds.floating_point_word_size = np.int32(8)
    ds.file_size = np.int32(1)
    ds.title = 'substitute shell mesh (peridigm_deck_survey.py)'
    for name, size in (('len_string', 33), ('len_name', 33), ('len_line', 81), ('four', 4),
                       ('num_dim', 3), ('num_nodes', 4), ('num_elem', 1), ('num_el_blk', 1),
                       ('num_el_in_blk1', 1), ('num_nod_per_el1', 4)):
        ds.createDimension(name, size)
    ds.createDimension('time_step', None)
    ds.createVariable('time_whole', 'f8', ('time_step',))
    v = ds.createVariable('eb_status', 'i4', ('num_el_blk',))
    v[:] = 1
    v = ds.createVariable('eb_prop1', 'i4', ('num_el_blk',))
    v.setncattr('name', 'ID')
    v[:] = 1
    x = 2.0 * spacing
    lo, hi = -spacing, 4.0 * spacing
    coords = {'x': [x, x, x, x], 'y': [lo, hi, hi, lo], 'z': [lo, lo, hi, hi]}
    for c in 'xyz':
        v = ds.createVariable('coord' + c, 'f8', ('num_nodes',))
        v[:] = coords[c]
    v = ds.createVariable('connect1', 'i4', ('num_el_in_blk1', 'num_nod_per_el1'))
    v.elem_type = 'SHELL4'
    v[:] = np.array([[1, 2, 3, 4]])
    ds.close()


def write_substitute_exodus(path, blocks, sets, spacing):
    import numpy as np
    from netCDF4 import Dataset
    nb = max(1, len(blocks))
    nx, ny, nz = 4 * nb, 3, 3
    xs = np.arange(nx + 1) * spacing
    ys = np.arange(ny + 1) * spacing
    zs = np.arange(nz + 1) * spacing
    Z, Y, X = np.meshgrid(zs, ys, xs, indexing='ij')
    nid = lambda i, j, k: k * (ny + 1) * (nx + 1) + j * (nx + 1) + i + 1
    conn = [[] for _ in range(nb)]
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                b = min(i // 4, nb - 1)
                conn[b].append([nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                                nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                                nid(i, j + 1, k + 1)])
    # node sets: alternate the x-min and x-max faces, then the y and z faces, so that every set
    # has nodes and opposite BCs act on opposite ends
    faces = []
    for axis, n in ((0, nx), (1, ny), (2, nz)):
        for side in (0, n):
            ids = []
            for k in range(nz + 1):
                for j in range(ny + 1):
                    for i in range(nx + 1):
                        if (i, j, k)[axis] == side:
                            ids.append(nid(i, j, k))
            faces.append(ids)
    ds = Dataset(path, 'w', format='NETCDF3_64BIT_OFFSET')
    ds.api_version = np.float32(8.0)
    ds.version = np.float32(8.0)
    ds.floating_point_word_size = np.int32(8)
    ds.file_size = np.int32(1)
    ds.maximum_name_length = np.int32(32)
    ds.int64_status = np.int32(0)
    ds.title = 'substitute mesh (peridigm_deck_survey.py)'
    ds.createDimension('len_string', 33)
    ds.createDimension('len_name', 33)
    ds.createDimension('len_line', 81)
    ds.createDimension('four', 4)
    ds.createDimension('time_step', None)
    ds.createDimension('num_dim', 3)
    ds.createDimension('num_nodes', X.size)
    ds.createDimension('num_elem', sum(len(c) for c in conn))
    ds.createDimension('num_el_blk', nb)
    ds.createVariable('time_whole', 'f8', ('time_step',))
    names = lambda n: np.array([list(s.ljust(33, '\0')[:33]) for s in n], dtype='S1')
    bnames = blocks if blocks else ['block_1']
    ids = []
    for b in bnames:
        m = re.fullmatch(r'block_(\d+)', b)
        ids.append(int(m.group(1)) if m else len(ids) + 1)
    v = ds.createVariable('eb_status', 'i4', ('num_el_blk',))
    v[:] = 1
    v = ds.createVariable('eb_prop1', 'i4', ('num_el_blk',))
    v.setncattr('name', 'ID')
    v[:] = ids
    v = ds.createVariable('eb_names', 'S1', ('num_el_blk', 'len_name'))
    v[:] = names([b if not re.fullmatch(r'block_\d+', b) else '' for b in bnames])
    for c in ('x', 'y', 'z'):
        v = ds.createVariable('coord' + c, 'f8', ('num_nodes',))
        v[:] = {'x': X, 'y': Y, 'z': Z}[c].ravel()
    v = ds.createVariable('coor_names', 'S1', ('num_dim', 'len_name'))
    v[:] = names(['x', 'y', 'z'])
    for b, c in enumerate(conn, 1):
        ds.createDimension('num_el_in_blk%d' % b, len(c))
        ds.createDimension('num_nod_per_el%d' % b, 8)
        v = ds.createVariable('connect%d' % b, 'i4', ('num_el_in_blk%d' % b, 'num_nod_per_el%d' % b))
        v.elem_type = 'HEX8'
        v[:] = np.array(c)
    if sets:
        ds.createDimension('num_node_sets', len(sets))
        sids = []
        for s in sets:
            m = re.fullmatch(r'nodelist_(\d+)', s)
            sids.append(int(m.group(1)) if m else 100 + len(sids))
        v = ds.createVariable('ns_status', 'i4', ('num_node_sets',))
        v[:] = 1
        v = ds.createVariable('ns_prop1', 'i4', ('num_node_sets',))
        v.setncattr('name', 'ID')
        v[:] = sids
        v = ds.createVariable('ns_names', 'S1', ('num_node_sets', 'len_name'))
        v[:] = names([s if not re.fullmatch(r'nodelist_\d+', s) else '' for s in sets])
        for n, s in enumerate(sets, 1):
            face = faces[(n - 1) % len(faces)]
            ds.createDimension('num_nod_ns%d' % n, len(face))
            v = ds.createVariable('node_ns%d' % n, 'i4', ('num_nod_ns%d' % n,))
            v[:] = face
    ds.close()


def find_horizon(deck):
    h = deck.get('Discretization', {}).get('Horizon')
    if h is None:
        for k, v in flat(deck.get('Blocks', {})):
            if k.endswith('Horizon'):
                h = v
                break
    try:
        return float(h)
    except (TypeError, ValueError):
        return 1.0


def prepare(deck_path, work):
    """Copy the case folder to work/ and add substitute meshes. Returns (deck copy, note)."""
    case_dir = os.path.dirname(deck_path)
    dest = os.path.join(work, os.path.relpath(case_dir, ARGS.decks))
    if os.path.exists(dest):
        shutil.rmtree(dest)
    shutil.copytree(case_dir, dest, ignore=shutil.ignore_patterns('*.e', '*.e.*', '*.out'))
    deck_copy = os.path.join(dest, os.path.basename(deck_path))
    deck = read_deck(deck_copy)
    note = ''
    disc = deck.get('Discretization', {})
    mesh = disc.get('Input Mesh File')
    if disc.get('Type') == 'Exodus' and mesh:
        target = os.path.join(dest, mesh)
        if not os.path.exists(os.path.join(case_dir, mesh)):
            blocks, sets = mesh_names(deck)
            os.makedirs(os.path.dirname(target) or '.', exist_ok=True)
            write_substitute_exodus(target, blocks, sets, find_horizon(deck) / 3.015)
            note = 'substitute mesh'
    if disc.get('Type') == 'Text File' and mesh:
        target = os.path.join(dest, mesh)
        if not os.path.exists(os.path.join(case_dir, mesh)):
            blocks, _ = mesh_names(deck)
            os.makedirs(os.path.dirname(target) or '.', exist_ok=True)
            write_substitute_text(target, blocks, find_horizon(deck) / 3.015)
            note = 'substitute mesh'
    # `Exodus Mesh` bond filters (Discretization or Initial Damage): a one-facet substitute
    for k, v in flat(deck):
        if k.endswith('/File Name') and 'Bond Filters/' in k:
            target = os.path.join(dest, v)
            if not os.path.exists(os.path.join(case_dir, v)):
                write_substitute_shell(target, find_horizon(deck) / 3.015)
                note = 'substitute mesh'
    # node sets read from files ('Node Set Top: ../nodelist_2.csv'): a two-point substitute
    for k, v in deck.get('Boundary Conditions', {}).items():
        if isinstance(v, str) and re.search(r'\.(csv|txt|dat)$', v.strip()):
            target = os.path.join(dest, v.strip())
            if not os.path.exists(os.path.join(case_dir, v.strip())):
                os.makedirs(os.path.dirname(target) or '.', exist_ok=True)
                with open(target, 'w') as f:
                    f.write('1\n2\n')
                note = 'substitute mesh'
    return deck_copy, deck, note


BAD_SIGNS = re.compile(r'ignor|unknown key|unused', re.I)


def first_message(text):
    for line in text.splitlines():
        if 'error' in line:
            return line.strip()
    for line in text.splitlines():
        s = line.strip()
        if s and ('rror' in s or 'not ' in s or 'refus' in s.lower() or 'unknown' in s.lower()):
            return s
    lines = [l.strip() for l in text.splitlines() if l.strip()]
    return lines[-1] if lines else ''


def run_one(deck_path):
    deck_copy, deck, note = prepare(deck_path, ARGS.work)
    cwd = os.path.dirname(deck_copy)
    name = os.path.basename(deck_copy)
    try:
        chk = subprocess.run([ARGS.peridot, '--check', name], cwd=cwd, capture_output=True,
                             text=True, timeout=ARGS.timeout)
    except subprocess.TimeoutExpired:
        return deck, note, 'bad', 'hang: --check did not finish in %d s' % ARGS.timeout
    out = chk.stdout + chk.stderr
    if chk.returncode < 0 or chk.returncode > 128:
        return deck, note, 'bad', 'crash (exit %d): %s' % (chk.returncode, first_message(out))
    if chk.returncode != 0:
        return deck, note, 'refused', first_message(out)
    warn = [l.strip() for l in out.splitlines() if BAD_SIGNS.search(l)]
    if warn:
        return deck, note, 'bad', 'check passes but: ' + warn[0]
    if ARGS.no_run:
        return deck, note, 'runs', '--check only'
    try:
        run = subprocess.run([ARGS.peridot, name], cwd=cwd, capture_output=True, text=True,
                             timeout=ARGS.timeout)
    except subprocess.TimeoutExpired:
        return deck, note, 'runs', 'check passes; run longer than %d s (stopped)' % ARGS.timeout
    rout = run.stdout + run.stderr
    if run.returncode == 0:
        return deck, note, 'runs', ''
    if run.returncode < 0 or run.returncode > 128:
        return deck, note, 'bad', 'run crashed (exit %d): %s' % (run.returncode, first_message(rout))
    if note and 0 < run.returncode < 128 and 'peridot: error' in rout:
        # A clean stop on a substitute mesh (its node sets are guesses, so a load can invert or
        # not converge): the deck's vocabulary passed; the run says nothing about Peridot.
        return deck, note, 'check only', 'run on the substitute mesh stops: ' + first_message(rout)
    return deck, note, 'bad', 'check passes but run fails: ' + first_message(rout)


def main():
    global ARGS
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('decks')
    p.add_argument('--peridot', default=os.path.join(os.path.dirname(__file__), '..', 'build',
                                                     'peridot'))
    p.add_argument('--timeout', type=float, default=60)
    p.add_argument('--work', default='/tmp/peridigm_deck_survey')
    p.add_argument('--no-run', action='store_true')
    p.add_argument('--markdown', action='store_true', help='print a markdown table')
    ARGS = p.parse_args()
    ARGS.peridot = os.path.abspath(ARGS.peridot)
    ARGS.decks = os.path.abspath(ARGS.decks)
    decks = []
    for root, _, files in os.walk(ARGS.decks):
        for f in files:
            if f.endswith(('.xml', '.yaml')) and not f.startswith('_'):
                decks.append(os.path.join(root, f))
    decks.sort()
    rows = []
    for d in decks:
        case = os.path.relpath(d, ARGS.decks)
        try:
            deck, note, result, msg = run_one(d)
            solver, mats, dmg, feats = summary(deck)
        except Exception as e:  # a deck the reader cannot parse is reported, not fatal
            solver = mats = dmg = '?'
            feats, note, result, msg = [], '', 'bad', 'survey could not read it: %s' % e
        rows.append((case, solver, mats, dmg, ', '.join(feats), result, note, msg))
        print('%-70s %-8s %s' % (case, result, msg), file=sys.stderr, flush=True)
    n = len(rows)
    count = {r: sum(1 for x in rows if x[5] == r) for r in ('runs', 'check only', 'refused', 'bad')}
    line = '%d of %d run; %d refused naming the feature; %d bad' % (
        count['runs'] + count['check only'], n, count['refused'], count['bad'])
    if count['check only']:
        line += ' (%d of the runs only to --check: their run on a substitute mesh stops)' % (
            count['check only'])
    print(line)
    if ARGS.markdown:
        print()
        print('| case | solver | materials | damage | features | result | mesh | message |')
        print('|---|---|---|---|---|---|---|---|')
        for r in rows:
            print('| ' + ' | '.join(x.replace('|', '/') for x in r) + ' |')
    else:
        for r in rows:
            print('\t'.join(r))


if __name__ == '__main__':
    main()
