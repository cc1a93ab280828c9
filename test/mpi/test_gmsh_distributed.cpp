// The Gmsh reader on any number of ranks: the shares together are the one-rank cloud to the bit
// (positions, volumes, blocks, ids, node sets and layers), and a bad file stops every rank with
// the one-rank message. Meshes are made by gmsh from a .geo (skipped without gmsh).
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "discretization/Discretization.hpp"

namespace {

using namespace peridot;

int rankOf() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

bool haveGmsh() {
  int ok = 0;
  if (rankOf() == 0) ok = std::system("gmsh --version > /dev/null 2>&1") == 0 ? 1 : 0;
  MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return ok == 1;
}

// Rank 0 meshes the .geo with gmsh into the given format; every rank gets the path.
std::string meshed(const std::string& geo, const std::string& stem, const std::string& options) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  // Named by rank count: ctest runs the np1-3 variants at once in one folder.
  const std::string base = (std::filesystem::temp_directory_path() /
                            ("peridot_gmsh_np" + std::to_string(size) + "_" + stem))
                               .string();
  int status = 0;
  if (rankOf() == 0) {
    std::ofstream(base + ".geo") << geo;
    const std::string command =
        "gmsh " + base + ".geo " + options + " -o " + base + ".msh > /dev/null 2>&1";
    status = std::system(command.c_str());
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
  EXPECT_EQ(status, 0);
  return base + ".msh";
}

DiscretizationConfig config(const std::string& file, const std::string& extra) {
  auto deck = parseDeck("Peridigm:\n  Discretization:\n    Type: Gmsh\n    Input Mesh File: \"" +
                            file + "\"\n" + extra,
                        "yaml");
  return readDiscretizationConfig(ListReader(deck->sublist("Discretization"), "Discretization"));
}

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

// The shares, gathered in rank order, equal the one-rank read to the bit.
void expectSameAsWhole(const DiscretizationConfig& c) {
  const PointCloud whole = buildWholePointCloud(c);
  const PointCloud share = buildPointCloud(c, MPI_COMM_WORLD);
  EXPECT_EQ(share.globalNumPoints, whole.globalNumPoints);
  EXPECT_EQ(share.blockNames, whole.blockNames);
  EXPECT_EQ(share.dimension, whole.dimension);
  const auto x = allGather(share.x, MPI_DOUBLE);
  const auto v = allGather(share.volume, MPI_DOUBLE);
  const auto b = allGather(share.blockId, MPI_INT);
  const auto g = allGather(share.globalId, MPI_LONG_LONG);
  ASSERT_EQ(v.size(), whole.size());
  EXPECT_EQ(std::memcmp(x.data(), whole.x.data(), x.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(v.data(), whole.volume.data(), v.size() * sizeof(double)), 0);
  EXPECT_EQ(b, whole.blockId);
  EXPECT_EQ(g, whole.globalId);
  ASSERT_EQ(share.pointSets.size(), whole.pointSets.size());
  for (std::size_t s = 0; s < whole.pointSets.size(); ++s) {
    EXPECT_EQ(share.pointSets[s].name, whole.pointSets[s].name);
    EXPECT_EQ(allGather(share.pointSets[s].globalIds, MPI_LONG_LONG), whole.pointSets[s].globalIds)
        << whole.pointSets[s].name;
  }
}

const char* kBox =
    "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 2, 1, 1};\n"
    "Physical Volume(\"solid\") = {1};\nPhysical Surface(\"left\") = {1};\n"
    "Physical Surface(\"right\") = {2};\nMesh.CharacteristicLengthMax = 0.3;\n";

TEST(GmshDistributed, BoxInBothVersionsSameAsOneRank) {
  if (!haveGmsh()) GTEST_SKIP() << "gmsh is not installed";
  // Both versions and both encodings (each of the four is checked at one rank in the unit
  // tests; the distribution does not depend on the format).
  const std::vector<std::pair<std::string, std::string>> formats = {{"msh41", ""},
                                                                    {"msh22", "-bin"}};
  for (const auto& [format, bin] : formats) {
    {
      const std::string file =
          meshed(kBox, "box" + format + bin, "-3 -format " + format + " " + bin);
      const DiscretizationConfig c =
          config(file, "    Node Set Layers: \"left, right\"\n    Node Set Layer Depth: 0.25\n");
      expectSameAsWhole(c);
      // The total volume is the box's, and the layers hold every point within 0.25 of x = 0
      // (resp. x = 2) and no point farther than that that does not touch the face.
      const PointCloud whole = buildWholePointCloud(c);
      double total = 0;
      for (double vol : whole.volume) total += vol;
      EXPECT_NEAR(total, 2.0, 1e-12);
      for (const PointSet& set : whole.pointSets) {
        std::vector<char> in(whole.size(), 0);
        for (long long id : set.globalIds) in[static_cast<std::size_t>(id)] = 1;
        for (std::size_t p = 0; p < whole.size(); ++p) {
          const double distance = set.name == "left" ? whole.x[3 * p] : 2.0 - whole.x[3 * p];
          if (distance <= 0.25) {
            EXPECT_TRUE(in[p]) << set.name << " " << p;
          } else if (distance > 0.35) {  // farther than a cell: not touching the face either
            EXPECT_FALSE(in[p]) << set.name << " " << p;
          }
        }
      }
      MPI_Barrier(MPI_COMM_WORLD);  // every rank is done with the file
      if (rankOf() == 0) std::filesystem::remove(file);
    }
  }
}

TEST(GmshDistributed, PlanarSameAsOneRank) {
  if (!haveGmsh()) GTEST_SKIP() << "gmsh is not installed";
  const std::string geo =
      "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 0.5, 0}; Point(4) = {0, 0.5, "
      "0};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
      "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
      "Physical Surface(\"plate\") = {1}; Physical Curve(\"bottom\") = {1};\n"
      "Mesh.CharacteristicLengthMax = 0.1; Mesh.RecombineAll = 1;\n";
  const std::string file = meshed(geo, "plate", "-2 -format msh41");
  const DiscretizationConfig c = config(file,
                                        "    Thickness: 0.01\n    Node Set Layers: bottom\n"
                                        "    Node Set Layer Depth: 0.15\n");
  expectSameAsWhole(c);
  const PointCloud whole = buildWholePointCloud(c);
  EXPECT_EQ(whole.dimension, 2);
  double total = 0;
  for (double vol : whole.volume) total += vol;
  EXPECT_NEAR(total, 0.5 * 0.01, 1e-14);
  MPI_Barrier(MPI_COMM_WORLD);
  if (rankOf() == 0) std::filesystem::remove(file);
}

TEST(GmshDistributed, BadFileSameMessageOnEveryRank) {
  if (!haveGmsh()) GTEST_SKIP() << "gmsh is not installed";
  const std::string file = meshed(kBox, "bad", "-3 -format msh22");
  // Break one element near the end: its last node refers to a node that does not exist.
  if (rankOf() == 0) {
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t end = text.find("\n$EndElements");
    const std::size_t last = text.rfind(' ', end);
    text.replace(last + 1, end - last - 1, "999999");
    std::ofstream(file) << text;
  }
  MPI_Barrier(MPI_COMM_WORLD);
  std::string whole, share;
  try {
    buildWholePointCloud(config(file, ""));
  } catch (const InputError& e) {
    whole = e.what();
  }
  try {
    buildPointCloud(config(file, ""), MPI_COMM_WORLD);
  } catch (const InputError& e) {
    share = e.what();
  }
  EXPECT_NE(whole.find("refers to node 999999"), std::string::npos) << whole;
  EXPECT_EQ(share, whole);
  MPI_Barrier(MPI_COMM_WORLD);
  if (rankOf() == 0) std::filesystem::remove(file);
}

}  // namespace
