// Decomposition, neighbour lists and ghost exchange on 1, 2 and 3 ranks: every rank's lists
// must equal a brute-force search over the whole cloud, and ghost copies must equal the owner's.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>

#include "../common/CloudShare.hpp"
#include "fields/FieldManager.hpp"
#include "parallel/Topology.hpp"

namespace peridot {
namespace {

PointCloud randomCloud(std::size_t n, unsigned seed) {
  PointCloud c;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    c.x.insert(c.x.end(), {u(gen), u(gen), 0.5 * u(gen)});
    c.volume.push_back(1e-3);
    c.blockId.push_back(i % 7 == 0 ? 2 : 1);
    c.globalId.push_back(static_cast<long long>(3 * i + 5));  // ids need not be contiguous
  }
  c.blockNames = {{1, "block_1"}, {2, "block_2"}};
  return c;
}

// Neighbour global ids of every point by brute force.
std::map<long long, std::vector<long long>> bruteForce(const PointCloud& c,
                                                       const std::vector<double>& h,
                                                       const std::vector<BondFilter>& filters) {
  std::map<long long, std::vector<long long>> out;
  for (std::size_t i = 0; i < c.size(); ++i) {
    auto& list = out[c.globalId[i]];
    for (std::size_t j = 0; j < c.size(); ++j) {
      if (i == j) continue;
      double d2 = 0;
      for (int d = 0; d < 3; ++d) d2 += std::pow(c.x[3 * j + d] - c.x[3 * i + d], 2);
      if (d2 > h[i] * h[i]) continue;
      bool cut = false;
      for (const auto& f : filters) cut = cut || f.cuts(&c.x[3 * i], &c.x[3 * j]);
      if (!cut) list.push_back(c.globalId[j]);
    }
    std::sort(list.begin(), list.end());
  }
  return out;
}

// Every owned point's list, as global ids in list order, is expected's list for it.
void expectOwnedListsAre(const Topology& t,
                         const std::map<long long, std::vector<long long>>& expected) {
  for (int i = 0; i < t.numOwned; ++i) {
    std::vector<long long> got;
    for (auto b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b)
      got.push_back(t.overlapGlobalId[t.neighbors[b]]);
    EXPECT_EQ(got, expected.at(t.overlapGlobalId[i])) << "point " << t.overlapGlobalId[i];
  }
}

void expectListsMatch(const PointCloud& cloud, const std::vector<double>& h,
                      const std::vector<BondFilter>& filters) {
  TopologyOptions options;
  options.bondFilters = &filters;
  Topology t = testing::topologyOfWhole(cloud, h, options, MPI_COMM_WORLD);
  const auto expected = bruteForce(cloud, h, filters);
  long long owned = t.numOwned, total = 0, bonds = 0;
  MPI_Allreduce(&owned, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(total, static_cast<long long>(cloud.size()));
  for (const auto& kv : expected) bonds += static_cast<long long>(kv.second.size());
  EXPECT_EQ(t.globalNumBonds, bonds);
  expectOwnedListsAre(t, expected);
}

TEST(Topology, NeighbourListsMatchBruteForce) {
  PointCloud cloud = randomCloud(1500, 7);
  std::vector<double> h(cloud.size(), 0.09);
  expectListsMatch(cloud, h, {});
}

// Partial volumes: j is listed when its cube (edge V_j^(1/3), volumes differ here) overlaps the
// ball of radius h around i; brute force over the whole cloud with the same rule written out.
TEST(Topology, CellOverlapListsMatchBruteForce) {
  PointCloud cloud = randomCloud(1500, 5);
  for (std::size_t i = 0; i < cloud.size(); ++i) cloud.volume[i] = i % 3 == 0 ? 8e-3 : 1e-3;
  std::vector<double> h(cloud.size(), 0.08);
  TopologyOptions options;
  options.rule.kind = NeighborhoodRule::Kind::CellOverlap;
  Topology t = testing::topologyOfWhole(cloud, h, options, MPI_COMM_WORLD);
  std::map<long long, std::vector<long long>> expected;
  long long bonds = 0, beyond = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    auto& list = expected[cloud.globalId[i]];
    for (std::size_t j = 0; j < cloud.size(); ++j) {
      if (i == j) continue;
      const double half = 0.5 * std::cbrt(cloud.volume[j]);
      double nearest2 = 0, d2 = 0;
      for (int d = 0; d < 3; ++d) {
        const double dx = cloud.x[3 * j + d] - cloud.x[3 * i + d];
        nearest2 += std::pow(std::max(std::fabs(dx) - half, 0.0), 2);
        d2 += dx * dx;
      }
      if (nearest2 < h[i] * h[i]) {
        list.push_back(cloud.globalId[j]);
        beyond += d2 > h[i] * h[i];
      }
    }
    std::sort(list.begin(), list.end());
    bonds += static_cast<long long>(list.size());
  }
  EXPECT_GT(beyond, 0);  // the rule reaches past the horizon
  EXPECT_EQ(t.globalNumBonds, bonds);
  expectOwnedListsAre(t, expected);
}

TEST(Topology, VariableHorizonListsAreUnionsWithSides) {
  // Differing horizons: j is listed by i if either horizon holds the bond; bit 0 of the bond's
  // sides says whether i's does, bit 1 whether j's does.
  PointCloud cloud = randomCloud(1200, 11);
  std::vector<double> h(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) h[i] = 0.05 + 0.08 * cloud.x[3 * i];
  Topology t = testing::topologyOfWhole(cloud, h, TopologyOptions{}, MPI_COMM_WORLD);
  std::map<long long, std::size_t> indexOf;
  for (std::size_t i = 0; i < cloud.size(); ++i) indexOf[cloud.globalId[i]] = i;
  ASSERT_FALSE(t.bondSides.empty() && t.numOwned > 50);
  long long oneSided = 0;
  for (int i = 0; i < t.numOwned; ++i) {
    const std::size_t ci = indexOf.at(t.overlapGlobalId[i]);
    std::vector<long long> expected;
    for (std::size_t j = 0; j < cloud.size(); ++j) {
      if (j == ci) continue;
      double d2 = 0;
      for (int d = 0; d < 3; ++d) d2 += std::pow(cloud.x[3 * j + d] - cloud.x[3 * ci + d], 2);
      if (d2 <= std::max(h[ci], h[j]) * std::max(h[ci], h[j]))
        expected.push_back(cloud.globalId[j]);
    }
    std::sort(expected.begin(), expected.end());
    std::vector<long long> got;
    for (auto b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
      const long long g = t.overlapGlobalId[t.neighbors[b]];
      got.push_back(g);
      const std::size_t cj = indexOf.at(g);
      double d2 = 0;
      for (int d = 0; d < 3; ++d) d2 += std::pow(cloud.x[3 * cj + d] - cloud.x[3 * ci + d], 2);
      const int sides = t.bondSides.empty() ? 3 : t.bondSides[b];
      EXPECT_EQ((sides & 1) != 0, d2 <= h[ci] * h[ci]);
      EXPECT_EQ((sides & 2) != 0, d2 <= h[cj] * h[cj]);
      oneSided += sides != 3;
    }
    EXPECT_EQ(got, expected) << "point " << t.overlapGlobalId[i];
  }
  long long total = 0;
  MPI_Allreduce(&oneSided, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(total, 0);
}

TEST(Topology, BondFiltersMatchBruteForce) {
  PointCloud cloud = randomCloud(1500, 3);
  std::vector<double> h(cloud.size(), 0.1);
  BondFilter plane;  // a crack from x = 0.5 halfway up the plate
  plane.kind = BondFilter::Kind::RectangularPlane;
  const double n[3] = {1, 0, 0}, corner[3] = {0.5, -0.1, -0.1}, bottom[3] = {0, 1, 0};
  std::copy(n, n + 3, plane.normal);
  std::copy(corner, corner + 3, plane.lowerLeftCorner);
  std::copy(bottom, bottom + 3, plane.bottomUnitVector);
  plane.bottomLength = 0.6;
  plane.sideLength = 1.0;
  BondFilter disk;
  disk.kind = BondFilter::Kind::Disk;
  const double c[3] = {0.25, 0.25, 0.25}, dn[3] = {0, 0, 1};
  std::copy(c, c + 3, disk.center);
  std::copy(dn, dn + 3, disk.normal);
  disk.radius = 0.2;
  expectListsMatch(cloud, h, {plane, disk});
  // The filters must actually remove bonds, or this test proves nothing.
  auto all = bruteForce(cloud, h, {}), cut = bruteForce(cloud, h, {plane, disk});
  std::size_t a = 0, b = 0;
  for (const auto& kv : all) a += kv.second.size();
  for (const auto& kv : cut) b += kv.second.size();
  EXPECT_LT(b, a - 100);
}

TEST(Topology, GhostExchangeCopiesOwnerValues) {
  PointCloud cloud = randomCloud(2000, 5);
  std::vector<double> h(cloud.size(), 0.08);
  Topology t = testing::topologyOfWhole(cloud, h, TopologyOptions{}, MPI_COMM_WORLD);
  FieldManager fields(t);
  double* s = fields.node("Scalar", 1);
  double* v = fields.node("Vector", 3);
  double* m = fields.node("Tensor", 9);  // a whole point a packet, whatever its width
  for (int i = 0; i < t.numOverlap; ++i) {
    const bool owned = i < t.numOwned;
    s[i] = owned ? 0.5 * static_cast<double>(t.overlapGlobalId[i]) : -1.0;
    for (int d = 0; d < 3; ++d) v[3 * i + d] = owned ? 10.0 * t.overlapGlobalId[i] + d : -1.0;
    for (int d = 0; d < 9; ++d) m[9 * i + d] = owned ? 100.0 * t.overlapGlobalId[i] + d : -1.0;
  }
  fields.refreshGhosts("Scalar");
  fields.refreshGhosts("Vector");
  fields.refreshGhosts("Tensor");
  for (int i = 0; i < t.numOverlap; ++i) {
    EXPECT_EQ(s[i], 0.5 * static_cast<double>(t.overlapGlobalId[i]));
    for (int d = 0; d < 3; ++d) EXPECT_EQ(v[3 * i + d], 10.0 * t.overlapGlobalId[i] + d);
    for (int d = 0; d < 9; ++d) EXPECT_EQ(m[9 * i + d], 100.0 * t.overlapGlobalId[i] + d);
  }
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size > 1) {
    long long ghosts = t.numOverlap - t.numOwned, total = 0;
    MPI_Allreduce(&ghosts, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_GT(total, 0);  // the exchange was exercised
  }
}

TEST(Topology, WeightedPartitionBalancesBonds) {
  // Points twice as dense on one side: balancing by bonds, not points.
  PointCloud cloud = randomCloud(3000, 9);
  for (std::size_t i = 0; i < cloud.size(); i += 2) cloud.x[3 * i] *= 0.3;
  std::vector<double> h(cloud.size(), 0.08);
  Topology t = testing::topologyOfWhole(cloud, h, TopologyOptions{}, MPI_COMM_WORLD);
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  long long mine = t.numBonds() + t.numOwned, maxWork = 0, total = 0;
  MPI_Allreduce(&mine, &maxWork, 1, MPI_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(&mine, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_LT(static_cast<double>(maxWork), 1.15 * static_cast<double>(total) / size);
}

}  // namespace
}  // namespace peridot

namespace peridot {
namespace {

TEST(Topology, PeriodicImagesMatchMinimumImageBruteForce) {
  // Periodic in x and y on [0,1)^2 x [0,0.5]: bonds to the images across the faces.
  PointCloud cloud = randomCloud(1500, 21);
  std::vector<double> h(cloud.size(), 0.12);
  TopologyOptions options;
  options.periodic.periodic[0] = options.periodic.periodic[1] = true;
  options.periodic.upper[0] = options.periodic.upper[1] = 1.0;
  Topology t = testing::topologyOfWhole(cloud, h, options, MPI_COMM_WORLD);
  FieldManager fields(t);
  double* x = fields.node("Model_Coordinates", 3);
  fields.markPosition("Model_Coordinates");
  for (int k = 0; k < t.numOwned; ++k)
    for (int d = 0; d < 3; ++d) x[3 * k + d] = t.referencePosition[3 * k + d];
  fields.refreshGhosts("Model_Coordinates");
  long long bonds = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    for (std::size_t j = 0; j < cloud.size(); ++j) {
      if (i == j) continue;
      double d2 = 0;
      for (int d = 0; d < 3; ++d) {
        double dx = cloud.x[3 * j + d] - cloud.x[3 * i + d];
        if (d < 2) dx -= std::round(dx);  // minimum image (the box is 1 wide)
        d2 += dx * dx;
      }
      if (d2 <= 0.12 * 0.12) ++bonds;
    }
  EXPECT_EQ(t.globalNumBonds, bonds);
  // Every bond, image or not, is within the horizon in the refreshed positions.
  for (int i = 0; i < t.numOwned; ++i)
    for (auto b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
      const int j = t.neighbors[b];
      double d2 = 0;
      for (int d = 0; d < 3; ++d) d2 += std::pow(x[3 * j + d] - x[3 * i + d], 2);
      ASSERT_LE(d2, 0.12 * 0.12 * (1 + 1e-12));
    }
  long long images = static_cast<long long>(t.imageSource.size()), total = 0;
  MPI_Allreduce(&images, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(total, 0);
}

}  // namespace
}  // namespace peridot

#include "neighbor/HalfBondList.hpp"
#include "neighbor/NeighborSearch.hpp"

namespace peridot {
namespace {

// A lattice whose spacing is no binary fraction, with neighbours at exactly 3 spacings in real
// arithmetic (the rounding decides them), global ids in a scrambled order (so the order of the
// lists is not the order of space): every rank's lists must be the per-query search of the
// whole cloud, sorted by global id, with the weighted re-partition (bond counts carried to the
// new owners) and without it.
TEST(Topology, KnifeEdgeLatticeListsMatchPerQuerySearchInOrder) {
  const int n = 14;
  const double h = 0.1, origin = 0.37;
  PointCloud cloud;
  std::vector<long long> ids(static_cast<std::size_t>(n) * n * n);
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<long long>(i);
  std::shuffle(ids.begin(), ids.end(), std::mt19937(5));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        cloud.x.insert(cloud.x.end(), {origin + i * h, origin + j * h, origin + k * h});
        cloud.volume.push_back(h * h * h);
        cloud.blockId.push_back(1);
        cloud.globalId.push_back(ids[cloud.globalId.size()]);
      }
  cloud.blockNames = {{1, "block_1"}};
  std::vector<double> horizon(cloud.size(), 3 * h);

  // The per-query search over the whole cloud, lists as sorted global ids.
  NeighborSearchInput in;
  in.x = cloud.x.data();
  in.numPoints = cloud.size();
  in.horizon = horizon.data();
  std::vector<std::size_t> queries(cloud.size());
  for (std::size_t q = 0; q < queries.size(); ++q) queries[q] = q;
  std::vector<long long> offsets;
  std::vector<std::size_t> found;
  findNeighbors(in, queries, offsets, found);
  std::map<long long, std::vector<long long>> expected;
  long long expectedBonds = 0;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    auto& list = expected[cloud.globalId[q]];
    for (long long b = offsets[q]; b < offsets[q + 1]; ++b)
      list.push_back(cloud.globalId[found[b]]);
    std::sort(list.begin(), list.end());
    expectedBonds += static_cast<long long>(list.size());
  }
  ASSERT_GT(expectedBonds, 0);

  // Also with the search's count and fill passes shared among threads (a rank's spare
  // processors): the same lists.
  for (int threads : {1, 3})
    for (bool weighted : {true, false}) {
      SCOPED_TRACE(weighted ? "weighted re-partition" : "one partition");
      SCOPED_TRACE("threads " + std::to_string(threads));
      TopologyOptions options;
      options.weightByBondCount = weighted;
      options.searchThreads = threads;
      Topology t = testing::topologyOfWhole(cloud, horizon, options, MPI_COMM_WORLD);
      EXPECT_EQ(t.globalNumBonds, expectedBonds);
      expectOwnedListsAre(t, expected);
    }
}

// The half bond list built with its passes shared among threads is the one-thread list, array
// for array: owned rows split among threads, and (on 2 and 3 ranks) ghost rows whose pairs come
// from several threads' runs of rows.
TEST(Topology, HalfBondListTheSameOnThreads) {
  const int n = 22;
  PointCloud cloud;
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        cloud.x.insert(cloud.x.end(), {i + jitter(gen), j + jitter(gen), k + jitter(gen)});
        cloud.volume.push_back(1.0);
        cloud.blockId.push_back(1);
        cloud.globalId.push_back(static_cast<long long>(cloud.globalId.size()));
      }
  cloud.blockNames = {{1, "block_1"}};
  std::vector<double> horizon(cloud.size(), 2.1);
  Topology t = testing::topologyOfWhole(cloud, horizon, TopologyOptions{}, MPI_COMM_WORLD);
  HalfBondList one;
  ASSERT_TRUE(buildHalfBondList(t, one, 1));
  ASSERT_GT(one.numPairs(), 0);
  for (int threads : {2, 3, 8}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    HalfBondList many;
    ASSERT_TRUE(buildHalfBondList(t, many, threads));
    EXPECT_EQ(one.rowPoint, many.rowPoint);
    EXPECT_EQ(one.rowPairOffsets, many.rowPairOffsets);
    EXPECT_EQ(one.rowIntact, many.rowIntact);
    EXPECT_EQ(one.pairPoint, many.pairPoint);
    EXPECT_EQ(one.pairSlot, many.pairSlot);
    EXPECT_EQ(one.pairSlotHigh, many.pairSlotHigh);
    EXPECT_EQ(one.longestRow, many.longestRow);
  }
}

}  // namespace
}  // namespace peridot
