// The stable time step estimates on 1, 2 and 3 ranks, against the dispersion relation of a
// fully periodic lattice (an independent computation of the true Verlet limit): the "Verlet
// Limit" estimate (solvers/VerletLimit.hpp) and Peridigm's estimate with partial volumes.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "app/Simulation.hpp"
#include "deck/Deck.hpp"
#include "neighbor/PartialVolume.hpp"
#include "solvers/VerletLimit.hpp"

namespace peridot {
namespace {

const double kPi = 3.14159265358979323846;
const int kPoints = 10;  // per axis, spacing 1
const double kDensity = 2.0, kBulk = 5.0, kHorizon = 2.5;

std::ostringstream runLog;

// A periodic kPoints^3 cube of `material`; `verlet` is the body of the Verlet list.
std::unique_ptr<Simulation> periodicCube(const std::string& verlet, const std::string& material,
                                         bool partialVolumes, const std::string& damage) {
  std::ostringstream d;
  d << "Peridigm:\n"
       "  Discretization:\n"
       "    Type: PdQuickGrid\n"
       "    NeighborhoodType: Spherical\n"
       "    Periodic X: true\n    Periodic Y: true\n    Periodic Z: true\n"
    << (partialVolumes ? "    Partial Volumes: true\n" : "")
    << "    TensorProduct3DMeshGenerator:\n"
       "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
    << "      X Length: " << kPoints << "\n      Y Length: " << kPoints
    << "\n      Z Length: " << kPoints << "\n      Number Points X: " << kPoints
    << "\n      Number Points Y: " << kPoints << "\n      Number Points Z: " << kPoints
    << "\n  Materials:\n    M:\n      Material Model: \"" << material
    << "\"\n      Density: " << kDensity << "\n      Bulk Modulus: " << kBulk << "\n"
    << (material == "Elastic" ? "      Shear Modulus: 3.0\n" : "")
    << (damage.empty() ? ""
                       : "  Damage Models:\n    D:\n      Damage Model: \"Critical Stretch\"\n"
                         "      Critical Stretch: " +
                             damage + "\n")
    << "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n"
    << (damage.empty() ? "" : "      Damage Model: D\n") << "      Horizon: " << kHorizon
    << "\n  Solver:\n    Final Time: 100.0\n    Verlet:\n"
    << verlet;
  auto deck = parseDeck(d.str(), "yaml");
  return std::make_unique<Simulation>(readRunConfig(*deck), MPI_COMM_WORLD, runLog);
}

// Largest eigenvalue of a symmetric 3 x 3 matrix (the trigonometric closed form).
double largestEigenvalue3(const double m[3][3]) {
  const double p1 = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
  const double q = (m[0][0] + m[1][1] + m[2][2]) / 3.0;
  if (p1 == 0) return std::max({m[0][0], m[1][1], m[2][2]});
  const double p2 = (m[0][0] - q) * (m[0][0] - q) + (m[1][1] - q) * (m[1][1] - q) +
                    (m[2][2] - q) * (m[2][2] - q) + 2.0 * p1;
  const double p = std::sqrt(p2 / 6.0);
  double b[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) b[r][c] = (m[r][c] - (r == c ? q : 0.0)) / p;
  const double det = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
                     b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                     b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
  const double r = std::clamp(det / 2.0, -1.0, 1.0);
  return q + 2.0 * p * std::cos(std::acos(r) / 3.0);
}

// The true Verlet limit of the linearized PMB lattice: the largest eigenvalue of the dynamical
// matrix D(k) = (1/rho) sum_xi (c / |xi|) (1 - cos k.xi) e e^T V over the wave vectors of the
// periodic box, c = 18 K / (pi delta^4), V = 1.
double exactPmbLimit() {
  const double c = 18.0 * kBulk / (kPi * std::pow(kHorizon, 4));
  double lambda = 0;
  const int reach = static_cast<int>(kHorizon);
  for (int n1 = 0; n1 < kPoints; ++n1)
    for (int n2 = 0; n2 < kPoints; ++n2)
      for (int n3 = 0; n3 < kPoints; ++n3) {
        const double k[3] = {2 * kPi * n1 / kPoints, 2 * kPi * n2 / kPoints,
                             2 * kPi * n3 / kPoints};
        double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        for (int a = -reach; a <= reach; ++a)
          for (int b = -reach; b <= reach; ++b)
            for (int e = -reach; e <= reach; ++e) {
              const double xi[3] = {double(a), double(b), double(e)};
              const double len = std::sqrt(xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]);
              if (len == 0 || len >= kHorizon) continue;
              const double w =
                  c / len * (1 - std::cos(k[0] * xi[0] + k[1] * xi[1] + k[2] * xi[2])) / kDensity;
              for (int r = 0; r < 3; ++r)
                for (int s = 0; s < 3; ++s) m[r][s] += w * xi[r] * xi[s] / (len * len);
            }
        lambda = std::max(lambda, largestEigenvalue3(m));
      }
  return 2.0 / std::sqrt(lambda);
}

TEST(VerletLimit, MatchesTheDispersionRelationOfAPeriodicLattice) {
  const double exact = exactPmbLimit();
  auto sim = periodicCube("      Stable Time Step Estimate: \"Verlet Limit\"\n",
                          "Elastic Bond Based", false, "");
  const double estimate = sim->stableTimeStepEstimate();
  // On the safe side of the limit (the Ritz residual is added) and within 0.1% of it.
  EXPECT_LE(estimate, exact * (1 + 1e-9));
  EXPECT_GT(estimate, 0.999 * exact);
  // Peridigm's estimate (row sums) is about half of it on this lattice.
  auto peridigm = periodicCube("      Safety Factor: 1.0\n", "Elastic Bond Based", false, "");
  EXPECT_GT(estimate / peridigm->stableTimeStepEstimate(), 1.8);
  // The same bits on every rank count: the Lanczos dot products are summed exactly.
  double bits[2] = {estimate, -estimate};
  MPI_Allreduce(MPI_IN_PLACE, bits, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_EQ(bits[0], -bits[1]);
}

TEST(VerletLimit, ProbingBreaksNoBond) {
  // A critical stretch far below the probe's stretch (1e-6 of the horizon): no bond may break
  // while the stiffness is probed, and the estimate is the undamaged one.
  auto undamaged = periodicCube("      Stable Time Step Estimate: \"Verlet Limit\"\n",
                                "Elastic Bond Based", false, "");
  auto brittle = periodicCube("      Stable Time Step Estimate: \"Verlet Limit\"\n",
                              "Elastic Bond Based", false, "1.0e-12");
  EXPECT_EQ(brittle->stableTimeStepEstimate(), undamaged->stableTimeStepEstimate());
  std::vector<double> damage;
  brittle->variables().nodeVariable("Damage", damage);
  double largest = 0;
  for (double v : damage) largest = std::max(largest, v);
  EXPECT_EQ(largest, 0.0);
}

TEST(VerletLimit, StateBasedLimitIsLargerThanPeridigmsEstimate) {
  // LPS: no closed form here, but the Lanczos estimate must be a step Verlet can take, which
  // Peridigm's bound also is; both are of the same order, the true limit the larger.
  auto lps =
      periodicCube("      Stable Time Step Estimate: \"Verlet Limit\"\n", "Elastic", false, "");
  auto peridigm = periodicCube("      Safety Factor: 1.0\n", "Elastic", false, "");
  const double ratio = lps->stableTimeStepEstimate() / peridigm->stableTimeStepEstimate();
  EXPECT_GT(ratio, 1.0);
  EXPECT_LT(ratio, 4.0);
}

TEST(StableTimeStep, PartialVolumesWeighTheEstimateByTheCellFractions) {
  // With partial volumes Peridigm's stiffness sum is c sum_j phi_j V_j / |xi_j| over the cells
  // that overlap the horizon: summed here over the lattice offsets directly. Without the
  // fractions the shell of overlapping cells would count whole (a stiffer sum, a smaller step).
  auto sim = periodicCube("      Safety Factor: 1.0\n", "Elastic", true, "");
  const double c = 18.0 * kBulk / (kPi * std::pow(kHorizon, 4));
  double weighted = 0, whole = 0;
  const int reach = static_cast<int>(kHorizon) + 1;
  for (int a = -reach; a <= reach; ++a)
    for (int b = -reach; b <= reach; ++b)
      for (int e = -reach; e <= reach; ++e) {
        const double xi[3] = {double(a), double(b), double(e)};
        const double len = std::sqrt(xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]);
        if (len == 0 || !cellOverlapsHorizon(xi, 1.0, kHorizon, 3)) continue;
        weighted += cellFractionInHorizon(xi, len, 1.0, kHorizon, 3) / len;
        whole += 1.0 / len;
      }
  const double expected = std::sqrt(2.0 * kDensity / (c * weighted));
  EXPECT_NEAR(sim->stableTimeStepEstimate() / expected, 1.0, 1e-9);
  EXPECT_GT(whole / weighted, 1.1);  // what the fractions change
}

TEST(VerletLimit, TridiagonalEigenvalue) {
  // tridiag(-1, 2, -1) of size n: eigenvalues 2 - 2 cos(k pi / (n + 1)).
  const int n = 30;
  std::vector<double> alpha(n, 2.0), beta(n - 1, -1.0);
  const double exact = 2.0 - 2.0 * std::cos(n * kPi / (n + 1));
  EXPECT_NEAR(largestTridiagonalEigenvalue(alpha.data(), beta.data(), n), exact, 1e-12);
}

}  // namespace
}  // namespace peridot
