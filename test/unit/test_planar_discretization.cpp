// Planar (2D) discretizations: the 2D generator's layout and neighbourhoods, 2D text files, the
// Thickness / Dimension / Periodic Z keys, and the 2D Exodus output read back.
#include <exodusII.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "TempFile.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "discretization/Discretization.hpp"
#include "neighbor/NeighborSearch.hpp"
#include "output/ExodusCompare.hpp"
#include "output/ExodusWriter.hpp"

namespace peridot {
namespace {

using peridot::testing::TempFile;
using peridot::testing::tempPath;

// The Discretization list of a YAML deck body (indented by 4 under "Discretization:").
DiscretizationConfig config(const std::string& body) {
  std::string indented;
  std::size_t start = 0;
  while (start < body.size()) {
    const std::size_t end = body.find('\n', start);
    indented += "  " + body.substr(start, end - start + 1);
    start = end + 1;
  }
  auto deck = parseDeck("Peridigm:\n  Discretization:\n" + indented, "yaml");
  return readDiscretizationConfig(ListReader(deck->sublist("Discretization"), "Discretization"));
}

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

const std::string kGenerator2D =
    "  Type: PdQuickGrid\n"
    "  Thickness: 0.5\n"
    "  TensorProduct2DMeshGenerator:\n"
    "    X Origin: -1.0\n    Y Origin: 2.0\n"
    "    X Length: 3.0\n    Y Length: 1.0\n"
    "    Number Points X: 3\n    Number Points Y: 2\n";

TEST(PlanarDiscretization, GeneratorLayoutIsCellCentredXFastest) {
  const auto c = config(kGenerator2D);
  EXPECT_EQ(c.dimension, 2);
  const PointCloud cloud = buildWholePointCloud(c);
  ASSERT_EQ(cloud.size(), 6u);
  EXPECT_EQ(cloud.dimension, 2);
  EXPECT_EQ(cloud.thickness, 0.5);
  // Cells 1 x 0.5: centres x = -0.5, 0.5, 1.5 and y = 2.25, 2.75; ids 0..5, x fastest.
  const double xs[3] = {-0.5, 0.5, 1.5}, ys[2] = {2.25, 2.75};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const std::size_t p = static_cast<std::size_t>(3 * j + i);
      EXPECT_EQ(cloud.globalId[p], static_cast<long long>(p));
      EXPECT_DOUBLE_EQ(cloud.x[3 * p], xs[i]);
      EXPECT_DOUBLE_EQ(cloud.x[3 * p + 1], ys[j]);
      EXPECT_EQ(cloud.x[3 * p + 2], 0.0);
      EXPECT_DOUBLE_EQ(cloud.volume[p], 1.0 * 0.5 * 0.5);  // area x thickness
      EXPECT_EQ(cloud.blockId[p], 1);
    }
}

TEST(PlanarDiscretization, ThicknessDefaultsToOne) {
  const auto c = config(
      "  Type: PdQuickGrid\n"
      "  TensorProduct2DMeshGenerator:\n"
      "    X Origin: 0.0\n    Y Origin: 0.0\n    X Length: 2.0\n    Y Length: 2.0\n"
      "    Number Points X: 2\n    Number Points Y: 4\n");
  const PointCloud cloud = buildWholePointCloud(c);
  EXPECT_EQ(cloud.thickness, 1.0);
  EXPECT_DOUBLE_EQ(cloud.volume[0], 0.5);
}

// Neighbour counts of the interior point of a 9 x 9 grid of unit cells.
int centreNeighbours(const std::string& neighborhood, double horizon) {
  const auto c =
      config("  Type: PdQuickGrid\n" + neighborhood +
             "  TensorProduct2DMeshGenerator:\n"
             "    X Origin: 0.0\n    Y Origin: 0.0\n    X Length: 9.0\n    Y Length: 9.0\n"
             "    Number Points X: 9\n    Number Points Y: 9\n");
  const PointCloud cloud = buildWholePointCloud(c);
  std::vector<double> h(cloud.size(), horizon);
  NeighborSearchInput in;
  in.x = cloud.x.data();
  in.numPoints = cloud.size();
  in.horizon = h.data();
  in.rule = neighborhoodRule(c);
  std::vector<long long> offsets;
  std::vector<std::size_t> neighbors;
  findNeighbors(in, {40}, offsets, neighbors);  // point 40 = cell (4, 4)
  return static_cast<int>(offsets[1] - offsets[0]);
}

TEST(PlanarDiscretization, GeneratorNeighbourhoodsAreSquaresAndDisks) {
  // Box rule: delta = 2.1 h rounds to n = 2 cells per axis: a 5 x 5 square less the point.
  EXPECT_EQ(centreNeighbours("", 2.1), 24);
  // Spherical (strict): offsets with i^2 + j^2 < 2.1^2 = 4.41: 4 at 1, 4 at 2, 4 at 4.
  EXPECT_EQ(centreNeighbours("  NeighborhoodType: Spherical\n", 2.1), 12);
  // delta = 3: i^2 + j^2 < 9 adds 8 at 5 and 4 at 8 (the 4 at exactly 9 are out).
  EXPECT_EQ(centreNeighbours("  NeighborhoodType: Spherical\n", 3.0), 24);
}

TEST(PlanarDiscretization, TextFileInTwoDimensions) {
  TempFile file(tempPath("points.txt"));
  {
    std::ofstream out(file.path);
    out << "# x y z block area\n0 0 0 1 0.25\n0.5 0 0 1 0.25\n0 0.5 0 2 0.5\n";
  }
  const auto c = config("  Type: Text File\n  Input Mesh File: " + file.path +
                        "\n  Dimension: 2\n  Thickness: 0.1\n");
  EXPECT_EQ(c.dimension, 2);
  const PointCloud cloud = buildWholePointCloud(c);
  EXPECT_EQ(cloud.dimension, 2);
  EXPECT_EQ(cloud.thickness, 0.1);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_DOUBLE_EQ(cloud.volume[0], 0.025);
  EXPECT_DOUBLE_EQ(cloud.volume[2], 0.05);
  EXPECT_EQ(cloud.blockId, (std::vector<int>{1, 1, 2}));
  // Without Dimension the same file is a 3D cloud with the fifth column as volume.
  const PointCloud solid =
      buildWholePointCloud(config("  Type: Text File\n  Input Mesh File: " + file.path + "\n"));
  EXPECT_EQ(solid.dimension, 3);
  EXPECT_DOUBLE_EQ(solid.volume[0], 0.25);
}

TEST(PlanarDiscretization, TextFileOffThePlaneIsAnError) {
  TempFile file(tempPath("tilted.txt"));
  {
    std::ofstream out(file.path);
    out << "0 0 0 1 0.25\n# comment\n1 0 0.2 1 0.25\n";
  }
  const auto c =
      config("  Type: Text File\n  Input Mesh File: " + file.path + "\n  Dimension: 2\n");
  expectInputError([&] { buildWholePointCloud(c); },
                   {"Discretization -> Input Mesh File", "line 3", "z is 0.2", "z = 0"});
}

TEST(PlanarDiscretization, ThicknessInThreeDimensionsIsAnError) {
  expectInputError(
      [] {
        config(
            "  Type: PdQuickGrid\n  Thickness: 2.0\n"
            "  TensorProduct3DMeshGenerator:\n"
            "    X Origin: 0.0\n    Y Origin: 0.0\n    Z Origin: 0.0\n"
            "    X Length: 1.0\n    Y Length: 1.0\n    Z Length: 1.0\n"
            "    Number Points X: 2\n    Number Points Y: 2\n    Number Points Z: 2\n");
      },
      {"Discretization -> Thickness", "only for 2D", "3D"});
  expectInputError([] { config("  Type: Text File\n  Input Mesh File: a.txt\n  Thickness: 1\n"); },
                   {"Discretization -> Thickness", "Dimension: 2"});
  // An Exodus mesh tells its dimension when read: WaveInBar is 3D.
  const auto c = config("  Type: Exodus\n  Input Mesh File: " + std::string(PERIDOT_SHARED_DIR) +
                        "/peridigm-cases/WaveInBar/WaveInBar.g\n  Thickness: 2.0\n");
  expectInputError([&] { buildWholePointCloud(c); },
                   {"Discretization -> Thickness", "WaveInBar.g", "is 3D"});
}

TEST(PlanarDiscretization, DimensionKeyIsForTextFilesOnly) {
  expectInputError([] { config(kGenerator2D + "  Dimension: 2\n"); },
                   {"Discretization -> Dimension", "only for Text File", "generator"});
  expectInputError([] { config("  Type: Text File\n  Input Mesh File: a.txt\n  Dimension: 1\n"); },
                   {"Discretization -> Dimension", "expected 2 or 3"});
}

TEST(PlanarDiscretization, PeriodicZInTwoDimensionsIsAnError) {
  expectInputError([] { config(kGenerator2D + "  Periodic Z: true\n"); },
                   {"Discretization -> Periodic Z", "2D"});
  // Periodic X takes the generator's box.
  const auto c = config(kGenerator2D + "  Periodic X: true\n");
  EXPECT_TRUE(c.periodic.periodic[0]);
  EXPECT_EQ(c.periodic.lower[0], -1.0);
  EXPECT_EQ(c.periodic.upper[0], 2.0);
}

TEST(PlanarDiscretization, ExodusOutputRoundTripsInTwoDimensions) {
  TempFile file(tempPath("out2d.e"));
  ExodusHeader header;
  header.dimension = 2;
  header.numPoints = 3;
  header.blockIds = {1, 7};
  header.blockNames = {"plate", "stiffener"};
  header.blockCounts = {2, 1};
  header.setNames = {"edge"};
  header.setSizes = {2};
  header.nodalNames = {"DisplacementX", "DisplacementY"};
  header.elementNames = {"Volume"};
  header.globalNames = {"TotalX", "TotalY"};
  {
    // Written in pieces, as rank 0 writes the ranks' ranges: the pieces cross the block
    // boundary (positions 1 and 2 are in different blocks).
    ExodusWriter writer(file.path, header);
    const long long ids[3] = {4, 2, 9};
    const double xyz[9] = {0.5, -1.0, 0.0, 1.5, 0.25, 0.0, 2.5, 3.0, 0.0};
    writer.putMesh(0, 1, ids, xyz);
    writer.putMesh(1, 2, ids + 1, xyz + 3);
    const long long edge[2] = {0, 2};
    writer.putSet(0, 0, 1, edge);
    writer.putSet(0, 1, 1, edge + 1);
    const double zero[3] = {0, 0, 0}, volume[3] = {0.1, 0.2, 0.3};
    writer.beginRecord(0.0, {0.0, 0.0});
    writer.putNodal(0, 0, 3, zero);
    writer.putNodal(1, 0, 3, zero);
    writer.putElement(0, 0, 3, volume);
    writer.endRecord();
    const double ux[3] = {1e-3, -2e-3, 3e-3}, uy[3] = {4e-3, 5e-3, -6e-3};
    writer.beginRecord(0.5, {2e-3, 3e-3});
    writer.putNodal(0, 0, 2, ux);
    writer.putNodal(0, 2, 1, ux + 2);
    writer.putNodal(1, 0, 1, uy);
    writer.putNodal(1, 1, 2, uy + 1);
    writer.putElement(0, 0, 1, volume);
    writer.putElement(0, 1, 2, volume + 1);
    writer.endRecord();
  }
  const ExodusResults r = readExodusResults(file.path);
  EXPECT_EQ(r.dimension, 2);
  EXPECT_EQ(r.nodeIds, (std::vector<long long>{4, 2, 9}));
  ASSERT_EQ(r.nodeCoordinates.size(), 9u);
  EXPECT_EQ(r.nodeCoordinates,
            (std::vector<double>{0.5, -1.0, 0.0, 1.5, 0.25, 0.0, 2.5, 3.0, 0.0}));
  EXPECT_EQ(r.nodalNames, (std::vector<std::string>{"DisplacementX", "DisplacementY"}));
  EXPECT_EQ(r.times, (std::vector<double>{0.0, 0.5}));
  ASSERT_EQ(r.nodal.size(), 2u);
  EXPECT_EQ(r.nodal[1][1], (std::vector<double>{4e-3, 5e-3, -6e-3}));
  EXPECT_EQ(r.element[0][1], (std::vector<double>{0.1, 0.2, 0.3}));
  EXPECT_EQ(r.global[1][1], (std::vector<double>{3e-3}));
  {
    // The node set, through the Exodus API: positions 0 and 2 are nodes 1 and 3.
    int cpu = sizeof(double), io = 0;
    float version = 0;
    const int exoid = ex_open(file.path.c_str(), EX_READ, &cpu, &io, &version);
    ASSERT_GE(exoid, 0);
    int nodes[2] = {0, 0};
    EXPECT_GE(ex_get_set(exoid, EX_NODE_SET, 1, nodes, nullptr), 0);
    EXPECT_EQ(nodes[0], 1);
    EXPECT_EQ(nodes[1], 3);
    char name[64] = {0};
    EXPECT_GE(ex_get_name(exoid, EX_NODE_SET, 1, name), 0);
    EXPECT_STREQ(name, "edge");
    ex_close(exoid);
  }
  // The comparison tool accepts 2D files: the file against itself passes, against a changed
  // value fails.
  CompSpec spec = parseCompText(
      "COORDINATES absolute 0\nNODAL VARIABLES absolute 1e-12\nGLOBAL VARIABLES absolute 0\n",
      "test.comp");
  EXPECT_TRUE(compareExodusResults(r, r, spec).passed());
  ExodusResults changed = r;
  changed.nodal[0][1][2] += 1e-9;
  EXPECT_FALSE(compareExodusResults(changed, r, spec).passed());
}

}  // namespace
}  // namespace peridot
