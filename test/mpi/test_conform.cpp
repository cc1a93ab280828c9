// Peridigm deck forms (issue 12) run through the Simulation on 1, 2 and 3 ranks, each checked
// against an independent result.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "../common/TestExodusMesh.hpp"
#include "app/RunVariables.hpp"
#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "output/ExodusCompare.hpp"

namespace peridot {
namespace {

using testing::addNode;
using testing::TestBlock;
using testing::TestMesh;

std::ostringstream quiet;

// A mesh file every rank sees: rank 0 writes it, everyone removes nothing until the end.
struct MeshFile {
  explicit MeshFile(const TestMesh& mesh) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    path = (std::filesystem::temp_directory_path() /
            ("peridot_conform_" + std::to_string(::getpid()) + ".g"))
               .string();
    int length = static_cast<int>(path.size());
    MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
    path.resize(static_cast<std::size_t>(length));
    MPI_Bcast(path.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
    if (rank == 0) testing::writeMesh(path, mesh);
    MPI_Barrier(MPI_COMM_WORLD);
  }
  ~MeshFile() {
    MPI_Barrier(MPI_COMM_WORLD);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    std::error_code ec;
    if (rank == 0) std::filesystem::remove(path, ec);
  }
  std::string path;
};

// One layer of nx x ny HEX8 elements of size a x a x h (z in [-h/2, h/2]): Peridigm's way of
// writing a 2D model.
TestMesh oneLayer(int nx, int ny, double a, double h) {
  TestMesh mesh;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) addNode(mesh, a * i, a * j, h * (k - 0.5));
  const auto node = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k); };
  TestBlock block;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      for (int k = 0; k < 2; ++k) {
        for (const auto& c :
             {std::pair{i, j}, std::pair{i + 1, j}, std::pair{i + 1, j + 1}, std::pair{i, j + 1}}) {
          block.connectivity.push_back(node(c.first, c.second, k));
        }
      }
    }
  }
  mesh.blocks = {block};
  return mesh;
}

std::vector<double> runAndGet(const std::string& deck, const std::string& variable) {
  Simulation sim(readRunConfig(*parseDeck(deck, "yaml")), MPI_COMM_WORLD, quiet);
  sim.run();
  std::vector<double> values;
  sim.variables().nodeVariable(variable, values);
  return values;
}

std::string bondBasedDeck(const std::string& mesh, const std::string& material) {
  return "Peridigm:\n"
         "  Discretization:\n    Type: Exodus\n    Input Mesh File: \"" +
         mesh +
         "\"\n"
         "  Materials:\n    M:\n      Material Model: Elastic Bond Based\n      Density: 7800.0\n" +
         material +
         "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 0.751\n"
         "  Boundary Conditions:\n    All Node Set: \"1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 "
         "19 20 "
         "21 22 23 24\"\n"
         "    V:\n      Type: Initial Velocity\n      Node Set: All Node Set\n      Coordinate: y\n"
         "      Value: \"1.0e3*y*y + 2.0e2*x\"\n"
         "  Solver:\n    Final Time: 2.0e-7\n    Verlet:\n      Fixed dt: 2.0e-8\n";
}

// Peridigm's 2D bond-based form: plane stress on a one-layer HEX8 mesh, 3D points and bonds,
// micromodulus 12 K / (pi h delta^3). The same run in 3D with the bulk modulus whose 3D
// micromodulus 18 K3 / (pi delta^4) is that value (K3 = 2 K delta / (3 h)) is the gold.
TEST(Conform, BondBasedPlaneStressOnOneLayerOfHexes) {
  const double K = 200.0e9, h = 0.25, delta = 0.751;
  MeshFile mesh(oneLayer(6, 4, 0.25, h));
  std::ostringstream planar, solid, young;
  planar.precision(17);
  solid.precision(17);
  planar << "      Bulk Modulus: " << K << "\n      Plane Stress: true\n      Height: " << h
         << "\n";
  solid << "      Bulk Modulus: " << 2.0 * K * delta / (3.0 * h) << "\n";
  // Young's modulus in plane stress: nu = 1/3, K = E.
  young << "      Young's Modulus: " << K << "\n      Plane Stress: true\n      Height: " << h
        << "\n";
  for (const char* variable : {"Displacement", "Force_Density"}) {
    const auto a = runAndGet(bondBasedDeck(mesh.path, planar.str()), variable);
    const auto b = runAndGet(bondBasedDeck(mesh.path, solid.str()), variable);
    const auto c = runAndGet(bondBasedDeck(mesh.path, young.str()), variable);
    ASSERT_EQ(a.size(), b.size());
    double scale = 0;
    for (double v : b) scale = std::max(scale, std::fabs(v));
    ASSERT_GT(scale, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_NEAR(a[i], b[i], 1e-12 * scale) << variable << " " << i;
      EXPECT_EQ(a[i], c[i]) << variable << " " << i;
    }
  }
  // Plane strain is the same constant for a given K (only E -> K differs: nu = 1/4).
  std::ostringstream strain;
  strain.precision(17);
  strain << "      Bulk Modulus: " << K << "\n      Plane Strain: true\n      Height: " << h
         << "\n";
  EXPECT_EQ(runAndGet(bondBasedDeck(mesh.path, strain.str()), "Displacement"),
            runAndGet(bondBasedDeck(mesh.path, planar.str()), "Displacement"));
}

TEST(Conform, BondBasedPlaneModeOnSolidMeshNeedsHeight) {
  MeshFile mesh(oneLayer(6, 4, 0.25, 0.25));
  const std::string deck =
      bondBasedDeck(mesh.path, "      Bulk Modulus: 1.0e9\n      Plane Strain: true\n");
  try {
    runAndGet(deck, "Displacement");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Height"), std::string::npos) << e.what();
  }
}

// Contact only: pairs of points far apart compared with the horizon (no bonds at all) meet
// head-on through the short-range contact force. Equal masses and a frictionless linear spring:
// an elastic collision, after which the two velocities are exchanged (the gold).
TestMesh collidingPairs(int pairs) {
  TestMesh mesh;
  TestBlock left, right;
  for (TestBlock* b : {&left, &right}) {
    b->type = "SPHERE";
    b->nodesPerElement = 1;
    b->numAttributes = 2;
  }
  left.id = 1;
  right.id = 2;
  for (int p = 0; p < pairs; ++p) {
    addNode(mesh, 0.0, 10.0 * p, 0.0);
    addNode(mesh, 1.5, 10.0 * p, 0.0);
    left.connectivity.push_back(2 * p + 1);
    right.connectivity.push_back(2 * p + 2);
    for (TestBlock* b : {&left, &right}) b->attributes.insert(b->attributes.end(), {0.6, 1.0});
  }
  mesh.blocks = {left, right};
  return mesh;
}

std::string contactDeck(const std::string& mesh, const std::string& verlet) {
  return "Peridigm:\n"
         "  Discretization:\n    Type: Exodus\n    Input Mesh File: \"" +
         mesh +
         "\"\n"
         "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 1.0\n"
         "      Bulk Modulus: 1.0e3\n      Shear Modulus: 1.0e3\n"
         "  Blocks:\n    B:\n      Block Names: default\n      Material: M\n      Horizon: 0.5\n"
         "  Contact:\n    Search Radius: 2.0\n    Search Frequency: 1\n"
         "    Models:\n      C:\n        Contact Model: Short Range Force\n"
         "        Contact Radius: 1.0\n        Spring Constant: 1.0e3\n"
         "    Interactions:\n      General Contact:\n        Contact Model: C\n"
         "  Boundary Conditions:\n"
         "    V:\n      Type: Initial Velocity\n      Node Set: All Node Set\n      Coordinate: x\n"
         "      Value: \"1.0 - 2.0*(x > 1)\"\n"
         "    All Node Set: \"1 2 3 4 5 6\"\n"
         "  Solver:\n    Final Time: 0.5\n    Verlet:\n" +
         verlet;
}

TEST(Conform, ContactOnlyDeckRunsAndCollisionsAreElastic) {
  MeshFile mesh(collidingPairs(3));
  Simulation sim(
      readRunConfig(*parseDeck(contactDeck(mesh.path, "      Fixed dt: 2.0e-5\n"), "yaml")),
      MPI_COMM_WORLD, quiet);
  sim.run();
  std::vector<double> v, x;
  sim.variables().nodeVariable("Velocity", v);
  sim.variables().nodeVariable("Model_Coordinates", x);
  ASSERT_EQ(v.size(), x.size());
  int touched = 0;
  for (std::size_t p = 0; 3 * p < v.size(); ++p) {
    // The left point (x = 0) left with +1 and comes back with -1, the right one the reverse.
    const double expected = x[3 * p] < 1.0 ? -1.0 : 1.0;
    EXPECT_NEAR(v[3 * p], expected, 1e-3) << "point at x = " << x[3 * p];
    EXPECT_NEAR(v[3 * p + 1], 0.0, 1e-12);
    EXPECT_NEAR(v[3 * p + 2], 0.0, 1e-12);
    ++touched;
  }
  int total = 0;
  MPI_Allreduce(&touched, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(total, 6);
}

TEST(Conform, ContactOnlyDeckWithoutFixedDtSaysWhy) {
  MeshFile mesh(collidingPairs(3));
  try {
    Simulation sim(
        readRunConfig(*parseDeck(contactDeck(mesh.path, "      Safety Factor: 0.5\n"), "yaml")),
        MPI_COMM_WORLD, quiet);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Fixed dt"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("contact"), std::string::npos) << e.what();
  }
}

// Nearest_Point_Data and Radius on a 4x4x4 grid of unit cells with v_y = x + 10 z: the tracked
// point's value is the expression at the nearest cell centre (by hand), a tie between two
// centres goes to the smaller id, and a vector comes out as <label>_X/_Y/_Z.
TEST(Conform, NearestPointDataAndRadius) {
  std::string all;
  for (int i = 1; i <= 64; ++i) all += std::to_string(i) + " ";
  const std::string deck =
      "Peridigm:\n"
      "  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
      "    TensorProduct3DMeshGenerator:\n"
      "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
      "      X Length: 4.0\n      Y Length: 4.0\n      Z Length: 4.0\n"
      "      Number Points X: 4\n      Number Points Y: 4\n      Number Points Z: 4\n"
      "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 2.0\n"
      "      Bulk Modulus: 5.0\n      Shear Modulus: 3.0\n"
      "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 2.1\n"
      "  Boundary Conditions:\n    All Node Set: \"" +
      all +
      "\"\n"
      "    V:\n      Type: Initial Velocity\n      Node Set: All Node Set\n"
      "      Coordinate: y\n      Value: \"x + 10*z\"\n"
      "  Compute Class Parameters:\n"
      "    Gauge:\n      Compute Class: Nearest_Point_Data\n      X: 2.4\n      Y: 0.1\n"
      "      Z: 3.3\n      Variable: Velocity\n      Output Label: Gauge_Velocity\n"
      "    Tie:\n      Compute Class: Nearest_Point_Data\n      X: 1.0\n      Y: 0.5\n"
      "      Z: 0.5\n      Variable: Velocity\n      Output Label: Tie_Velocity\n"
      "      Verbose: false\n"
      "    Size:\n      Compute Class: Nearest_Point_Data\n      X: 0.0\n      Y: 0.0\n"
      "      Z: 0.0\n      Variable: Radius\n      Output Label: Corner_Radius\n"
      "  Solver:\n    Final Time: 1.0\n    Verlet:\n      Fixed dt: 0.5\n";
  Simulation sim(readRunConfig(*parseDeck(deck, "yaml")), MPI_COMM_WORLD, quiet);
  std::vector<double> g;
  // Nearest centre to (2.4, 0.1, 3.3) is (2.5, 0.5, 3.5): v_y = 2.5 + 35.
  sim.variables().globalVariable("Gauge_Velocity", g);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_EQ(g[0], 0.0);
  EXPECT_EQ(g[1], 37.5);
  EXPECT_EQ(g[2], 0.0);
  // (1.0, 0.5, 0.5) is as far from (0.5, 0.5, 0.5) (id 1) as from (1.5, 0.5, 0.5) (id 2).
  sim.variables().globalVariable("Tie_Velocity", g);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_EQ(g[1], 5.5);
  const double radius = std::cbrt(3.0 / (4.0 * std::acos(-1.0)));  // unit volume
  sim.variables().globalVariable("Corner_Radius", g);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_NEAR(g[0], radius, 1e-15);
  std::vector<double> r;
  sim.variables().nodeVariable("Radius", r);
  for (double v : r) EXPECT_NEAR(v, radius, 1e-15);
  EXPECT_EQ(sim.variables().globalComponentName("Gauge_Velocity", 1), "Gauge_Velocity_Y");
}

// A stream of global variables only is a `.h` file on Peridigm's placeholder mesh: one node at
// the origin, one element in block 1, no node sets. Its kinetic energy by hand: 64 unit cells,
// density 2, v_y = 2: 64 x 1/2 x 2 x 4 = 256.
TEST(Conform, GlobalsOnlyStreamHasPeridigmsPlaceholderMesh) {
  std::string base = (std::filesystem::temp_directory_path() /
                      ("peridot_conform_hist_" + std::to_string(::getpid())))
                         .string();
  int length = static_cast<int>(base.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  base.resize(static_cast<std::size_t>(length));
  MPI_Bcast(base.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  std::string all;
  for (int i = 1; i <= 64; ++i) all += std::to_string(i) + " ";
  const std::string deck =
      "Peridigm:\n"
      "  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
      "    TensorProduct3DMeshGenerator:\n"
      "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
      "      X Length: 4.0\n      Y Length: 4.0\n      Z Length: 4.0\n"
      "      Number Points X: 4\n      Number Points Y: 4\n      Number Points Z: 4\n"
      "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 2.0\n"
      "      Bulk Modulus: 5.0\n      Shear Modulus: 3.0\n"
      "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 2.1\n"
      "  Boundary Conditions:\n    All Node Set: \"" +
      all +
      "\"\n"
      "    V:\n      Type: Initial Velocity\n      Node Set: All Node Set\n"
      "      Coordinate: y\n      Value: \"2.0\"\n"
      "  Solver:\n    Final Time: 1.0\n    Verlet:\n      Fixed dt: 0.5\n"
      "  Output:\n    Output File Type: ExodusII\n    Output Filename: \"" +
      base +
      "\"\n    Output Frequency: 1\n"
      "    Output Variables:\n      Global_Kinetic_Energy: true\n";
  {
    Simulation sim(readRunConfig(*parseDeck(deck, "yaml")), MPI_COMM_WORLD, quiet);
    sim.run();
  }
  MPI_Barrier(MPI_COMM_WORLD);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) {
    const auto h = readExodusResults(base + ".h");
    EXPECT_EQ(h.nodeIds, (std::vector<long long>{1}));
    EXPECT_EQ(h.nodeCoordinates, (std::vector<double>{0.0, 0.0, 0.0}));
    EXPECT_EQ(h.elementIds, (std::vector<long long>{1}));
    EXPECT_EQ(h.elementBlock, (std::vector<long long>{1}));
    EXPECT_TRUE(h.nodalNames.empty());
    EXPECT_TRUE(h.elementNames.empty());
    ASSERT_EQ(h.globalNames, (std::vector<std::string>{"Global_Kinetic_Energy"}));
    ASSERT_EQ(h.times.size(), 3u);
    EXPECT_EQ(h.global[0][0][0], 256.0);
    std::filesystem::remove(base + ".h");
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

}  // namespace
}  // namespace peridot
