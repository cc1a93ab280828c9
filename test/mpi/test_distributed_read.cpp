// The distributed readers (buildPointCloud): on any number of ranks the shares together are the
// whole cloud of a one-rank read (buildWholePointCloud), to the bit, and every problem stops every
// rank with the message the one-rank read gives.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "../common/TestExodusMesh.hpp"
#include "core/Error.hpp"
#include "discretization/Discretization.hpp"

namespace {

using namespace peridot;
using peridot::testing::addNode;
using peridot::testing::TestBlock;
using peridot::testing::TestMesh;
using peridot::testing::TestNodeSet;

int rankOf(MPI_Comm comm = MPI_COMM_WORLD) {
  int r = 0;
  MPI_Comm_rank(comm, &r);
  return r;
}

// A file every rank sees: rank 0 names it (its pid), writes it, and removes it once all ranks
// are done with it.
struct SharedFile {
  explicit SharedFile(const std::string& stem) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path = (std::filesystem::temp_directory_path() / (std::string("peridot_") + info->name() + "_" +
                                                      std::to_string(::getpid()) + "_" + stem))
               .string();
    int length = static_cast<int>(path.size());
    MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
    path.resize(static_cast<std::size_t>(length));
    MPI_Bcast(path.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  }
  ~SharedFile() {
    MPI_Barrier(MPI_COMM_WORLD);
    std::error_code ec;
    if (rankOf() == 0) std::filesystem::remove(path, ec);
  }
  void writeMesh(const TestMesh& mesh) const {
    if (rankOf() == 0) peridot::testing::writeMesh(path, mesh);
    MPI_Barrier(MPI_COMM_WORLD);
  }
  void writeText(const std::string& text) const {
    if (rankOf() == 0) std::ofstream(path) << text;
    MPI_Barrier(MPI_COMM_WORLD);
  }
  std::string path;
};

template <class T>
std::vector<T> allGather(const std::vector<T>& mine, MPI_Datatype type) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(size)), displ(static_cast<std::size_t>(size));
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::exclusive_scan(counts.begin(), counts.end(), displ.begin(), 0);
  std::vector<T> all(static_cast<std::size_t>(displ.back() + counts.back()));
  MPI_Allgatherv(mine.data(), count, type, all.data(), counts.data(), displ.data(), type,
                 MPI_COMM_WORLD);
  return all;
}

uint64_t bits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// Checks this rank's share against the contract, gathers the shares and compares their union,
// point by point in id order, with the one-rank cloud.
void expectSharesMakeWhole(const PointCloud& share, const PointCloud& whole) {
  const std::size_t n = share.size();
  ASSERT_EQ(share.x.size(), 3 * n);
  ASSERT_EQ(share.blockId.size(), n);
  ASSERT_EQ(share.globalId.size(), n);
  EXPECT_EQ(share.blockNames, whole.blockNames);
  EXPECT_EQ(share.dimension, whole.dimension);
  EXPECT_EQ(bits(share.thickness), bits(whole.thickness));
  EXPECT_EQ(share.globalNumPoints, static_cast<long long>(whole.size()));
  ASSERT_EQ(share.pointSets.size(), whole.pointSets.size());
  for (std::size_t s = 0; s < share.pointSets.size(); ++s) {
    const auto& ids = share.pointSets[s].globalIds;
    EXPECT_EQ(share.pointSets[s].name, whole.pointSets[s].name);
    EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
    EXPECT_EQ(std::adjacent_find(ids.begin(), ids.end()), ids.end());
    for (long long g : ids) {
      EXPECT_NE(std::find(share.globalId.begin(), share.globalId.end(), g), share.globalId.end())
          << "set " << share.pointSets[s].name << " lists " << g << ", not in this share";
    }
  }

  const auto ids = allGather(share.globalId, MPI_LONG_LONG);
  const auto x = allGather(share.x, MPI_DOUBLE);
  const auto volume = allGather(share.volume, MPI_DOUBLE);
  const auto block = allGather(share.blockId, MPI_INT);
  ASSERT_EQ(ids.size(), whole.size());
  std::map<long long, std::size_t> wholeAt;
  for (std::size_t p = 0; p < whole.size(); ++p) wholeAt[whole.globalId[p]] = p;
  ASSERT_EQ(wholeAt.size(), whole.size());
  std::vector<long long> seen(ids);
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(std::adjacent_find(seen.begin(), seen.end()), seen.end()) << "a point on two ranks";
  for (std::size_t p = 0; p < ids.size(); ++p) {
    const auto it = wholeAt.find(ids[p]);
    ASSERT_NE(it, wholeAt.end()) << "id " << ids[p];
    const std::size_t q = it->second;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(bits(x[3 * p + k]), bits(whole.x[3 * q + k])) << ids[p];
    EXPECT_EQ(bits(volume[p]), bits(whole.volume[q])) << ids[p];
    EXPECT_EQ(block[p], whole.blockId[q]) << ids[p];
  }
  for (std::size_t s = 0; s < whole.pointSets.size(); ++s) {
    auto members = allGather(share.pointSets[s].globalIds, MPI_LONG_LONG);
    std::sort(members.begin(), members.end());
    EXPECT_EQ(members, whole.pointSets[s].globalIds) << whole.pointSets[s].name;
  }
}

// buildPointCloud on all ranks and buildWholePointCloud agree; returns the whole cloud.
PointCloud expectDistributedEqualsWhole(const DiscretizationConfig& c) {
  const PointCloud whole = buildWholePointCloud(c);
  const PointCloud share = buildPointCloud(c, MPI_COMM_WORLD);
  expectSharesMakeWhole(share, whole);
  return whole;
}

// Every rank throws InputError from buildPointCloud, with the one-rank read's message, which
// contains `part`.
void expectSameErrorEverywhere(const DiscretizationConfig& c, const std::string& part) {
  std::string serial, distributed;
  try {
    buildWholePointCloud(c);
  } catch (const InputError& e) {
    serial = e.what();
  }
  try {
    buildPointCloud(c, MPI_COMM_WORLD);
  } catch (const InputError& e) {
    distributed = e.what();
  }
  EXPECT_NE(serial.find(part), std::string::npos)
      << "\"" << serial << "\" lacks \"" << part << "\"";
  EXPECT_EQ(distributed, serial);
  std::vector<char> mine(distributed.begin(), distributed.end());
  const auto all = allGather(mine, MPI_CHAR);
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::string expected;
  for (int r = 0; r < size; ++r) expected += serial;
  EXPECT_EQ(std::string(all.begin(), all.end()), expected) << "the ranks disagree";
}

DiscretizationConfig exodus(const std::string& path) {
  DiscretizationConfig c;
  c.type = "Exodus";
  c.meshFile = path;
  c.meshFilePath = "Discretization -> Input Mesh File";
  c.dimension = 0;
  return c;
}

// A slightly irregular (nx+1) x (ny+1) x (nz+1) node grid: non-affine hexes, exact bits matter.
void addGrid(TestMesh& mesh, int nx, int ny, int nz) {
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const double wobble = 0.013 * std::sin(1.7 * i + 2.3 * j + 0.7 * k);
        addNode(mesh, i * 0.31 + wobble, j * 0.29 - wobble, k * 0.37 + 0.5 * wobble);
      }
}

int64_t gridNode(int nx, int ny, int i, int j, int k) {
  return 1 + i + (nx + 1) * (j + (ny + 1) * static_cast<int64_t>(k));
}

// Hexes over a 4 x 3 x 3 grid (two blocks), tets filling the top layer's cells, an empty block, a
// SPHERE block, gaps in the element ids and three node sets (one empty).
TestMesh mixedMesh() {
  const int nx = 4, ny = 3, nz = 3;
  TestMesh mesh;
  addGrid(mesh, nx, ny, nz);
  TestBlock hexA, hexB, tets, empty, balls;
  hexA.id = 7;
  hexA.name = "lower";
  hexB.id = 3;
  tets.id = 12;
  tets.type = "TETRA";
  tets.nodesPerElement = 4;
  tets.name = "top tets";
  empty.id = 20;
  empty.type = "WEDGE6";  // any type: an empty block has nothing to read
  empty.nodesPerElement = 6;
  balls.id = 30;
  balls.type = "SPHERE";
  balls.nodesPerElement = 1;
  balls.numAttributes = 2;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int64_t n[8] = {gridNode(nx, ny, i, j, k),
                              gridNode(nx, ny, i + 1, j, k),
                              gridNode(nx, ny, i + 1, j + 1, k),
                              gridNode(nx, ny, i, j + 1, k),
                              gridNode(nx, ny, i, j, k + 1),
                              gridNode(nx, ny, i + 1, j, k + 1),
                              gridNode(nx, ny, i + 1, j + 1, k + 1),
                              gridNode(nx, ny, i, j + 1, k + 1)};
        if (k == nz - 1) {
          // Five tets per cell: the corner tets and the middle one.
          const int split[5][4] = {
              {0, 1, 3, 4}, {1, 2, 3, 6}, {1, 4, 5, 6}, {3, 4, 6, 7}, {1, 3, 4, 6}};
          for (const auto& t : split)
            for (int a : t) tets.connectivity.push_back(n[a]);
        } else {
          TestBlock& b = k == 0 ? hexA : hexB;
          b.connectivity.insert(b.connectivity.end(), n, n + 8);
        }
      }
  for (int s = 0; s < 5; ++s) {
    balls.connectivity.push_back(1 + 7 * s);
    balls.attributes.insert(balls.attributes.end(), {0.1 * s, 0.01 + 0.002 * s});
  }
  mesh.blocks = {hexA, hexB, tets, empty, balls};
  int64_t numElements = 0;
  for (const auto& b : mesh.blocks) numElements += b.size();
  // Ids with gaps, not in file order.
  for (int64_t e = 0; e < numElements; ++e) mesh.elementIds.push_back(1000 - 3 * e + (e % 2) * 7);
  TestNodeSet bottom{5, "", {}}, corner{6, "corner", {gridNode(nx, ny, nx, ny, nz), 2, 2}},
      none{9, "nothing", {}};
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) bottom.nodes.push_back(gridNode(nx, ny, i, j, 0));
  mesh.nodeSets = {bottom, corner, none};
  return mesh;
}

TEST(DistributedRead, ExodusBlocksIdGapsNodeSetsHexTetSphere) {
  SharedFile file("mixed.g");
  file.writeMesh(mixedMesh());
  const PointCloud whole = expectDistributedEqualsWhole(exodus(file.path));
  EXPECT_EQ(whole.size(), 4u * 3 * 2 + 4 * 3 * 5 + 5);
  ASSERT_EQ(whole.pointSets.size(), 3u);
  EXPECT_EQ(whole.pointSets[0].name, "nodelist_5");
  // The bottom hexes and the spheres on nodes 1, 8 and 15.
  EXPECT_EQ(whole.pointSets[0].globalIds.size(), 12u + 3);
  EXPECT_TRUE(whole.pointSets[2].globalIds.empty());
}

TEST(DistributedRead, PlanarQuadAndTriMesh) {
  TestMesh mesh;
  mesh.dimension = 2;
  const int nx = 5, ny = 4;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) addNode(mesh, i * 0.5 + 0.01 * j * j, j * 0.4 + 0.02 * i, 0);
  TestBlock quads, tris;
  quads.type = "QUAD4";
  quads.nodesPerElement = 4;
  tris.id = 2;
  tris.type = "TRI3";
  tris.nodesPerElement = 3;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int64_t a = 1 + i + (nx + 1) * j, b = a + 1, c = b + nx + 1, d = a + nx + 1;
      if (j < 2) {
        quads.connectivity.insert(quads.connectivity.end(), {a, b, c, d});
      } else {
        tris.connectivity.insert(tris.connectivity.end(), {a, b, c, a, c, d});
      }
    }
  mesh.blocks = {quads, tris};
  mesh.nodeSets = {TestNodeSet{1, "left", {1, 1 + nx + 1, 1 + 2 * (nx + 1)}}};
  SharedFile file("planar.g");
  file.writeMesh(mesh);
  DiscretizationConfig c = exodus(file.path);
  c.thickness = 0.3;
  c.thicknessGiven = true;
  const PointCloud whole = expectDistributedEqualsWhole(c);
  EXPECT_EQ(whole.dimension, 2);
  EXPECT_EQ(whole.size(), 10u + 20u);
}

DiscretizationConfig textFile(const std::string& path, int dimension = 3) {
  DiscretizationConfig c;
  c.type = "Text File";
  c.meshFile = path;
  c.meshFilePath = "Discretization -> Input Mesh File";
  c.dimension = dimension;
  return c;
}

// Lines of different lengths, comments and blank lines, so byte ranges cut lines anywhere.
std::string textMesh(int points, bool planar) {
  std::string text = "# x y z block volume\n\n";
  for (int p = 0; p < points; ++p) {
    if (p % 7 == 3) text += "   \n// a comment\n";
    text += std::to_string(0.1 * p) + " " + std::to_string(p % 5 * 1.25) + " " +
            (planar ? "0" : std::to_string(-0.3 * p)) + " " + std::to_string(1 + p % 3) + " " +
            std::to_string(0.001 * (p + 1)) + (p % 4 == 0 ? "\r\n" : "\n");
  }
  return text;
}

TEST(DistributedRead, TextFile) {
  for (const int points : {1, 2, 40}) {
    SharedFile file("mesh.txt");
    file.writeText(textMesh(points, false));
    const PointCloud whole = expectDistributedEqualsWhole(textFile(file.path));
    ASSERT_EQ(whole.size(), static_cast<std::size_t>(points));
    EXPECT_EQ(whole.globalId.back(), points - 1);
    EXPECT_EQ(whole.x[3 * (points - 1)], std::stod(std::to_string(0.1 * (points - 1))));
  }
}

TEST(DistributedRead, PlanarTextFileWithoutFinalNewline) {
  SharedFile file("planar.txt");
  std::string text = textMesh(23, true);
  text.pop_back();
  file.writeText(text);
  DiscretizationConfig c = textFile(file.path, 2);
  c.thickness = 0.25;
  const PointCloud whole = expectDistributedEqualsWhole(c);
  EXPECT_EQ(whole.size(), 23u);
  EXPECT_EQ(whole.volume.back(), 0.023 * 0.25);
}

TEST(DistributedRead, TextFileErrorsNameTheLine) {
  {
    SharedFile file("bad.txt");
    file.writeText(textMesh(30, false) + "1 2 3 1\n" + textMesh(2, false));
    const int line = 2 + 30 + 2 * 4 + 1;  // header, points, comments (p = 3, 10, 17, 24)
    expectSameErrorEverywhere(textFile(file.path),
                              "line " + std::to_string(line) + ": expected five numbers");
  }
  {
    SharedFile file("offplane.txt");
    file.writeText(textMesh(30, true) + "1 2 0.5 1 1\n");
    expectSameErrorEverywhere(textFile(file.path, 2), "every point has z = 0");
  }
  {
    SharedFile file("empty.txt");
    file.writeText("# nothing\n\n\n");
    expectSameErrorEverywhere(textFile(file.path), "contains no points");
  }
  expectSameErrorEverywhere(textFile("no_such_dir/none.txt"), "cannot open text mesh");
}

// The generators' cells, written out independently of Discretization.cpp.
TEST(DistributedRead, Generators) {
  DiscretizationConfig box;
  box.type = "PdQuickGrid";
  box.generator = DiscretizationConfig::Generator::TensorProduct3D;
  const double origin[3] = {-1.0, 0.5, 0.1}, length[3] = {2.0, 1.3, 0.7};
  const long long n[3] = {7, 5, 3};
  for (int d = 0; d < 3; ++d) {
    box.origin[d] = origin[d];
    box.length[d] = length[d];
    box.numPoints[d] = n[d];
  }
  const PointCloud whole = expectDistributedEqualsWhole(box);
  ASSERT_EQ(whole.size(), 105u);
  const double h[3] = {length[0] / n[0], length[1] / n[1], length[2] / n[2]};
  std::size_t p = 0;
  for (long long k = 0; k < n[2]; ++k)
    for (long long j = 0; j < n[1]; ++j)
      for (long long i = 0; i < n[0]; ++i, ++p) {
        EXPECT_EQ(whole.x[3 * p], origin[0] + (i + 0.5) * h[0]);
        EXPECT_EQ(whole.x[3 * p + 1], origin[1] + (j + 0.5) * h[1]);
        EXPECT_EQ(whole.x[3 * p + 2], origin[2] + (k + 0.5) * h[2]);
        EXPECT_EQ(whole.volume[p], h[0] * h[1] * h[2]);
        EXPECT_EQ(whole.globalId[p], static_cast<long long>(p));
      }

  DiscretizationConfig plane = box;
  plane.generator = DiscretizationConfig::Generator::TensorProduct2D;
  plane.numPoints[2] = 1;
  plane.dimension = 2;
  plane.thickness = 0.2;
  const PointCloud planar = expectDistributedEqualsWhole(plane);
  ASSERT_EQ(planar.size(), 35u);
  EXPECT_EQ(planar.dimension, 2);
  EXPECT_EQ(planar.x[3 * 34 + 2], 0.0);
  EXPECT_EQ(planar.volume[0], h[0] * h[1] * 0.2);

  DiscretizationConfig cylinder;
  cylinder.type = "PdQuickGrid";
  cylinder.generator = DiscretizationConfig::Generator::Cylinder;
  cylinder.innerRadius = 0.5;
  cylinder.outerRadius = 1.0;
  cylinder.cylinderLength = 1.2;
  cylinder.numRadius = 3;
  cylinder.ringCenter[0] = 0.25;
  const PointCloud tube = expectDistributedEqualsWhole(cylinder);
  const double dr = 0.5 / 3;
  const long long nz = std::llround(1.2 / dr), nTheta = std::llround(2.0 * M_PI * 0.75 / dr);
  ASSERT_EQ(tube.size(), static_cast<std::size_t>(nz * nTheta * 3));
  const std::size_t last = tube.size() - 1;  // outer ring, last angle, top layer
  const double r = 0.5 * ((0.5 + 2 * dr) + (0.5 + 2 * dr + dr));
  const double theta = (nTheta - 0.5) * (2.0 * M_PI / nTheta);
  EXPECT_NEAR(tube.x[3 * last], 0.25 + r * std::cos(theta), 1e-14);
  EXPECT_NEAR(tube.x[3 * last + 2], (nz - 0.5) * (1.2 / nz), 1e-14);
}

// Each problem is planted in the last elements or nodes of the file, which the last rank reads.
TEST(DistributedRead, ExodusErrorsStopEveryRankWithTheSerialMessage) {
  expectSameErrorEverywhere(exodus("no_such_dir/none.g"), "cannot open Exodus mesh");
  const auto check = [](TestMesh mesh, const std::string& part,
                        const DiscretizationConfig* config = nullptr) {
    SharedFile file("bad.g");
    file.writeMesh(mesh);
    DiscretizationConfig c = config ? *config : exodus(file.path);
    c.meshFile = file.path;
    expectSameErrorEverywhere(c, part);
  };
  {
    TestMesh m = mixedMesh();
    m.elementIds.back() = m.elementIds.front();
    check(m, "contains the id 1000 twice");
  }
  {
    TestMesh m = mixedMesh();
    m.blocks.back().attributes.back() = -1.0;  // the last sphere's volume
    check(m, "the element volume is -1.000000 (second attribute)");
  }
  {
    TestMesh m = mixedMesh();
    auto& tets = m.blocks[2].connectivity;
    const std::size_t last = tets.size() - 4;  // the last tet collapsed to a point
    for (std::size_t a = 1; a < 4; ++a) tets[last + a] = tets[last];
    check(m, "element block 12, element");
  }
  {
    TestMesh m = mixedMesh();
    m.blocks[2].connectivity.back() = 10000;
    check(m, "the connectivity refers to node 10000");
  }
  {
    TestMesh m = mixedMesh();
    m.nodeSets[1].nodes.back() = 999;
    check(m, "node set 6 (\"corner\") refers to node 999");
  }
  {
    TestMesh m = mixedMesh();
    m.nodeSets[2].name = "corner";
    check(m, "node sets 6 and 9 are both named \"corner\"");
  }
  {
    TestMesh m = mixedMesh();
    m.blocks[1].name = "lower";
    check(m, "element blocks 7 and 3 are both named \"lower\"");
  }
  {
    TestMesh m = mixedMesh();
    m.blocks[2].type = "PYRAMID";
    check(m, "has element type \"PYRAMID\"");
  }
  {
    // A degenerate hex early and an unsupported block late: the hex is met first.
    TestMesh m = mixedMesh();
    m.blocks[0].connectivity[1] = m.blocks[0].connectivity[0];
    m.blocks[0].connectivity[2] = m.blocks[0].connectivity[0];
    m.blocks[0].connectivity[3] = m.blocks[0].connectivity[0];
    m.blocks[0].connectivity[5] = m.blocks[0].connectivity[4];
    m.blocks[0].connectivity[6] = m.blocks[0].connectivity[4];
    m.blocks[0].connectivity[7] = m.blocks[0].connectivity[4];
    m.blocks[2].type = "PYRAMID";
    check(m, "element block 7, element 1000");
  }
  {
    TestMesh m = mixedMesh();
    DiscretizationConfig c = exodus("");
    c.thicknessGiven = true;
    c.thicknessPath = "Discretization -> Thickness";
    check(m, "Discretization -> Thickness: only for 2D discretizations", &c);
  }
  {
    // A planar mesh in a 3D file whose last node leaves z = 0, and a mixed mesh.
    TestMesh m;
    for (int j = 0; j <= 3; ++j)
      for (int i = 0; i <= 3; ++i) addNode(m, i, j, 0);
    TestBlock quads;
    quads.type = "QUAD4";
    quads.nodesPerElement = 4;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const int64_t a = 1 + i + 4 * j;
        quads.connectivity.insert(quads.connectivity.end(), {a, a + 1, a + 5, a + 4});
      }
    m.blocks = {quads};
    TestMesh reentrant = m;  // the last node pushed into the last quad
    reentrant.x.back() = reentrant.y.back() = 2.2;
    check(reentrant, "element 9: the quadrilateral is self-intersecting or not convex");
    m.z.back() = 0.5;
    check(m, "node 16 has z = 0.500000");
    m.z.back() = 0.0;
    TestBlock hex;
    hex.id = 2;
    hex.connectivity = {1, 2, 6, 5, 1, 2, 6, 5};
    m.blocks.push_back(hex);
    check(m, "the mesh mixes 2D and 3D element blocks");
  }
  {
    // A truncated copy: every rank refuses it before reading.
    SharedFile good("good.g");
    good.writeMesh(mixedMesh());
    SharedFile cut("cut.g");
    if (rankOf() == 0) {
      std::filesystem::copy_file(good.path, cut.path);
      std::filesystem::resize_file(cut.path, std::filesystem::file_size(good.path) - 100);
    }
    MPI_Barrier(MPI_COMM_WORLD);
    expectSameErrorEverywhere(exodus(cut.path), "truncated");
  }
}

}  // namespace
