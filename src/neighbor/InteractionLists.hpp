#pragma once
// Two-neighbour interactions of continuum-kinematics-inspired peridynamics (paper 004, eq. 2.15):
// for each owned point i, the unordered pairs {j, k} of its bonded neighbours that are mutually
// within i's horizon, |X_j - X_k| <= delta_i, whose bond j-k is not cut by a bond filter, and
// whose triangle is not degenerate (|X_ij x X_ik| > 1e-10 delta^2). Built once from the CSR bond
// lists. A pair is stored as the two positions (slots) of j and k in i's bond list, a < b; since
// each bond list is sorted by global id, the pairs are sorted by (gid j, gid k) and the lists
// are the same on any number of ranks.
//
// No second ghost layer is needed: j and k are neighbours of an owned point, so they are owned
// or ghosted already; and every two- or three-neighbour interaction that involves an owned
// point p (as its centre or as one of the other corners) has all its corners in p's horizon,
// because its corners are mutually within delta (uniform horizon).
//
// Three-neighbour interactions (eq. 2.24) are not stored: they are the triples a < b < c of
// slots whose three pairs (a,b), (a,c), (b,c) are all pairs of i; `TripleScan` enumerates them
// on the fly from the pairs (measured in bench/RESULTS.md: stored triples would cost ~30 bytes per
// triple and 10^4-10^5 triples per point in 3D).
#include <cstdint>
#include <vector>

#include "discretization/Discretization.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

struct InteractionLists {
  // Per owned point: pairs [pairOffsets[i], pairOffsets[i + 1]); empty for points not asked for.
  std::vector<std::int64_t> pairOffsets;
  std::vector<std::uint16_t> pairSlots;  // 2 per pair: slots a < b in i's bond list
  std::int64_t numPairs() const { return pairOffsets.empty() ? 0 : pairOffsets.back(); }
};

// Builds the pairs of `points` (owned local indices, sorted or not). `x`: reference positions
// (overlap), `horizon`: per overlap point. Throws RunError if a point has 65536 or more
// neighbours (slots are 16-bit).
InteractionLists buildPairLists(const Topology& topology, const double* x, const double* horizon,
                                const std::vector<int>& points,
                                const std::vector<BondFilter>* bondFilters);

// Enumerates the three-neighbour interactions of one point from its pairs: a dense n x n table
// of pair indices (n = the point's neighbours), rebuilt per point in a buffer that is reused.
class TripleScan {
 public:
  // Prepares point i; returns the number of its neighbours.
  int reset(const Topology& topology, const InteractionLists& lists, int i);
  // Pair index (global, into pairSlots / 2) of slots a < b, or -1.
  std::int64_t pair(int a, int b) const { return table_[static_cast<std::size_t>(a) * n_ + b]; }
  // Calls visit(a, b, c, qab, qac, qbc) for every triple a < b < c of mutually paired slots, in
  // lexicographic order (so in global-id order).
  template <class Visit>
  void forEach(const InteractionLists& lists, int i, Visit&& visit) const {
    for (std::int64_t q = lists.pairOffsets[i]; q < lists.pairOffsets[i + 1]; ++q) {
      const int a = lists.pairSlots[2 * q], b = lists.pairSlots[2 * q + 1];
      const std::int64_t* rowA = &table_[static_cast<std::size_t>(a) * n_];
      const std::int64_t* rowB = &table_[static_cast<std::size_t>(b) * n_];
      for (int c = b + 1; c < n_; ++c) {
        if (rowA[c] < 0 || rowB[c] < 0) continue;
        visit(a, b, c, q, rowA[c], rowB[c]);
      }
    }
  }

 private:
  int n_ = 0;
  std::vector<std::int64_t> table_;
};

}  // namespace peridot
