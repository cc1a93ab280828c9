#pragma once
// Cell-list neighbour search: O(N) in the number of candidate points for a bounded horizon.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "discretization/Discretization.hpp"

namespace peridot {

struct NeighborSearchInput {
  const double* x = nullptr;        // 3 per candidate point
  std::size_t numPoints = 0;        // candidates
  const double* horizon = nullptr;  // per candidate point; a query uses its own
  const int* blockId = nullptr;     // per candidate; only read when omitting inter-block bonds
  bool omitBondsBetweenBlocks = false;
  NeighborhoodRule rule;
  const std::vector<BondFilter>* bondFilters = nullptr;
  // If set (one entry per filter), each filter's count of the bonds it cut is added to it: a
  // filter that cuts none is a warning (a pre-crack turned the wrong way).
  std::vector<long long>* bondFilterCuts = nullptr;
  // Sphere rules: keep j if it is within the query's horizon or the query within j's (so that
  // lists are symmetric when horizons differ).
  bool unionOfHorizons = false;
  const double* cellEdge = nullptr;  // CellOverlap: per candidate
  // Threads fillNeighbors may use for the sphere rules (the rank's spare processors): the lists
  // are the same whatever the number.
  int threads = 1;
};

// For each query (an index into the candidates), appends the indices of its neighbours (self
// excluded) to `neighbors`; offsets has queries.size()+1 entries. Neighbours come in no
// particular order.
void findNeighbors(const NeighborSearchInput& in, const std::vector<std::size_t>& queries,
                   std::vector<long long>& offsets, std::vector<std::size_t>& neighbors);

// The same bonds as findNeighbors, found the other way round: the candidates are visited in
// index order and each scans the queries within reach of it (cells of half the reach, rows of
// cells contiguous in memory), so every query's neighbours come out in increasing candidate
// index -- number the candidates in the order the lists must have and no list needs sorting.
// Two passes: countNeighbors gives each query's number of neighbours (counts[i] for
// queries[i]); fillNeighbors then writes the neighbours of queries[i] to
// out[begin[i] .. begin[i] + counts[i]) and throws std::logic_error if a count differs.
// Bond filter cuts are counted by whichever pass is given in.bondFilterCuts.
void countNeighbors(const NeighborSearchInput& in, const std::vector<std::size_t>& queries,
                    std::vector<int>& counts);
void fillNeighbors(const NeighborSearchInput& in, const std::vector<std::size_t>& queries,
                   const std::vector<std::int64_t>& begin, const std::vector<int>& counts,
                   int* out);

// The reach of a query point: the largest |xi| any neighbour of it can have.
double searchReach(const NeighborhoodRule& rule, double horizon);

}  // namespace peridot
