# ImplicitChainBar (QuasiStatic then Implicit) at 2 and 3 ranks against 1 rank. Not bitwise:
# Krylov sums and the ILU follow the partition. Measured at 2 and 3 ranks: displacement 3.3e-15,
# velocity 2.6e-11, force density 2.7e-3. Displacement: 1e-13 absolute (1e-11 of the largest,
# 0.0098). Velocity: Newmark's v moves by gamma / (beta dt) = 16384 x the change of u, so 1e-9
# (1e-7 of the largest, 0.0098). Force density: the QuasiStatic steps stop at 1e-8 x the reaction
# norm, which allows up to ~45 per component (see quasistatic.comp); the largest is 4e8.
DEFAULT TOLERANCE absolute 0.0
COORDINATES absolute 0.0
TIME STEPS absolute 0.0
NODAL VARIABLES absolute 1.0E-13
	DisplacementX	absolute 1.0E-13
	DisplacementY	absolute 1.0E-13
	DisplacementZ	absolute 1.0E-13
	VelocityX	absolute 1.0E-9
	VelocityY	absolute 1.0E-9
	VelocityZ	absolute 1.0E-9
	Force_DensityX	absolute 50.0
	Force_DensityY	absolute 50.0
	Force_DensityZ	absolute 50.0
