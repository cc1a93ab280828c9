#include "solvers/StableTimeStep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace peridot {

double stableTimeStep(const Topology& t, const double* density, const double* stiffnessSum) {
  double dtMin = std::numeric_limits<double>::max();
  for (int i = 0; i < t.numOwned; ++i)
    if (stiffnessSum[i] > 0) dtMin = std::min(dtMin, std::sqrt(2.0 * density[i] / stiffnessSum[i]));
  MPI_Allreduce(MPI_IN_PLACE, &dtMin, 1, MPI_DOUBLE, MPI_MIN, t.comm);
  return dtMin;
}

}  // namespace peridot
