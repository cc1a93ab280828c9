#!/usr/bin/python3
"""Writes a QuasiStatic deck: an LPS block NX x NY x NZ (spacing 1, horizon 1.51) pulled by its
end layers (uniaxial strain 1e-3 at t = 1, lateral contraction nu = 0.25 on the layers), in one
load step. Usage: make_deck.py NX NY NZ PRECONDITIONER OUT.xml [SOLVER]; SOLVER is QuasiStatic
(the default) or a NOXQuasiStatic variant: nox-newton (assembled tangent, CG), nox-newton-mf
(matrix-free, GMRES), nox-nlcg (NonlinearCG preconditioned by PRECONDITIONER, rebuilt at every
iteration), nox-nlcg-mf (the same with matrix-free Jacobian products and the preconditioner
rebuilt every 20 iterations)."""
import sys

nx, ny, nz = (int(a) for a in sys.argv[1:4])
preconditioner, out = sys.argv[4], sys.argv[5]
solver = sys.argv[6] if len(sys.argv) > 6 else "QuasiStatic"
delta = 1.51
left, right, gid = [], [], 0
for k in range(nz):
    for j in range(ny):
        for i in range(nx):
            gid += 1
            x = i + 0.5
            if x < delta:
                left.append(gid)
            if x > nx - delta:
                right.append(gid)
open("left.txt", "w").write("\n".join(map(str, left)) + "\n")
open("right.txt", "w").write("\n".join(map(str, right)) + "\n")
cy, cz = ny / 2.0, nz / 2.0
conditions = ""
for s in ("Left", "Right"):
    for axis, value in (("x", "1.0e-3*t*x"), ("y", "-0.25e-3*t*(y-%g)" % cy),
                        ("z", "-0.25e-3*t*(z-%g)" % cz)):
        conditions += f"""    <ParameterList name="{s} {axis}">
      <Parameter name="Type" type="string" value="Prescribed Displacement"/>
      <Parameter name="Node Set" type="string" value="{s} Node Set"/>
      <Parameter name="Coordinate" type="string" value="{axis}"/>
      <Parameter name="Value" type="string" value="{value}"/>
    </ParameterList>
"""
if solver == "QuasiStatic":
    solver_list = """    <ParameterList name="QuasiStatic">
      <Parameter name="Number of Load Steps" type="int" value="1"/>
      <Parameter name="Relative Tolerance" type="double" value="1.0e-6"/>
      <Parameter name="Belos Relative Tolerance" type="double" value="1.0e-8"/>
      <Parameter name="Belos Maximum Iterations" type="int" value="20000"/>
    </ParameterList>
  </ParameterList>
"""
else:
    age = 1
    if solver in ("nox-nlcg", "nox-nlcg-mf"):
        mf = solver == "nox-nlcg-mf"
        age = 20 if mf else 1
        direction = f"""        <Parameter name="Method" type="string" value="NonlinearCG"/>
        <ParameterList name="Nonlinear CG">
          <Parameter name="Restart Frequency" type="int" value="50"/>
          <Parameter name="Precondition" type="string" value="On"/>
          <Parameter name="Orthogonalize" type="string" value="Polak-Ribiere"/>
          <ParameterList name="Linear Solver">
            <Parameter name="Jacobian Operator" type="string" value="{'Matrix-Free' if mf else 'Use Jacobian'}"/>
            <Parameter name="Preconditioner" type="string" value="User Defined"/>
          </ParameterList>
        </ParameterList>
"""
        line_search, iterations = "NonlinearCG", 5000
    else:
        mf = solver == "nox-newton-mf"
        direction = f"""        <Parameter name="Method" type="string" value="Newton"/>
        <ParameterList name="Newton">
          <ParameterList name="Linear Solver">
            <Parameter name="Jacobian Operator" type="string" value="{'Matrix-Free' if mf else 'Use Jacobian'}"/>
            <Parameter name="Aztec Solver" type="string" value="{'GMRES' if mf else 'CG'}"/>
            <Parameter name="Preconditioner" type="string" value="{'None' if preconditioner == 'None' else 'User Defined'}"/>
            <Parameter name="Tolerance" type="double" value="{1e-6 if mf else 1e-8}"/>
            <Parameter name="Max Iterations" type="int" value="20000"/>
            <Parameter name="Size of Krylov Subspace" type="int" value="500"/>
          </ParameterList>
        </ParameterList>
"""
        line_search, iterations = "Full Step", 50
    solver_list = f"""    <ParameterList name="NOXQuasiStatic">
      <Parameter name="Number of Load Steps" type="int" value="1"/>
      <Parameter name="Relative Tolerance" type="double" value="1.0e-6"/>
      <Parameter name="Max Solver Iterations" type="int" value="{iterations}"/>
      <Parameter name="Max Age Of Prec" type="int" value="{age}"/>
      <ParameterList name="Direction">
{direction}      </ParameterList>
      <ParameterList name="Line Search">
        <Parameter name="Method" type="string" value="{line_search}"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
"""
open(out, "w").write(f"""<ParameterList>
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="PdQuickGrid"/>
    <Parameter name="NeighborhoodType" type="string" value="Spherical"/>
    <ParameterList name="TensorProduct3DMeshGenerator">
      <Parameter name="X Origin" type="double" value="0.0"/>
      <Parameter name="Y Origin" type="double" value="0.0"/>
      <Parameter name="Z Origin" type="double" value="0.0"/>
      <Parameter name="X Length" type="double" value="{nx}"/>
      <Parameter name="Y Length" type="double" value="{ny}"/>
      <Parameter name="Z Length" type="double" value="{nz}"/>
      <Parameter name="Number Points X" type="int" value="{nx}"/>
      <Parameter name="Number Points Y" type="int" value="{ny}"/>
      <Parameter name="Number Points Z" type="int" value="{nz}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="LPS">
      <Parameter name="Material Model" type="string" value="Elastic"/>
      <Parameter name="Density" type="double" value="7800.0"/>
      <Parameter name="Young's Modulus" type="double" value="200.0e9"/>
      <Parameter name="Poisson's Ratio" type="double" value="0.25"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="Block">
      <Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="LPS"/>
      <Parameter name="Horizon" type="double" value="{delta}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
    <Parameter name="Left Node Set" type="string" value="left.txt"/>
    <Parameter name="Right Node Set" type="string" value="right.txt"/>
{conditions}  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Final Time" type="double" value="1.0"/>
    <Parameter name="Peridigm Preconditioner" type="string" value="{preconditioner}"/>
{solver_list}  <ParameterList name="Output">
    <Parameter name="Output Filename" type="string" value="block"/>
    <ParameterList name="Output Variables">
      <Parameter name="Displacement" type="bool" value="true"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
""")
