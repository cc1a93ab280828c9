#pragma once
// Peridigm's stable time step estimate: dt_i = sqrt(2 rho_i / sum_j V_j c_i / |xi_ij|) with the
// bond-based spring constant c_i = 18 K_i / (pi delta_i^4), for every model; the global minimum.
#include "parallel/Topology.hpp"

namespace peridot {

// All arrays overlap-indexed except density and bulkModulus (owned).
double stableTimeStep(const Topology& topology, const double* x, const double* volume,
                      const double* horizon, const double* density, const double* bulkModulus);

}  // namespace peridot
