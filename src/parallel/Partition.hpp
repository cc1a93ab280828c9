#pragma once
// Zoltan recursive coordinate bisection of a point cloud known on every rank.
#include <mpi.h>

#include <vector>

namespace peridot {

// Returns, for every point of the cloud (replicated on all ranks), the rank that owns it.
// `weights` (empty = unweighted) gives each point's cost, e.g. its bond count.
std::vector<int> partitionPoints(const std::vector<double>& x, const std::vector<double>& weights,
                                 MPI_Comm comm);

// Splits the points into `numParts` contiguous pieces of the Morton curve with equal weight.
std::vector<int> partitionAlongCurve(const std::vector<double>& x,
                                     const std::vector<double>& weights, int numParts);

// Morton (Z-order) key of a point in a bounding box: ordering owned points along this
// space-filling curve keeps a point's neighbours close in memory.
unsigned long long mortonKey(const double* x, const double* boxMin, const double* boxMax);

}  // namespace peridot
