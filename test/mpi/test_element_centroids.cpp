// Exodus hexes become points at Peridigm's volume-weighted centroid, whatever the rank count: a
// cylinder-like ring of hexes (annular sectors with straight chords: planar faces, non-affine)
// read by 1-3 ranks, each point checked against its sector's centroid computed by hand.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../common/TestExodusMesh.hpp"
#include "discretization/Discretization.hpp"

namespace {

using peridot::testing::addNode;
using peridot::testing::TestBlock;
using peridot::testing::TestMesh;

constexpr int kSectors = 12, kRings = 2, kLayers = 2;
constexpr double kInner = 1.0, kRingWidth = 0.4, kHeight = 0.3;
const double kPi = std::acos(-1.0);

int nodeIndex(int sector, int ring, int layer) {  // 1-based Exodus node number
  return 1 + (layer * (kRings + 1) + ring) * kSectors + sector % kSectors;
}

TestMesh ringMesh() {
  TestMesh mesh;
  for (int layer = 0; layer <= kLayers; ++layer) {
    for (int ring = 0; ring <= kRings; ++ring) {
      for (int s = 0; s < kSectors; ++s) {
        const double r = kInner + kRingWidth * ring, t = 2 * kPi * s / kSectors;
        addNode(mesh, r * std::cos(t), r * std::sin(t), kHeight * layer);
      }
    }
  }
  TestBlock block;
  for (int layer = 0; layer < kLayers; ++layer) {
    for (int ring = 0; ring < kRings; ++ring) {
      for (int s = 0; s < kSectors; ++s) {
        for (int up = 0; up < 2; ++up) {  // counter-clockwise seen from +z, bottom then top
          for (const auto& corner : {std::pair{s, ring}, std::pair{s, ring + 1},
                                     std::pair{s + 1, ring + 1}, std::pair{s + 1, ring}}) {
            block.connectivity.push_back(nodeIndex(corner.first, corner.second, layer + up));
          }
        }
      }
    }
  }
  mesh.blocks = {block};
  return mesh;
}

TEST(ElementCentroids, CylinderRingPointsAreSectorCentroidsAtAnyRankCount) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::string path = (std::filesystem::temp_directory_path() /
                      ("peridot_ring_" + std::to_string(::getpid()) + ".g"))
                         .string();
  int length = static_cast<int>(path.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  path.resize(static_cast<std::size_t>(length));
  MPI_Bcast(path.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  if (rank == 0) peridot::testing::writeMesh(path, ringMesh());
  MPI_Barrier(MPI_COMM_WORLD);

  peridot::DiscretizationConfig config;
  config.type = "Exodus";
  config.meshFile = path;
  config.meshFilePath = "Discretization -> Input Mesh File";
  config.dimension = 0;
  const peridot::PointCloud share = peridot::buildPointCloud(config, MPI_COMM_WORLD);
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0) std::filesystem::remove(path);

  long long count = static_cast<long long>(share.size()), total = 0;
  MPI_Allreduce(&count, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  ASSERT_EQ(total, kSectors * kRings * kLayers);
  // The sector section is the quadrilateral of its corners: centroid by the polygon formula.
  const double dt = 2 * kPi / kSectors;
  for (std::size_t p = 0; p < share.size(); ++p) {
    const long long e = share.globalId[p];  // element id - 1, in the order written
    const int s = static_cast<int>(e % kSectors), ring = static_cast<int>(e / kSectors % kRings);
    const int layer = static_cast<int>(e / (kSectors * kRings));
    const double r1 = kInner + kRingWidth * ring, r2 = r1 + kRingWidth;
    const double t1 = dt * s, t2 = dt * (s + 1);
    const double q[4][2] = {{r1 * std::cos(t1), r1 * std::sin(t1)},
                            {r2 * std::cos(t1), r2 * std::sin(t1)},
                            {r2 * std::cos(t2), r2 * std::sin(t2)},
                            {r1 * std::cos(t2), r1 * std::sin(t2)}};
    double area = 0.0, cx = 0.0, cy = 0.0;
    for (int a = 0; a < 4; ++a) {
      const double cross = q[a][0] * q[(a + 1) % 4][1] - q[(a + 1) % 4][0] * q[a][1];
      area += 0.5 * cross;
      cx += (q[a][0] + q[(a + 1) % 4][0]) * cross / 6.0;
      cy += (q[a][1] + q[(a + 1) % 4][1]) * cross / 6.0;
    }
    EXPECT_NEAR(share.x[3 * p], cx / area, 1e-14) << "element " << e + 1;
    EXPECT_NEAR(share.x[3 * p + 1], cy / area, 1e-14) << "element " << e + 1;
    EXPECT_NEAR(share.x[3 * p + 2], kHeight * (layer + 0.5), 1e-14) << "element " << e + 1;
    EXPECT_NEAR(share.volume[p], area * kHeight, 1e-14) << "element " << e + 1;
    // The corner mean lies 2% of the ring width inside: the check can tell them apart.
    const double meanR = 0.5 * (r1 + r2) * std::cos(dt / 2);
    EXPECT_GT(std::hypot(cx / area, cy / area) - meanR, 0.01 * kRingWidth);
  }
}

}  // namespace
