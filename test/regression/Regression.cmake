# Peridigm's own cases (from shared/peridigm-cases), run unmodified from a copy of the case
# folder at 1, 2 and 3 ranks, each output compared with the gold file by peridot-diff.
set(PERIDOT_CASES_DIR "${PERIDOT_SHARED_DIR}/peridigm-cases")
