#pragma once
// The bond-based pair force (PMB, normalized PMB) over the half bond list: each bond once, its
// force added to one end and subtracted from the other (neighbor/HalfBondList.hpp for the order
// that keeps results identical at any rank count). The same force as pairForce in
// BondBasedKernels.hpp (linear law, optionally the fused critical stretch), summed in another
// order. Writes the force density of every owned point; `c` is the per-point micromodulus.
#include "materials/MaterialModel.hpp"

namespace peridot {

// normalized: the normalized PMB's force (divided by |xi|) instead of PMB's.
void halfPairForce(const ModelState& s, const double* c, bool normalized);

}  // namespace peridot
