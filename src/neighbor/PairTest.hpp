#pragma once
// The test of one pair (query, candidate) shared by the two neighbour searches
// (NeighborSearch.cpp, CandidateSearch.cpp): both decide every pair here, with the same
// arithmetic, so they find the same bonds to the last bit of a distance at the horizon.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "neighbor/NeighborSearch.hpp"
#include "neighbor/PartialVolume.hpp"

namespace peridot::pairtest {

// Cells per axis of the box rule: Peridigm rounds delta/h half up and caps it at the cell count.
inline int boxCells(const NeighborhoodRule& rule, int d, double horizon) {
  const int n = static_cast<int>(std::floor(horizon / rule.cellSize[d] + 0.5));
  return std::min(n, rule.cellCount[d]);
}

// What the test of a pair needs of its query point.
struct QueryTerms {
  std::size_t index;  // of the query among the candidates
  const double* x;
  double h, h2;
  double halfBox[3];  // CellBox only
};

inline QueryTerms queryTerms(const NeighborSearchInput& in, std::size_t q) {
  QueryTerms t;
  t.index = q;
  t.x = in.x + 3 * q;
  t.h = in.horizon[q];
  t.h2 = t.h * t.h;
  for (int d = 0; d < 3; ++d) t.halfBox[d] = 0;
  if (in.rule.kind == NeighborhoodRule::Kind::CellBox)
    for (int d = 0; d < 3; ++d)
      t.halfBox[d] = in.rule.cellCount[d] == 0  // 2D: no z axis, every point has z = 0
                         ? std::numeric_limits<double>::infinity()
                         : (boxCells(in.rule, d, t.h) + 0.5) * in.rule.cellSize[d];
  return t;
}

// Whether candidate j (not the query itself) is a neighbour of the query: the neighbourhood
// rule, then blocks and bond filters. Both searches decide every pair here, with the same
// arithmetic, so they find the same bonds to the last bit of a distance at the horizon.
inline bool isNeighbor(const NeighborSearchInput& in, const QueryTerms& query, std::size_t j) {
  const double* xq = query.x;
  const double* xj = in.x + 3 * j;
  const double dx = xj[0] - xq[0], dy = xj[1] - xq[1], dz = xj[2] - xq[2];
  bool inside;
  switch (in.rule.kind) {
    case NeighborhoodRule::Kind::CellBox:
      inside = std::fabs(dx) < query.halfBox[0] && std::fabs(dy) < query.halfBox[1] &&
               std::fabs(dz) < query.halfBox[2];
      break;
    case NeighborhoodRule::Kind::CellOverlap: {
      const double xi[3] = {dx, dy, dz};
      inside = cellOverlapsHorizon(xi, in.cellEdge[j], query.h, in.rule.dimension);
      break;
    }
    default: {
      const double d2 = dx * dx + dy * dy + dz * dz;
      const double hj2 =
          in.unionOfHorizons ? std::max(query.h2, in.horizon[j] * in.horizon[j]) : query.h2;
      inside = in.rule.kind == NeighborhoodRule::Kind::SphereStrict ? d2 < hj2 : d2 <= hj2;
    }
  }
  if (!inside) return false;
  if (in.omitBondsBetweenBlocks && in.blockId[j] != in.blockId[query.index]) return false;
  if (in.bondFilters && !in.bondFilters->empty()) {
    for (std::size_t k = 0; k < in.bondFilters->size(); ++k)
      if ((*in.bondFilters)[k].cuts(xq, xj)) {
        if (in.bondFilterCuts) ++(*in.bondFilterCuts)[k];
        return false;
      }
  }
  return true;
}

}  // namespace peridot::pairtest
