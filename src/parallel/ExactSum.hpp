#pragma once
// Sums over all ranks that have the same bits at any rank count: each term is rounded to a
// multiple of 2^-s (s chosen from the largest term and the number of terms so that the 64-bit
// integer sum cannot overflow) and the integers are summed, in any order, exactly. The rounding
// loses about 2^-(62 - log2 N) of the largest term. Solvers whose decisions depend on global
// norms (Lanczos, dynamic relaxation) use it to keep results independent of the rank count.
#include <mpi.h>

#include <vector>

namespace peridot {

// Sum of `terms` (this rank's) over all ranks; `globalCount` bounds the number of terms on all
// ranks together. Collective.
double exactSum(const std::vector<double>& terms, long long globalCount, MPI_Comm comm);

}  // namespace peridot
