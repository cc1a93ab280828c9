// The topology's neighbour search, organised by candidate (see countNeighbors in
// NeighborSearch.hpp): the queries sit in a dense grid of cells, each candidate in turn scans
// the rows of cells within its reach, and the sphere rule's distance test runs in vector lanes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "neighbor/NeighborSearch.hpp"
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "core/ProcessorsPerRank.hpp"
#include "neighbor/PairTest.hpp"

namespace peridot {

using pairtest::isNeighbor;
using pairtest::queryTerms;
using pairtest::QueryTerms;

namespace {

// The queries bucketed in a dense grid of cells of edge reach / kCellsPerReach (a counting
// sort), with what the scan reads of them copied in cell order, so that a row of cells is one
// contiguous run of each array.
constexpr int kCellsPerReach = 2;

struct QueryGrid {
  double lo[3] = {0, 0, 0};
  double edge = 0, inverseEdge = 0;  // 0: one cell holds every query
  int dim[3] = {1, 1, 1};
  std::vector<int> cellStart;  // per cell + 1: slots [cellStart[c], cellStart[c + 1])
  std::vector<double> x[3];    // per slot
  std::vector<double> h2;      // per slot: the squared horizon (the sphere rule's bound)
  std::vector<int> query;      // per slot: index into queries

  int cellOf(double v, int d) const {
    const double c = (v - lo[d]) * inverseEdge;
    if (!(c > 0)) return 0;  // also NaN
    return c >= dim[d] - 1 ? dim[d] - 1 : static_cast<int>(c);
  }
};

// Builds the grid, or returns false when a dense grid would need more than a few cells per
// query even with cells of four reaches (points spread over a far larger box than they fill,
// which the sparse per-query search handles).
bool buildQueryGrid(const NeighborSearchInput& in, const std::vector<std::size_t>& queries,
                    double reach, QueryGrid& g) {
  const std::size_t nq = queries.size();
  double hi[3];
  for (int d = 0; d < 3; ++d) {
    g.lo[d] = std::numeric_limits<double>::max();
    hi[d] = std::numeric_limits<double>::lowest();
  }
  for (std::size_t q : queries)
    for (int d = 0; d < 3; ++d) {
      const double v = in.x[3 * q + d];
      if (v < g.lo[d]) g.lo[d] = v;
      if (v > hi[d]) hi[d] = v;
    }
  if (reach > 0 && std::isfinite(reach)) {
    const double maxCells = 8.0 * static_cast<double>(nq) + 4096.0;
    double edge = reach / kCellsPerReach;
    auto cellsAlong = [&](int d, double e) {
      const double extent = hi[d] - g.lo[d];
      return std::isfinite(extent) && extent > 0 ? std::floor(extent / e) + 1 : 1.0;
    };
    while (cellsAlong(0, edge) * cellsAlong(1, edge) * cellsAlong(2, edge) > maxCells) {
      edge *= 2;
      if (edge > 4 * reach) return false;
    }
    g.edge = edge;
    g.inverseEdge = 1.0 / edge;
    for (int d = 0; d < 3; ++d) g.dim[d] = static_cast<int>(cellsAlong(d, edge));
  }
  const std::size_t numCells = static_cast<std::size_t>(g.dim[0]) * g.dim[1] * g.dim[2];
  std::vector<int> cellOfQuery(nq);
  g.cellStart.assign(numCells + 1, 0);
  for (std::size_t i = 0; i < nq; ++i) {
    const double* xq = in.x + 3 * queries[i];
    const int c =
        (g.cellOf(xq[2], 2) * g.dim[1] + g.cellOf(xq[1], 1)) * g.dim[0] + g.cellOf(xq[0], 0);
    cellOfQuery[i] = c;
    ++g.cellStart[c + 1];
  }
  for (std::size_t c = 0; c < numCells; ++c) g.cellStart[c + 1] += g.cellStart[c];
  std::vector<int> next(g.cellStart.begin(), g.cellStart.end() - 1);
  for (int d = 0; d < 3; ++d) g.x[d].resize(nq);
  g.h2.resize(nq);
  g.query.resize(nq);
  for (std::size_t i = 0; i < nq; ++i) {
    const int s = next[cellOfQuery[i]]++;
    g.query[s] = static_cast<int>(i);
    for (int d = 0; d < 3; ++d) g.x[d][s] = in.x[3 * queries[i] + d];
    g.h2[s] = in.horizon[queries[i]] * in.horizon[queries[i]];
  }
  return true;
}

double largestReach(const NeighborSearchInput& in, const std::vector<std::size_t>& queries) {
  double reach = 0;
  for (std::size_t q : queries) reach = std::max(reach, searchReach(in.rule, in.horizon[q]));
  if (in.unionOfHorizons)
    for (std::size_t i = 0; i < in.numPoints; ++i)
      reach = std::max(reach, searchReach(in.rule, in.horizon[i]));
  return reach;
}

// Whether a pair is decided by the squared distance against the query's squared horizon alone
// (the usual case), which the scan then tests in vector lanes.
bool sphereOnly(const NeighborSearchInput& in) {
  return (in.rule.kind == NeighborhoodRule::Kind::SphereInclusive ||
          in.rule.kind == NeighborhoodRule::Kind::SphereStrict) &&
         !in.unionOfHorizons && !in.omitBondsBetweenBlocks &&
         !(in.bondFilters && !in.bondFilters->empty());
}

// The cells candidate j scans along each axis: within the reach of it, padded like the
// per-query search, so that they hold every query that could take j (the pair test alone
// decides). False if none.
bool scanRange(const QueryGrid& g, double reach, const double* xj, int* c0, int* c1, double* pad) {
  for (int d = 0; d < 3; ++d) {
    if (g.inverseEdge == 0) {
      c0[d] = c1[d] = 0;
      pad[d] = 0;
      continue;
    }
    pad[d] = std::min(1e-14 * (std::fabs(xj[d]) + reach), 1e-3 * reach);
    const double a = (xj[d] - reach - pad[d] - g.lo[d]) * g.inverseEdge;
    const double b = (xj[d] + reach + pad[d] - g.lo[d]) * g.inverseEdge;
    if (b < 0 || a >= g.dim[d]) return false;  // beyond the grid (NaN bounds scan it all)
    c0[d] = a > 0 ? static_cast<int>(a) : 0;
    c1[d] = b < g.dim[d] - 1 ? static_cast<int>(b) : g.dim[d] - 1;
  }
  return true;
}

// Candidate j scans the rows of cells (cz, cy) in [c0, c1] (its scanRange, cut to a block),
// each row cut to the x interval the sphere of the reach spans at the row's distance from j;
// visit(first, last, j) gets each run of slots.
template <class Visit>
void scanRows(const NeighborSearchInput& in, const QueryGrid& g, double reach, std::size_t j,
              const int* c0, const int* c1, const double* pad, Visit& visit) {
  const double* xj = in.x + 3 * j;
  if (g.inverseEdge == 0) {
    if (g.cellStart[1] > 0) visit(0, g.cellStart[1], j);
    return;
  }
  const double reach2 = reach * reach;
  const bool finite = std::isfinite(xj[0]) && std::isfinite(xj[1]) && std::isfinite(xj[2]);
  for (int cz = c0[2]; cz <= c1[2]; ++cz) {
    // Distance from xj to the layer of cells cz (and below, to the row cy) along the axis,
    // less a margin of 1e-9 of a cell for the rounding of the cell bounds and the pad: never
    // more than the truth.
    const double zLow = g.lo[2] + cz * g.edge, zHigh = zLow + g.edge;
    const double gz = std::max(0.0, std::max(zLow - xj[2], xj[2] - zHigh) - 1e-9 * g.edge - pad[2]);
    for (int cy = c0[1]; cy <= c1[1]; ++cy) {
      int x0 = c0[0], x1 = c1[0];
      if (finite) {
        const double yLow = g.lo[1] + cy * g.edge, yHigh = yLow + g.edge;
        const double gy =
            std::max(0.0, std::max(yLow - xj[1], xj[1] - yHigh) - 1e-9 * g.edge - pad[1]);
        const double rest = reach2 - (gy * gy + gz * gz);
        if (rest < 0) continue;  // the row lies beyond the reach
        const double w = std::sqrt(rest) * (1 + 1e-9) + pad[0];
        const double a = (xj[0] - w - g.lo[0]) * g.inverseEdge;
        const double b = (xj[0] + w - g.lo[0]) * g.inverseEdge;
        x0 = std::max(x0, a > 0 ? static_cast<int>(a) : 0);
        x1 = std::min(x1, b < g.dim[0] - 1 ? static_cast<int>(b) : g.dim[0] - 1);
      }
      if (x0 > x1) continue;
      const std::size_t row = (static_cast<std::size_t>(cz) * g.dim[1] + cy) * g.dim[0];
      const int first = g.cellStart[row + x0], last = g.cellStart[row + x1 + 1];
      if (first < last) visit(first, last, j);
    }
  }
}

// Visits every candidate j in increasing index (scanRows over its whole scanRange).
template <class Visit>
void forEachRun(const NeighborSearchInput& in, const QueryGrid& g, double reach, Visit visit) {
  for (std::size_t j = 0; j < in.numPoints; ++j) {
    int c0[3], c1[3];
    double pad[3];
    if (scanRange(g, reach, in.x + 3 * j, c0, c1, pad))
      scanRows(in, g, reach, j, c0, c1, pad, visit);
  }
}

// The same visits, grouped by blocks of kBlockZ x kBlockY cells of the grid (full rows in x):
// within a block the candidates still come in increasing index, so each list is still written
// in order, but the lists being written at any moment are the block's few thousand instead of
// every list within the reach of a plane of candidates (whose write positions do not fit in
// the cache: the fill pass ran 3x slower than the count pass at 128^3 without blocks).
constexpr int kBlockZ = 2, kBlockY = 8;

template <class Visit>
void forEachRunBlocked(const NeighborSearchInput& in, const QueryGrid& g, double reach, Visit visit,
                       int threads) {
  if (g.inverseEdge == 0 || (g.dim[2] <= kBlockZ && g.dim[1] <= kBlockY)) {
    forEachRun(in, g, reach, visit);
    return;
  }
  const int nbz = (g.dim[2] + kBlockZ - 1) / kBlockZ, nby = (g.dim[1] + kBlockY - 1) / kBlockY;
  const std::size_t numBlocks = static_cast<std::size_t>(nbz) * nby;
  // Each candidate in every block its scan range meets, in increasing index (counting sort).
  std::vector<std::int64_t> start(numBlocks + 1, 0);
  auto forBlocksOf = [&](std::size_t j, auto&& f) {
    int c0[3], c1[3];
    double pad[3];
    if (!scanRange(g, reach, in.x + 3 * j, c0, c1, pad)) return;
    for (int bz = c0[2] / kBlockZ; bz <= c1[2] / kBlockZ; ++bz)
      for (int by = c0[1] / kBlockY; by <= c1[1] / kBlockY; ++by)
        f(static_cast<std::size_t>(bz) * nby + by);
  };
  for (std::size_t j = 0; j < in.numPoints; ++j)
    forBlocksOf(j, [&](std::size_t b) { ++start[b + 1]; });
  for (std::size_t b = 0; b < numBlocks; ++b) start[b + 1] += start[b];
  std::vector<std::int64_t> next(start.begin(), start.end() - 1);
  std::vector<std::uint32_t> members(static_cast<std::size_t>(start[numBlocks]));
  for (std::size_t j = 0; j < in.numPoints; ++j)
    forBlocksOf(j, [&](std::size_t b) { members[next[b]++] = static_cast<std::uint32_t>(j); });
  next = std::vector<std::int64_t>();
  auto scanBlocks = [&](std::size_t firstBlock, std::size_t lastBlock) {
    for (std::size_t b = firstBlock; b < lastBlock; ++b) {
      const int bz = static_cast<int>(b / nby), by = static_cast<int>(b % nby);
      for (std::int64_t m = start[b]; m < start[b + 1]; ++m) {
        const std::size_t j = members[m];
        int c0[3], c1[3];
        double pad[3];
        scanRange(g, reach, in.x + 3 * j, c0, c1, pad);
        c0[2] = std::max(c0[2], bz * kBlockZ);
        c1[2] = std::min(c1[2], bz * kBlockZ + kBlockZ - 1);
        c0[1] = std::max(c0[1], by * kBlockY);
        c1[1] = std::min(c1[1], by * kBlockY + kBlockY - 1);
        scanRows(in, g, reach, j, c0, c1, pad, visit);
      }
    }
  };
  // A block's queries are in no other block, so blocks scanned by different threads write
  // different lists, each still by its candidates in increasing index: the lists do not depend
  // on the number of threads, nor on which thread scanned which block. The threads take runs
  // of a few blocks as they come free (about 16 runs a thread).
  const int numThreads = static_cast<int>(std::min<std::size_t>(
      static_cast<std::size_t>(std::max(threads, 1)), std::max<std::size_t>(numBlocks / 4, 1)));
  if (numThreads == 1) {
    scanBlocks(0, numBlocks);
    return;
  }
  runChunksOnThreads(numThreads, numBlocks, numBlocks / (16 * numThreads),
                     [&](int, std::size_t first, std::size_t last) { scanBlocks(first, last); });
}

// The scan of one pass. Per run of slots [s0, s0 + n) of one row and candidate j, with
// inside[k] = whether the sphere rule takes the pair (slot s0 + k, j) -- counting the query
// itself -- pass.sphere(s0, n, inside, j) is called (sphere rule only); for other rules
// pass.found(slot, j) is called for each bond. Candidates come in increasing j.
template <class Pass>
void scanByCandidate(const NeighborSearchInput& in, const std::vector<std::size_t>& queries,
                     const QueryGrid& g, double reach, Pass& pass, bool blocked) {
  // Threads only for the sphere rule: the other rules' tests count bond filter cuts.
  const int threads = sphereOnly(in) ? in.threads : 1;
  auto forEach = [&](auto visit) {
    if (blocked)
      forEachRunBlocked(in, g, reach, visit, threads);
    else
      forEachRun(in, g, reach, visit);
  };
  constexpr int kChunk = 64;  // one bit per slot of a run in a 64-bit mask
  const double* gx = g.x[0].data();
  const double* gy = g.x[1].data();
  const double* gz = g.x[2].data();
  if (sphereOnly(in)) {
    // The sphere rule's own test, in the same arithmetic as isNeighbor.
    const bool strict = in.rule.kind == NeighborhoodRule::Kind::SphereStrict;
    const double* h2 = g.h2.data();
    forEach([&](int first, int last, std::size_t j) {
      const double xj0 = in.x[3 * j], xj1 = in.x[3 * j + 1], xj2 = in.x[3 * j + 2];
      for (int s0 = first; s0 < last; s0 += kChunk) {
        const int n = std::min(kChunk, last - s0);
        // 0 or -1 (all bits), as wide as the doubles: the compare's own vector mask.
        alignas(32) std::int64_t inside[kChunk];
        if (strict) {
          for (int k = 0; k < n; ++k) {
            const double dx = xj0 - gx[s0 + k], dy = xj1 - gy[s0 + k], dz = xj2 - gz[s0 + k];
            const double d2 = dx * dx + dy * dy + dz * dz;
            inside[k] = -static_cast<std::int64_t>(d2 < h2[s0 + k]);
          }
        } else {
          for (int k = 0; k < n; ++k) {
            const double dx = xj0 - gx[s0 + k], dy = xj1 - gy[s0 + k], dz = xj2 - gz[s0 + k];
            const double d2 = dx * dx + dy * dy + dz * dz;
            inside[k] = -static_cast<std::int64_t>(d2 <= h2[s0 + k]);
          }
        }
        pass.sphere(s0, n, inside, j);
      }
    });
    return;
  }
  std::vector<QueryTerms> terms(queries.size());
  for (std::size_t s = 0; s < queries.size(); ++s) terms[s] = queryTerms(in, queries[g.query[s]]);
  // Every pair the exact test keeps is within the reach (up to rounding): a cheap bound with a
  // margin of 1e-9 of it goes first; non-finite values pass it to the exact test.
  const double bound = std::isfinite(reach) ? reach * reach * (1 + 1e-9) : reach;
  forEach([&](int first, int last, std::size_t j) {
    const double xj0 = in.x[3 * j], xj1 = in.x[3 * j + 1], xj2 = in.x[3 * j + 2];
    for (int s0 = first; s0 < last; s0 += kChunk) {
      const int n = std::min(kChunk, last - s0);
      std::int64_t near[kChunk];
      for (int k = 0; k < n; ++k) {
        const double dx = xj0 - gx[s0 + k], dy = xj1 - gy[s0 + k], dz = xj2 - gz[s0 + k];
        near[k] = !(dx * dx + dy * dy + dz * dz > bound);
      }
      for (int k = 0; k < n; ++k) {
        const int s = s0 + k;
        if (near[k] && queries[g.query[s]] != j && isNeighbor(in, terms[s], j)) pass.found(s, j);
      }
    }
  });
}

struct CountPass {
  std::vector<int> perSlot;
  void sphere(int s0, int n, const std::int64_t* inside, std::size_t) {
    int* c = perSlot.data() + s0;
    for (int k = 0; k < n; ++k) c[k] -= static_cast<int>(inside[k]);
  }
  void found(int s, std::size_t) { ++perSlot[s]; }
};

// The sphere rule's count, each pair of queries tested once. A pair's squared distance has the
// same bits from either end (x_j - x_q is the negation of x_q - x_j, and the sum of squares does
// not see the sign), so the candidate that is the query of the lower slot tests the pair for
// both: whether it is within the other's horizon (that query's count) and within its own (its
// count). Such a candidate scans only the slots after its own -- the layers of cells from its
// own up (slots are in cell order: z, y, x) and, in its own row, the slots past its own; a
// candidate that is no query (a halo point) scans everything, for the queries' side only. Each
// pair gets the test the fill pass gives it, so the counts are the same: half the scan of
// countNeighbors' other rules.
void countSphereOnce(const NeighborSearchInput& in, const std::vector<std::size_t>& queries,
                     const QueryGrid& g, double reach, std::vector<int>& perSlot) {
  std::vector<int> slotOf(in.numPoints, -1);
  for (std::size_t s = 0; s < queries.size(); ++s)
    slotOf[queries[g.query[s]]] = static_cast<int>(s);
  const bool strict = in.rule.kind == NeighborhoodRule::Kind::SphereStrict;
  const double* gx = g.x[0].data();
  const double* gy = g.x[1].data();
  const double* gz = g.x[2].data();
  const double* h2 = g.h2.data();
  constexpr int kChunk = 64;
  // The candidates [first, last), adding to count (per slot).
  auto countRange = [&](std::size_t firstCandidate, std::size_t lastCandidate, int* count) {
    for (std::size_t j = firstCandidate; j < lastCandidate; ++j) {
      const double* xj = in.x + 3 * j;
      int c0[3], c1[3];
      double pad[3];
      if (!scanRange(g, reach, xj, c0, c1, pad)) continue;
      const int self = slotOf[j];
      const double h2j = self >= 0 ? h2[self] : 0.0;
      if (self >= 0) c0[2] = std::max(c0[2], g.cellOf(gz[self], 2));
      std::int64_t own = 0;  // minus the count of j's own neighbours found here
      auto visit = [&](int first, int last, std::size_t) {
        if (self >= 0 && first <= self) first = self + 1;
        const double xj0 = xj[0], xj1 = xj[1], xj2 = xj[2];
        for (int s0 = first; s0 < last; s0 += kChunk) {
          const int n = std::min(kChunk, last - s0);
          // 0 or -1, as wide as the doubles (the compare's own vector mask), as in the fill.
          alignas(32) std::int64_t inside[kChunk];
          alignas(32) std::int64_t mine[kChunk];
          for (int k = 0; k < n; ++k) {
            const double dx = xj0 - gx[s0 + k], dy = xj1 - gy[s0 + k], dz = xj2 - gz[s0 + k];
            const double d2 = dx * dx + dy * dy + dz * dz;
            inside[k] = -static_cast<std::int64_t>(strict ? d2 < h2[s0 + k] : d2 <= h2[s0 + k]);
            mine[k] = -static_cast<std::int64_t>(strict ? d2 < h2j : d2 <= h2j);
          }
          int* c = count + s0;
          for (int k = 0; k < n; ++k) {
            c[k] -= static_cast<int>(inside[k]);
            own += mine[k];
          }
        }
      };
      scanRows(in, g, reach, j, c0, c1, pad, visit);
      if (self >= 0) count[self] -= static_cast<int>(own);
    }
  };
  // Threads take runs of candidates, each adding to counts of its own (a candidate adds to
  // slots of any run); the integer sums do not depend on how the candidates were split.
  const auto numThreads = static_cast<std::size_t>(threadsFor(in.threads, in.numPoints));
  if (numThreads == 1) {
    countRange(0, in.numPoints, perSlot.data());
    return;
  }
  std::vector<std::vector<int>> partial(numThreads - 1, std::vector<int>(perSlot.size(), 0));
  // About 64 chunks a thread: small enough that the threads finish together.
  runChunksOnThreads(static_cast<int>(numThreads), in.numPoints,
                     std::max<std::size_t>(in.numPoints / (64 * numThreads), 1024),
                     [&](int t, std::size_t first, std::size_t last) {
                       countRange(first, last, t == 0 ? perSlot.data() : partial[t - 1].data());
                     });
  for (const auto& p : partial)
    for (std::size_t s = 0; s < perSlot.size(); ++s) perSlot[s] += p[s];
}

// Bit k set where inside[k] (0 or -1) is set, k < n <= 64.
inline std::uint64_t maskOf(const std::int64_t* inside, int n) {
  std::uint64_t bits = 0;
  int k = 0;
#if defined(__AVX__)
  for (; k + 4 <= n; k += 4)
    bits |= static_cast<std::uint64_t>(_mm256_movemask_pd(_mm256_castsi256_pd(
                _mm256_loadu_si256(reinterpret_cast<const __m256i*>(inside + k)))))
            << k;
#elif defined(__SSE2__)
  for (; k + 2 <= n; k += 2)
    bits |= static_cast<std::uint64_t>(_mm_movemask_pd(
                _mm_castsi128_pd(_mm_loadu_si128(reinterpret_cast<const __m128i*>(inside + k)))))
            << k;
#endif
  for (; k < n; ++k) bits |= static_cast<std::uint64_t>(inside[k] & 1) << k;
  return bits;
}

// Each bond costs one load and two stores here (the list's write position, the neighbour), so
// the pass does not also load each list's end: a count that differs only shows when the pass
// is over (a list that ran past its end, or short of it, has its position off its end), and
// meanwhile a write is kept inside `out` by one compare with its size, held in a register.
struct FillPass {
  std::vector<int> slotOf;  // per candidate: the slot of the query it is, or -1
  std::vector<std::int64_t> next;
  std::int64_t size;  // of out
  int* out;
  [[noreturn]] static void mismatch() {
    throw std::logic_error(
        "neighbour search: a point's bonds differ from its count (internal error)");
  }
  void sphere(int s0, int n, const std::int64_t* inside, std::size_t j) {
    std::uint64_t bits = maskOf(inside, n);
    const int self = slotOf[j] - s0;  // the query itself is no neighbour
    if (self >= 0 && self < n) bits &= ~(std::uint64_t{1} << self);
    while (bits) {
      const int k = __builtin_ctzll(bits);
      bits &= bits - 1;
      found(s0 + k, j);
    }
  }
  void found(int s, std::size_t j) {
    const std::int64_t at = next[s]++;
    if (static_cast<std::uint64_t>(at) >= static_cast<std::uint64_t>(size)) mismatch();
    out[at] = static_cast<int>(j);
  }
};

}  // namespace

void countNeighbors(const NeighborSearchInput& in, const std::vector<std::size_t>& queries,
                    std::vector<int>& counts) {
  counts.assign(queries.size(), 0);
  if (in.numPoints == 0 || queries.empty()) return;
  const double reach = largestReach(in, queries);
  QueryGrid g;
  if (!buildQueryGrid(in, queries, reach, g)) {
    std::vector<long long> offsets;
    std::vector<std::size_t> neighbors;
    findNeighbors(in, queries, offsets, neighbors);
    for (std::size_t i = 0; i < queries.size(); ++i)
      counts[i] = static_cast<int>(offsets[i + 1] - offsets[i]);
    return;
  }
  CountPass pass;
  pass.perSlot.assign(queries.size(), 0);
  if (sphereOnly(in))
    countSphereOnce(in, queries, g, reach, pass.perSlot);  // a query never meets itself there
  else
    scanByCandidate(in, queries, g, reach, pass, false);
  for (std::size_t s = 0; s < queries.size(); ++s) counts[g.query[s]] = pass.perSlot[s];
}

void fillNeighbors(const NeighborSearchInput& in, const std::vector<std::size_t>& queries,
                   const std::vector<std::int64_t>& begin, const std::vector<int>& counts,
                   int* out) {
  if (in.numPoints == 0 || queries.empty()) return;
  const double reach = largestReach(in, queries);
  QueryGrid g;
  if (!buildQueryGrid(in, queries, reach, g)) {
    std::vector<long long> offsets;
    std::vector<std::size_t> neighbors;
    findNeighbors(in, queries, offsets, neighbors);
    for (std::size_t i = 0; i < queries.size(); ++i) {
      if (offsets[i + 1] - offsets[i] != counts[i]) FillPass::mismatch();
      std::sort(neighbors.begin() + offsets[i], neighbors.begin() + offsets[i + 1]);
      for (long long b = offsets[i]; b < offsets[i + 1]; ++b)
        out[begin[i] + (b - offsets[i])] = static_cast<int>(neighbors[b]);
    }
    return;
  }
  const std::size_t nq = queries.size();
  FillPass pass;
  pass.slotOf.assign(in.numPoints, -1);
  for (std::size_t s = 0; s < nq; ++s) pass.slotOf[queries[g.query[s]]] = static_cast<int>(s);
  pass.next.resize(nq);
  pass.out = out;
  pass.size = 0;
  for (std::size_t s = 0; s < nq; ++s) {
    pass.next[s] = begin[g.query[s]];
    pass.size = std::max(pass.size, pass.next[s] + counts[g.query[s]]);
  }
  scanByCandidate(in, queries, g, reach, pass, true);
  for (std::size_t s = 0; s < nq; ++s)
    if (pass.next[s] != begin[g.query[s]] + counts[g.query[s]]) FillPass::mismatch();
}

}  // namespace peridot
