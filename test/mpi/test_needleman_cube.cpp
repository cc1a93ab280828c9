// The regression deck test/regression/decks/NeedlemanCube ("Viscoplastic Needleman
// Correspondence" with a flaw, every point driven by a homogeneous uniaxial strain along z, loaded
// then reversed twice as fast past the reverse yield) run through the Simulation at 1, 2 and 3
// ranks. For an affine motion F and the velocity gradient are exact at every point, so every
// point — surface points included — follows the law with its own yield stress
// sigma_Y (1 - 0.3 exp(-|x - (6, 6, 6)|^2 / 9)). Gold, computed here independently of the model:
// per point the scalar recursion of test/common/NeedlemanGold.hpp, with d_zz dt = De / (1 + e)
// (e at the step's end, De the step's change of the prescribed strain).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "../common/NeedlemanGold.hpp"
#include "app/Simulation.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream runLog;

TEST(NeedlemanCubeDeck, EveryPointFollowsTheScalarReturnWithItsOwnYieldStress) {
  auto deck =
      loadDeck(std::string(PERIDOT_TEST_DIR) + "/regression/decks/NeedlemanCube/NeedlemanCube.xml");
  std::ostringstream ids;
  for (int i = 1; i <= 1728; ++i) ids << i << ' ';
  deck->sublist("Boundary Conditions").set("All Node Set", ids.str());
  deck->remove("Output");
  Simulation sim(readRunConfig(*deck), MPI_COMM_WORLD, runLog);

  // The deck's constants.
  const double K = 1.6666666666666667, G = 1.0;
  testing::NeedlemanLaw law;
  law.sigmaY = 1e-7;
  law.N = 0.2;
  law.m = 0.1;
  law.rate0 = 1e-7;
  law.eps0 = 5e-8;
  law.eps1 = 2e-6;
  auto strain = [](double t) { return t < 1.0 ? 2.5e-7 * t : 2.5e-7 - 5e-7 * (t - 1.0); };

  // One scalar state per distinct yield stress (points at the same distance from the flaw).
  const Topology& t = sim.topology();
  const double* x = sim.fields().node("Model_Coordinates", 3);
  std::map<double, testing::Uniaxial> golds;
  std::vector<double> yieldOf(t.numOwned);
  for (int i = 0; i < t.numOwned; ++i) {
    double r2 = 0;
    for (int d = 0; d < 3; ++d) r2 += (x[3 * i + d] - 6.0) * (x[3 * i + d] - 6.0);
    yieldOf[i] = law.sigmaY * (1.0 - 0.3 * std::exp(-r2 / 9.0));
    golds[yieldOf[i]];
  }
  double timePrevious = 0, worstStress = 0, worstEqps = 0, largest = 0;
  int steps = 0, flowed = 0;
  sim.setStepObserver([&](long long, double time) {
    const double e = strain(time), ePrevious = strain(timePrevious);
    const double dt = time - timePrevious, delta = (e - ePrevious) / (1 + e);
    for (auto& [sigmaY, gold] : golds) {
      testing::NeedlemanLaw pointLaw = law;
      pointLaw.sigmaY = sigmaY;
      flowed += testing::needlemanStep(pointLaw, K, G, gold, delta, dt);
      largest = std::max(largest, gold.eqps);
    }
    timePrevious = time;
    const double* sigma = sim.fields().node("Cauchy_Stress", 9);
    const double* eq = sim.fields().node("Equivalent_Plastic_Strain", 1);
    for (int i = 0; i < t.numOwned; ++i) {
      const testing::Uniaxial& gold = golds.at(yieldOf[i]);
      worstStress = std::max(worstStress, std::abs(sigma[9 * i + 8] - gold.axial()));
      worstStress = std::max(worstStress, std::abs(sigma[9 * i] - gold.lateral()));
      worstEqps = std::max(worstEqps, std::abs(eq[i] - gold.eqps));
    }
    ++steps;
  });
  sim.run();
  double local[3] = {worstStress, worstEqps, largest}, global[3];
  MPI_Allreduce(local, global, 3, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (rank == 0)
    std::printf(
        "  NeedlemanCube (%d ranks, %zu distinct yield stresses on rank 0): eps_p max %.6g, "
        "|sigma - gold| / sigma_Y %.2e, |eps_p - gold| / eps_p max %.2e\n",
        size, golds.size(), global[2], global[0] / law.sigmaY, global[1] / global[2]);
  EXPECT_EQ(steps, 81);
  EXPECT_GT(flowed, 40);                     // past yield both ways
  EXPECT_GT(global[2], 3 * law.sigmaY / G);  // several yield strains of plastic flow
  // F's lattice sums round at ~1e-16 relative: the stresses (~1e-7) carry ~1e-16 absolute.
  EXPECT_LT(global[0] / law.sigmaY, 1e-6) << global[0];
  EXPECT_LT(global[1] / global[2], 1e-6) << global[1];
}

}  // namespace
}  // namespace peridot
