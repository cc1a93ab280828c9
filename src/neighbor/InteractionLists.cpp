#include "neighbor/InteractionLists.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace peridot {

InteractionLists buildPairLists(const Topology& t, const double* x, const double* horizon,
                                const std::vector<int>& points,
                                const std::vector<BondFilter>* bondFilters) {
  InteractionLists lists;
  std::vector<char> wanted(t.numOwned, 0);
  for (int i : points) wanted[i] = 1;
  lists.pairOffsets.assign(t.numOwned + 1, 0);
  const bool filtered = bondFilters && !bondFilters->empty();
  for (int i = 0; i < t.numOwned; ++i) {
    lists.pairOffsets[i] = static_cast<std::int64_t>(lists.pairSlots.size() / 2);
    if (!wanted[i]) continue;
    const std::int64_t b0 = t.bondOffsets[i];
    const int n = t.numNeighbors(i);
    if (n > 65535) {
      throw RunError("continuum-kinematics interactions: point " +
                     std::to_string(t.overlapGlobalId[i]) + " has " + std::to_string(n) +
                     " neighbours; at most 65535 are supported (reduce the horizon)");
    }
    const double h2 = horizon[i] * horizon[i];
    const double minArea = 1e-10 * h2;
    const double* xi = x + 3 * i;
    for (int a = 0; a < n; ++a) {
      const int j = t.neighbors[b0 + a];
      const double* xj = x + 3 * j;
      const double J0 = xj[0] - xi[0], J1 = xj[1] - xi[1], J2 = xj[2] - xi[2];
      for (int b = a + 1; b < n; ++b) {
        const int k = t.neighbors[b0 + b];
        const double* xk = x + 3 * k;
        // |X_k - X_j|^2 as the neighbour search computes it (squares: the same bits from j's
        // side and from k's), so that the pair is the bond j-k of j's and k's lists.
        const double d0 = xk[0] - xj[0], d1 = xk[1] - xj[1], d2 = xk[2] - xj[2];
        if (!(d0 * d0 + d1 * d1 + d2 * d2 <= h2)) continue;
        const double K0 = xk[0] - xi[0], K1 = xk[1] - xi[1], K2 = xk[2] - xi[2];
        const double A0 = J1 * K2 - J2 * K1, A1 = J2 * K0 - J0 * K2, A2 = J0 * K1 - J1 * K0;
        if (!(std::sqrt(A0 * A0 + A1 * A1 + A2 * A2) > minArea)) continue;
        if (filtered) {
          // The cut is evaluated from the end with the smaller global id, whoever asks.
          const bool jFirst = t.overlapGlobalId[j] < t.overlapGlobalId[k];
          const double* p = jFirst ? xj : xk;
          const double* q = jFirst ? xk : xj;
          bool cut = false;
          for (const auto& f : *bondFilters) cut = cut || f.cuts(p, q);
          if (cut) continue;
        }
        lists.pairSlots.push_back(static_cast<std::uint16_t>(a));
        lists.pairSlots.push_back(static_cast<std::uint16_t>(b));
      }
    }
  }
  lists.pairOffsets[t.numOwned] = static_cast<std::int64_t>(lists.pairSlots.size() / 2);
  lists.pairSlots.shrink_to_fit();
  return lists;
}

int TripleScan::reset(const Topology& t, const InteractionLists& lists, int i) {
  n_ = t.numNeighbors(i);
  table_.assign(static_cast<std::size_t>(n_) * n_, -1);
  for (std::int64_t q = lists.pairOffsets[i]; q < lists.pairOffsets[i + 1]; ++q) {
    const int a = lists.pairSlots[2 * q], b = lists.pairSlots[2 * q + 1];
    table_[static_cast<std::size_t>(a) * n_ + b] = q;
  }
  return n_;
}

}  // namespace peridot
