# NOXQuasiStatic at 2 and 3 ranks against 1 rank. Not bitwise: NOX's norms and inner products
# and the Krylov iterates are sums in partition order, so the iterations differ in their last
# bits and the results agree within the solver tolerance only. Both decks stop a load step when
# ||V f|| over the free components is below 1e-8 x the reaction norm. Displacement: the error
# that leaves is at most cond(K) x 1e-8 of the displacements (cond(K) < 1e4 for this bar, max
# |u| = 1e-2): 1e-6 absolute (measured: 1e-14 matrix-free Newton, 8e-11 nonlinear CG).
# Dilatation: the displacement bound over the point spacing (0.5), x 5: 1e-5 (measured 4e-11).
# Force density: the criterion allows ~45 per free component (V = 0.125), so two runs differ
# by at most 90 there; the held components carry the reactions (4e8), which the criterion does
# not bound: 100 covers both (measured 0.008 and 10).
DEFAULT TOLERANCE absolute 0.0
COORDINATES absolute 0.0
TIME STEPS absolute 0.0
NODAL VARIABLES absolute 1.0E-6
	DisplacementX	absolute 1.0E-6
	DisplacementY	absolute 1.0E-6
	DisplacementZ	absolute 1.0E-6
	Force_DensityX	absolute 100.0
	Force_DensityY	absolute 100.0
	Force_DensityZ	absolute 100.0
ELEMENT VARIABLES absolute 1.0E-5
	Dilatation	absolute 1.0E-5
