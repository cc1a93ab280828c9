# QuasiStaticPlasticBar at 2 and 3 ranks against 1 rank: not bitwise, for the reasons of
# quasistatic.comp (Krylov sums and the ILU blocks follow the partition); the finite-difference
# tangent itself does not depend on the partition. Force density: the Newton criterion allows
# ~50 per component (see quasistatic.comp; 2e-3 measured). Displacement, dilatation: 1e-12
# absolute (2.5e-15 and 6e-16 measured). Lambda (at most 5.4e-11): 1e-20 absolute, 2e-10 of the
# largest (1.2e-23 measured); a history advanced differently on some rank is off by its own
# order.
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
	Lambda	absolute 1.0E-20
