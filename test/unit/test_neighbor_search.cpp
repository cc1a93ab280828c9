// The topology's search by candidate (countNeighbors + fillNeighbors) must find exactly the
// bonds of the per-query search (findNeighbors), in increasing candidate index, for every
// neighbourhood rule -- including pairs at the horizon to the last bit, where a different
// rounding of the squared distance would change the bond set.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "neighbor/NeighborSearch.hpp"

namespace peridot {
namespace {

struct Lists {
  std::vector<std::int64_t> begin;  // per query + 1
  std::vector<int> neighbors;
};

// The second code path: the per-query search, each list sorted.
Lists perQuery(const NeighborSearchInput& in, const std::vector<std::size_t>& queries) {
  std::vector<long long> offsets;
  std::vector<std::size_t> found;
  findNeighbors(in, queries, offsets, found);
  Lists l;
  l.begin.assign(offsets.begin(), offsets.end());
  for (std::size_t i = 0; i < queries.size(); ++i)
    std::sort(found.begin() + offsets[i], found.begin() + offsets[i + 1]);
  l.neighbors.assign(found.begin(), found.end());
  return l;
}

Lists byCandidate(const NeighborSearchInput& in, const std::vector<std::size_t>& queries) {
  std::vector<int> counts;
  countNeighbors(in, queries, counts);
  Lists l;
  l.begin.assign(queries.size() + 1, 0);
  for (std::size_t i = 0; i < queries.size(); ++i) l.begin[i + 1] = l.begin[i] + counts[i];
  l.neighbors.assign(static_cast<std::size_t>(l.begin.back()), -1);
  fillNeighbors(in, queries, l.begin, counts, l.neighbors.data());
  return l;
}

void expectSameLists(const NeighborSearchInput& in, const std::vector<std::size_t>& queries) {
  const Lists a = perQuery(in, queries), b = byCandidate(in, queries);
  ASSERT_EQ(a.begin, b.begin);
  EXPECT_EQ(a.neighbors, b.neighbors);
}

std::vector<std::size_t> allQueries(std::size_t n) {
  std::vector<std::size_t> q(n);
  for (std::size_t i = 0; i < n; ++i) q[i] = i;
  return q;
}

// An n^3 lattice of spacing h (not a binary fraction) far from the origin: many neighbours lie
// at exactly k h in real arithmetic, and whether the rounded squared distance passes the
// rounded squared horizon is decided by the last bit.
std::vector<double> lattice(int n, double h, double origin) {
  std::vector<double> x;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        x.insert(x.end(), {origin + i * h, origin + j * h, origin + k * h});
  return x;
}

TEST(NeighborSearchByCandidate, LatticeWithNeighboursAtTheHorizon) {
  for (double origin : {0.0, 0.37, 1234.567}) {
    for (double factor : {2.0, 3.0, std::sqrt(8.0)}) {
      for (auto kind :
           {NeighborhoodRule::Kind::SphereInclusive, NeighborhoodRule::Kind::SphereStrict}) {
        const double h = 0.1;
        std::vector<double> x = lattice(11, h, origin);
        const std::size_t n = x.size() / 3;
        std::vector<double> horizon(n, factor * h);
        NeighborSearchInput in;
        in.x = x.data();
        in.numPoints = n;
        in.horizon = horizon.data();
        in.rule.kind = kind;
        // The scene must have pairs on the knife edge, or it tests nothing.
        long long edge = 0;
        const double h2 = horizon[0] * horizon[0];
        for (std::size_t j = 1; j < n; ++j) {
          double d2 = 0;
          for (int d = 0; d < 3; ++d) d2 += (x[3 * j + d] - x[d]) * (x[3 * j + d] - x[d]);
          edge += std::fabs(d2 - h2) < 1e-9 * h2;
        }
        EXPECT_GT(edge, 0);
        expectSameLists(in, allQueries(n));
      }
    }
  }
}

// Random points, some queries only (the others are candidates, like a halo), every rule and
// option the topology uses.
TEST(NeighborSearchByCandidate, EveryRuleAndOption) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t n = 3000;
  std::vector<double> x(3 * n), horizon(n), edge(n);
  std::vector<int> block(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) x[3 * i + d] = u(gen) * (d == 2 ? 0.3 : 1.0);
    horizon[i] = i % 5 == 0 ? 0.16 : 0.12;
    edge[i] = i % 3 == 0 ? 0.05 : 0.03;
    block[i] = i % 4 == 0 ? 2 : 1;
  }
  std::vector<std::size_t> queries;  // points with x < 0.5, scattered over the index range
  for (std::size_t i = 0; i < n; ++i)
    if (x[3 * i] < 0.5) queries.push_back(i);
  BondFilter plane;
  plane.kind = BondFilter::Kind::RectangularPlane;
  plane.normal[0] = 1;
  plane.normal[2] = 0;
  plane.lowerLeftCorner[0] = 0.1;
  plane.lowerLeftCorner[1] = -0.5;
  plane.lowerLeftCorner[2] = -0.5;
  plane.bottomUnitVector[0] = 0;
  plane.bottomUnitVector[1] = 1;
  plane.bottomLength = 1.0;
  plane.sideLength = 1.0;
  const std::vector<BondFilter> filters{plane};

  auto base = [&] {
    NeighborSearchInput in;
    in.x = x.data();
    in.numPoints = n;
    in.horizon = horizon.data();
    in.blockId = block.data();
    return in;
  };
  {
    SCOPED_TRACE("sphere, horizons differ (each query its own)");
    expectSameLists(base(), queries);
  }
  {
    SCOPED_TRACE("union of horizons");
    NeighborSearchInput in = base();
    in.unionOfHorizons = true;
    expectSameLists(in, queries);
  }
  {
    SCOPED_TRACE("blocks omitted from each other, bond filter");
    NeighborSearchInput in = base();
    in.omitBondsBetweenBlocks = true;
    in.bondFilters = &filters;
    std::vector<long long> cutsA(1, 0), cutsB(1, 0);
    in.bondFilterCuts = &cutsA;
    const Lists a = perQuery(in, queries);
    std::vector<int> counts;
    in.bondFilterCuts = nullptr;
    countNeighbors(in, queries, counts);
    Lists b;
    b.begin.assign(queries.size() + 1, 0);
    for (std::size_t i = 0; i < queries.size(); ++i) b.begin[i + 1] = b.begin[i] + counts[i];
    b.neighbors.resize(static_cast<std::size_t>(b.begin.back()));
    in.bondFilterCuts = &cutsB;
    fillNeighbors(in, queries, b.begin, counts, b.neighbors.data());
    EXPECT_EQ(a.begin, b.begin);
    EXPECT_EQ(a.neighbors, b.neighbors);
    EXPECT_GT(cutsA[0], 0);
    EXPECT_EQ(cutsA, cutsB);  // one pass counts the cuts
  }
  {
    SCOPED_TRACE("box rule");
    NeighborSearchInput in = base();
    in.rule.kind = NeighborhoodRule::Kind::CellBox;
    for (int d = 0; d < 3; ++d) {
      in.rule.cellSize[d] = 0.05;
      in.rule.cellCount[d] = 40;
    }
    expectSameLists(in, queries);
  }
  {
    SCOPED_TRACE("cell overlap (partial volumes)");
    NeighborSearchInput in = base();
    std::vector<double> h(n, 0.12);
    in.horizon = h.data();
    in.rule.kind = NeighborhoodRule::Kind::CellOverlap;
    in.rule.overlapReach = 0.5 * std::sqrt(3.0) * 0.05;
    in.cellEdge = edge.data();
    expectSameLists(in, queries);
  }
}

// Points spread over a box far larger than they fill (an outlier 1e9 horizons away): the
// dense grid is refused and the sparse per-query search answers, with the same lists.
TEST(NeighborSearchByCandidate, FarOutlierUsesTheSparseSearch) {
  std::vector<double> x = lattice(8, 1.0, 0.0);
  x.insert(x.end(), {1e9, 2e9, -3e9});
  x.insert(x.end(), {1e9 + 0.5, 2e9, -3e9});
  const std::size_t n = x.size() / 3;
  std::vector<double> horizon(n, 1.5);
  NeighborSearchInput in;
  in.x = x.data();
  in.numPoints = n;
  in.horizon = horizon.data();
  const Lists l = byCandidate(in, allQueries(n));
  EXPECT_EQ(l.begin[n] - l.begin[n - 1], 1);  // the outliers see each other
  expectSameLists(in, allQueries(n));
}

// A count that does not match the lists is an internal error, not a silent overrun.
TEST(NeighborSearchByCandidate, WrongCountsAreRefused) {
  std::vector<double> x = lattice(4, 1.0, 0.0);
  const std::size_t n = x.size() / 3;
  std::vector<double> horizon(n, 1.1);
  NeighborSearchInput in;
  in.x = x.data();
  in.numPoints = n;
  in.horizon = horizon.data();
  std::vector<int> counts;
  countNeighbors(in, allQueries(n), counts);
  counts[5] -= 1;
  std::vector<std::int64_t> begin(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) begin[i + 1] = begin[i] + counts[i];
  std::vector<int> out(static_cast<std::size_t>(begin[n]) + 8);
  EXPECT_THROW(fillNeighbors(in, allQueries(n), begin, counts, out.data()), std::logic_error);
  // The list that ends the buffer one short: the pass must stop at the buffer's end (the fill
  // checks each list's end only when it is over), so the guard word after it stays untouched.
  countNeighbors(in, allQueries(n), counts);
  counts[n - 1] -= 1;
  for (std::size_t i = 0; i < n; ++i) begin[i + 1] = begin[i] + counts[i];
  std::vector<int> exact(static_cast<std::size_t>(begin[n]) + 1, -7);
  EXPECT_THROW(fillNeighbors(in, allQueries(n), begin, counts, exact.data()), std::logic_error);
  EXPECT_EQ(exact.back(), -7);
}

// The fill split among threads (by blocks of cells) writes the lists of one thread's run alone:
// the lists are those of one thread and of the per-query search, whatever the number, and a
// wrong count still throws (from whichever thread meets it).
TEST(NeighborSearchByCandidate, ThreadsWriteTheSameLists) {
  std::vector<double> x = lattice(28, 0.1, 0.37);
  const std::size_t n = x.size() / 3;
  std::vector<double> horizon(n, 3.015 * 0.1);
  NeighborSearchInput in;
  in.x = x.data();
  in.numPoints = n;
  in.horizon = horizon.data();
  const Lists one = byCandidate(in, allQueries(n));
  ASSERT_GT(one.neighbors.size(), 100 * n);  // ~120 a point inside: the blocks are many
  for (int threads : {2, 3, 7, 64}) {
    in.threads = threads;
    const Lists many = byCandidate(in, allQueries(n));
    EXPECT_EQ(one.begin, many.begin) << threads;
    EXPECT_EQ(one.neighbors, many.neighbors) << threads;
  }
  expectSameLists(in, allQueries(n));
  std::vector<int> counts;
  countNeighbors(in, allQueries(n), counts);
  counts[n - 10] += 1;  // a list late in the curve: the last thread's
  std::vector<std::int64_t> begin(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) begin[i + 1] = begin[i] + counts[i];
  std::vector<int> out(static_cast<std::size_t>(begin[n]));
  in.threads = 2;
  EXPECT_THROW(fillNeighbors(in, allQueries(n), begin, counts, out.data()), std::logic_error);
}

}  // namespace
// A bond filter gives the same answer from either end of a bond (the search asks from each end,
// and a cut seen from one end only would leave a one-sided bond): segments crossing a tilted
// rectangle and disk close to their edges, where the hit point's rounding decides.
TEST(BondFilters, CutTheSameFromEitherEnd) {
  BondFilter plane;
  plane.kind = BondFilter::Kind::RectangularPlane;
  const double n[3] = {0.36, 0.48, 0.8};  // unit
  const double bottom[3] = {0.8, -0.6, 0.0};
  for (int d = 0; d < 3; ++d) {
    plane.normal[d] = n[d];
    plane.bottomUnitVector[d] = bottom[d];
    plane.lowerLeftCorner[d] = 0.1 * (d + 1);
  }
  plane.bottomLength = 0.7;
  plane.sideLength = 0.3;
  BondFilter disk = plane;
  disk.kind = BondFilter::Kind::Disk;
  for (int d = 0; d < 3; ++d) disk.center[d] = plane.lowerLeftCorner[d];
  disk.radius = 0.3;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double side[3] = {n[1] * bottom[2] - n[2] * bottom[1], n[2] * bottom[0] - n[0] * bottom[2],
                          n[0] * bottom[1] - n[1] * bottom[0]};
  int differ = 0, cut = 0;
  for (const BondFilter* f : {&plane, &disk})
    for (int k = 0; k < 200000; ++k) {
      // A point on the filter's edge (a corner side, or the disk's rim), then a short bond
      // through it.
      double on[3];
      const double t = 0.5 * (u(rng) + 1.0);
      for (int d = 0; d < 3; ++d)
        on[d] = f == &plane ? plane.lowerLeftCorner[d] + t * plane.bottomLength * bottom[d]
                            : disk.center[d] + disk.radius * (std::cos(7 * t) * bottom[d] +
                                                              std::sin(7 * t) * side[d]);
      double p[3], q[3];
      for (int d = 0; d < 3; ++d) {
        const double dir = u(rng) * 1e-3;
        p[d] = on[d] + dir + 1e-3 * n[d];
        q[d] = on[d] - dir - 1e-3 * n[d];
      }
      const bool pq = f->cuts(p, q), qp = f->cuts(q, p);
      differ += pq != qp;
      cut += pq;
    }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(cut, 0);
}

}  // namespace peridot
