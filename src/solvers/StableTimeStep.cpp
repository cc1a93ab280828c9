#include "solvers/StableTimeStep.hpp"

#include <cmath>
#include <limits>

namespace peridot {

double stableTimeStep(const Topology& t, const double* x, const double* volume,
                      const double* horizon, const double* density, const double* bulkModulus) {
  const double pi = 3.14159265358979323846;
  double dtMin = std::numeric_limits<double>::max();
  for (int i = 0; i < t.numOwned; ++i) {
    const double d = horizon[i];
    const double c = 18.0 * bulkModulus[i] / (pi * d * d * d * d);
    double sum = 0;
    for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
      const int j = t.neighbors[b];
      double z2 = 0;
      for (int k = 0; k < 3; ++k) z2 += (x[3 * j + k] - x[3 * i + k]) * (x[3 * j + k] - x[3 * i + k]);
      sum += volume[j] * c / std::sqrt(z2);
    }
    if (sum > 0) dtMin = std::min(dtMin, std::sqrt(2.0 * density[i] / sum));
  }
  MPI_Allreduce(MPI_IN_PLACE, &dtMin, 1, MPI_DOUBLE, MPI_MIN, t.comm);
  return dtMin;
}

}  // namespace peridot
