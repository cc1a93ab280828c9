// Continuum-kinematics runs on 1, 2 and 3 ranks: a 2D plate and a 3D block pulled apart by an
// initial velocity field, with and without critical-stretch damage, write nodal values
// (displacement, velocity, force, damage) identical to the bit to the same run on one rank.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/Simulation.hpp"
#include "deck/Deck.hpp"
#include "output/ExodusCompare.hpp"

namespace peridot {
namespace {

std::ostringstream quiet;

std::string ckiDeck(const std::string& outputFile, bool planar, bool damage) {
  std::ostringstream d;
  const int nx = planar ? 16 : 8, ny = planar ? 10 : 6, nz = planar ? 1 : 4;
  d << "Peridigm:\n  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n";
  if (planar)
    d << "    Thickness: 0.1\n    TensorProduct2DMeshGenerator:\n";
  else
    d << "    TensorProduct3DMeshGenerator:\n";
  d << "      X Origin: 0.0\n      Y Origin: 0.0\n"
    << "      X Length: " << nx << ".0\n      Y Length: " << ny << ".0\n"
    << "      Number Points X: " << nx << "\n      Number Points Y: " << ny << "\n";
  if (!planar)
    d << "      Z Origin: 0.0\n      Z Length: " << nz << ".0\n      Number Points Z: " << nz
      << "\n";
  d << "  Materials:\n    M:\n      Material Model: Continuum Kinematics\n      Density: 1.0\n"
    << "      Young's Modulus: 1.0\n      Poisson's Ratio: " << (planar ? "0.2" : "0.35") << "\n"
    << (planar ? "      Plane Stress: true\n" : "");
  if (damage)
    d << "  Damage Models:\n    D:\n      Damage Model: Critical Stretch\n"
         "      Critical Stretch: 0.02\n";
  d << "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n"
    << (damage ? "      Damage Model: D\n" : "") << "      Horizon: " << (planar ? "3.1" : "2.1")
    << "\n  Boundary Conditions:\n    All Node Set: \"";
  const int n = nx * ny * nz;
  for (int i = 1; i <= n; ++i) d << i << (i < n ? " " : "\"\n");
  // Opening about x = nx/2 (faster near the middle of y: a crack can start there) and a shear.
  d << "    Open:\n      Type: Initial Velocity\n      Node Set: All Node Set\n"
       "      Coordinate: x\n      Value: \"0.01 * (x - "
    << nx / 2 << ") * (1 + 0.05 * y)\"\n"
    << "    Shear:\n      Type: Initial Velocity\n      Node Set: All Node Set\n"
       "      Coordinate: y\n      Value: \"0.002 * x - 0.001 * y\"\n"
       "  Solver:\n    Final Time: 60.0\n    Verlet:\n      Fixed dt: 0.3\n"
       "  Output:\n    Output Filename: "
    << outputFile
    << "\n    Output Frequency: 50\n    Output Variables:\n"
       "      Displacement: true\n      Velocity: true\n      Force: true\n"
       "      Damage: true\n";
  return d.str();
}

std::unique_ptr<Simulation> makeSimulation(const std::string& deck, MPI_Comm comm) {
  return std::make_unique<Simulation>(readRunConfig(*parseDeck(deck, "yaml")), comm, quiet);
}

void checkIdentical(bool planar, bool damage) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  long long pid = ::getpid();
  MPI_Bcast(&pid, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  const std::string base = (std::filesystem::temp_directory_path() /
                            ("peridot_cki_" + std::to_string(pid) + "_np" + std::to_string(size) +
                             (planar ? "_2d" : "_3d") + (damage ? "_d" : "")))
                               .string();
  {
    auto sim = makeSimulation(ckiDeck(base + "_all", planar, damage), MPI_COMM_WORLD);
    EXPECT_LE(sim->timeStep(), sim->stableTimeStepEstimate());
    sim->run();
  }
  if (rank == 0) {
    {
      auto serial = makeSimulation(ckiDeck(base + "_one", planar, damage), MPI_COMM_SELF);
      serial->run();
    }
    const ExodusResults all = readExodusResults(base + "_all.e");
    const ExodusResults one = readExodusResults(base + "_one.e");
    ASSERT_EQ(all.times.size(), 5u);
    // With damage, some bonds broke by the end (the case is meant to exercise the interactions'
    // failure), and none without.
    double damageSum = 0;
    ASSERT_EQ(all.elementNames, (std::vector<std::string>{"Damage"}));
    for (double v : all.element[0].back()) damageSum += v;
    if (damage) {
      EXPECT_GT(damageSum, 0.0);
    } else {
      EXPECT_EQ(damageSum, 0.0);
    }
    const CompSpec spec = parseCompText(
        "COORDINATES absolute 0\nTIME STEPS absolute 0\nNODAL VARIABLES absolute 0\n"
        "ELEMENT VARIABLES absolute 0\n",
        "cki.comp");
    const CompareReport report = compareExodusResults(all, one, spec);
    std::ostringstream text;
    printCompareReport(text, report, true);
    EXPECT_TRUE(report.passed()) << text.str();
    std::remove((base + "_all.e").c_str());
    std::remove((base + "_one.e").c_str());
  }
}

TEST(ContinuumKinematicsMpi, Planar) { checkIdentical(true, false); }
TEST(ContinuumKinematicsMpi, PlanarWithDamage) { checkIdentical(true, true); }
TEST(ContinuumKinematicsMpi, ThreeD) { checkIdentical(false, false); }
TEST(ContinuumKinematicsMpi, ThreeDWithDamage) { checkIdentical(false, true); }

}  // namespace
}  // namespace peridot
