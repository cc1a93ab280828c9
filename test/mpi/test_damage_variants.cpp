// Initial Damage (Rectangular_Plane and Exodus Mesh filters), the Exodus Mesh bond filter of the
// discretization, Time Dependent Critical Stretch and Time Dependent Short Range Force, through
// the Simulation on 1, 2 and 3 ranks. Golds are hand counts and closed forms (below each test).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "../common/TestExodusMesh.hpp"
#include "app/Simulation.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream quiet;

int worldSize() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}
int worldRank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

std::unique_ptr<Simulation> run(const std::string& deck) {
  return std::make_unique<Simulation>(readRunConfig(*parseDeck(deck, "yaml")), MPI_COMM_WORLD,
                                      quiet);
}

// The 4 x 4 x 4 unit grid (cell centres 0.5 .. 3.5), horizon 1.1: face neighbours only.
const std::string kGrid =
    "  Discretization:\n"
    "    Type: PdQuickGrid\n"
    "    NeighborhoodType: Spherical\n"
    "    TensorProduct3DMeshGenerator:\n"
    "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
    "      X Length: 4.0\n      Y Length: 4.0\n      Z Length: 4.0\n"
    "      Number Points X: 4\n      Number Points Y: 4\n      Number Points Z: 4\n";
const std::string kPmb =
    "  Materials:\n    M:\n      Material Model: Elastic Bond Based\n      Density: 1.0\n"
    "      Bulk Modulus: 1.0\n";

// Indices of a point of the 4^3 grid from its reference position, and its face-neighbour count.
void gridIndex(const double* x, int* ijk) {
  for (int d = 0; d < 3; ++d) ijk[d] = static_cast<int>(std::floor(x[d]));
}
int faceNeighbours(const int* ijk) {
  int n = 0;
  for (int d = 0; d < 3; ++d) n += (ijk[d] > 0) + (ijk[d] < 3);
  return n;
}

// The plane x = 2 between the layers x = 1.5 and 2.5, over y in [0, 2] (whole z): the bonds
// (1.5, y, z)-(2.5, y, z) with y = 0.5 or 1.5 cross it, one per point of those two layers.
int cutBonds(const int* ijk) { return (ijk[0] == 1 || ijk[0] == 2) && ijk[1] <= 1 ? 1 : 0; }

std::string initialDamageDeck(const std::string& filter, const std::string& velocity) {
  return "Peridigm:\n" + kGrid + kPmb +
         "  Damage Models:\n    D:\n      Damage Model: Initial Damage\n      Bond Filters:\n" +
         filter +
         "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n"
         "      Damage Model: D\n      Horizon: 1.1\n"
         "  Boundary Conditions:\n    All Node Set: \"" +
         [] {
           std::string ids;
           for (int i = 1; i <= 64; ++i) ids += std::to_string(i) + " ";
           return ids;
         }() +
         "\"\n    V:\n      Type: Initial Velocity\n      Node Set: All Node Set\n"
         "      Coordinate: x\n      Value: \"" +
         velocity + "\"\n  Solver:\n    Final Time: 1.0\n    Verlet:\n      Fixed dt: 0.1\n";
}

const std::string kRectangle =
    "        Crack:\n          Type: Rectangular_Plane\n"
    "          Normal_X: 1.0\n          Normal_Y: 0.0\n          Normal_Z: 0.0\n"
    "          Lower_Left_Corner_X: 2.0\n          Lower_Left_Corner_Y: 0.0\n"
    "          Lower_Left_Corner_Z: 0.0\n"
    "          Bottom_Unit_Vector_X: 0.0\n          Bottom_Unit_Vector_Y: 1.0\n"
    "          Bottom_Unit_Vector_Z: 0.0\n"
    "          Bottom_Length: 2.0\n          Side_Length: 4.0\n";

// Damage = broken / bonds of each point (Peridigm's count fraction), bonds kept in the lists.
void expectInitialDamage(Simulation& sim, const char* where) {
  std::vector<double> damage, neighbours, x;
  sim.variables().nodeVariable("Damage", damage);
  sim.variables().nodeVariable("Number_Of_Neighbors", neighbours);
  sim.variables().nodeVariable("Model_Coordinates", x);
  for (int i = 0; i < sim.topology().numOwned; ++i) {
    int ijk[3];
    gridIndex(&x[3 * i], ijk);
    const int n = faceNeighbours(ijk);
    EXPECT_EQ(neighbours[i], n) << where << " point " << i;
    EXPECT_EQ(damage[i], static_cast<double>(cutBonds(ijk)) / n)
        << where << " point at " << x[3 * i] << " " << x[3 * i + 1] << " " << x[3 * i + 2];
  }
}

TEST(InitialDamage, RectangularPlaneBreaksTheCrossingBondsOnly) {
  // Every point moves with v_x = x: all bonds along x stretch by 10% per unit time, far beyond
  // any critical stretch; Initial Damage never breaks more than its filters did.
  auto sim = run(initialDamageDeck(kRectangle, "x"));
  expectInitialDamage(*sim, "initial");
  sim->setStepObserver([&](long long step, double) {
    if (step % 5 == 0) expectInitialDamage(*sim, "during the run");
  });
  sim->run();
}

TEST(InitialDamage, AFullCutLetsTheHalvesMoveApartFreely) {
  // The plane over the whole cross-section: the halves x < 2 and x > 2 share no intact bond.
  // With v_x = -1 and +1 each half translates rigidly: u_x = -t and +t (no force), where the
  // intact bonds would pull them back.
  std::string full = kRectangle;
  full.replace(full.find("Bottom_Length: 2.0"), 18, "Bottom_Length: 4.0");
  auto sim = run(initialDamageDeck(full, " if(x < 2.0){ value = -1.0; } else{ value = 1.0; } "));
  sim->run();
  std::vector<double> u, x;
  sim->variables().nodeVariable("Displacement", u);
  sim->variables().nodeVariable("Model_Coordinates", x);
  const double t = sim->time();
  EXPECT_NEAR(t, 1.0, 1e-12);
  for (int i = 0; i < sim->topology().numOwned; ++i) {
    EXPECT_NEAR(u[3 * i], x[3 * i] < 2.0 ? -t : t, 1e-12);
    EXPECT_NEAR(u[3 * i + 1], 0.0, 1e-12);
  }
}

// Writes the shell mesh of the plane x = 2, y in [0, 2], z in [0, 4]: a QUAD4 over y in [0, 1]
// and two TRI3 over y in [1, 2] (rank 0 writes; file named per rank count).
std::string writeShells() {
  const std::string path = "shells_np" + std::to_string(worldSize()) + ".g";
  if (worldRank() == 0) {
    testing::TestMesh mesh;
    mesh.x = {2, 2, 2, 2, 2, 2};
    mesh.y = {0, 1, 1, 0, 2, 2};
    mesh.z = {0, 0, 4, 4, 0, 4};
    testing::TestBlock quads;
    quads.id = 1;
    quads.type = "QUAD4";
    quads.nodesPerElement = 4;
    quads.connectivity = {1, 2, 3, 4};
    testing::TestBlock tris;
    tris.id = 2;
    tris.type = "TRI3";
    tris.nodesPerElement = 3;
    tris.connectivity = {2, 5, 6, 2, 6, 3};
    mesh.blocks = {quads, tris};
    testing::writeMesh(path, mesh);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return path;
}

TEST(InitialDamage, ExodusMeshFilterBreaksTheSameBonds) {
  const std::string shells = writeShells();
  auto sim = run(initialDamageDeck(
      "        Shell:\n          Type: Exodus Mesh\n          File Name: " + shells + "\n", "x"));
  expectInitialDamage(*sim, "shell mesh");
}

TEST(BondFilter, ExodusMeshRemovesTheCrossingBonds) {
  // The same grid as a text mesh (bond filters need an Exodus or text discretization): the
  // filter removes the crossing bonds from the lists.
  const std::string shells = writeShells();
  const std::string points = "grid_np" + std::to_string(worldSize()) + ".txt";
  if (worldRank() == 0) {
    std::ofstream out(points);
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
          out << i + 0.5 << " " << j + 0.5 << " " << k + 0.5 << " 1 1.0\n";
  }
  MPI_Barrier(MPI_COMM_WORLD);
  auto sim =
      run("Peridigm:\n  Discretization:\n    Type: Text File\n    Input Mesh File: " + points +
          "\n    Bond Filters:\n      Shell:\n        Type: Exodus Mesh\n"
          "        File Name: " +
          shells + "\n" + kPmb +
          "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n"
          "      Horizon: 1.1\n"
          "  Solver:\n    Final Time: 0.1\n    Verlet:\n      Fixed dt: 0.1\n");
  std::vector<double> neighbours, x;
  sim->variables().nodeVariable("Number_Of_Neighbors", neighbours);
  sim->variables().nodeVariable("Model_Coordinates", x);
  for (int i = 0; i < sim->topology().numOwned; ++i) {
    int ijk[3];
    gridIndex(&x[3 * i], ijk);
    EXPECT_EQ(neighbours[i], faceNeighbours(ijk) - cutBonds(ijk));
  }
}

// Two points 1 apart, one bond; point 1 fixed, point 2 pulled at 0.01 per unit time, so the
// stretch is 0.01 t.
std::string pulledBond(const std::string& damage) {
  return "Peridigm:\n"
         "  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
         "    TensorProduct3DMeshGenerator:\n"
         "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
         "      X Length: 2.0\n      Y Length: 1.0\n      Z Length: 1.0\n"
         "      Number Points X: 2\n      Number Points Y: 1\n      Number Points Z: 1\n" +
         kPmb + "  Damage Models:\n    D:\n" + damage +
         "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n"
         "      Damage Model: D\n      Horizon: 1.1\n"
         "  Boundary Conditions:\n    Left Node Set: \"1\"\n    Right Node Set: \"2\"\n"
         "    Fix:\n      Type: Prescribed Displacement\n      Node Set: Left Node Set\n"
         "      Coordinate: x\n      Value: \"0.0\"\n"
         "    Pull:\n      Type: Prescribed Displacement\n      Node Set: Right Node Set\n"
         "      Coordinate: x\n      Value: \"0.01*t\"\n"
         "  Solver:\n    Final Time: 6.0\n    Verlet:\n      Fixed dt: 0.1\n";
}

// The first step whose (owned) points have damage 1; -1 if none.
long long breakingStep(Simulation& sim) {
  long long first = -1;
  sim.setStepObserver([&](long long step, double) {
    std::vector<double> damage;
    sim.variables().nodeVariable("Damage", damage);
    for (double d : damage)
      if (d == 1.0 && first < 0) first = step;
  });
  sim.run();
  long long global = first < 0 ? 1LL << 60 : first;
  MPI_Allreduce(MPI_IN_PLACE, &global, 1, MPI_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
  return global == 1LL << 60 ? -1 : global;
}

TEST(TimeDependentCriticalStretch, ThresholdFollowsTheTimeOfEachEvaluation) {
  // s_c = 1 up to t = 4.15, then 0.001: the bond (stretch 0.042 at t = 4.2) breaks in the first
  // evaluation after 4.15, step 42 (t = 4.2). Evaluating s_c at the step's start time would
  // give step 43; a constant s_c = 1 never breaks it.
  auto sim =
      run(pulledBond("      Damage Model: Time Dependent Critical Stretch\n"
                     "      Time Dependent Critical Stretch: \" if(t <= 4.15){ value = 1.0; } "
                     "else{ value = 0.001; } \"\n"));
  EXPECT_EQ(breakingStep(*sim), 42);
}

TEST(TimeDependentCriticalStretch, DecreasingThreshold) {
  // s_c(t) = 0.05 - 0.002 t against s(t) = 0.01 t: they cross at t = 0.05 / 0.012 = 4.1667,
  // so the first step past it is 42 (t = 4.2: s = 0.042 > s_c = 0.0416; at 4.1: 0.041 < 0.0418).
  auto sim =
      run(pulledBond("      Damage Model: Time Dependent Critical Stretch\n"
                     "      Time Dependent Critical Stretch: \"0.05 - 0.002*t\"\n"));
  EXPECT_EQ(breakingStep(*sim), 42);
}

// Two blocks of two points each (a text mesh), 0.9 apart across the blocks with contact radius
// 1: two contact pairs, block 2 sliding along x at speed 1, so friction acts.
std::unique_ptr<Simulation> slidingPair(const std::string& model, double initialTime) {
  const std::string points = "sliding_np" + std::to_string(worldSize()) + ".txt";
  if (worldRank() == 0) {
    std::ofstream out(points);
    out << "0 0 0 1 1.0\n1 0 0 1 1.0\n0.3 0 0.9 2 1.0\n1.3 0 0.9 2 1.0\n";
  }
  MPI_Barrier(MPI_COMM_WORLD);
  std::ostringstream t0;
  t0.precision(17);
  t0 << initialTime;
  return run(
      "Peridigm:\n  Discretization:\n    Type: Text File\n    Input Mesh File: " + points +
      "\n    Omit Bonds Between Blocks: All\n" + kPmb +
      "  Blocks:\n    B:\n      Block Names: block_1 block_2\n      Material: M\n"
      "      Horizon: 1.1\n"
      "  Contact:\n    Search Radius: 1.2\n    Search Frequency: 1\n    Models:\n      C:\n" +
      model +
      "        Contact Radius: 1.0\n        Spring Constant: 1.0\n"
      "    Interactions:\n      General Contact:\n        Contact Model: C\n"
      "  Boundary Conditions:\n    Top Node Set: \"3 4\"\n"
      "    V:\n      Type: Initial Velocity\n      Node Set: Top Node Set\n"
      "      Coordinate: x\n      Value: \"1.0\"\n"
      "  Solver:\n    Initial Time: " +
      t0.str() + "\n    Final Time: " + std::to_string(initialTime + 0.5) +
      "\n    Verlet:\n      Fixed dt: 0.05\n");
}

std::vector<double> contactForce(Simulation& sim) {
  std::vector<double> f;
  sim.variables().nodeVariable("Contact_Force_Density", f);
  return f;
}

TEST(TimeDependentShortRangeForce, FrictionFollowsTheExpressionInTime) {
  const std::string timeDependent =
      "        Contact Model: Time Dependent Short Range Force\n"
      "        Friction Coefficient: \" if(t <= 0.5){ value = 0.3; } else{ value = 0.0; } \"\n";
  const std::string fixed03 =
      "        Contact Model: Short Range Force\n        Friction Coefficient: 0.3\n";
  const std::string fixed0 = "        Contact Model: Short Range Force\n";
  // Before the switch the coefficient is 0.3: the same forces as the constant model, to the bit.
  {
    auto a = slidingPair(timeDependent, 0.0);
    auto b = slidingPair(fixed03, 0.0);
    std::vector<std::vector<double>> fa, fb;
    a->setStepObserver([&](long long step, double) {
      if (step <= 10) fa.push_back(contactForce(*a));
    });
    b->setStepObserver([&](long long step, double) {
      if (step <= 10) fb.push_back(contactForce(*b));
    });
    a->run();
    b->run();
    ASSERT_EQ(fa.size(), fb.size());
    for (std::size_t k = 0; k < fa.size(); ++k) EXPECT_EQ(fa[k], fb[k]) << "step " << k;
  }
  // After it (a run starting at t = 1) the coefficient is 0: the frictionless forces, which
  // differ from those with friction (the tangential component is gone).
  auto late = slidingPair(timeDependent, 1.0);
  auto frictionless = slidingPair(fixed0, 1.0);
  auto withFriction = slidingPair(fixed03, 1.0);
  late->run();
  frictionless->run();
  withFriction->run();
  EXPECT_EQ(contactForce(*late), contactForce(*frictionless));
  double difference = 0;
  const auto a = contactForce(*late), c = contactForce(*withFriction);
  for (std::size_t k = 0; k < a.size(); ++k) difference += std::fabs(a[k] - c[k]);
  MPI_Allreduce(MPI_IN_PLACE, &difference, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(difference, 1e-6);
}

}  // namespace
}  // namespace peridot
