#include "parallel/ExactSum.hpp"

#include <algorithm>
#include <cmath>

namespace peridot {

double exactSum(const std::vector<double>& terms, long long globalCount, MPI_Comm comm) {
  double largest = 0;
  for (double t : terms) largest = std::max(largest, std::fabs(t));
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (largest == 0) return 0.0;
  int countBits = 0;
  while ((1LL << countBits) <= globalCount && countBits < 40) ++countBits;
  int exponent = 0;
  std::frexp(largest, &exponent);                 // largest < 2^exponent
  const int scale = (61 - countBits) - exponent;  // terms < 2^(61 - countBits) once scaled
  long long sum = 0;
  for (double t : terms) sum += std::llround(std::ldexp(t, scale));
  MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_LONG_LONG, MPI_SUM, comm);
  return std::ldexp(static_cast<double>(sum), -scale);
}

}  // namespace peridot
