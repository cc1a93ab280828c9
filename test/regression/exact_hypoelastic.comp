# Rank-count invariance of the hypoelastic correspondence deck: every variable to the bit.
DEFAULT TOLERANCE absolute 0.0
COORDINATES absolute 0.0
TIME STEPS absolute 0.0
NODAL VARIABLES absolute 0.0
	DisplacementX	absolute 0.0
	DisplacementY	absolute 0.0
	DisplacementZ	absolute 0.0
	VelocityX	absolute 0.0
	VelocityY	absolute 0.0
	VelocityZ	absolute 0.0
	Force_DensityX	absolute 0.0
	Force_DensityY	absolute 0.0
	Force_DensityZ	absolute 0.0
ELEMENT VARIABLES absolute 0.0
	Cauchy_StressXX	absolute 0.0
	Cauchy_StressXY	absolute 0.0
	Cauchy_StressYZ	absolute 0.0
	Cauchy_StressZZ	absolute 0.0
	Equivalent_Plastic_Strain	absolute 0.0
	Von_Mises_Stress	absolute 0.0
	Jacobian_Determinant	absolute 0.0
	Deformation_GradientXX	absolute 0.0
	Deformation_GradientYX	absolute 0.0
