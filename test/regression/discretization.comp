# The discretization as Peridigm builds it: point ids (matched), blocks, coordinates,
# volumes and neighbour counts at record 0 and after.
DEFAULT TOLERANCE absolute 1.0E-12
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
ELEMENT VARIABLES
	Volume	relative 1.0E-12
	Number_Of_Neighbors	absolute 0.0
