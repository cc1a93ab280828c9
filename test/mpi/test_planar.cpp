// Planar (2D) runs on 1, 2 and 3 ranks: neighbourhoods are disks (lists equal a brute-force
// search, with and without periodic images), and a whole 2D run writes a num_dim = 2 file whose
// nodal values are identical, to the bit, to the same run on one rank.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>

#include "../common/CloudShare.hpp"
#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "materials/MaterialModel.hpp"
#include "output/ExodusCompare.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

// A test-only plane-stress material, self-contained so that the test depends on no real model:
// bond springs f = c s Y/|Y| V_j (pull form, both ends' halves), declaring itself planar.
class PlaneStressTestSpring : public MaterialModel {
 public:
  explicit PlaneStressTestSpring(ListReader& p)
      : density_(p.positiveNumber("Density")), c_(p.positiveNumber("Spring Constant")) {}
  double density() const override { return density_; }
  double bulkModulus() const override { return c_; }
  PlaneMode planeMode() const override { return PlaneMode::PlaneStress; }
  std::string family() const override { return "test spring"; }
  void initialize(const ModelState& state, const std::vector<int>&) override {
    seenDimension = state.dimension;  // what the run told the models
    seenThickness = state.thickness;
  }
  void computeForce(const ModelState& s, const std::vector<int>& points) override {
    const Topology& t = *s.topology;
    for (int i : points) {
      double f[3] = {0, 0, 0};
      for (auto b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
        const int j = t.neighbors[b];
        double X2 = 0, Y2 = 0, Y[3];
        for (int d = 0; d < 3; ++d) {
          const double X = s.x[3 * j + d] - s.x[3 * i + d];
          Y[d] = s.y[3 * j + d] - s.y[3 * i + d];
          X2 += X * X;
          Y2 += Y[d] * Y[d];
        }
        const double stretch = (std::sqrt(Y2) - std::sqrt(X2)) / std::sqrt(X2);
        for (int d = 0; d < 3; ++d) f[d] += c_ * stretch * Y[d] / std::sqrt(Y2) * s.volume[j];
      }
      for (int d = 0; d < 3; ++d) s.forceDensity[3 * i + d] = f[d];
    }
  }
  void storedEnergyDensity(const ModelState&, const std::vector<int>& points,
                           double* w) const override {
    for (int i : points) w[i] = 0.0;
  }
  void stiffnessSum(const ModelState& s, const std::vector<int>& points,
                    double* sum) const override {
    const Topology& t = *s.topology;
    for (int i : points) {
      sum[i] = 0.0;
      for (auto b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b)
        sum[i] += c_ / s.bondLength[b] * s.volume[t.neighbors[b]];
    }
  }
  static inline int seenDimension = 0;
  static inline double seenThickness = 0.0;

 private:
  double density_, c_;
};

PERIDOT_REGISTER_MATERIAL("Test Plane Stress Spring", PlaneStressTestSpring,
                          "test only: bond springs declaring plane stress",
                          (std::vector<ParameterDoc>{{"Density", "positive number"},
                                                     {"Spring Constant", "positive number"}}))

namespace {

std::ostringstream quiet;

PointCloud randomPlanarCloud(std::size_t n, unsigned seed) {
  PointCloud c;
  c.dimension = 2;
  c.thickness = 0.1;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    c.x.insert(c.x.end(), {u(gen), 0.6 * u(gen), 0.0});
    c.volume.push_back(1e-4);
    c.blockId.push_back(1);
    c.globalId.push_back(static_cast<long long>(2 * i + 1));
  }
  c.blockNames = {{1, "block_1"}};
  return c;
}

// Number of one-sided bonds |xi| <= h by brute force, with minimum images along periodic axes
// (box [0,1) x [0,0.6)).
long long bruteForceBonds(const PointCloud& c, double h, bool periodic,
                          std::map<long long, int>* counts = nullptr) {
  long long bonds = 0;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = 0; j < c.size(); ++j) {
      if (i == j) continue;
      double dx = c.x[3 * j] - c.x[3 * i], dy = c.x[3 * j + 1] - c.x[3 * i + 1];
      if (periodic) {
        dx -= std::round(dx);
        dy -= 0.6 * std::round(dy / 0.6);
      }
      if (dx * dx + dy * dy <= h * h) {
        ++bonds;
        if (counts) ++(*counts)[c.globalId[i]];
      }
    }
  return bonds;
}

TEST(Planar, NeighbourhoodsAreDisksOnAnyRankCount) {
  const PointCloud cloud = randomPlanarCloud(1200, 3);
  const double h = 0.05;
  std::vector<double> horizon(cloud.size(), h);
  Topology t = testing::topologyOfWhole(cloud, horizon, TopologyOptions(), MPI_COMM_WORLD);
  std::map<long long, int> expected;
  EXPECT_EQ(t.globalNumBonds, bruteForceBonds(cloud, h, false, &expected));
  // Every point is owned once, and RCB on a flat cloud gives every rank a share.
  long long owned = t.numOwned, total = 0;
  MPI_Allreduce(&owned, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(total, static_cast<long long>(cloud.size()));
  EXPECT_GT(t.numOwned, static_cast<int>(cloud.size()) / (2 * t.numRanks));
  for (int i = 0; i < t.numOwned; ++i) {
    const long long id = t.overlapGlobalId[i];
    EXPECT_EQ(t.numNeighbors(i), expected.count(id) ? expected.at(id) : 0) << "point " << id;
    for (auto b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
      EXPECT_EQ(t.referencePosition[3 * t.neighbors[b] + 2], 0.0);
    }
  }
}

TEST(Planar, CrackLineAsABondFilterStraddlingThePlane) {
  // A crack along x = 0.5 for 0.1 <= y <= 0.4: a rectangle normal to x spanning z in [-1, 1].
  const PointCloud cloud = randomPlanarCloud(1200, 5);
  const double h = 0.05;
  std::vector<double> horizon(cloud.size(), h);
  std::vector<BondFilter> filters(1);
  BondFilter& f = filters[0];
  f.normal[0] = 1.0;
  f.normal[2] = 0.0;
  f.lowerLeftCorner[0] = 0.5;
  f.lowerLeftCorner[1] = 0.1;
  f.lowerLeftCorner[2] = -1.0;
  f.bottomUnitVector[0] = 0.0;
  f.bottomUnitVector[1] = 1.0;
  f.bottomLength = 0.3;
  f.sideLength = 2.0;  // along normal x bottom = +z
  TopologyOptions options;
  options.bondFilters = &filters;
  Topology t = testing::topologyOfWhole(cloud, horizon, options, MPI_COMM_WORLD);
  long long kept = 0, cut = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    for (std::size_t j = 0; j < cloud.size(); ++j) {
      if (i == j) continue;
      const double dx = cloud.x[3 * j] - cloud.x[3 * i],
                   dy = cloud.x[3 * j + 1] - cloud.x[3 * i + 1];
      if (dx * dx + dy * dy > h * h) continue;
      // Independent of BondFilter::cuts: the segment crosses x = 0.5 at a y in [0.1, 0.4].
      const double xi = cloud.x[3 * i], xj = cloud.x[3 * j];
      bool crosses = (xi - 0.5) * (xj - 0.5) < 0;
      if (crosses) {
        const double y = cloud.x[3 * i + 1] + (0.5 - xi) / (xj - xi) * dy;
        crosses = y >= 0.1 && y <= 0.4;
      }
      (crosses ? cut : kept) += 1;
    }
  EXPECT_GT(cut, 0);
  EXPECT_EQ(t.globalNumBonds, kept);
}

TEST(Planar, PeriodicImagesInThePlane) {
  const PointCloud cloud = randomPlanarCloud(1200, 11);
  const double h = 0.07;
  std::vector<double> horizon(cloud.size(), h);
  TopologyOptions options;
  options.periodic.periodic[0] = options.periodic.periodic[1] = true;
  options.periodic.upper[0] = 1.0;
  options.periodic.upper[1] = 0.6;
  Topology t = testing::topologyOfWhole(cloud, horizon, options, MPI_COMM_WORLD);
  EXPECT_EQ(t.globalNumBonds, bruteForceBonds(cloud, h, true));
  for (std::size_t k = 0; k < t.imageSource.size(); ++k) EXPECT_EQ(t.imageShift[3 * k + 2], 0.0);
}

// A 12 x 8 plate, thickness 0.1: stretched by an initial velocity field, left edge held.
std::string plateDeck(const std::string& outputFile, const std::string& material,
                      const std::string& generator = "TensorProduct2DMeshGenerator") {
  const bool planar = generator == "TensorProduct2DMeshGenerator";
  return "Peridigm:\n"
         "  Discretization:\n"
         "    Type: PdQuickGrid\n"
         "    NeighborhoodType: Spherical\n" +
         std::string(planar ? "    Thickness: 0.1\n" : "") + "    " + generator +
         ":\n"
         "      X Origin: 0.0\n      Y Origin: 0.0\n"
         "      X Length: 12.0\n      Y Length: 8.0\n"
         "      Number Points X: 12\n      Number Points Y: 8\n" +
         std::string(
             planar ? "" : "      Z Origin: 0.0\n      Z Length: 1.0\n      Number Points Z: 1\n") +
         "  Materials:\n    M:\n      Material Model: " + material + "\n      Density: 1.0\n" +
         (material == "Elastic Bond Based" ? "      Bulk Modulus: 1.0\n"
                                           : "      Spring Constant: 0.01\n") +
         "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 3.1\n"
         "  Boundary Conditions:\n    Left Node Set: \"1 13 25 37 49 61 73 85\"\n"
         "    Stretch:\n      Type: Initial Velocity\n      Node Set: All Node Set\n"
         "      Coordinate: x\n      Value: \"0.01 * x * (1 + 0.1 * y)\"\n"
         "    Shear:\n      Type: Initial Velocity\n      Node Set: All Node Set\n"
         "      Coordinate: y\n      Value: \"0.003 * x * x - 0.002 * y\"\n"
         "    Hold:\n      Type: Prescribed Displacement\n      Node Set: Left Node Set\n"
         "      Coordinate: x\n      Value: \"0.0\"\n"
         "    All Node Set: \"" +
         [] {
           std::string ids;
           for (int i = 1; i <= 96; ++i) ids += std::to_string(i) + (i < 96 ? " " : "");
           return ids;
         }() +
         "\"\n"
         "  Compute Class Parameters:\n"
         "    Momentum:\n      Compute Class: Block_Data\n      Calculation Type: Sum\n"
         "      Block: block_1\n      Variable: Velocity\n      Output Label: VelocitySum\n"
         "  Solver:\n    Final Time: 20.0\n    Verlet:\n      Fixed dt: 0.5\n"
         "  Output:\n    Output Filename: " +
         outputFile +
         "\n    Output Frequency: 10\n    Output Variables:\n"
         "      Displacement: true\n      Velocity: true\n      Force: true\n"
         "      Volume: true\n      VelocitySum: true\n";
}

std::unique_ptr<Simulation> makeSimulation(const std::string& deck, MPI_Comm comm) {
  return std::make_unique<Simulation>(readRunConfig(*parseDeck(deck, "yaml")), comm, quiet);
}

TEST(Planar, RunIsIdenticalToTheSerialRunAndWritesA2DFile) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  long long pid = ::getpid();
  MPI_Bcast(&pid, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  const std::string base =
      (std::filesystem::temp_directory_path() /
       ("peridot_planar_" + std::to_string(pid) + "_np" + std::to_string(size)))
          .string();
  {
    auto sim = makeSimulation(plateDeck(base + "_all", "Test Plane Stress Spring"), MPI_COMM_WORLD);
    EXPECT_LE(sim->timeStep(), sim->stableTimeStepEstimate());
    EXPECT_EQ(PlaneStressTestSpring::seenDimension, 2);
    EXPECT_EQ(PlaneStressTestSpring::seenThickness, 0.1);
    sim->run();
    // Nothing moved out of the plane.
    std::vector<double> u;
    sim->variables().nodeVariable("Displacement", u);
    double largestZ = 0.0, largestX = 0.0;
    for (std::size_t k = 0; k < u.size(); k += 3) {
      largestX = std::max(largestX, std::fabs(u[k]));
      largestZ = std::max(largestZ, std::fabs(u[k + 2]));
    }
    EXPECT_EQ(largestZ, 0.0);
    if (!u.empty()) {
      EXPECT_GT(largestX, 0.0);
    }
  }
  if (rank == 0) {
    {
      auto serial =
          makeSimulation(plateDeck(base + "_one", "Test Plane Stress Spring"), MPI_COMM_SELF);
      serial->run();
    }
    const ExodusResults all = readExodusResults(base + "_all.e");
    const ExodusResults one = readExodusResults(base + "_one.e");
    EXPECT_EQ(all.dimension, 2);
    EXPECT_EQ(all.nodalNames,
              (std::vector<std::string>{"DisplacementX", "DisplacementY", "VelocityX", "VelocityY",
                                        "ForceX", "ForceY"}));
    EXPECT_EQ(all.globalNames, (std::vector<std::string>{"VelocitySumX", "VelocitySumY"}));
    ASSERT_EQ(all.times.size(), 5u);  // steps 0, 10, 20, 30, 40
    // Point 14 (cell (1, 1)) at (1.5, 1.5); its volume is 1 x 1 x thickness.
    EXPECT_EQ(all.nodeCoordinates[3 * 13], 1.5);
    EXPECT_EQ(all.nodeCoordinates[3 * 13 + 1], 1.5);
    ASSERT_EQ(all.elementNames, (std::vector<std::string>{"Volume"}));
    EXPECT_DOUBLE_EQ(all.element[0][0][13], 0.1);
    // The stretch moved the points.
    EXPECT_GT(std::fabs(all.nodal[0][4][95]), 1e-3);
    // Nodal values and coordinates to the bit; globals are sums whose order depends on the rank
    // count, so a relative 1e-12.
    const CompSpec spec = parseCompText(
        "COORDINATES absolute 0\nTIME STEPS absolute 0\nNODAL VARIABLES absolute 0\n"
        "ELEMENT VARIABLES absolute 0\nGLOBAL VARIABLES relative 1e-12 floor 1e-15\n",
        "planar.comp");
    const CompareReport report = compareExodusResults(all, one, spec);
    std::ostringstream text;
    printCompareReport(text, report, true);
    EXPECT_TRUE(report.passed()) << text.str();
    EXPECT_GT(report.valuesCompared(), 5u * 96u * 6u);
    std::remove((base + "_all.e").c_str());
    std::remove((base + "_one.e").c_str());
  }
}

TEST(Planar, DeformationGradientIsTheInPlaneGradient) {
  // An affine in-plane displacement u = (0.01 x + 0.02 y, 0.03 x - 0.01 y): F = N K^-1 is exact
  // at every point (also at the edges), in-plane I + grad u, and F_zz = 1 (the plane's K has no
  // z row to invert).
  std::string deck = plateDeck("peridot_planar_never_written", "Test Plane Stress Spring");
  auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = deck.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    deck.replace(at, from.size(), to);
  };
  replace("Type: Initial Velocity", "Type: Initial Displacement");
  replace("Type: Initial Velocity", "Type: Initial Displacement");
  replace("\"0.01 * x * (1 + 0.1 * y)\"", "\"0.01 * x + 0.02 * y\"");
  replace("\"0.003 * x * x - 0.002 * y\"", "\"0.03 * x - 0.01 * y\"");
  replace("Coordinate: x\n      Value: \"0.0\"",
          "Coordinate: x\n      Value: \"0.01 * x + 0.02 * y\"");
  // One step with a density so large that the edges' unbalanced forces move nothing: the
  // current positions are then x + u.
  replace("Density: 1.0\n", "Density: 1.0e30\n");
  replace("Final Time: 20.0", "Final Time: 0.5");
  deck = deck.substr(0, deck.find("  Output:\n"));  // no output file
  auto sim = makeSimulation(deck, MPI_COMM_WORLD);
  sim->run();
  std::vector<double> F;
  sim->variables().nodeVariable("Deformation_Gradient", F);
  const double expected[9] = {1.01, 0.02, 0.0, 0.03, 0.99, 0.0, 0.0, 0.0, 1.0};
  for (std::size_t i = 0; i < F.size() / 9; ++i)
    for (int k = 0; k < 9; ++k)
      EXPECT_NEAR(F[9 * i + k], expected[k], 1e-12) << "point " << i << " component " << k;
  int owned = static_cast<int>(F.size() / 9), total = 0;
  MPI_Allreduce(&owned, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(total, 96);
}

TEST(Planar, MaterialsMustMatchTheDimension) {
  const std::string file =
      (std::filesystem::temp_directory_path() / "peridot_planar_never_written").string();
  try {
    makeSimulation(plateDeck(file, "Elastic Bond Based"), MPI_COMM_WORLD);
    ADD_FAILURE() << "a 3D material on a 2D discretization was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("Blocks -> B -> Material"), std::string::npos) << m;
    EXPECT_NE(m.find("Plane Stress"), std::string::npos) << m;
  }
  try {
    makeSimulation(plateDeck(file, "Test Plane Stress Spring", "TensorProduct3DMeshGenerator"),
                   MPI_COMM_WORLD);
    ADD_FAILURE() << "a plane-stress material on a 3D discretization was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("is plane stress but the discretization is 3D"), std::string::npos) << m;
  }
}

TEST(Planar, TractionSurfaceAreaIsEdgeLengthTimesThickness) {
  std::string top;
  for (int id = 85; id <= 96; ++id) top += std::to_string(id) + (id < 96 ? " " : "");
  std::string deck = plateDeck("unused", "Test Plane Stress Spring");
  // Replace the conditions by a traction on the top edge (length 12, thickness 0.1).
  const auto begin = deck.find("    Stretch:");
  const auto end = deck.find("  Compute Class Parameters:");
  deck.replace(begin, end - begin,
               "    Top Node Set: \"" + top +
                   "\"\n"
                   "    Pull:\n      Type: Traction\n      Node Set: Top Node Set\n"
                   "      Coordinate: y\n      Value: 2.5\n      Surface Area: 1.2\n");
  deck.replace(deck.find("      Block: block_1\n      Variable: Velocity"),
               std::string("      Block: block_1\n      Variable: Velocity").size(),
               "      Block: block_1\n      Variable: External_Force_Density");
  deck = deck.substr(0, deck.find("  Output:"));
  auto sim = makeSimulation(deck, MPI_COMM_WORLD);
  sim->run();  // the body force is applied when the run starts
  std::vector<double> g;
  sim->variables().globalVariable("VelocitySum",
                                  g);  // the relabelled sum of the body force density
  ASSERT_EQ(g.size(), 3u);
  // 12 points of volume 1 x 1 x 0.1: total force = sum(b) V = sigma x (12 x 0.1) = 3.
  EXPECT_NEAR(g[1] * 0.1, 2.5 * 12.0 * 0.1, 1e-12);
  EXPECT_EQ(g[2], 0.0);
}

}  // namespace
}  // namespace peridot
