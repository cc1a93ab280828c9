// Strain_Energy, Strain_Energy_Density and Global_Strain_Energy (the older Peridigm names of the
// stored elastic energy) for the elastic models whose energy of an isotropic stretch is exact at
// every point, surface included (LPS, Pals, elastic-plastic below yield; the bond-based models
// are exact in the bulk only): a 7^3 block with every point driven by u = s t x. Gold, the
// continuum: W = 9 K s^2 / 2 at every point, W V per point, 343 W V in total, at 1-3 ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <sstream>

#include "app/RunVariables.hpp"
#include "app/Simulation.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream quietLog;

std::string deck(const std::string& material) {
  std::ostringstream ids;
  for (int i = 1; i <= 343; ++i) ids << i << ' ';
  std::ostringstream d;
  d << "Peridigm:\n"
       "  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
       "    TensorProduct3DMeshGenerator:\n"
       "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
       "      X Length: 7.0\n      Y Length: 7.0\n      Z Length: 7.0\n"
       "      Number Points X: 7\n      Number Points Y: 7\n      Number Points Z: 7\n"
       "  Materials:\n    M:\n"
    << material
    << "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 2.015\n"
       "  Boundary Conditions:\n    All Node Set: \""
    << ids.str() << "\"\n";
  for (const char* c : {"x", "y", "z"})
    d << "    Stretch " << c
      << ":\n      Type: Prescribed Displacement\n      Node Set: All Node Set\n"
      << "      Coordinate: " << c << "\n      Value: \"value = 1.0e-6*t*" << c << ";\"\n";
  d << "  Solver:\n    Final Time: 1.0\n    Verlet:\n      Fixed dt: 0.1\n";
  return d.str();
}

TEST(StrainEnergy, IsotropicStretchAtEveryPoint) {
  const double K = 2.0, s = 1e-6, W = 4.5 * K * s * s;
  const char* materials[] = {
      "      Material Model: Elastic\n      Density: 1.0\n      Bulk Modulus: 2.0\n"
      "      Shear Modulus: 1.2\n",
      "      Material Model: Pals\n      Density: 1.0\n      Bulk Modulus: 2.0\n"
      "      Shear Modulus: 1.2\n",
      "      Material Model: Elastic Plastic\n      Density: 1.0\n      Bulk Modulus: 2.0\n"
      "      Shear Modulus: 1.2\n      Yield Stress: 1.0\n"};
  for (const char* m : materials) {
    Simulation sim(readRunConfig(*parseDeck(deck(m), "yaml")), MPI_COMM_WORLD, quietLog);
    sim.run();
    std::vector<double> density, energy, stored, total;
    sim.variables().nodeVariable("Strain_Energy_Density", density);
    sim.variables().nodeVariable("Strain_Energy", energy);
    sim.variables().nodeVariable("Stored_Elastic_Energy_Density", stored);
    sim.variables().globalVariable("Global_Strain_Energy", total);
    double worst = 0;
    for (std::size_t i = 0; i < density.size(); ++i) {
      worst = std::max(worst, std::abs(density[i] / W - 1));
      EXPECT_EQ(energy[i], density[i]);  // unit volumes
      EXPECT_EQ(stored[i], density[i]);
    }
    MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    // First order in s: the extension of a stretched bond is s |xi| exactly, rounding aside.
    EXPECT_LT(worst, 1e-6) << m;
    ASSERT_EQ(total.size(), 1u);
    EXPECT_NEAR(total[0] / (343 * W), 1.0, 1e-6) << m;
  }
}

}  // namespace
}  // namespace peridot
