#include "neighbor/NeighborSearch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "neighbor/PairTest.hpp"

namespace peridot {

using pairtest::boxCells;
using pairtest::isNeighbor;
using pairtest::queryTerms;
using pairtest::QueryTerms;

namespace {

constexpr std::uint64_t kMaxCell = (1ULL << 21) - 1;

}  // namespace

double searchReach(const NeighborhoodRule& rule, double horizon) {
  if (rule.kind == NeighborhoodRule::Kind::CellOverlap) return horizon + rule.overlapReach;
  if (rule.kind != NeighborhoodRule::Kind::CellBox) return horizon;
  double r2 = 0;
  for (int d = 0; d < 3; ++d) {
    if (rule.cellCount[d] == 0) continue;  // an axis a 2D grid does not have
    const double half = (boxCells(rule, d, horizon) + 0.5) * rule.cellSize[d];
    r2 += half * half;
  }
  return std::sqrt(r2);
}

void findNeighbors(const NeighborSearchInput& in, const std::vector<std::size_t>& queries,
                   std::vector<long long>& offsets, std::vector<std::size_t>& neighbors) {
  offsets.assign(1, 0);
  offsets.reserve(queries.size() + 1);
  neighbors.clear();
  if (in.numPoints == 0) {
    offsets.resize(queries.size() + 1, 0);
    return;
  }
  double lo[3], hi[3];
  for (int d = 0; d < 3; ++d) {
    lo[d] = std::numeric_limits<double>::max();
    hi[d] = std::numeric_limits<double>::lowest();
  }
  double reach = 0;
  for (std::size_t i = 0; i < in.numPoints; ++i) {
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], in.x[3 * i + d]);
      hi[d] = std::max(hi[d], in.x[3 * i + d]);
    }
  }
  for (std::size_t q : queries) reach = std::max(reach, searchReach(in.rule, in.horizon[q]));
  if (in.unionOfHorizons)
    for (std::size_t i = 0; i < in.numPoints; ++i)
      reach = std::max(reach, searchReach(in.rule, in.horizon[i]));
  // Cells of edge = the largest reach, so a query scans at most 3 cells per axis. Only the
  // occupied cells are stored (points sorted by cell key), so memory is O(points) however far
  // apart the points lie. Cell coordinates are clamped to 21 bits per axis; clamping is
  // monotone, so the cells a query scans still hold all its neighbours (points beyond 2^21
  // cells from the lowest only share cells, which costs candidates, never bonds).
  const double cell = reach > 0 && std::isfinite(reach) ? reach : 0.0;
  auto cellIndex = [&](double v, int d) -> std::uint64_t {
    if (cell == 0.0) return 0;  // no reach, or an infinite one: one cell holds every point
    const double c = std::floor((v - lo[d]) / cell);
    if (!(c > 0)) return 0;  // also NaN
    return c >= static_cast<double>(kMaxCell) ? kMaxCell : static_cast<std::uint64_t>(c);
  };
  auto keyOf = [](std::uint64_t cx, std::uint64_t cy, std::uint64_t cz) {
    return (cz << 42) | (cy << 21) | cx;
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> sorted(in.numPoints);
  std::uint64_t maxCell[3] = {0, 0, 0};
  for (std::size_t i = 0; i < in.numPoints; ++i) {
    std::uint64_t c[3];
    for (int d = 0; d < 3; ++d) {
      c[d] = cellIndex(in.x[3 * i + d], d);
      maxCell[d] = std::max(maxCell[d], c[d]);
    }
    sorted[i] = {keyOf(c[0], c[1], c[2]), i};
  }
  std::sort(sorted.begin(), sorted.end());

  for (std::size_t q : queries) {
    const QueryTerms query = queryTerms(in, q);
    const double r = in.unionOfHorizons ? reach : searchReach(in.rule, query.h);
    std::uint64_t c0[3], c1[3];
    for (int d = 0; d < 3; ++d) {
      // The range is padded by far more than the rounding of xq +- r, which can land a hair
      // inside a neighbour at almost exactly the reach (the distance test, on the difference,
      // keeps it): without the pad the cells scanned, and so the bonds, depended on where the
      // cell grid starts, i.e. on the rank count.
      // Capped at 1e-3 of the reach: for coordinates beyond 1e11 reaches (a degenerate mesh) the
      // scan must stay within a few cells, not sweep the clamped grid.
      const double pad = std::min(1e-14 * (std::fabs(query.x[d]) + r), 1e-3 * r);
      c0[d] = cellIndex(query.x[d] - r - pad, d);
      const double upper = query.x[d] + r + pad;
      c1[d] = std::isnan(upper) ? maxCell[d] : std::min(maxCell[d], cellIndex(upper, d));
    }
    for (std::uint64_t cz = c0[2]; cz <= c1[2]; ++cz)
      for (std::uint64_t cy = c0[1]; cy <= c1[1]; ++cy) {
        // Keys of one row of cells (cx from c0 to c1) are consecutive in the sorted order.
        const std::uint64_t last = keyOf(c1[0], cy, cz);
        auto it = std::lower_bound(sorted.begin(), sorted.end(),
                                   std::make_pair(keyOf(c0[0], cy, cz), std::size_t{0}));
        for (; it != sorted.end() && it->first <= last; ++it) {
          const std::size_t j = it->second;
          if (j != q && isNeighbor(in, query, j)) neighbors.push_back(j);
        }
      }
    offsets.push_back(static_cast<long long>(neighbors.size()));
  }
}

}  // namespace peridot
