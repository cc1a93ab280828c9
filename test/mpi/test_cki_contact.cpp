// Contact in 2D with continuum-kinematics bodies: two plates (text mesh, planar, no bonds
// between the blocks) driven against each other bounce apart through the short-range force.
// Checked: they touch only through contact (the bodies reverse), the total momentum is kept,
// nothing leaves the plane, and the nodal output is identical to the bit at 1, 2 and 3 ranks.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/Simulation.hpp"
#include "deck/Deck.hpp"
#include "output/ExodusCompare.hpp"

namespace peridot {
namespace {

std::ostringstream quiet;

// Plates of 8 x 6 points (spacing 1, area 1), block 1 at x = 0..7, block 2 at x = 8.6..15.6.
std::string contactDeck(const std::string& files, const std::string& base) {
  std::ostringstream d;
  d << "Peridigm:\n  Discretization:\n    Type: Text File\n    Input Mesh File: " << files
    << "_mesh.txt\n    Dimension: 2\n    Thickness: 0.5\n    Omit Bonds Between Blocks: All\n"
       "  Materials:\n    M:\n      Material Model: Continuum Kinematics\n      Density: 1.0\n"
       "      Young's Modulus: 1.0\n      Poisson's Ratio: 0.2\n      Plane Stress: true\n"
       "  Blocks:\n    B:\n      Block Names: block_1 block_2\n      Material: M\n"
       "      Horizon: 2.1\n"
       "  Contact:\n    Search Radius: 2.0\n    Search Frequency: 5\n    Models:\n"
       "      Soft:\n        Contact Model: Short Range Force\n        Contact Radius: 0.9\n"
       "        Spring Constant: 2.0\n    Interactions:\n      Plates:\n"
       "        First Block: block_1\n        Second Block: block_2\n        Contact Model: Soft\n"
       "  Boundary Conditions:\n    Left Node Set: "
    << files << "_left.txt\n    Right Node Set: " << files
    << "_right.txt\n"
       "    Push:\n      Type: Initial Velocity\n      Node Set: Left Node Set\n"
       "      Coordinate: x\n      Value: \"0.05 + 0.002 * y\"\n"
       "    Pull:\n      Type: Initial Velocity\n      Node Set: Right Node Set\n"
       "      Coordinate: x\n      Value: \"-0.05\"\n"
       "  Solver:\n    Final Time: 60.0\n    Verlet:\n      Fixed dt: 0.2\n"
       "  Output:\n    Output Filename: "
    << base << "_out\n    Output Frequency: 100\n    Output Variables:\n"
    << "      Displacement: true\n      Velocity: true\n      Force: true\n"
       "      Contact_Force_Density: true\n";
  return d.str();
}

TEST(ContinuumKinematicsContact, PlanarPlatesBounceIdenticallyOnAnyRankCount) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  long long pid = ::getpid();
  MPI_Bcast(&pid, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  const std::string base =
      (std::filesystem::temp_directory_path() /
       ("peridot_cki_contact_" + std::to_string(pid) + "_np" + std::to_string(size)))
          .string();
  if (rank == 0) {
    std::ofstream mesh(base + "_mesh.txt"), left(base + "_left.txt"), right(base + "_right.txt");
    int id = 0;
    for (int b = 0; b < 2; ++b)
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 6; ++j) {
          mesh << (b == 0 ? i : 8.6 + i) << " " << j << " 0 " << b + 1 << " 1.0\n";
          (b == 0 ? left : right) << ++id << "\n";
        }
  }
  MPI_Barrier(MPI_COMM_WORLD);
  double momentumBefore = 0, momentumAfter = 0, leftAfter = 0;
  {
    auto sim = std::make_unique<Simulation>(
        readRunConfig(*parseDeck(contactDeck(base, base + "_all"), "yaml")), MPI_COMM_WORLD, quiet);
    auto momenta = [&](double& total, double& left) {
      const double* v = sim->fields().node("Velocity", 3);
      const double* vol = sim->fields().node("Volume", 1);
      const double* x = sim->fields().node("Model_Coordinates", 3);
      double local[2] = {0, 0}, global[2];
      for (int i = 0; i < sim->topology().numOwned; ++i) {
        local[0] += v[3 * i] * vol[i];
        if (x[3 * i] < 8) local[1] += v[3 * i] * vol[i];
      }
      MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
      total = global[0];
      left = global[1];
    };
    double unused = 0;
    momenta(momentumBefore, unused);
    sim->run();
    momenta(momentumAfter, leftAfter);
  }
  // Initially 48 * 0.5 * (0.05 + 0.002 * 2.5) - 48 * 0.5 * 0.05 = 0.12; the left plate moved
  // right at 24 * 0.055 = 1.32 and is now moving left: it bounced.
  EXPECT_NEAR(momentumBefore, 0.12, 1e-12);
  EXPECT_NEAR(momentumAfter, momentumBefore, 1e-12);
  EXPECT_LT(leftAfter, 0.0);
  if (rank == 0) {
    // The same base name on one rank: the mesh and node-set files are shared.
    {
      Simulation serial(readRunConfig(*parseDeck(contactDeck(base, base + "_one"), "yaml")),
                        MPI_COMM_SELF, quiet);
      serial.run();
    }
    const ExodusResults all = readExodusResults(base + "_all_out.e");
    const ExodusResults one = readExodusResults(base + "_one_out.e");
    EXPECT_EQ(all.dimension, 2);
    const CompSpec spec = parseCompText(
        "COORDINATES absolute 0\nTIME STEPS absolute 0\nNODAL VARIABLES absolute 0\n"
        "ELEMENT VARIABLES absolute 0\n",
        "contact2d.comp");
    const CompareReport report = compareExodusResults(all, one, spec);
    std::ostringstream text;
    printCompareReport(text, report, true);
    EXPECT_TRUE(report.passed()) << text.str();
    for (const char* suffix : {"_all_out.e", "_one_out.e", "_mesh.txt", "_left.txt", "_right.txt"})
      std::remove((base + suffix).c_str());
  }
}

}  // namespace
}  // namespace peridot
