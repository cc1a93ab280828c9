// Element geometry and the Exodus mesh reader.
#include <exodusII.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numeric>
#include <string>
#include <vector>

#include "TempFile.hpp"
#include "TestExodusMesh.hpp"
#include "core/Error.hpp"
#include "discretization/ElementGeometry.hpp"
#include "discretization/ExodusMeshReader.hpp"
#include "output/ExodusCompare.hpp"

#ifndef PERIDOT_SHARED_DIR
#define PERIDOT_SHARED_DIR "../shared"
#endif

namespace {

using peridot::InputError;

const std::string kCases = std::string(PERIDOT_SHARED_DIR) + "/peridigm-cases";
const char* const kDeckPath = "Discretization -> Input Mesh File";

// Reference corners of the unit cube [0,1]^3 in Exodus HEX8 order.
constexpr double kUnitCube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

using peridot::testing::addNode;
using peridot::testing::TempFile;
using peridot::testing::tempPath;
using peridot::testing::TestBlock;
using peridot::testing::TestMesh;
using peridot::testing::TestNodeSet;
using peridot::testing::writeMesh;

// Expects f() to throw InputError whose message contains every one of parts.
template <class F>
void expectInputError(F f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no InputError thrown";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const auto& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos)
          << "message \"" << message << "\" lacks \"" << part << "\"";
    }
  }
}

// ---- independent reference for the trilinear hex: Simpson's rule in each reference direction
// (exact for polynomials of degree 3, which detJ and x*detJ are), with the Jacobian from central
// differences of the map (exact, the map being linear in each reference coordinate).

void trilinearMap(const double nodes[8][3], double u, double v, double w, double x[3]) {
  // (u, v, w) in [0,1]^3; corner a sits at kUnitCube[a].
  for (int k = 0; k < 3; ++k) x[k] = 0.0;
  for (int a = 0; a < 8; ++a) {
    const double s = (kUnitCube[a][0] ? u : 1 - u) * (kUnitCube[a][1] ? v : 1 - v) *
                     (kUnitCube[a][2] ? w : 1 - w);
    for (int k = 0; k < 3; ++k) x[k] += s * nodes[a][k];
  }
}

double referenceHex(const double nodes[8][3], double centroid[3]) {
  const int n = 4;  // Simpson intervals per direction
  const double h = 1.0 / n;
  const double eps = 0.25;
  double volume = 0.0;
  double moment[3] = {0, 0, 0};
  const auto weight = [&](int i) { return (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0); };
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      for (int k = 0; k <= n; ++k) {
        const double p[3] = {i * h, j * h, k * h};
        double J[3][3];
        for (int d = 0; d < 3; ++d) {
          double plus[3] = {p[0], p[1], p[2]};
          double minus[3] = {p[0], p[1], p[2]};
          plus[d] += eps;
          minus[d] -= eps;
          double xp[3], xm[3];
          trilinearMap(nodes, plus[0], plus[1], plus[2], xp);
          trilinearMap(nodes, minus[0], minus[1], minus[2], xm);
          for (int c = 0; c < 3; ++c) J[c][d] = (xp[c] - xm[c]) / (2 * eps);
        }
        const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                           J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                           J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
        const double wgt = weight(i) * weight(j) * weight(k) * (h / 3) * (h / 3) * (h / 3);
        double x[3];
        trilinearMap(nodes, p[0], p[1], p[2], x);
        volume += wgt * det;
        for (int c = 0; c < 3; ++c) moment[c] += wgt * det * x[c];
      }
    }
  }
  for (int c = 0; c < 3; ++c) centroid[c] = moment[c] / volume;
  return volume;
}

// ---- ElementGeometry ----

TEST(ElementGeometry, AffineHexVolumeIsDeterminant) {
  const double A[3][3] = {{2.0, 0.3, 0.1}, {0.2, 1.5, -0.4}, {0.1, 0.25, 0.8}};
  const double b[3] = {1.0, -2.0, 0.5};
  double nodes[8][3];
  for (int a = 0; a < 8; ++a) {
    for (int i = 0; i < 3; ++i) {
      nodes[a][i] = b[i];
      for (int j = 0; j < 3; ++j) nodes[a][i] += A[i][j] * kUnitCube[a][j];
    }
  }
  const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                     A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                     A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  ASSERT_GT(det, 0.0);
  EXPECT_NEAR(peridot::hexVolume(nodes), det, 1e-14);
  double average[3], centroid[3];
  peridot::hexNodeAverage(nodes, average);
  EXPECT_NEAR(peridot::hexCentroid(nodes, centroid), det, 1e-14);
  for (int i = 0; i < 3; ++i) {
    const double expected = b[i] + 0.5 * (A[i][0] + A[i][1] + A[i][2]);
    EXPECT_NEAR(average[i], expected, 1e-14);
    EXPECT_NEAR(centroid[i], expected, 1e-14);  // affine: centroid = node average
  }
}

TEST(ElementGeometry, FrustumHexVolumeAndCentroid) {
  // Square frustum: base [0,2]^2 at z=0, top [0.5,1.5]^2 at z=1. Planar faces, non-affine map.
  // V = h/3 (A1 + A2 + sqrt(A1 A2)) = 7/3; centroid height h (A1 + 2 sqrt(A1 A2) + 3 A2) /
  // (4 (A1 + sqrt(A1 A2) + A2)) = 11/28.
  const double nodes[8][3] = {{0, 0, 0},       {2, 0, 0},       {2, 2, 0},       {0, 2, 0},
                              {0.5, 0.5, 1.0}, {1.5, 0.5, 1.0}, {1.5, 1.5, 1.0}, {0.5, 1.5, 1.0}};
  EXPECT_NEAR(peridot::hexVolume(nodes), 7.0 / 3.0, 1e-14);
  double centroid[3], average[3];
  EXPECT_NEAR(peridot::hexCentroid(nodes, centroid), 7.0 / 3.0, 1e-14);
  EXPECT_NEAR(centroid[0], 1.0, 1e-14);
  EXPECT_NEAR(centroid[1], 1.0, 1e-14);
  EXPECT_NEAR(centroid[2], 11.0 / 28.0, 1e-14);
  peridot::hexNodeAverage(nodes, average);  // not the point: see hexTetCentroid
  EXPECT_DOUBLE_EQ(average[0], 1.0);
  EXPECT_DOUBLE_EQ(average[1], 1.0);
  EXPECT_DOUBLE_EQ(average[2], 0.5);
}

TEST(ElementGeometry, DistortedHexMatchesIndependentIntegration) {
  // A hex with one node pulled out and warped (non-planar) faces.
  double nodes[8][3];
  std::copy(&kUnitCube[0][0], &kUnitCube[0][0] + 24, &nodes[0][0]);
  nodes[6][0] = 1.6;
  nodes[6][1] = 1.3;
  nodes[6][2] = 1.45;
  nodes[1][2] = 0.2;
  nodes[3][0] = -0.15;
  nodes[4][1] = 0.1;
  double expectedCentroid[3];
  const double expected = referenceHex(nodes, expectedCentroid);
  double centroid[3], average[3];
  EXPECT_NEAR(peridot::hexVolume(nodes), expected, 1e-13);
  EXPECT_NEAR(peridot::hexCentroid(nodes, centroid), expected, 1e-13);
  peridot::hexNodeAverage(nodes, average);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(centroid[k], expectedCentroid[k], 1e-13);
    double sum = 0.0;
    for (int a = 0; a < 8; ++a) sum += nodes[a][k];
    EXPECT_DOUBLE_EQ(average[k], sum / 8.0);
  }
  // A unit cube with only node 7 moved out along the diagonal.
  double moved[8][3];
  std::copy(&kUnitCube[0][0], &kUnitCube[0][0] + 24, &moved[0][0]);
  moved[6][0] = moved[6][1] = moved[6][2] = 1.5;
  double c[3];
  EXPECT_NEAR(peridot::hexVolume(moved), referenceHex(moved, c), 1e-13);
}

// ---- Peridigm's hex point: 24 tetrahedra ----

// A hex of planar faces is the polyhedron itself, so its centroid is a property of the solid:
// a truncated pyramid over a general quadrilateral (top = bottom scaled by 0.6 towards an apex
// off the axis), i.e. skewed and graded. Gold: the independent Gauss integration referenceHex.
TEST(ElementGeometry, HexTetCentroidIsExactForPlanarFaces) {
  const double bottom[4][3] = {{0, 0, 0}, {2.0, 0.3, 0}, {2.4, 1.9, 0}, {-0.2, 1.5, 0}};
  const double apex[3] = {1.7, 0.4, 3.0};
  double nodes[8][3];
  for (int a = 0; a < 4; ++a) {
    for (int k = 0; k < 3; ++k) {
      nodes[a][k] = bottom[a][k];
      nodes[a + 4][k] = apex[k] + 0.6 * (bottom[a][k] - apex[k]);
    }
  }
  double expected[3], centroid[3], average[3];
  const double volume = referenceHex(nodes, expected);
  EXPECT_NEAR(peridot::hexTetCentroid(nodes, centroid), volume, 1e-13);
  peridot::hexNodeAverage(nodes, average);
  double offset = 0.0;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(centroid[k], expected[k], 1e-13) << k;
    offset = std::max(offset, std::fabs(average[k] - expected[k]));
  }
  EXPECT_GT(offset, 0.05);  // the corner mean is far off: the test can tell them apart
}

TEST(ElementGeometry, HexTetCentroidOfAFrustum) {
  // The frustum above, by hand: V = 7/3, centroid (1, 1, 11/28) where the corner mean has z = 1/2.
  const double nodes[8][3] = {{0, 0, 0},       {2, 0, 0},       {2, 2, 0},       {0, 2, 0},
                              {0.5, 0.5, 1.0}, {1.5, 0.5, 1.0}, {1.5, 1.5, 1.0}, {0.5, 1.5, 1.0}};
  double c[3];
  EXPECT_NEAR(peridot::hexTetCentroid(nodes, c), 7.0 / 3.0, 1e-14);
  EXPECT_NEAR(c[0], 1.0, 1e-14);
  EXPECT_NEAR(c[1], 1.0, 1e-14);
  EXPECT_NEAR(c[2], 11.0 / 28.0, 1e-14);
}

// A cylinder's element: the annular sector r in [r1, r2], theta in [t1, t2], z in [0, h], with
// straight chords. Its section is the quadrilateral of the four corners, extruded along z, so the
// centroid is the section's (polygon formula, by hand) at z = h/2 and the volume area x h.
TEST(ElementGeometry, HexTetCentroidOfACylinderSector) {
  const double r1 = 1.0, r2 = 1.5, t1 = 0.3, t2 = 0.3 + 0.4, h = 0.25;
  const double q[4][2] = {{r1 * std::cos(t1), r1 * std::sin(t1)},
                          {r2 * std::cos(t1), r2 * std::sin(t1)},
                          {r2 * std::cos(t2), r2 * std::sin(t2)},
                          {r1 * std::cos(t2), r1 * std::sin(t2)}};
  double area = 0.0, cx = 0.0, cy = 0.0;
  for (int a = 0; a < 4; ++a) {
    const double* p = q[a];
    const double* n = q[(a + 1) % 4];
    const double cross = p[0] * n[1] - n[0] * p[1];
    area += 0.5 * cross;
    cx += (p[0] + n[0]) * cross / 6.0;
    cy += (p[1] + n[1]) * cross / 6.0;
  }
  cx /= area;
  cy /= area;
  double nodes[8][3];
  for (int a = 0; a < 4; ++a) {
    nodes[a][0] = nodes[a + 4][0] = q[a][0];
    nodes[a][1] = nodes[a + 4][1] = q[a][1];
    nodes[a][2] = 0.0;
    nodes[a + 4][2] = h;
  }
  double c[3], average[3];
  EXPECT_NEAR(peridot::hexTetCentroid(nodes, c), area * h, 1e-14);
  EXPECT_NEAR(c[0], cx, 1e-14);
  EXPECT_NEAR(c[1], cy, 1e-14);
  EXPECT_NEAR(c[2], h / 2, 1e-14);
  peridot::hexNodeAverage(nodes, average);
  EXPECT_GT(std::hypot(average[0] - cx, average[1] - cy), 1e-3);  // 0.2% of the element size
}

// With warped faces the split is an approximation of the trilinear solid: its volume is still
// exact (the fan around each face centre integrates the bilinear face exactly), its centroid not.
TEST(ElementGeometry, HexTetVolumeIsTheTrilinearVolumeForWarpedFaces) {
  double nodes[8][3];
  std::copy(&kUnitCube[0][0], &kUnitCube[0][0] + 24, &nodes[0][0]);
  nodes[6][0] = 1.6;
  nodes[6][1] = 1.3;
  nodes[6][2] = 1.45;
  nodes[1][2] = 0.2;
  nodes[3][0] = -0.15;
  nodes[4][1] = 0.1;
  double expected[3], c[3];
  EXPECT_NEAR(peridot::hexTetCentroid(nodes, c), referenceHex(nodes, expected), 1e-13);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], expected[k], 0.02);
  double mirrored[8][3];
  for (int a = 0; a < 8; ++a) std::copy(nodes[(a + 4) % 8], nodes[(a + 4) % 8] + 3, mirrored[a]);
  double m[3];
  EXPECT_NEAR(peridot::hexTetCentroid(mirrored, m), -referenceHex(nodes, expected), 1e-13);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(m[k], c[k], 1e-14);
}

TEST(ElementGeometry, QuadCentroidIsThePolygonCentroid) {
  const double q[4][2] = {{0.1, -0.2}, {2.3, 0.1}, {1.9, 1.7}, {-0.4, 1.1}};
  double area = 0.0, cx = 0.0, cy = 0.0;
  for (int a = 0; a < 4; ++a) {
    const double* p = q[a];
    const double* n = q[(a + 1) % 4];
    const double cross = p[0] * n[1] - n[0] * p[1];
    area += 0.5 * cross;
    cx += (p[0] + n[0]) * cross / 6.0;
    cy += (p[1] + n[1]) * cross / 6.0;
  }
  double c[2];
  EXPECT_NEAR(peridot::quadCentroid(q, c), area, 1e-14);
  EXPECT_NEAR(c[0], cx / area, 1e-14);
  EXPECT_NEAR(c[1], cy / area, 1e-14);
}

TEST(ElementGeometry, MirroredHexHasNegativeVolume) {
  double nodes[8][3];
  for (int a = 0; a < 8; ++a) {
    for (int k = 0; k < 3; ++k) nodes[a][k] = kUnitCube[(a + 4) % 8][k];  // top face first
  }
  EXPECT_NEAR(peridot::hexVolume(nodes), -1.0, 1e-14);
}

TEST(ElementGeometry, TetVolumeAndCentroid) {
  const double tet[4][3] = {{1, 1, 1}, {3, 1, 1}, {1, 4, 1}, {1, 1, 5}};
  EXPECT_NEAR(peridot::tetVolume(tet), 2.0 * 3.0 * 4.0 / 6.0, 1e-14);
  const double flipped[4][3] = {{1, 1, 1}, {1, 4, 1}, {3, 1, 1}, {1, 1, 5}};
  EXPECT_NEAR(peridot::tetVolume(flipped), 4.0, 1e-14);
  double c[3];
  peridot::tetCentroid(tet, c);
  EXPECT_DOUBLE_EQ(c[0], 1.5);
  EXPECT_DOUBLE_EQ(c[1], 1.75);
  EXPECT_DOUBLE_EQ(c[2], 2.0);
  const double flat[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  EXPECT_EQ(peridot::tetVolume(flat), 0.0);
}

// ---- reading the shipped meshes ----

TEST(ExodusMeshReader, ReadsWaveInBar) {
  const auto cloud = peridot::readExodusMesh(kCases + "/WaveInBar/WaveInBar.g", kDeckPath);
  ASSERT_EQ(cloud.size(), 525u);
  EXPECT_EQ(cloud.dimension, 3);
  EXPECT_EQ(cloud.x.size(), 3 * 525u);
  EXPECT_EQ(cloud.blockId.size(), 525u);
  ASSERT_EQ(cloud.blockNames.size(), 1u);
  EXPECT_EQ(cloud.blockNames.at(1), "block_1");
  for (int b : cloud.blockId) EXPECT_EQ(b, 1);
  // No element number map in the file: ids 1..525 in file order.
  for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_EQ(cloud.globalId[i], (long long)i);
  // The bar is the box [-0.021,0.021] x [-0.005,0.005]^2 filled with hexes.
  const double total = std::accumulate(cloud.volume.begin(), cloud.volume.end(), 0.0);
  EXPECT_NEAR(total, 0.042 * 0.01 * 0.01, 1e-12 * 4.2e-6 * 525);
  for (double v : cloud.volume) EXPECT_GT(v, 0.0);
  ASSERT_EQ(cloud.pointSets.size(), 1u);
  EXPECT_EQ(cloud.pointSets[0].name, "nodelist_1");
  const auto& ids = cloud.pointSets[0].globalIds;
  EXPECT_FALSE(ids.empty());
  EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
  EXPECT_EQ(std::adjacent_find(ids.begin(), ids.end()), ids.end());
  for (long long id : ids) {
    EXPECT_GE(id, 0);
    EXPECT_LT(id, 525);
  }
}

// The points are where Peridigm put them: compare with the gold output's sphere nodes by id.
void expectPositionsMatchGold(const std::string& mesh, const std::string& gold) {
  const auto cloud = peridot::readExodusMesh(mesh, kDeckPath);
  const auto results = peridot::readExodusResults(gold);
  ASSERT_EQ(results.nodeIds.size(), cloud.size());
  std::vector<long long> index(cloud.size() + 1, -1);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    ASSERT_LT(cloud.globalId[i], (long long)cloud.size());
    index[static_cast<std::size_t>(cloud.globalId[i])] = static_cast<long long>(i);
  }
  for (std::size_t n = 0; n < results.nodeIds.size(); ++n) {
    const long long p = index[static_cast<std::size_t>(results.nodeIds[n] - 1)];
    ASSERT_GE(p, 0);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(cloud.x[3 * static_cast<std::size_t>(p) + k], results.nodeCoordinates[3 * n + k],
                  1e-12)
          << "node id " << results.nodeIds[n];
    }
  }
}

TEST(ExodusMeshReader, PositionsMatchPeridigmGolds) {
  expectPositionsMatchGold(kCases + "/WaveInBar/WaveInBar.g",
                           kCases + "/WaveInBar/WaveInBar_gold.e");
  expectPositionsMatchGold(kCases + "/Contact_Cubes/Contact_Cubes.g",
                           kCases + "/Contact_Cubes/Contact_Cubes_gold.e");
  expectPositionsMatchGold(kCases + "/ElasticBondBased3D/ElasticBondBased3D.g",
                           kCases + "/ElasticBondBased3D/ElasticBondBased3D_gold.e");
}

// Peridigm 1.5 wrote ElasticBondBased3D's gold: its points and volumes are reproduced to the
// bit (the 24-tetrahedra split, same operands, same order, no fused multiply-add). The WaveInBar
// and Contact_Cubes golds come from an older Peridigm that used the corner mean: on their box
// meshes the two differ by rounding only (below 1e-15).
TEST(ExodusMeshReader, ElasticBondBased3DPointsAreBitwisePeridigms) {
  const auto cloud =
      peridot::readExodusMesh(kCases + "/ElasticBondBased3D/ElasticBondBased3D.g", kDeckPath);
  const auto gold =
      peridot::readExodusResults(kCases + "/ElasticBondBased3D/ElasticBondBased3D_gold.e");
  const auto it = std::find(gold.elementNames.begin(), gold.elementNames.end(), "Volume");
  ASSERT_NE(it, gold.elementNames.end());
  const auto& volume = gold.element[static_cast<std::size_t>(it - gold.elementNames.begin())][0];
  std::vector<long long> index(385, -1);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    index[static_cast<std::size_t>(cloud.globalId[i])] = static_cast<long long>(i);
  }
  ASSERT_EQ(gold.nodeIds.size(), 384u);
  for (std::size_t n = 0; n < gold.nodeIds.size(); ++n) {
    const auto p = static_cast<std::size_t>(index[static_cast<std::size_t>(gold.nodeIds[n] - 1)]);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(cloud.x[3 * p + k], gold.nodeCoordinates[3 * n + k]);
  }
  for (std::size_t e = 0; e < gold.elementIds.size(); ++e) {
    const auto p =
        static_cast<std::size_t>(index[static_cast<std::size_t>(gold.elementIds[e] - 1)]);
    EXPECT_EQ(cloud.volume[p], volume[e]);
  }
}

TEST(ExodusMeshReader, ElasticBondBased3DVolumesBlocksAndMapMatchGold) {
  const auto cloud =
      peridot::readExodusMesh(kCases + "/ElasticBondBased3D/ElasticBondBased3D.g", kDeckPath);
  const auto gold =
      peridot::readExodusResults(kCases + "/ElasticBondBased3D/ElasticBondBased3D_gold.e");
  ASSERT_EQ(cloud.size(), 384u);
  ASSERT_EQ(cloud.blockNames.size(), 3u);
  EXPECT_EQ(cloud.blockNames.at(2), "block_2");
  // The file's element number map puts block 1's elements at ids 289..384.
  EXPECT_EQ(cloud.globalId[0], 288);
  EXPECT_EQ(cloud.blockId[0], 1);
  const auto it = std::find(gold.elementNames.begin(), gold.elementNames.end(), "Volume");
  ASSERT_NE(it, gold.elementNames.end());
  const auto& volume = gold.element[static_cast<std::size_t>(it - gold.elementNames.begin())][0];
  std::vector<long long> index(385, -1);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    index[static_cast<std::size_t>(cloud.globalId[i])] = static_cast<long long>(i);
  }
  for (std::size_t e = 0; e < gold.elementIds.size(); ++e) {
    const long long p = index[static_cast<std::size_t>(gold.elementIds[e] - 1)];
    ASSERT_GE(p, 0);
    EXPECT_NEAR(cloud.volume[static_cast<std::size_t>(p)], volume[e], 1e-15 + 1e-12 * volume[e]);
    EXPECT_EQ(cloud.blockId[static_cast<std::size_t>(p)], gold.elementBlock[e]);
  }
  // The single node set holds every node, hence every point.
  ASSERT_EQ(cloud.pointSets.size(), 1u);
  EXPECT_EQ(cloud.pointSets[0].globalIds.size(), 384u);
}

TEST(ExodusMeshReader, ContactCubesNodeSetsAreTheCubes) {
  const auto cloud = peridot::readExodusMesh(kCases + "/Contact_Cubes/Contact_Cubes.g", kDeckPath);
  ASSERT_EQ(cloud.size(), 128u);
  ASSERT_EQ(cloud.pointSets.size(), 2u);
  for (int s = 0; s < 2; ++s) {
    EXPECT_EQ(cloud.pointSets[s].name, "nodelist_" + std::to_string(s + 1));
    std::vector<long long> block;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      if (cloud.blockId[i] == s + 1) block.push_back(cloud.globalId[i]);
    }
    std::sort(block.begin(), block.end());
    EXPECT_EQ(cloud.pointSets[s].globalIds, block);
  }
}

// ---- errors ----

TEST(ExodusMeshReader, MissingFileNamesTheFile) {
  expectInputError(
      [] { peridot::readExodusMesh("no_such_dir/foo.g", kDeckPath); },
      {kDeckPath, "cannot open Exodus mesh \"no_such_dir/foo.g\"", "No such file or directory"});
}

TEST(ExodusMeshReader, TruncatedFilesAreRejected) {
  std::ifstream in(kCases + "/WaveInBar/WaveInBar.g", std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 20000u);
  for (std::size_t length : {std::size_t{1000}, std::size_t{20000}, bytes.size() - 8}) {
    TempFile file(tempPath("truncated.g"));
    {
      std::ofstream out(file.path, std::ios::binary);
      out.write(bytes.data(), static_cast<std::streamsize>(length));
    }
    expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                     {kDeckPath, file.path, "truncated"});
  }
}

TEST(ExodusMeshReader, HeaderLengthPastTheEndIsRejectedBeforeNetcdfReadsIt) {
  // A fuzzer's bit flip in a header length once made netCDF's open allocate and copy for 15 s
  // per rank (a hang at 2 ranks). The first dimension's name length (bytes 16-19 of a classic
  // file: magic, record count, dimension tag, dimension count) set beyond the file's size must be
  // refused by Peridot's own header walk, before netCDF sees it.
  std::ifstream in(kCases + "/WaveInBar/WaveInBar.g", std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 20000u);
  ASSERT_EQ(std::string(bytes.data(), 3), "CDF");
  ASSERT_EQ(bytes[11], 0x0A);  // the dimension list's tag
  bytes[16] = 0x7F;
  TempFile file(tempPath("flipped.g"));
  {
    std::ofstream out(file.path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                   {kDeckPath, file.path, "runs past the end of the file"});
}

TEST(ExodusMeshReader, NotAnExodusFile) {
  TempFile file(tempPath("text.g"));
  {
    std::ofstream out(file.path);
    out << "this is not a mesh\n";
  }
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                   {"cannot open Exodus mesh", file.path});
}

// ---- meshes written by the test ----

TEST(ExodusMeshReader, ReadsSphereElements) {
  TestMesh mesh;
  addNode(mesh, 0.0, 0.0, 0.0);
  addNode(mesh, 1.0, 2.0, 3.0);
  addNode(mesh, -1.0, 0.5, 2.0);
  TestBlock balls;
  balls.id = 5;
  balls.type = "SPHERE";
  balls.nodesPerElement = 1;
  balls.numAttributes = 2;
  balls.connectivity = {3, 1, 2};
  balls.attributes = {0.1, 0.25, 0.2, 0.5, 0.3, 0.75};  // (radius, volume) per element
  balls.name = "balls";
  mesh.blocks.push_back(balls);
  mesh.elementIds = {30, 10, 20};
  mesh.nodeSets.push_back({1, "", {2}});
  mesh.nodeSets.push_back({7, "corner", {1, 3}});
  TempFile file(tempPath("spheres.g"));
  writeMesh(file.path, mesh);

  const auto cloud = peridot::readExodusMesh(file.path, kDeckPath);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.blockNames.at(5), "balls");
  EXPECT_EQ(cloud.globalId, (std::vector<long long>{29, 9, 19}));
  EXPECT_EQ(cloud.blockId, (std::vector<int>{5, 5, 5}));
  EXPECT_EQ(cloud.volume, (std::vector<double>{0.25, 0.5, 0.75}));
  EXPECT_EQ(cloud.x, (std::vector<double>{-1.0, 0.5, 2.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0}));
  ASSERT_EQ(cloud.pointSets.size(), 2u);
  EXPECT_EQ(cloud.pointSets[0].name, "nodelist_1");
  EXPECT_EQ(cloud.pointSets[0].globalIds, (std::vector<long long>{19}));
  EXPECT_EQ(cloud.pointSets[1].name, "corner");
  EXPECT_EQ(cloud.pointSets[1].globalIds, (std::vector<long long>{9, 29}));
}

TEST(ExodusMeshReader, SphereWithoutVolumeAttributeIsAnError) {
  TestMesh mesh;
  addNode(mesh, 0.0, 0.0, 0.0);
  TestBlock ball;
  ball.id = 2;
  ball.type = "SPHERE";
  ball.nodesPerElement = 1;
  ball.numAttributes = 1;
  ball.connectivity = {1};
  ball.attributes = {0.1};
  mesh.blocks.push_back(ball);
  TempFile file(tempPath("sphere1.g"));
  writeMesh(file.path, mesh);
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                   {kDeckPath, "element block 2", "second attribute"});
}

TEST(ExodusMeshReader, MixedHexTetAndHex20) {
  // A unit cube (HEX8, block 1), a tet on top of it (TET4, block 2), and a cube shifted in x
  // written as a HEX20 (block 3; its 12 mid-edge nodes are ignored for the geometry).
  TestMesh mesh;
  for (const auto& c : kUnitCube) addNode(mesh, c[0], c[1], c[2]);        // nodes 1-8
  addNode(mesh, 0.5, 0.5, 2.0);                                           // node 9
  for (const auto& c : kUnitCube) addNode(mesh, c[0] + 2.0, c[1], c[2]);  // nodes 10-17
  for (int i = 0; i < 12; ++i) addNode(mesh, 2.5, 0.5, 0.5);              // nodes 18-29
  TestBlock hex;
  hex.id = 1;
  hex.connectivity = {1, 2, 3, 4, 5, 6, 7, 8};
  TestBlock tet;
  tet.id = 2;
  tet.type = "TETRA";
  tet.nodesPerElement = 4;
  tet.connectivity = {5, 6, 7, 9};
  tet.name = "roof";
  TestBlock hex20;
  hex20.id = 3;
  hex20.type = "HEX20";
  hex20.nodesPerElement = 20;
  for (int64_t n = 10; n <= 29; ++n) hex20.connectivity.push_back(n);
  mesh.blocks = {hex, tet, hex20};
  mesh.nodeSets.push_back({4, "", {7}});   // shared by the hex and the tet
  mesh.nodeSets.push_back({5, "", {20}});  // a mid-edge node of the HEX20
  TempFile file(tempPath("mixed.g"));
  writeMesh(file.path, mesh);

  const auto cloud = peridot::readExodusMesh(file.path, kDeckPath);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_NEAR(cloud.volume[0], 1.0, 1e-14);
  EXPECT_NEAR(cloud.volume[1], 0.5 * 1.0 / 3.0, 1e-14);  // base triangle 1/2, height 1
  EXPECT_NEAR(cloud.volume[2], 1.0, 1e-14);
  const std::vector<double> expectedX = {0.5, 0.5, 0.5, 0.625, 0.375, 1.25, 2.5, 0.5, 0.5};
  for (std::size_t i = 0; i < expectedX.size(); ++i) EXPECT_NEAR(cloud.x[i], expectedX[i], 1e-14);
  EXPECT_EQ(cloud.blockNames.at(1), "block_1");
  EXPECT_EQ(cloud.blockNames.at(2), "roof");
  EXPECT_EQ(cloud.blockNames.at(3), "block_3");
  ASSERT_EQ(cloud.pointSets.size(), 2u);
  EXPECT_EQ(cloud.pointSets[0].name, "nodelist_4");
  EXPECT_EQ(cloud.pointSets[0].globalIds, (std::vector<long long>{0, 1}));
  EXPECT_EQ(cloud.pointSets[1].globalIds, (std::vector<long long>{2}));
}

TEST(ExodusMeshReader, UnsupportedElementTypeNamesBlockAndType) {
  TestMesh mesh;
  for (int i = 0; i < 6; ++i) addNode(mesh, i % 2, (i / 2) % 2, i / 4);
  TestBlock wedge;
  wedge.id = 9;
  wedge.type = "WEDGE6";
  wedge.nodesPerElement = 6;
  wedge.connectivity = {1, 2, 3, 4, 5, 6};
  mesh.blocks.push_back(wedge);
  TempFile file(tempPath("wedge.g"));
  writeMesh(file.path, mesh);
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                   {kDeckPath, "element block 9", "WEDGE6", "not supported yet"});
}

// ---- planar meshes ----

// The bilinear quad's area by 2x2 Gauss integration of its Jacobian (exact: the determinant is
// affine in each reference coordinate), an independent check of the shoelace area.
double gaussQuadArea(const double n[4][2]) {
  const double g = 1.0 / std::sqrt(3.0);
  const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  double area = 0.0;
  for (const auto& q : corner) {
    const double xi = q[0] * g, eta = q[1] * g;
    double J[2][2] = {{0, 0}, {0, 0}};  // J[k][i] = d x_k / d r_i
    for (int a = 0; a < 4; ++a) {
      const double dxi = corner[a][0] * (1 + corner[a][1] * eta) / 4;
      const double deta = corner[a][1] * (1 + corner[a][0] * xi) / 4;
      for (int k = 0; k < 2; ++k) {
        J[k][0] += dxi * n[a][k];
        J[k][1] += deta * n[a][k];
      }
    }
    area += J[0][0] * J[1][1] - J[0][1] * J[1][0];
  }
  return area;
}

TEST(ElementGeometry, QuadAreaMatchesGaussIntegration) {
  // Convex, non-affine quads (a trapezoid, a kite-like one, a general one) in both orientations.
  const double quads[3][4][2] = {{{0, 0}, {4, 0}, {3, 2}, {1, 2}},
                                 {{0, 0}, {2, -1}, {3, 1}, {1, 3}},
                                 {{0.3, 0.1}, {1.7, 0.4}, {2.1, 1.9}, {-0.2, 1.2}}};
  for (const auto& q : quads) {
    const double reference = gaussQuadArea(q);
    EXPECT_GT(reference, 0.0);
    EXPECT_NEAR(peridot::quadArea(q), reference, 1e-13 * reference);
    EXPECT_TRUE(peridot::quadIsValid(q));
    const double reversed[4][2] = {
        {q[0][0], q[0][1]}, {q[3][0], q[3][1]}, {q[2][0], q[2][1]}, {q[1][0], q[1][1]}};
    EXPECT_NEAR(peridot::quadArea(reversed), -reference, 1e-13 * reference);
    EXPECT_TRUE(peridot::quadIsValid(reversed));
  }
  // The trapezoid by hand: (4 + 2) / 2 * 2 = 6.
  EXPECT_DOUBLE_EQ(peridot::quadArea(quads[0]), 6.0);
  double c[2];
  peridot::quadNodeAverage(quads[0], c);
  EXPECT_DOUBLE_EQ(c[0], 2.0);
  EXPECT_DOUBLE_EQ(c[1], 1.0);
}

TEST(ElementGeometry, BowTieAndReentrantQuadsAreInvalid) {
  const double bowTie[4][2] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_FALSE(peridot::quadIsValid(bowTie));
  const double reentrant[4][2] = {{0, 0}, {2, 0}, {0.5, 0.5}, {0, 2}};  // dent at node 3
  EXPECT_FALSE(peridot::quadIsValid(reentrant));
  EXPECT_GT(peridot::quadArea(reentrant), 0.0);
  const double collapsed[4][2] = {{0, 0}, {1, 0}, {2, 0}, {0, 1}};  // nodes 1-3 collinear
  EXPECT_TRUE(peridot::quadIsValid(collapsed));
  EXPECT_DOUBLE_EQ(peridot::quadArea(collapsed), 1.0);
}

TEST(ElementGeometry, TriAreaAndCentroid) {
  const double tri[3][2] = {{1, 1}, {4, 1}, {1, 3}};
  EXPECT_DOUBLE_EQ(peridot::triArea(tri), 3.0);
  const double flipped[3][2] = {{1, 1}, {1, 3}, {4, 1}};
  EXPECT_DOUBLE_EQ(peridot::triArea(flipped), -3.0);
  double c[2];
  peridot::triCentroid(tri, c);
  EXPECT_DOUBLE_EQ(c[0], 2.0);
  EXPECT_NEAR(c[1], 5.0 / 3.0, 1e-15);
}

// Two QUAD4 (one clockwise) and a TRI3 block in a num_dim = 2 file, with node sets.
TestMesh planarMesh() {
  TestMesh mesh;
  mesh.dimension = 2;
  // nodes 1..6: a 2 x 1 strip of unit-high cells, the right one a trapezoid; 7: a triangle apex
  addNode(mesh, 0, 0, 0);    // 1
  addNode(mesh, 1, 0, 0);    // 2
  addNode(mesh, 3, 0, 0);    // 3
  addNode(mesh, 0, 1, 0);    // 4
  addNode(mesh, 1, 1, 0);    // 5
  addNode(mesh, 2, 1, 0);    // 6
  addNode(mesh, 1.5, 4, 0);  // 7
  TestBlock quads;
  quads.id = 3;
  quads.type = "QUAD4";
  quads.nodesPerElement = 4;
  quads.connectivity = {1, 2, 5, 4,   // unit square, counter-clockwise
                        2, 5, 6, 3};  // trapezoid 1..3 / 1..2, clockwise (mirrored)
  quads.name = "plate";
  TestBlock tris;
  tris.id = 8;
  tris.type = "TRI3";
  tris.nodesPerElement = 3;
  tris.connectivity = {5, 6, 7};
  mesh.blocks = {quads, tris};
  mesh.elementIds = {11, 12, 13};
  mesh.nodeSets.push_back({1, "left", {1, 4}});
  mesh.nodeSets.push_back({2, "middle", {5}});
  return mesh;
}

TEST(ExodusMeshReader, ReadsQuadAndTriBlocksAsAPlanarCloud) {
  TempFile file(tempPath("planar.g"));
  writeMesh(file.path, planarMesh());
  const double thickness = 0.25;
  const auto cloud = peridot::readExodusMesh(file.path, kDeckPath, thickness);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.dimension, 2);
  EXPECT_EQ(cloud.thickness, thickness);
  EXPECT_EQ(cloud.globalId, (std::vector<long long>{10, 11, 12}));
  EXPECT_EQ(cloud.blockId, (std::vector<int>{3, 3, 8}));
  EXPECT_EQ(cloud.blockNames.at(3), "plate");
  EXPECT_EQ(cloud.blockNames.at(8), "block_8");
  // Areas by hand: unit square 1; trapezoid with parallel sides 2 (y = 0) and 1 (y = 1), height
  // 1: 1.5; triangle (1,1), (2,1), (1.5,4): base 1, height 3: 1.5.
  EXPECT_DOUBLE_EQ(cloud.volume[0], 1.0 * thickness);
  EXPECT_DOUBLE_EQ(cloud.volume[1], 1.5 * thickness);
  EXPECT_DOUBLE_EQ(cloud.volume[2], 1.5 * thickness);
  // Positions: area centroids (z = 0). The trapezoid (1,0) (1,1) (2,1) (3,0) is the unit square
  // [1,2]x[0,1] (centroid (3/2, 1/2)) plus the triangle (2,0) (3,0) (2,1) (area 1/2, centroid
  // (7/3, 1/3)): ((3/2 + 7/6) / (3/2), (1/2 + 1/6) / (3/2)) = (16/9, 4/9).
  const std::vector<double> expected = {0.5, 0.5, 0.0, 16.0 / 9, 4.0 / 9, 0.0, 1.5, 2.0, 0.0};
  ASSERT_EQ(cloud.x.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(cloud.x[k], expected[k], 1e-15);
  ASSERT_EQ(cloud.pointSets.size(), 2u);
  EXPECT_EQ(cloud.pointSets[0].name, "left");
  EXPECT_EQ(cloud.pointSets[0].globalIds, (std::vector<long long>{10}));
  EXPECT_EQ(cloud.pointSets[1].name, "middle");  // node 5 touches all three elements
  EXPECT_EQ(cloud.pointSets[1].globalIds, (std::vector<long long>{10, 11, 12}));
}

TEST(ExodusMeshReader, HigherOrderPlanarElementsUseTheirCorners) {
  // QUAD8 / TRI6 blocks: the mid-side nodes (here off the straight edges) do not change the
  // point; SHELL4 counts as a quad.
  TestMesh mesh;
  mesh.dimension = 2;
  for (const auto& p : std::vector<std::array<double, 2>>{
           {0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, -0.3}, {2.2, 1}, {1, 2.4}, {-0.1, 1}})
    addNode(mesh, p[0], p[1], 0);
  TestBlock quad8;
  quad8.id = 1;
  quad8.type = "QUAD8";
  quad8.nodesPerElement = 8;
  quad8.connectivity = {1, 2, 3, 4, 5, 6, 7, 8};
  TestBlock tri6;
  tri6.id = 2;
  tri6.type = "TRI6";
  tri6.nodesPerElement = 6;
  tri6.connectivity = {1, 2, 3, 5, 6, 7};
  TestBlock shell;
  shell.id = 3;
  shell.type = "SHELL4";
  shell.nodesPerElement = 4;
  shell.connectivity = {1, 2, 3, 4};
  mesh.blocks = {quad8, tri6, shell};
  TempFile file(tempPath("quad8.g"));
  writeMesh(file.path, mesh);
  const auto cloud = peridot::readExodusMesh(file.path, kDeckPath);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.volume, (std::vector<double>{4.0, 2.0, 4.0}));
  EXPECT_EQ(cloud.x[0], 1.0);
  EXPECT_EQ(cloud.x[1], 1.0);
  EXPECT_NEAR(cloud.x[3], 4.0 / 3, 1e-15);
  EXPECT_NEAR(cloud.x[4], 2.0 / 3, 1e-15);
}

TEST(ExodusMeshReader, PlanarMeshWithThreeCoordinatesInZZero) {
  TestMesh mesh = planarMesh();
  mesh.dimension = 3;
  TempFile file(tempPath("planar3.g"));
  writeMesh(file.path, mesh);
  const auto cloud = peridot::readExodusMesh(file.path, kDeckPath);
  EXPECT_EQ(cloud.dimension, 2);
  EXPECT_EQ(cloud.volume, (std::vector<double>{1.0, 1.5, 1.5}));
}

TEST(ExodusMeshReader, PlanarMeshOffTheXYPlaneIsAnError) {
  TestMesh mesh = planarMesh();
  mesh.dimension = 3;
  mesh.z[6] = 0.5;
  TempFile file(tempPath("tilted.g"));
  writeMesh(file.path, mesh);
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                   {kDeckPath, "element block 3", "node 7", "z = 0"});
}

TEST(ExodusMeshReader, MixedPlanarAndSolidBlocksAreAnError) {
  TestMesh mesh;
  for (const auto& c : kUnitCube) addNode(mesh, c[0], c[1], c[2]);
  TestBlock hex;
  hex.connectivity = {1, 2, 3, 4, 5, 6, 7, 8};
  TestBlock quad;
  quad.id = 2;
  quad.type = "QUAD4";
  quad.nodesPerElement = 4;
  quad.connectivity = {1, 2, 3, 4};
  mesh.blocks = {hex, quad};
  TempFile file(tempPath("mixed.g"));
  writeMesh(file.path, mesh);
  // The planar block's nodes are in z = 0 but others are not: the z check speaks first.
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); }, {"element block 2"});
  // With every node in z = 0 except none used off-plane, the mix itself is the error.
  TestMesh flat = planarMesh();
  flat.dimension = 3;
  TestBlock tet;
  tet.id = 20;
  tet.type = "TET4";
  tet.nodesPerElement = 4;
  tet.connectivity = {1, 2, 4, 7};  // flat, but the mix is reported before its volume
  flat.blocks.push_back(tet);
  flat.elementIds.push_back(14);  // one id per element: the map is written from this vector
  TempFile file2(tempPath("mixed2.g"));
  writeMesh(file2.path, flat);
  expectInputError([&] { peridot::readExodusMesh(file2.path, kDeckPath); },
                   {"mixes 2D and 3D", "element block 3", "element block 20", "TET4"});
}

TEST(ExodusMeshReader, SolidBlockInATwoDimensionalFileIsAnError) {
  TestMesh mesh;
  mesh.dimension = 2;
  addNode(mesh, 0.0, 0.0, 0.0);
  TestBlock ball;
  ball.id = 4;
  ball.type = "SPHERE";
  ball.nodesPerElement = 1;
  ball.numAttributes = 2;
  ball.connectivity = {1};
  ball.attributes = {0.5, 1.0};
  mesh.blocks.push_back(ball);
  TempFile file(tempPath("ball2d.g"));
  writeMesh(file.path, mesh);
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                   {"element block 4", "SPHERE", "2D mesh"});
}

TEST(ExodusMeshReader, BowTieQuadIsAnError) {
  TestMesh mesh;
  mesh.dimension = 2;
  addNode(mesh, 0, 0, 0);
  addNode(mesh, 1, 1, 0);
  addNode(mesh, 1, 0, 0);
  addNode(mesh, 0, 2, 0);  // not symmetric: the signed area is not zero
  TestBlock quad;
  quad.type = "QUAD4";
  quad.nodesPerElement = 4;
  quad.connectivity = {1, 2, 3, 4};
  mesh.blocks.push_back(quad);
  mesh.elementIds = {77};
  TempFile file(tempPath("bowtie.g"));
  writeMesh(file.path, mesh);
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                   {"element 77", "self-intersecting"});
}

TEST(ExodusMeshReader, DegenerateTriangleIsAnError) {
  TestMesh mesh;
  mesh.dimension = 2;
  addNode(mesh, 0, 0, 0);
  addNode(mesh, 1, 1, 0);
  addNode(mesh, 2, 2, 0);
  TestBlock tri;
  tri.type = "TRI3";
  tri.nodesPerElement = 3;
  tri.connectivity = {1, 2, 3};
  mesh.blocks.push_back(tri);
  mesh.elementIds = {5};
  TempFile file(tempPath("flattri.g"));
  writeMesh(file.path, mesh);
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                   {"element 5", "area x thickness", "degenerate"});
}

TEST(ExodusMeshReader, MeshWithoutElementsIsAnError) {
  TestMesh mesh;
  addNode(mesh, 0.0, 0.0, 0.0);
  TempFile file(tempPath("empty.g"));
  writeMesh(file.path, mesh);
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                   {kDeckPath, file.path, "no elements"});
}

TEST(ExodusMeshReader, DegenerateElementIsAnError) {
  TestMesh mesh;
  for (const auto& c : kUnitCube) addNode(mesh, c[0], c[1], 0.0);  // flattened cube
  TestBlock hex;
  hex.connectivity = {1, 2, 3, 4, 5, 6, 7, 8};
  mesh.blocks.push_back(hex);
  mesh.elementIds = {42};
  TempFile file(tempPath("flat.g"));
  writeMesh(file.path, mesh);
  expectInputError([&] { peridot::readExodusMesh(file.path, kDeckPath); },
                   {"element 42", "volume"});
}

}  // namespace
