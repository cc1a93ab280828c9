# Adaptive Load-Stepping (AdaptiveNotchedBar) at 2 and 3 ranks against 1 rank. The step
# sequence must be the same: TIME STEPS exact (every cut, every Verlet step after the switch),
# Damage exact (the same bonds broken), Nonlinear_Solver_Iterations exact. Displacement: not
# bitwise (Krylov sums and the ILU blocks follow the partition); Newton stops at 1e-8 of the
# reaction norm, 1e-12 absolute bounds it (1e-11 of the largest displacement, 0.1); 1.1e-14
# was measured.
DEFAULT TOLERANCE absolute 0.0
COORDINATES absolute 0.0
TIME STEPS absolute 0.0
GLOBAL VARIABLES absolute 0.0
	Nonlinear_Solver_Iterations	absolute 0.0
NODAL VARIABLES absolute 1.0E-12
	DisplacementX	absolute 1.0E-12
	DisplacementY	absolute 1.0E-12
	DisplacementZ	absolute 1.0E-12
ELEMENT VARIABLES absolute 0.0
	Damage	absolute 0.0
