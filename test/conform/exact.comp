# Same run written two ways: every value equal to the bit.
DEFAULT TOLERANCE absolute 0.0
COORDINATES absolute 0.0
TIME STEPS absolute 0.0
GLOBAL VARIABLES absolute 0.0
NODAL VARIABLES absolute 0.0
ELEMENT VARIABLES absolute 0.0
