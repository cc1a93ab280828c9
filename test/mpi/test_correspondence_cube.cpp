// The regression deck test/regression/decks/CorrespondenceCube ("Isotropic Hardening
// Correspondence", every point driven by a homogeneous uniaxial strain along z past yield,
// reversed past the reverse yield) run through the Simulation at 1, 2 and 3 ranks, with each
// "Stress Integration". For an affine motion the deformation gradient and the velocity gradient
// are exact at every point, so every point — surface points included — must follow the continuum
// response. Golds, computed here independently of the model, as scalar return mappings along the
// one deviatoric direction diag(-1/3, -1/3, 2/3):
//   rate form (default): each step the unrotated rate of deformation d_zz dt = De / (1 + e) (e at
//     the step's end, the prescribed velocity times dt = De); mean stress p += K d_zz dt; signed
//     von Mises q += 2 mu d_zz dt, returned to sigma_y + H eps_p with dgamma = (|q| - yield) /
//     (3 mu + H); sigma_zz = p + 2q/3.
//   Green strain: with E^p = p diag(-1/2, -1/2, 1), the trial von Mises stress is 2 mu |g - 3p/2|
//     (g the Green strain E_zz), the return dgamma = (2 mu |a| - sigma_y) / (3 mu + H) moves p by
//     dgamma sign(a) and eps_p by dgamma, and S_zz = lambda g + 2 mu (g - p), sigma_zz = (1 + e)
//     S_zz.
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

void runCube(bool rate) {
  auto deck = loadDeck(std::string(PERIDOT_TEST_DIR) +
                       "/regression/decks/CorrespondenceCube/CorrespondenceCube.xml");
  std::ostringstream ids;
  for (int i = 1; i <= 2744; ++i) ids << i << ' ';
  deck->sublist("Boundary Conditions").set("All Node Set", ids.str());
  deck->remove("Output");
  if (!rate)
    deck->sublist("Materials")
        .sublist("Metal")
        .set("Stress Integration", "Total Lagrangian Green Strain");
  Simulation sim(readRunConfig(*deck), MPI_COMM_WORLD, runLog);

  // The deck's constants.
  const double K = 1.6666666666666667, G = 1.0, sigmaY = 1e-7, H = 0.1, strainRate = 2.5e-7;
  const double lambda = K - 2 * G / 3;
  double p = 0, q = 0, eqps = 0, largest = 0, ePrevious = 0;
  const Topology& t = sim.topology();
  double worstStress = 0, worstEqps = 0, worstYield = 0;
  int steps = 0, plastic = 0;
  sim.setStepObserver([&](long long, double time) {
    const double e = time < 1.0 ? strainRate * time : strainRate * (2.0 - time);
    const double yieldNow = sigmaY + H * eqps;
    double sigmaGold = 0;
    bool yields = false;
    if (rate) {
      const double delta = (e - ePrevious) / (1 + e);
      p += K * delta;
      q += 2 * G * delta;
      yields = std::abs(q) > yieldNow;
      if (yields) {
        const double dgamma = (std::abs(q) - yieldNow) / (3 * G + H);
        q -= (q > 0 ? 3 * G : -3 * G) * dgamma;
        eqps += dgamma;
      }
      sigmaGold = p + 2.0 * q / 3.0;
    } else {
      const double g = e + 0.5 * e * e;
      const double a = g - 1.5 * p;
      yields = 2 * G * std::abs(a) > yieldNow;
      if (yields) {
        const double dgamma = (2 * G * std::abs(a) - yieldNow) / (3 * G + H);
        p += a > 0 ? dgamma : -dgamma;
        eqps += dgamma;
      }
      sigmaGold = (1 + e) * (lambda * g + 2 * G * (g - p));
    }
    ePrevious = e;
    plastic += yields;
    largest = std::max(largest, eqps);
    const double* sigma = sim.fields().node("Cauchy_Stress", 9);
    const double* eq = sim.fields().node("Equivalent_Plastic_Strain", 1);
    const double* vm = sim.fields().node("Von_Mises_Stress", 1);
    for (int i = 0; i < t.numOwned; ++i) {
      worstStress = std::max(worstStress, std::abs(sigma[9 * i + 8] - sigmaGold));
      worstEqps = std::max(worstEqps, std::abs(eq[i] - eqps));
      // After a plastic step the point is on the (hardened) yield surface (with the Green
      // strain: the von Mises stress of sigma is that of S up to the O(e) change of frame).
      if (yields) worstYield = std::max(worstYield, std::abs(vm[i] / (sigmaY + H * eq[i]) - 1.0));
    }
    ++steps;
  });
  sim.run();
  double local[3] = {worstStress, worstEqps, worstYield}, global[3];
  MPI_Allreduce(local, global, 3, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf(
        "  CorrespondenceCube (%s): eps_p max %.6g, |sigma_zz - gold| / sigma_Y %.2e, |eps_p - "
        "gold| / eps_p max %.2e, |von Mises / yield - 1| %.2e\n",
        rate ? "rate form" : "Green strain", largest, global[0] / sigmaY, global[1] / largest,
        global[2]);
  EXPECT_EQ(steps, 61);
  EXPECT_GT(plastic, 30);              // past yield both ways
  EXPECT_GT(largest, 2 * sigmaY / G);  // several yield strains (sigma_Y / 2G) of plastic flow
  // F's lattice sums round at ~1e-16 relative: the stresses (~1e-7) carry ~1e-16 absolute.
  EXPECT_LT(global[0] / sigmaY, 1e-6) << global[0];
  EXPECT_LT(global[1] / largest, 1e-6) << global[1];
  // The rate form returns sigma itself; the Green strain S, O(e) from sigma (e < 1.3e-6).
  EXPECT_LT(global[2], rate ? 1e-9 : 1e-5) << global[2];
}

TEST(CorrespondenceCubeDeck, EveryPointFollowsTheScalarReturnMapping) { runCube(true); }

TEST(CorrespondenceCubeDeck, GreenStrainFormFollowsItsScalarReturnMapping) { runCube(false); }

}  // namespace
}  // namespace peridot

namespace peridot {
namespace {

// Peridigm's Deformation_Gradient compute on an ordinary model: the PlasticCube deck turned into
// an "Elastic" (LPS) block under simple shear u_x = g z (all points prescribed) at 1-3 ranks.
// Every point's F (component outputs included) is I + g e_x (x) e_z — surface points too, F
// being exact for an affine motion — and the correspondence-only outputs are refused.
TEST(DeformationGradientOutput, ElasticBlockUnderSimpleShearAtAnyRankCount) {
  auto deck =
      loadDeck(std::string(PERIDOT_TEST_DIR) + "/regression/decks/PlasticCube/PlasticCube.xml");
  std::ostringstream ids;
  for (int i = 1; i <= 2744; ++i) ids << i << ' ';
  auto& bcs = deck->sublist("Boundary Conditions");
  bcs.set("All Node Set", ids.str());
  bcs.sublist("Strain Z").set("Value", "0.0");
  bcs.sublist("Fix X").set("Value", "1.0e-3*t*z");
  auto& metal = deck->sublist("Materials").sublist("Metal");
  metal.set("Material Model", "Elastic");
  metal.remove("Yield Stress");
  deck->sublist("Solver").set("Final Time", 1.0);
  deck->remove("Output");
  Simulation sim(readRunConfig(*deck), MPI_COMM_WORLD, runLog);
  sim.run();
  std::vector<double> F, xz, yy;
  sim.variables().nodeVariable("Deformation_Gradient", F);
  sim.variables().nodeVariable("Deformation_GradientXZ", xz);
  sim.variables().nodeVariable("Deformation_GradientYY", yy);
  const double g = 1e-3;  // at t = 1
  const double expected[9] = {1, 0, g, 0, 1, 0, 0, 0, 1};
  double worst = 0;
  for (int i = 0; i < sim.topology().numOwned; ++i) {
    for (int k = 0; k < 9; ++k) worst = std::max(worst, std::abs(F[9 * i + k] - expected[k]));
    EXPECT_EQ(xz[i], F[9 * i + 2]);
    EXPECT_EQ(yy[i], F[9 * i + 4]);
  }
  double global = 0;
  MPI_Allreduce(&worst, &global, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_LT(global, 1e-13);

  auto bad =
      loadDeck(std::string(PERIDOT_TEST_DIR) + "/regression/decks/PlasticCube/PlasticCube.xml");
  bad->sublist("Materials").sublist("Metal").set("Material Model", "Elastic");
  bad->sublist("Materials").sublist("Metal").remove("Yield Stress");
  bad->sublist("Boundary Conditions").set("All Node Set", ids.str());
  auto& vars = bad->sublist("Output").sublist("Output Variables");
  vars.remove("Lambda");
  vars.set("Cauchy_Stress", true);
  try {
    Simulation s(readRunConfig(*bad), MPI_COMM_WORLD, runLog);
    FAIL() << "Cauchy_Stress without a correspondence material";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs a correspondence material"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace peridot
