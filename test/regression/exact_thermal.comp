# Rank-count invariance of a thermal run: these variables must agree to the bit.
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
	Damage	absolute 0.0
	Dilatation	absolute 0.0
	Temperature	absolute 0.0
	Temperature_Change	absolute 0.0
