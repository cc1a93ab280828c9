// The Gmsh discretization: small hand-written meshes in formats 2.2 and 4.1, ASCII and binary
// (the binary files written here byte by byte from the format's definition, and, when gmsh is
// installed, converted by gmsh itself), checked against hand-computed centroids, volumes, blocks,
// node sets and layers; and the errors for broken files.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "TempFile.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "deck/RunConfig.hpp"
#include "discretization/Discretization.hpp"

namespace peridot {
namespace {

using peridot::testing::TempFile;
using peridot::testing::tempPath;

// Nodes of a 3 x 2 x 2 grid, node 1 + i + 3j + 6k at (i, j, k), plus node 13 at (3, 0, 0).
// Two unit hexahedra in physical volume 1 "solid", one tetrahedron in the unnamed physical
// volume 2, the quadrangle x = 0 in physical surface 5 "left", node 13 in physical point 7.
std::vector<std::array<double, 3>> gridNodes() {
  std::vector<std::array<double, 3>> x;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) x.push_back({double(i), double(j), double(k)});
  x.push_back({3, 0, 0});
  return x;
}
const std::vector<long long> kHex1 = {1, 2, 5, 4, 7, 8, 11, 10};
const std::vector<long long> kHex2 = {2, 3, 6, 5, 8, 9, 12, 11};
const std::vector<long long> kTet = {3, 13, 6, 9};
const std::vector<long long> kLeft = {1, 4, 10, 7};

std::string nodeLines(bool withTags) {
  std::string s;
  const auto x = gridNodes();
  for (std::size_t n = 0; n < x.size(); ++n) {
    if (withTags) s += std::to_string(n + 1) + " ";
    s += std::to_string(x[n][0]) + " " + std::to_string(x[n][1]) + " " + std::to_string(x[n][2]) +
         "\n";
  }
  return s;
}

std::string join(const std::vector<long long>& v) {
  std::string s;
  for (long long n : v) s += " " + std::to_string(n);
  return s;
}

const std::string kNames = "$PhysicalNames\n2\n2 5 \"left\"\n3 1 \"solid\"\n$EndPhysicalNames\n";

std::string mesh22() {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + kNames + "$Nodes\n13\n" + nodeLines(true) +
         "$EndNodes\n$Elements\n5\n1 15 2 7 1 13\n2 3 2 5 1" + join(kLeft) + "\n3 5 2 1 1" +
         join(kHex1) + "\n4 5 2 1 1" + join(kHex2) + "\n5 4 2 2 2" + join(kTet) +
         "\n$EndElements\n";
}

const std::string kEntities41 =
    "$Entities\n1 0 1 2\n1 3 0 0 1 7\n1 0 0 0 0 1 1 1 5 0\n1 0 0 0 2 1 1 1 1 0\n"
    "2 2 0 0 3 1 1 1 2 0\n$EndEntities\n";

std::string mesh41() {
  std::string nodes = "$Nodes\n2 13 1 13\n3 1 0 12\n";
  for (int n = 1; n <= 12; ++n) nodes += std::to_string(n) + "\n";
  const std::string lines = nodeLines(false);
  nodes += lines.substr(0, lines.rfind("3.000000 0.000000"));
  nodes += "0 1 0 1\n13\n3 0 0\n$EndNodes\n";
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n" + kNames + kEntities41 + nodes +
         "$Elements\n4 5 1 5\n0 1 15 1\n1 13\n2 1 3 1\n2" + join(kLeft) + "\n3 1 5 2\n3" +
         join(kHex1) + "\n4" + join(kHex2) + "\n3 2 4 1\n5" + join(kTet) + "\n$EndElements\n";
}

// Binary writers, from the format's definition (little-endian machine).
struct Bytes {
  std::string s;
  template <class T>
  Bytes& put(T v) {
    s.append(reinterpret_cast<const char*>(&v), sizeof v);
    return *this;
  }
  Bytes& text(const std::string& t) {
    s += t;
    return *this;
  }
};

std::string mesh22Binary() {
  Bytes b;
  b.text("$MeshFormat\n2.2 1 8\n").put<int32_t>(1).text("\n$EndMeshFormat\n" + kNames);
  b.text("$Nodes\n13\n");
  const auto x = gridNodes();
  for (std::size_t n = 0; n < x.size(); ++n) {
    b.put<int32_t>(int32_t(n + 1)).put(x[n][0]).put(x[n][1]).put(x[n][2]);
  }
  b.text("\n$EndNodes\n$Elements\n5\n");
  // Groups: (type, count, numTags = 2), then per element: tag, physical, entity, nodes.
  const auto group = [&](int type, int tag, int physical, int entity,
                         const std::vector<std::vector<long long>>& elements) {
    b.put<int32_t>(type).put<int32_t>(int32_t(elements.size())).put<int32_t>(2);
    for (const auto& e : elements) {
      b.put<int32_t>(tag++).put<int32_t>(physical).put<int32_t>(entity);
      for (long long n : e) b.put<int32_t>(int32_t(n));
    }
  };
  group(15, 1, 7, 1, {{13}});
  group(3, 2, 5, 1, {kLeft});
  group(5, 3, 1, 1, {kHex1, kHex2});
  group(4, 5, 2, 2, {kTet});
  b.text("\n$EndElements\n");
  return b.s;
}

std::string mesh41Binary() {
  Bytes b;
  b.text("$MeshFormat\n4.1 1 8\n").put<int32_t>(1).text("\n$EndMeshFormat\n" + kNames);
  b.text("$Entities\n").put<uint64_t>(1).put<uint64_t>(0).put<uint64_t>(1).put<uint64_t>(2);
  b.put<int32_t>(1).put(3.0).put(0.0).put(0.0).put<uint64_t>(1).put<int32_t>(7);
  const auto entity = [&](int tag, int physical) {
    b.put<int32_t>(tag);
    for (int k = 0; k < 6; ++k) b.put(0.0);
    b.put<uint64_t>(1).put<int32_t>(physical).put<uint64_t>(0);
  };
  entity(1, 5);
  entity(1, 1);
  entity(2, 2);
  b.text("\n$EndEntities\n$Nodes\n");
  b.put<uint64_t>(2).put<uint64_t>(13).put<uint64_t>(1).put<uint64_t>(13);
  const auto x = gridNodes();
  b.put<int32_t>(3).put<int32_t>(1).put<int32_t>(0).put<uint64_t>(12);
  for (uint64_t n = 1; n <= 12; ++n) b.put(n);
  for (int n = 0; n < 12; ++n) b.put(x[n][0]).put(x[n][1]).put(x[n][2]);
  b.put<int32_t>(0).put<int32_t>(1).put<int32_t>(0).put<uint64_t>(1).put<uint64_t>(13);
  b.put(3.0).put(0.0).put(0.0);
  b.text("\n$EndNodes\n$Elements\n");
  b.put<uint64_t>(4).put<uint64_t>(5).put<uint64_t>(1).put<uint64_t>(5);
  const auto block = [&](int dim, int entity, int type, uint64_t tag,
                         const std::vector<std::vector<long long>>& elements) {
    b.put<int32_t>(dim).put<int32_t>(entity).put<int32_t>(type).put<uint64_t>(elements.size());
    for (const auto& e : elements) {
      b.put<uint64_t>(tag++);
      for (long long n : e) b.put<uint64_t>(uint64_t(n));
    }
  };
  block(0, 1, 15, 1, {{13}});
  block(2, 1, 3, 2, {kLeft});
  block(3, 1, 5, 3, {kHex1, kHex2});
  block(3, 2, 4, 5, {kTet});
  b.text("\n$EndElements\n");
  return b.s;
}

DiscretizationConfig config(const std::string& file, const std::string& extra = "") {
  auto deck = parseDeck("Peridigm:\n  Discretization:\n    Type: Gmsh\n    Input Mesh File: \"" +
                            file + "\"\n" + extra,
                        "yaml");
  return readDiscretizationConfig(ListReader(deck->sublist("Discretization"), "Discretization"));
}

PointCloud readText(const std::string& text, const std::string& extra = "") {
  TempFile f(tempPath("mesh.msh"));
  std::ofstream(f.path, std::ios::binary) << text;
  return buildWholePointCloud(config(f.path, extra));
}

std::string errorOf(const std::string& text, const std::string& extra = "") {
  try {
    readText(text, extra);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

const PointSet& setNamed(const PointCloud& c, const std::string& name) {
  for (const auto& s : c.pointSets)
    if (s.name == name) return s;
  throw std::runtime_error("no set " + name);
}

// The hand-computed cloud: hex centres (0.5, 0.5, 0.5) and (1.5, 0.5, 0.5), volume 1; the
// tetrahedron's centroid (2.25, 0.25, 0.25), volume 1/6.
void expectHandCloud(const PointCloud& c) {
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c.dimension, 3);
  EXPECT_EQ(c.globalNumPoints, 3);
  const double x[3][3] = {{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}, {2.25, 0.25, 0.25}};
  const double v[3] = {1.0, 1.0, 1.0 / 6.0};
  const int block[3] = {1, 1, 2};
  for (int p = 0; p < 3; ++p) {
    EXPECT_EQ(c.globalId[p], p);
    for (int d = 0; d < 3; ++d) EXPECT_DOUBLE_EQ(c.x[3 * p + d], x[p][d]) << p << " " << d;
    EXPECT_DOUBLE_EQ(c.volume[p], v[p]);
    EXPECT_EQ(c.blockId[p], block[p]);
  }
  ASSERT_EQ(c.blockNames.size(), 2u);
  EXPECT_EQ(c.blockNames.at(1), "solid");
  EXPECT_EQ(c.blockNames.at(2), "block_2");
  ASSERT_EQ(c.pointSets.size(), 2u);
  EXPECT_EQ(setNamed(c, "left").globalIds, (std::vector<long long>{0}));
  EXPECT_EQ(setNamed(c, "nodelist_7").globalIds, (std::vector<long long>{2}));
}

TEST(GmshMesh, Format22Ascii) { expectHandCloud(readText(mesh22())); }
TEST(GmshMesh, Format41Ascii) { expectHandCloud(readText(mesh41())); }
TEST(GmshMesh, Format22Binary) { expectHandCloud(readText(mesh22Binary())); }
TEST(GmshMesh, Format41Binary) { expectHandCloud(readText(mesh41Binary())); }

// gmsh's own binary writer, when gmsh is installed: convert the ASCII file.
TEST(GmshMesh, BinaryWrittenByGmsh) {
  if (std::system("gmsh --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "gmsh is not installed";
  TempFile in(tempPath("in.msh"));
  std::ofstream(in.path) << mesh41();
  for (const std::string format : {"msh22", "msh41"}) {
    TempFile out(tempPath(format + ".msh"));
    const std::string command =
        "gmsh " + in.path + " -0 -format " + format + " -bin -o " + out.path + " > /dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    // gmsh may write the cells in another order: put them back in the hand order (by x).
    PointCloud c = buildWholePointCloud(config(out.path));
    ASSERT_EQ(c.size(), 3u);
    std::vector<long long> order = {0, 1, 2};
    std::sort(order.begin(), order.end(),
              [&](long long a, long long b) { return c.x[3 * a] < c.x[3 * b]; });
    PointCloud sorted = c;
    for (std::size_t p = 0; p < 3; ++p) {
      const auto q = static_cast<std::size_t>(order[p]);
      std::copy_n(&c.x[3 * q], 3, &sorted.x[3 * p]);
      sorted.volume[p] = c.volume[q];
      sorted.blockId[p] = c.blockId[q];
    }
    for (PointSet& set : sorted.pointSets) {
      for (long long& id : set.globalIds)
        id = std::find(order.begin(), order.end(), id) - order.begin();
      std::sort(set.globalIds.begin(), set.globalIds.end());
    }
    expectHandCloud(sorted);
  }
}

TEST(GmshMesh, LayersGrowBySurfaceDistance) {
  // The surface x = 0: the first hex centre is 0.5 from it, the second 1.5, the tet 2.25.
  PointCloud c =
      readText(mesh41(), "    Node Set Layers: \"left\"\n    Node Set Layer Depth: 1.6\n");
  EXPECT_EQ(setNamed(c, "left").globalIds, (std::vector<long long>{0, 1}));
  c = readText(mesh41(),
               "    Node Set Layers: \"left, nodelist_7\"\n    Node Set Layer Depth: 1.4\n");
  EXPECT_EQ(setNamed(c, "left").globalIds, (std::vector<long long>{0}));
  // Point (3,0,0) is sqrt(1.5^2 + 0.25 + 0.25) = 1.658 from the second hex centre.
  EXPECT_EQ(setNamed(c, "nodelist_7").globalIds, (std::vector<long long>{2}));
  c = readText(mesh41(), "    Node Set Layers: \"nodelist_7\"\n    Node Set Layer Depth: 1.7\n");
  EXPECT_EQ(setNamed(c, "nodelist_7").globalIds, (std::vector<long long>{1, 2}));
  EXPECT_NE(errorOf(mesh41(), "    Node Set Layers: \"right\"\n    Node Set Layer Depth: 1\n")
                .find("Discretization -> Node Set Layers: \"right\" is not a physical group"),
            std::string::npos);
}

// The layer depth defaults to the largest block horizon; a varying horizon needs the key.
TEST(GmshMesh, LayerDepthDefaultsToHorizon) {
  const auto deck = [](const std::string& horizon2, const std::string& extra) {
    return parseDeck(
        "Peridigm:\n  Discretization:\n    Type: Gmsh\n    Input Mesh File: m.msh\n"
        "    Node Set Layers: left\n" +
            extra +
            "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 1.0\n"
            "      Bulk Modulus: 1.0\n      Shear Modulus: 1.0\n"
            "  Blocks:\n    A:\n      Block Names: solid\n      Material: M\n      Horizon: 0.5\n"
            "    B:\n      Block Names: block_2\n      Material: M\n      Horizon: \"" +
            horizon2 +
            "\"\n  Solver:\n    Final Time: 1.0\n    Verlet:\n      Safety Factor: 0.5\n",
        "yaml");
  };
  EXPECT_DOUBLE_EQ(readRunConfig(*deck("0.75", "")).discretization.layerDepth, 0.75);
  EXPECT_DOUBLE_EQ(
      readRunConfig(*deck("0.75", "    Node Set Layer Depth: 0.2\n")).discretization.layerDepth,
      0.2);
  try {
    readRunConfig(*deck("0.5 + 0.1 * x", ""));
    ADD_FAILURE() << "no error for a varying horizon";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give Node Set Layer Depth"), std::string::npos);
  }
}

// A 2D mesh: unit quads [0,1]x[0,1] and [1,2]x[0,1], the triangle (2,0) (3,0) (2,1), and the
// physical line "bottom" from (0,0) to (1,0).
std::string mesh2D(double zOfNode7 = 0.0) {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n1 3 \"bottom\"\n"
         "$EndPhysicalNames\n$Nodes\n7\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n5 1 1 0\n6 2 1 0\n"
         "7 3 0 " +
         std::to_string(zOfNode7) +
         "\n$EndNodes\n$Elements\n4\n1 1 2 3 1 1 2\n2 3 2 9 1 1 2 5 4\n3 3 2 9 1 2 3 6 5\n"
         "4 2 2 9 1 3 7 6\n$EndElements\n";
}

TEST(GmshMesh, PlanarMeshWithThickness) {
  const PointCloud c = readText(mesh2D(), "    Thickness: 0.1\n");
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c.dimension, 2);
  EXPECT_DOUBLE_EQ(c.thickness, 0.1);
  EXPECT_DOUBLE_EQ(c.x[0], 0.5);
  EXPECT_DOUBLE_EQ(c.x[4], 0.5);
  EXPECT_DOUBLE_EQ(c.x[6], 7.0 / 3.0);
  EXPECT_DOUBLE_EQ(c.x[7], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(c.volume[0], 0.1);
  EXPECT_DOUBLE_EQ(c.volume[2], 0.05);
  EXPECT_EQ(c.blockNames.at(9), "block_9");
  // Both quads touch the line's nodes. The triangle's centre is sqrt(16/9 + 1/9) = 1.374 from
  // the segment's end (1, 0).
  EXPECT_EQ(setNamed(c, "bottom").globalIds, (std::vector<long long>{0, 1}));
  PointCloud layered =
      readText(mesh2D(), "    Node Set Layers: bottom\n    Node Set Layer Depth: 1.37\n");
  EXPECT_EQ(setNamed(layered, "bottom").globalIds, (std::vector<long long>{0, 1}));
  layered = readText(mesh2D(), "    Node Set Layers: bottom\n    Node Set Layer Depth: 1.38\n");
  EXPECT_EQ(setNamed(layered, "bottom").globalIds, (std::vector<long long>{0, 1, 2}));
  EXPECT_NE(errorOf(mesh2D(0.5)).find("node 7 has z = 0.5"), std::string::npos);
}

TEST(GmshMesh, BrokenFilesNameFileAndPlace) {
  const std::string good = mesh41();
  // Truncated inside the nodes.
  std::string e = errorOf(good.substr(0, good.find("$EndNodes") - 20));
  EXPECT_NE(e.find("Discretization -> Input Mesh File: Gmsh mesh \""), std::string::npos) << e;
  EXPECT_NE(e.find(" line "), std::string::npos) << e;
  // A huge count is refused before any loop or allocation.
  std::string huge = good;
  huge.replace(huge.find("$Nodes\n2 13"), 11, "$Nodes\n2 99999999999");
  EXPECT_NE(errorOf(huge).find("bytes left in the file"), std::string::npos) << errorOf(huge);
  // An element refers to a node that does not exist.
  std::string missing = mesh22();
  missing.replace(missing.find("5 4 2 2 2 3 13"), 14, "5 4 2 2 2 3 99");
  EXPECT_NE(errorOf(missing).find("element 5 refers to node 99"), std::string::npos)
      << errorOf(missing);
  // Unsupported versions and cells.
  std::string v4 = good;
  v4.replace(v4.find("4.1 0 8"), 7, "4 0 8");
  EXPECT_NE(errorOf(v4).find("format 4 is not supported"), std::string::npos);
  std::string prism = mesh22();
  prism.replace(prism.find("5 4 2 2 2 3 13 6 9"), 18, "5 6 2 2 2 3 13 6 9 1 2");
  EXPECT_NE(errorOf(prism).find("is a 6-node prism"), std::string::npos) << errorOf(prism);
  // Binary truncated: the offset is named.
  const std::string bin = mesh41Binary();
  e = errorOf(bin.substr(0, bin.size() / 2));
  EXPECT_NE(e.find("byte offset"), std::string::npos) << e;
  // Not a regular file.
  EXPECT_NE(errorOf("").find("no $MeshFormat"), std::string::npos) << errorOf("");
  const std::string dir = tempPath("dir");
  ::mkdir(dir.c_str(), 0700);
  try {
    buildWholePointCloud(config(dir));
    ADD_FAILURE();
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("is not a regular file"), std::string::npos);
  }
  ::rmdir(dir.c_str());
  // Every prefix of the files (ASCII and binary) is refused with an InputError, never a crash.
  for (const std::string& text : {mesh22(), mesh41(), mesh22Binary(), mesh41Binary()}) {
    for (std::size_t n = 0; n + 1 < text.size(); n += 7) {
      EXPECT_NE(errorOf(text.substr(0, n)), "(no error)") << n;
    }
  }
}

// Mutated files (bytes overwritten, cut out, or replaced by extreme numbers; a fixed seed) give
// a cloud or an InputError, never another exception, a crash or a hang.
TEST(GmshMesh, MutatedFilesEndInACloudOrAnInputError) {
  std::mt19937 random(12345);
  const std::vector<std::string> inserts = {
      "99999999999",     "-1", "0", "1e308", "nan", "\n", "$EndNodes\n", std::string(1, '\0'),
      "\xff\xff\xff\x7f"};
  int errors = 0, clouds = 0;
  for (const std::string& text : {mesh22(), mesh41(), mesh22Binary(), mesh41Binary()}) {
    for (int i = 0; i < 150; ++i) {
      std::string m = text;
      const std::size_t at = random() % m.size();
      switch (random() % 3) {
        case 0:
          m[at] = static_cast<char>(random() % 256);
          break;
        case 1:
          m.erase(at, 1 + random() % 16);
          break;
        default:
          m.insert(at, inserts[random() % inserts.size()]);
          break;
      }
      try {
        readText(m, "    Node Set Layers: left\n    Node Set Layer Depth: 1\n");
        ++clouds;
      } catch (const InputError&) {
        ++errors;
      }
    }
  }
  EXPECT_EQ(errors + clouds, 600);
  EXPECT_GT(errors, 300);  // most mutations break the file
}

}  // namespace
}  // namespace peridot
