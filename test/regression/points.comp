# The discretization as Peridigm builds it, for golds without Volume or Number_Of_Neighbors:
# point ids (matched), blocks and coordinates.
DEFAULT TOLERANCE absolute 1.0E-12
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
