#include "neighbor/NeighborSearch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "neighbor/PartialVolume.hpp"

namespace peridot {

namespace {

// Cells per axis of the box rule: Peridigm rounds delta/h half up and caps it at the cell count.
int boxCells(const NeighborhoodRule& rule, int d, double horizon) {
  const int n = static_cast<int>(std::floor(horizon / rule.cellSize[d] + 0.5));
  return std::min(n, rule.cellCount[d]);
}

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
  // Cell edge = largest reach, so a query scans at most its 27 surrounding cells; grow the
  // cells if the grid would have far more cells than points (a huge box with few points).
  double cell = reach > 0 ? reach : 1.0;
  long long dims[3];
  for (;;) {
    long long total = 1;
    for (int d = 0; d < 3; ++d) {
      dims[d] = std::max<long long>(1, static_cast<long long>((hi[d] - lo[d]) / cell) + 1);
      total *= dims[d];
    }
    if (total <= 8 * static_cast<long long>(in.numPoints) + 64) break;
    cell *= 1.5;
  }
  auto cellCoord = [&](double v, int d) {
    return std::min<long long>(dims[d] - 1, static_cast<long long>((v - lo[d]) / cell));
  };
  const std::size_t numCells = static_cast<std::size_t>(dims[0] * dims[1] * dims[2]);
  std::vector<std::size_t> cellStart(numCells + 1, 0), cellPoints(in.numPoints);
  std::vector<std::size_t> cellOf(in.numPoints);
  for (std::size_t i = 0; i < in.numPoints; ++i) {
    const long long c[3] = {cellCoord(in.x[3 * i], 0), cellCoord(in.x[3 * i + 1], 1),
                            cellCoord(in.x[3 * i + 2], 2)};
    cellOf[i] = static_cast<std::size_t>((c[2] * dims[1] + c[1]) * dims[0] + c[0]);
    ++cellStart[cellOf[i] + 1];
  }
  for (std::size_t c = 0; c < numCells; ++c) cellStart[c + 1] += cellStart[c];
  {
    std::vector<std::size_t> fill(cellStart.begin(), cellStart.end() - 1);
    for (std::size_t i = 0; i < in.numPoints; ++i) cellPoints[fill[cellOf[i]]++] = i;
  }

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
    long long c0[3], c1[3];
    for (int d = 0; d < 3; ++d) {
      c0[d] =
          std::max<long long>(0, static_cast<long long>(std::floor((xq[d] - r - lo[d]) / cell)));
      c1[d] = cellCoord(std::min(hi[d], xq[d] + r), d);
    }
    for (long long cz = c0[2]; cz <= c1[2]; ++cz)
      for (long long cy = c0[1]; cy <= c1[1]; ++cy)
        for (long long cx = c0[0]; cx <= c1[0]; ++cx) {
          const std::size_t c = static_cast<std::size_t>((cz * dims[1] + cy) * dims[0] + cx);
          for (std::size_t k = cellStart[c]; k < cellStart[c + 1]; ++k) {
            const std::size_t j = cellPoints[k];
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
              for (const auto& f : *in.bondFilters)
                if (f.cuts(xq, xj)) {
                  cut = true;
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
