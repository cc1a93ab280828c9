"""ctest: the vocabulary that Peridigm's own test decks needed (doc/peridigm-decks.md), and the
survey script itself.

1. Tensor components as output variables (Cauchy_StressXX, Left_Stretch_TensorXX, ...): a cube
   of Elastic Correspondence under a fully prescribed uniaxial stretch F = diag(1 + e, 1, 1),
   reached in one step, must write the closed-form values of the rate form at every point (F is
   exact for a linear displacement at every point, surface included), also through a Block_Data
   compute of a component. A tensor asked together with its components (also by a second stream
   into the same file) writes each of the nine names once.
2. Keys Peridigm ignores where its decks carry them: Hourglass Coefficient on Elastic and Pals,
   the top-level Enable Bond-Associated Hypoelastic Model (accepted, and still checked: a
   negative coefficient is an error).
3. scripts/peridigm_deck_survey.py on three small cases: one that runs, one refused by name (the
   old Problem layout), one whose Exodus mesh is missing and gets a substitute.

usage: /usr/bin/python3 test_decksurvey.py PERIDOT SCRIPT
"""
import os
import shutil
import subprocess
import sys

import netCDF4
import numpy as np

peridot, script = sys.argv[1:3]
work = os.getcwd()
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


E, NU, STRAIN = 200.0e9, 0.3, 1.0e-3
DT = 5.0e-5  # below the stable step of the 4^3 unit lattice (8.96e-5): one step to t = DT
LAMBDA = E * NU / ((1 + NU) * (1 - 2 * NU))
MU = E / (2 * (1 + NU))


def cube(material, extra_top='', outputs='', computes='', more_outputs=''):
    ids = ' '.join(str(i) for i in range(1, 65))
    return f"""Peridigm:
{extra_top}  Discretization:
    Type: PdQuickGrid
    NeighborhoodType: Spherical
    TensorProduct3DMeshGenerator:
      X Origin: 0.0
      Y Origin: 0.0
      Z Origin: 0.0
      X Length: 4.0
      Y Length: 4.0
      Z Length: 4.0
      Number Points X: 4
      Number Points Y: 4
      Number Points Z: 4
  Materials:
    M:
{material}
  Blocks:
    B:
      Block Names: block_1
      Material: M
      Horizon: 1.75
  Boundary Conditions:
    All Node Set: "{ids}"
    X:
      Type: Prescribed Displacement
      Node Set: All Node Set
      Coordinate: x
      Value: "{STRAIN}*x*t/{DT}"
    Y:
      Type: Prescribed Displacement
      Node Set: All Node Set
      Coordinate: y
      Value: "0.0"
    Z:
      Type: Prescribed Displacement
      Node Set: All Node Set
      Coordinate: z
      Value: "0.0"
{computes}  Solver:
    Initial Time: 0.0
    Final Time: {DT}
    Verlet:
      Fixed dt: {DT}
  Output:
    Output Filename: cube
    Output Frequency: 1
    Output Variables:
{outputs}{more_outputs}"""


def run(deck_text, name, args=()):
    d = os.path.join(work, name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    with open(os.path.join(d, 'deck.yaml'), 'w') as f:
        f.write(deck_text)
    r = subprocess.run([peridot, *args, 'deck.yaml'], cwd=d, capture_output=True, text=True)
    return r, d


# ---- 1. tensor components -----------------------------------------------------------------
correspondence = f"""      Material Model: Elastic Correspondence
      Density: 7800.0
      Young's Modulus: {E}
      Poisson's Ratio: {NU}
      Hourglass Coefficient: 0.0"""
components = ['Cauchy_StressXX', 'Cauchy_StressYY', 'Cauchy_StressZZ', 'Cauchy_StressXY',
              'Unrotated_Cauchy_StressXX', 'Left_Stretch_TensorXX', 'Left_Stretch_TensorYY',
              'Rotation_TensorXX', 'Rotation_TensorXY', 'Deformation_GradientXX']
outputs = ''.join(f'      {c}: true\n' for c in components) + '      Max_Sxx: true\n'
computes = """  Compute Class Parameters:
    Max Sxx:
      Compute Class: Block_Data
      Calculation Type: Maximum
      Block: block_1
      Variable: Cauchy_StressXX
      Output Label: Max_Sxx
"""
r, d = run(cube(correspondence, outputs=outputs, computes=computes), 'components')
check(r.returncode == 0, 'correspondence cube with tensor-component outputs runs ' + r.stderr)
if r.returncode == 0:
    ds = netCDF4.Dataset(os.path.join(d, 'cube.e'))
    names = [b''.join(n).decode().strip('\0') for n in ds.variables['name_elem_var'][:]]
    names = [n.strip() for n in names]

    def element(name):
        k = names.index(name) + 1
        return np.array(ds.variables['vals_elem_var%deb1' % k][-1])

    # Elastic Correspondence is Peridigm's rate form: over the one step from F0 = I to
    # F1 = diag(1 + e, 1, 1) the velocity gradient is L = Fdot F1^-1 = diag(e / (1 + e), 0, 0) / dt,
    # with no spin, so the stress increment is C : d dt with d dt = diag(r, 0, 0), r = e / (1 + e),
    # the left stretch V = I + L V dt has V_xx = 1 + r, and R = I (rotated = unrotated stress).
    e = STRAIN
    r = e / (1 + e)
    expected = {
        'Cauchy_StressXX': (LAMBDA + 2 * MU) * r,
        'Cauchy_StressYY': LAMBDA * r,
        'Cauchy_StressZZ': LAMBDA * r,
        'Cauchy_StressXY': 0.0,
        'Unrotated_Cauchy_StressXX': (LAMBDA + 2 * MU) * r,
        'Left_Stretch_TensorXX': 1 + r,
        'Left_Stretch_TensorYY': 1.0,
        'Rotation_TensorXX': 1.0,
        'Rotation_TensorXY': 0.0,
        'Deformation_GradientXX': 1 + e,
    }
    stress_scale = (LAMBDA + 2 * MU) * e
    for name, value in expected.items():
        check(name in names, name + ' is an element variable of the output')
        if name in names:
            got = element(name)
            scale = stress_scale if 'Stress' in name and 'Stretch' not in name else 1.0
            err = np.max(np.abs(got - value)) / scale
            check(got.size == 64 and err < 1e-9,
                  '%s = %.12g at all 64 points (max error / scale %.1e)' % (name, value, err))
    glo = [b''.join(n).decode().strip('\0').strip() for n in ds.variables['name_glo_var'][:]]
    if 'Max_Sxx' in glo:
        got = float(ds.variables['vals_glo_var'][-1][glo.index('Max_Sxx')])
        want = (LAMBDA + 2 * MU) * r
        check(abs(got - want) < 1e-9 * stress_scale, 'Block_Data Maximum of Cauchy_StressXX')
    else:
        check(False, 'Max_Sxx is a global variable of the output')

# A tensor and some of its components, also from a second stream into the same file: each
# Exodus name once (the tensor's nine), with the tensor's values (the rate form's, as above).
r_ratio = STRAIN / (1 + STRAIN)
second = """  Output2:
    Output Filename: cube
    Output Frequency: 1
    Output Variables:
      Cauchy_StressYY: true
      Cauchy_Stress: true
"""
r, d = run(cube(correspondence, outputs='      Cauchy_StressXX: true\n      Cauchy_Stress: true\n',
                more_outputs=second), 'tensor_and_components')
check(r.returncode == 0, 'a tensor asked with its components runs ' + r.stderr)
if r.returncode == 0:
    ds = netCDF4.Dataset(os.path.join(d, 'cube.e'))
    names = [b''.join(n).decode().strip('\0').strip() for n in ds.variables['name_elem_var'][:]]
    want = ['Cauchy_Stress' + a + b for a in 'XYZ' for b in 'XYZ']
    check(sorted(names) == sorted(want) and len(set(names)) == len(names),
          'each element variable name once: %s' % names)
    for name, value in (('Cauchy_StressXX', (LAMBDA + 2 * MU) * r_ratio),
                        ('Cauchy_StressYY', LAMBDA * r_ratio)):
        if name in names:
            got = np.array(ds.variables['vals_elem_var%deb1' % (names.index(name) + 1)][-1])
            err = np.max(np.abs(got - value)) / ((LAMBDA + 2 * MU) * STRAIN)
            check(err < 1e-9, '%s of the tensor = %.12g (max error / scale %.1e)' % (name, value, err))

# ---- 2. keys Peridigm ignores ----------------------------------------------------------------
for model in ('Elastic', 'Pals'):
    material = f"""      Material Model: {model}
      Density: 7800.0
      Young's Modulus: {E}
      Poisson's Ratio: {NU}
      Hourglass Coefficient: %s"""
    r, _ = run(cube(material % '0.02', outputs='      Displacement: true\n'), 'hg_' + model,
               ['--check'])
    check(r.returncode == 0, 'Hourglass Coefficient accepted on %s %s' % (model, r.stderr))
    r, _ = run(cube(material % '-1.0', outputs='      Displacement: true\n'), 'hgneg_' + model,
               ['--check'])
    check(r.returncode != 0 and 'Hourglass Coefficient' in r.stderr,
          'a negative Hourglass Coefficient on %s is still an error' % model)
r, _ = run(cube(correspondence, extra_top='  Enable Bond-Associated Hypoelastic Model: true\n',
                outputs='      Displacement: true\n'), 'enable_ba', ['--check'])
check(r.returncode == 0, 'Enable Bond-Associated Hypoelastic Model accepted ' + r.stderr)

# ---- 3. the survey script --------------------------------------------------------------------
decks = os.path.join(work, 'survey_decks')
shutil.rmtree(decks, ignore_errors=True)
os.makedirs(os.path.join(decks, 'runs'))
with open(os.path.join(decks, 'runs', 'cube.yaml'), 'w') as f:
    f.write(cube(correspondence, outputs='      Cauchy_StressXX: true\n'))
os.makedirs(os.path.join(decks, 'old'))
with open(os.path.join(decks, 'old', 'old.xml'), 'w') as f:
    f.write('<ParameterList><ParameterList name="Problem"><ParameterList name="Discretization">'
            '<Parameter name="Type" type="string" value="PdQuickGrid"/></ParameterList>'
            '</ParameterList></ParameterList>\n')
os.makedirs(os.path.join(decks, 'exodus'))
with open(os.path.join(decks, 'exodus', 'bar.xml'), 'w') as f:
    f.write("""<ParameterList>
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="Exodus"/>
    <Parameter name="Input Mesh File" type="string" value="bar.g"/>
  </ParameterList>
  <ParameterList name="Materials"><ParameterList name="M">
    <Parameter name="Material Model" type="string" value="Elastic"/>
    <Parameter name="Density" type="double" value="7800.0"/>
    <Parameter name="Bulk Modulus" type="double" value="130.0e9"/>
    <Parameter name="Shear Modulus" type="double" value="78.0e9"/>
  </ParameterList></ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="Left"><Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="M"/>
      <Parameter name="Horizon" type="double" value="1.0"/></ParameterList>
    <ParameterList name="Right"><Parameter name="Block Names" type="string" value="block_2"/>
      <Parameter name="Material" type="string" value="M"/>
      <Parameter name="Horizon" type="double" value="1.0"/></ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
    <ParameterList name="Push">
      <Parameter name="Type" type="string" value="Initial Velocity"/>
      <Parameter name="Node Set" type="string" value="nodelist_1"/>
      <Parameter name="Coordinate" type="string" value="x"/>
      <Parameter name="Value" type="string" value="1.0"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Final Time" type="double" value="1.0e-6"/>
    <ParameterList name="Verlet"><Parameter name="Fixed dt" type="double" value="1.0e-7"/></ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output Filename" type="string" value="bar"/>
    <Parameter name="Output Frequency" type="int" value="5"/>
    <ParameterList name="Output Variables"><Parameter name="Displacement" type="bool" value="true"/></ParameterList>
  </ParameterList>
</ParameterList>
""")
r = subprocess.run([sys.executable, script, '--peridot', peridot, '--timeout', '120', '--work',
                    os.path.join(work, 'survey_work'), decks], capture_output=True, text=True)
print(r.stdout)
print(r.stderr)
lines = r.stdout.splitlines()
check(r.returncode == 0 and lines and lines[0] == '2 of 3 run; 1 refused naming the feature; 0 bad',
      'survey count line: ' + (lines[0] if lines else '(none)'))
rows = {l.split('\t')[0]: l.split('\t') for l in lines[1:] if '\t' in l}
check(rows.get('old/old.xml', [''] * 8)[5] == 'refused' and
      'Problem' in rows.get('old/old.xml', [''] * 8)[7], 'the Problem deck is refused by name')
check(rows.get('exodus/bar.xml', [''] * 8)[6] == 'substitute mesh' and
      rows.get('exodus/bar.xml', [''] * 8)[5] == 'runs', 'the Exodus deck runs on a substitute mesh')
check(not os.path.exists(os.path.join(decks, 'exodus', 'bar.g')),
      'the deck directory is left untouched (the substitute is in the work directory)')

print('%d failure(s)' % len(failures))
sys.exit(1 if failures else 0)
