#pragma once
// Stable time step estimate (Peridigm's form): dt_i = sqrt(2 rho_i / k_i), where k_i sums the
// bond stiffnesses of point i (each material model supplies them); the global minimum.
#include "parallel/Topology.hpp"

namespace peridot {

// `density` and `stiffnessSum` per owned point. Collective.
double stableTimeStep(const Topology& topology, const double* density, const double* stiffnessSum);

}  // namespace peridot
