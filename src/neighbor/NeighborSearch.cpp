#include "neighbor/NeighborSearch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "neighbor/PartialVolume.hpp"

namespace peridot {

namespace {

// Cells per axis of the box rule: Peridigm rounds delta/h half up and caps it at the cell count.
int boxCells(const NeighborhoodRule& rule, int d, double horizon) {
  const int n = static_cast<int>(std::floor(horizon / rule.cellSize[d] + 0.5));
  return std::min(n, rule.cellCount[d]);
}

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

  const bool box = in.rule.kind == NeighborhoodRule::Kind::CellBox;
  const bool strict = in.rule.kind == NeighborhoodRule::Kind::SphereStrict;
  const bool overlap = in.rule.kind == NeighborhoodRule::Kind::CellOverlap;
  const bool filtered = in.bondFilters && !in.bondFilters->empty();
  for (std::size_t q : queries) {
    const double* xq = in.x + 3 * q;
    const double h = in.horizon[q];
    const double h2 = h * h;
    double halfBox[3] = {0, 0, 0};
    if (box)
      for (int d = 0; d < 3; ++d)
        halfBox[d] = in.rule.cellCount[d] == 0  // 2D: no z axis, every point has z = 0
                         ? std::numeric_limits<double>::infinity()
                         : (boxCells(in.rule, d, h) + 0.5) * in.rule.cellSize[d];
    const double r = in.unionOfHorizons ? reach : searchReach(in.rule, h);
    std::uint64_t c0[3], c1[3];
    for (int d = 0; d < 3; ++d) {
      // The range is padded by far more than the rounding of xq +- r, which can land a hair
      // inside a neighbour at almost exactly the reach (the distance test, on the difference,
      // keeps it): without the pad the cells scanned, and so the bonds, depended on where the
      // cell grid starts, i.e. on the rank count.
      // Capped at 1e-3 of the reach: for coordinates beyond 1e11 reaches (a degenerate mesh) the
      // scan must stay within a few cells, not sweep the clamped grid.
      const double pad = std::min(1e-14 * (std::fabs(xq[d]) + r), 1e-3 * r);
      c0[d] = cellIndex(xq[d] - r - pad, d);
      const double upper = xq[d] + r + pad;
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
          if (j == q) continue;
          const double* xj = in.x + 3 * j;
          const double dx = xj[0] - xq[0], dy = xj[1] - xq[1], dz = xj[2] - xq[2];
          bool inside;
          if (box) {
            inside = std::fabs(dx) < halfBox[0] && std::fabs(dy) < halfBox[1] &&
                     std::fabs(dz) < halfBox[2];
          } else if (overlap) {
            const double xi[3] = {dx, dy, dz};
            inside = cellOverlapsHorizon(xi, in.cellEdge[j], h, in.rule.dimension);
          } else {
            const double d2 = dx * dx + dy * dy + dz * dz;
            const double hj2 =
                in.unionOfHorizons ? std::max(h2, in.horizon[j] * in.horizon[j]) : h2;
            inside = strict ? d2 < hj2 : d2 <= hj2;
          }
          if (!inside) continue;
          if (in.omitBondsBetweenBlocks && in.blockId[j] != in.blockId[q]) continue;
          if (filtered) {
            bool cut = false;
            for (std::size_t k = 0; k < in.bondFilters->size(); ++k)
              if ((*in.bondFilters)[k].cuts(xq, xj)) {
                cut = true;
                if (in.bondFilterCuts) ++(*in.bondFilterCuts)[k];
                break;
              }
            if (cut) continue;
          }
          neighbors.push_back(j);
        }
      }
    offsets.push_back(static_cast<long long>(neighbors.size()));
  }
}

}  // namespace peridot
