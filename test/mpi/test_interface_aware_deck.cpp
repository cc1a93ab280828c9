// "Interface Aware" damage across a bi-material interface, through the Simulation at 1, 2 and 3
// ranks: a 12 x 3 x 3 bar (text mesh), block_1 (x < 6) with s_c = 0.02 and block_2 with
// s_c = 0.005, every point driven by the uniaxial strain u_x = 0.008 t x. Gold by hand: a bond's
// stretch is 0.008 along x and at most 0.0041 in any other direction of the lattice within
// delta = 1.8, so exactly the x-bonds with an end in block_2 break (block_2's and the interface
// bonds, min(0.02, 0.005) = 0.005); block_1's x-bonds (0.008 < 0.02) hold.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "app/RunVariables.hpp"
#include "app/Simulation.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream quietRun;

TEST(InterfaceAwareDeck, BreaksAtTheWeakerSideOfTheInterface) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const std::string points = "interface_bar_np" + std::to_string(size) + ".txt";
  if (rank == 0) {
    std::ofstream out(points);
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 12; ++i)
          out << i << " " << j << " " << k << " " << (i < 6 ? 1 : 2) << " 1.0\n";
  }
  MPI_Barrier(MPI_COMM_WORLD);
  std::ostringstream ids;
  for (int i = 1; i <= 108; ++i) ids << i << ' ';
  std::ostringstream d;
  d << "Peridigm:\n  Discretization:\n    Type: Text File\n    Input Mesh File: " << points
    << "\n  Materials:\n    M:\n      Material Model: Pals\n      Density: 1.0\n"
       "      Bulk Modulus: 2.0\n      Shear Modulus: 1.2\n"
       "  Damage Models:\n    Strong:\n      Damage Model: Interface Aware\n"
       "      Critical Stretch: 0.02\n    Weak:\n      Damage Model: Interface Aware\n"
       "      Critical Stretch: 0.005\n"
       "  Blocks:\n    One:\n      Block Names: block_1\n      Material: M\n"
       "      Damage Model: Strong\n      Horizon: 1.8\n"
       "    Two:\n      Block Names: block_2\n      Material: M\n      Damage Model: Weak\n"
       "      Horizon: 1.8\n"
       "  Boundary Conditions:\n    All Node Set: \""
    << ids.str() << "\"\n";
  for (const char* c : {"x", "y", "z"})
    d << "    U" << c << ":\n      Type: Prescribed Displacement\n      Node Set: All Node Set\n"
      << "      Coordinate: " << c << "\n      Value: \""
      << (std::string(c) == "x" ? "value = 0.008*t*x;" : "0.0") << "\"\n";
  d << "  Solver:\n    Final Time: 1.0\n    Verlet:\n      Fixed dt: 0.5\n";
  Simulation sim(readRunConfig(*parseDeck(d.str(), "yaml")), MPI_COMM_WORLD, quietRun);
  sim.run();
  std::vector<double> damage, x, sc;
  sim.variables().nodeVariable("Damage", damage);
  sim.variables().nodeVariable("Model_Coordinates", x);
  sim.variables().nodeVariable("Critical_Stretch", sc);
  int checked = 0, anyBroken = 0;
  for (std::size_t p = 0; p < damage.size(); ++p) {
    const int i = static_cast<int>(std::lround(x[3 * p])),
              j = static_cast<int>(std::lround(x[3 * p + 1])),
              k = static_cast<int>(std::lround(x[3 * p + 2]));
    // Neighbours within 1.8 on the lattice: offsets with |o|^2 <= 3.
    int bonds = 0, broken = 0;
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = -1; c <= 1; ++c) {
          if ((a == 0 && b == 0 && c == 0) || i + a < 0 || i + a > 11 || j + b < 0 || j + b > 2 ||
              k + c < 0 || k + c > 2)
            continue;
          ++bonds;
          if (b == 0 && c == 0 && (i >= 6 || i + a >= 6)) ++broken;
        }
    EXPECT_DOUBLE_EQ(damage[p], double(broken) / bonds) << i << " " << j << " " << k;
    EXPECT_EQ(sc[p], i < 6 ? 0.02 : 0.005);
    anyBroken += broken > 0;
    ++checked;
  }
  int totals[2] = {checked, anyBroken};
  MPI_Allreduce(MPI_IN_PLACE, totals, 2, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(totals[0], 108);
  EXPECT_EQ(totals[1], 7 * 9);  // x = 5 (interface) .. 11
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0) std::remove(points.c_str());
}

}  // namespace
}  // namespace peridot
