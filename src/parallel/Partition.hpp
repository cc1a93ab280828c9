#pragma once
// Zoltan recursive coordinate bisection of a point cloud distributed over the ranks.
#include <mpi.h>

#include <vector>

namespace peridot {

// Collective. Each rank passes its share of the points (`x`, 3 per point) and gets back the
// rank that is to own each of them. `weights` (empty = unweighted, else one per point of the
// share) gives each point's cost, e.g. its bond count.
std::vector<int> partitionShare(const std::vector<double>& x, const std::vector<double>& weights,
                                MPI_Comm comm);

// Splits the points into `numParts` contiguous pieces of the Morton curve with equal weight.
std::vector<int> partitionAlongCurve(const std::vector<double>& x,
                                     const std::vector<double>& weights, int numParts);

// Morton (Z-order) key of a point in a bounding box: ordering owned points along this
// space-filling curve keeps a point's neighbours close in memory.
unsigned long long mortonKey(const double* x, const double* boxMin, const double* boxMax);

}  // namespace peridot
