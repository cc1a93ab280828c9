// The regression deck test/regression/decks/BondAssociatedCube ("Isotropic Hardening Bond
// Associated Correspondence", Peridigm's Power-law hardening; every point driven by a homogeneous
// uniaxial strain along z past yield, reversed past the reverse yield) run through the Simulation
// at 1, 2 and 3 ranks. For an affine motion every point's F and Fdot are exact, so is every bond's
// F_b (= F): every point, surface points included, and every bond must follow the continuum
// response. Gold, computed here independently of the model, as a scalar return mapping along the
// one deviatoric direction diag(-1/3, -1/3, 2/3): each step the unrotated rate of deformation
// d_zz dt = De / (1 + e); mean stress p += K d_zz dt; signed von Mises q += 2 mu d_zz dt; when
// |q| > sigma_y(eps_p) the return solves |q| - 3 mu dgamma = sigma_y(eps_p + dgamma) by bisection,
// sigma_y = sigma_Y (1 + eps_p / eps_0)^n; sigma_zz = p + 2q/3. Run with the deck's gradient
// order (1) and with order 2.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream runLog;

// `order` 0 runs the deck as it is (its default gradient order, 1).
void expectScalarReturnMapping(int order) {
  auto deck = loadDeck(std::string(PERIDOT_TEST_DIR) +
                       "/regression/decks/BondAssociatedCube/BondAssociatedCube.xml");
  if (order > 0)
    deck->sublist("Materials").sublist("Metal").set("Gradient Order Of Accuracy", order);
  std::ostringstream ids;
  for (int i = 1; i <= 1000; ++i) ids << i << ' ';
  deck->sublist("Boundary Conditions").set("All Node Set", ids.str());
  deck->remove("Output");
  Simulation sim(readRunConfig(*deck), MPI_COMM_WORLD, runLog);

  // The deck's constants.
  const double K = 1.6666666666666667, G = 1.0, sigmaY = 1e-7, eps0 = 1e-7, n = 0.2;
  const double strainRate = 2.5e-7;
  auto yieldOf = [&](double eqps) { return sigmaY * std::pow(1 + eqps / eps0, n); };
  double p = 0, q = 0, eqps = 0, ePrevious = 0;
  const Topology& t = sim.topology();
  double worstStress = 0, worstEqps = 0, worstYield = 0, worstBond = 0;
  int steps = 0, plastic = 0;
  sim.setStepObserver([&](long long, double time) {
    const double e = time < 1.0 ? strainRate * time : strainRate * (2.0 - time);
    const double delta = (e - ePrevious) / (1 + e);
    p += K * delta;
    q += 2 * G * delta;
    const bool yields = std::abs(q) > yieldOf(eqps);
    if (yields) {
      double lo = 0, hi = std::abs(q) / (3 * G);
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        (std::abs(q) - 3 * G * mid > yieldOf(eqps + mid) ? lo : hi) = mid;
      }
      const double dgamma = 0.5 * (lo + hi);
      q -= (q > 0 ? 3 * G : -3 * G) * dgamma;
      eqps += dgamma;
    }
    const double sigmaGold = p + 2.0 * q / 3.0, sigmaXXGold = p - q / 3.0;
    ePrevious = e;
    plastic += yields;
    const double* sigma = sim.fields().node("Cauchy_Stress", 9);
    const double* eq = sim.fields().node("Equivalent_Plastic_Strain", 1);
    const double* vm = sim.fields().node("Von_Mises_Stress", 1);
    const auto& bondZZ = sim.fields().bond("Unrotated_Cauchy_Stress_ZZ");
    const auto& bondXX = sim.fields().bond("Unrotated_Cauchy_Stress_XX");
    const auto& bondEqps = sim.fields().bond("Bond_Equivalent_Plastic_Strain");
    for (int i = 0; i < t.numOwned; ++i) {
      worstStress = std::max(worstStress, std::abs(sigma[9 * i + 8] - sigmaGold));
      worstEqps = std::max(worstEqps, std::abs(eq[i] - eqps));
      if (yields) worstYield = std::max(worstYield, std::abs(vm[i] / yieldOf(eq[i]) - 1.0));
      for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
        worstBond = std::max(worstBond, std::abs(bondZZ[b] - sigmaGold));
        worstBond = std::max(worstBond, std::abs(bondXX[b] - sigmaXXGold));
        worstEqps = std::max(worstEqps, std::abs(bondEqps[b] - eqps));
      }
    }
    ++steps;
  });
  sim.run();
  double local[4] = {worstStress, worstEqps, worstYield, worstBond}, global[4];
  MPI_Allreduce(local, global, 4, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf(
        "  BondAssociatedCube (gradient order %d): eps_p max %.6g, |sigma_zz - gold| / sigma_Y "
        "%.2e (points), %.2e (bonds), |eps_p - gold| / eps_p %.2e, |von Mises / yield - 1| "
        "%.2e\n",
        order > 0 ? order : 1, eqps, global[0] / sigmaY, global[3] / sigmaY, global[1] / eqps,
        global[2]);
  EXPECT_EQ(steps, 61);
  EXPECT_GT(plastic, 30);
  EXPECT_GT(eqps, 2 * sigmaY / G);
  EXPECT_LT(global[0] / sigmaY, 1e-6) << global[0];
  EXPECT_LT(global[3] / sigmaY, 1e-6) << global[3];
  EXPECT_LT(global[1] / eqps, 1e-6) << global[1];
  EXPECT_LT(global[2], 1e-9) << global[2];
}

TEST(BondAssociatedCubeDeck, EveryPointAndBondFollowsTheScalarReturnMapping) {
  expectScalarReturnMapping(0);
}

// The same homogeneous history with "Gradient Order Of Accuracy" 2: the higher-order weights are
// exact for the affine motion at every point, corners included, so every point and bond follows
// the same gold.
TEST(BondAssociatedCubeDeck, GradientOrderTwoFollowsTheScalarReturnMappingToo) {
  expectScalarReturnMapping(2);
}

}  // namespace
}  // namespace peridot
