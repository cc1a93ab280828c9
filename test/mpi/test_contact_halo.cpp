// Contact search with a halo on 1, 2 and 3 ranks: two bodies whose current positions are far
// from their reference ones (the second body has travelled towards the first), searched by
// ShortRangeContact. Every owned point's contact list must equal a brute-force search over the
// whole cloud (same ids, in global-id order), and each rank must receive exactly the other
// ranks' points near its box of current positions: not the whole cloud.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "../common/CloudShare.hpp"
#include "contact/ShortRangeContact.hpp"
#include "parallel/Topology.hpp"

namespace peridot {
namespace {

constexpr double kSpacing = 0.1;

struct Scene {
  PointCloud cloud;
  std::vector<double> horizon;
  std::vector<double> y;  // current positions, 3 per point of the whole cloud
};

// Body A: a 10x6x6 grid in [0, 1) x [0, 0.6)^2 (block_1). Body B: the same grid with reference
// positions at x + 5 (blocks 2 and 3, alternating), now displaced by -4 in x so that its
// near face is 0.1 from A's far face. Current positions carry a small random jitter; global
// ids are scrambled so that ownership and id order are unrelated.
Scene twoBodies() {
  Scene s;
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  long long id = 0;
  for (int body = 0; body < 2; ++body)
    for (int k = 0; k < 6; ++k)
      for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 10; ++i) {
          const double x[3] = {(i + 0.5) * kSpacing + (body ? 5.0 : 0.0), (j + 0.5) * kSpacing,
                               (k + 0.5) * kSpacing};
          s.cloud.x.insert(s.cloud.x.end(), x, x + 3);
          s.cloud.volume.push_back(kSpacing * kSpacing * kSpacing);
          s.cloud.blockId.push_back(body == 0 ? 1 : 2 + (i + j + k) % 2);
          s.cloud.globalId.push_back((id * 37) % 720);  // 720 points; 37 is prime to 720
          ++id;
          s.y.push_back(x[0] - (body ? 4.0 : 0.0) + jitter(gen));
          s.y.push_back(x[1] + jitter(gen));
          s.y.push_back(x[2] + jitter(gen));
        }
  s.cloud.blockNames = {{1, "block_1"}, {2, "block_2"}, {3, "block_3"}};
  s.horizon.assign(s.cloud.size(), 1.01 * kSpacing);  // bonds to the 6 nearest grid points
  return s;
}

double distance2(const double* a, const double* b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
  return dx * dx + dy * dy + dz * dz;
}

TEST(ContactHalo, ListsMatchBruteForceAndHaloIsLocal) {
  const Scene s = twoBodies();
  const std::size_t total = s.cloud.size();
  TopologyOptions options;
  options.omitBondsBetweenBlocks = true;
  Topology t = testing::topologyOfWhole(s.cloud, s.horizon, options, MPI_COMM_WORLD);

  ContactConfig config;
  config.enabled = true;
  config.searchRadius = 1.6 * kSpacing;
  config.contactRadius = 1.2 * kSpacing;
  config.springConstant = 1e12;
  // block_1 touches block_2 only; block_2 and block_3 touch each other and themselves.
  config.pairs = {{"block_1", "block_2"},
                  {"block_2", "block_2"},
                  {"block_2", "block_3"},
                  {"block_3", "block_3"}};
  std::map<long long, std::size_t> indexOfId;
  for (std::size_t p = 0; p < total; ++p) indexOfId[s.cloud.globalId[p]] = p;
  std::vector<std::string> blockName(t.numOwned);
  std::vector<double> horizon(t.numOwned), volume(t.numOwned), y(3 * t.numOwned);
  for (int i = 0; i < t.numOwned; ++i) {
    const std::size_t p = indexOfId.at(t.overlapGlobalId[i]);
    blockName[i] = s.cloud.blockNames.at(s.cloud.blockId[p]);
    horizon[i] = s.horizon[p];
    volume[i] = s.cloud.volume[p];
    for (int d = 0; d < 3; ++d) y[3 * i + d] = s.y[3 * p + d];
  }
  Timers timers;
  ShortRangeContact contact(config, t, blockName, horizon.data(), volume.data(), timers);
  contact.search(y.data());

  // Brute force: within the search radius now, not bonded (bonds: same block and within the
  // horizon in the reference configuration), and the blocks interact.
  const auto lists = contact.contactListIds();
  ASSERT_EQ(lists.size(), static_cast<std::size_t>(t.numOwned));
  long long pairs = 0, crossBody = 0;
  for (int i = 0; i < t.numOwned; ++i) {
    const std::size_t p = indexOfId.at(t.overlapGlobalId[i]);
    std::vector<long long> expected;
    for (std::size_t q = 0; q < total; ++q) {
      if (q == p) continue;
      if (distance2(&s.y[3 * p], &s.y[3 * q]) > config.searchRadius * config.searchRadius) continue;
      if (s.cloud.blockId[p] == s.cloud.blockId[q] &&
          distance2(&s.cloud.x[3 * p], &s.cloud.x[3 * q]) <= s.horizon[p] * s.horizon[p])
        continue;
      if (!config.interacts(s.cloud.blockNames.at(s.cloud.blockId[p]),
                            s.cloud.blockNames.at(s.cloud.blockId[q])))
        continue;
      expected.push_back(s.cloud.globalId[q]);
      if ((s.cloud.blockId[p] == 1) != (s.cloud.blockId[q] == 1)) ++crossBody;
    }
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(lists[i], expected) << "point " << t.overlapGlobalId[i];
    pairs += static_cast<long long>(expected.size());
  }
  long long allPairs = 0, allCross = 0;
  MPI_Allreduce(&pairs, &allPairs, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(&crossBody, &allCross, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(allCross, 0) << "the bodies must be in contact for the test to mean anything";
  EXPECT_GT(allPairs, allCross) << "and some same-body pairs must be in the lists too";

  // The halo: exactly the other ranks' points whose current position lies within the search
  // radius of this rank's box of current owned positions (positions are random, so no point is
  // within the search's small safety margin of that bound).
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (int i = 0; i < t.numOwned; ++i)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], y[3 * i + d]);
      hi[d] = std::max(hi[d], y[3 * i + d]);
    }
  std::vector<char> owned(total, 0);
  for (int i = 0; i < t.numOwned; ++i) owned[indexOfId.at(t.overlapGlobalId[i])] = 1;
  long long near = 0;
  for (std::size_t q = 0; q < total && t.numOwned > 0; ++q) {
    bool inside = !owned[q];
    for (int d = 0; d < 3 && inside; ++d)
      inside = s.y[3 * q + d] >= lo[d] - config.searchRadius &&
               s.y[3 * q + d] <= hi[d] + config.searchRadius;
    near += inside;
  }
  EXPECT_EQ(contact.numHaloPoints(), near);
  if (t.numRanks > 1) {
    EXPECT_LT(t.numOwned + contact.numHaloPoints(), static_cast<long long>(total))
        << "a rank holds the whole cloud during the search";
  } else {
    EXPECT_EQ(contact.numHaloPoints(), 0);
  }

  // The forces through the contact ghosts: equal and opposite pair forces sum to zero.
  std::vector<double> v(3 * t.numOwned, 0.0), f(3 * t.numOwned);
  contact.computeForce(y.data(), v.data(), f.data());
  double sum[3] = {0, 0, 0}, scale = 0, allSum[3], allScale = 0;
  for (int i = 0; i < t.numOwned; ++i)
    for (int d = 0; d < 3; ++d) {
      sum[d] += volume[i] * f[3 * i + d];
      scale += std::fabs(volume[i] * f[3 * i + d]);
    }
  MPI_Allreduce(sum, allSum, 3, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(&scale, &allScale, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(allScale, 0.0);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(allSum[d], 0.0, 1e-12 * allScale);
}

}  // namespace
}  // namespace peridot
