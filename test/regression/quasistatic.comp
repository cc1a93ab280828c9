# QuasiStatic at 2 and 3 ranks against 1 rank. Not bitwise: the Krylov iterates (sums in
# partition order) and the ILU preconditioner (built on each rank's diagonal block) depend on the
# partition, so results agree within the solver tolerances only. Force density: Newton stops
# when ||V f|| over the free components is below 1e-8 x the reaction norm (5.6 N here; V =
# 0.125), which allows up to ~45 per component: 50 is that bound (1e-3 was measured).
# Displacement and dilatation: 1e-12 absolute (1e-10 of the largest displacement, 1e-9 of the
# dilatation); 1.6e-15 was measured.
DEFAULT TOLERANCE absolute 0.0
COORDINATES absolute 0.0
TIME STEPS absolute 0.0
NODAL VARIABLES absolute 1.0E-12
	DisplacementX	absolute 1.0E-12
	DisplacementY	absolute 1.0E-12
	DisplacementZ	absolute 1.0E-12
	Force_DensityX	absolute 50.0
	Force_DensityY	absolute 50.0
	Force_DensityZ	absolute 50.0
ELEMENT VARIABLES absolute 1.0E-12
	Dilatation	absolute 1.0E-12
