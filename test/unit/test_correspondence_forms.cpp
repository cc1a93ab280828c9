// The two "Stress Integration" forms of "Elastic Correspondence" driven along the same path of
// homogeneous deformations on the 13^3 lattice: they agree to O(strain^2) at small strain (a
// tenth of the strain gives a hundredth of the difference), and differ at large shear, where the
// rate form follows Dienes' (1979) closed form for the Green-Naghdi rate (tan beta = gamma / 2):
//   sigma_xx = -sigma_yy = 4 mu [cos 2b ln cos b + b sin 2b - sin^2 b],
//   sigma_xy = 2 mu cos 2b [2b - 2 tan 2b ln cos b - tan b],
// and the Green strain form St Venant-Kirchhoff's sigma = F S F^T.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstdio>
#include <string>

#include "Materials.hpp"
#include "SerialProblem.hpp"
#include "materials/Correspondence.hpp"

namespace peridot {
namespace {

using testing::Problem;

const double kK = 2.0, kG = 1.0;
const int kN = 13;
const long long kCentre = 6 * kN * kN + 6 * kN + 6;

std::shared_ptr<MaterialModel> model(bool rate) {
  return testing::correspondence("Elastic Correspondence", kK, kG, 0.02,
                                 rate ? "Hypoelastic Rate" : "Total Lagrangian Green Strain");
}

std::vector<std::array<double, 3>> lattice(int n) { return testing::cubicLattice(n); }

// F(t) = I + t H over t in [0, 1] in `steps` steps (velocities H x), then the centre's Cauchy
// stress at t = 1.
std::array<double, 9> follow(bool rate, const double H[9], int steps) {
  Problem pr(lattice(kN), 3.015, model(rate));
  double* y = pr.fields->node("Coordinates", 3);
  double* v = pr.fields->node("Velocity", 3);
  const double* x = pr.fields->node("Model_Coordinates", 3);
  const double dt = 1.0 / steps;
  for (int n = 1; n <= steps; ++n) {
    const double t = n * dt;
    for (int p = 0; p < pr.topology.numOverlap; ++p)
      for (int a = 0; a < 3; ++a) {
        const double* X = x + 3 * p;
        const double HX = H[3 * a] * X[0] + H[3 * a + 1] * X[1] + H[3 * a + 2] * X[2];
        y[3 * p + a] = X[a] + t * HX;
        v[3 * p + a] = HX;
      }
    pr.evaluator->evaluate(dt);
  }
  std::array<double, 9> sigma;
  const double* s = pr.fields->node("Cauchy_Stress", 9) + 9 * pr.local(kCentre);
  std::copy(s, s + 9, sigma.begin());
  return sigma;
}

double maxDifference(const std::array<double, 9>& a, const std::array<double, 9>& b) {
  double worst = 0;
  for (int k = 0; k < 9; ++k) worst = std::max(worst, std::abs(a[k] - b[k]));
  return worst;
}

// A general small displacement gradient (stretch, shear and rotation together).
TEST(CorrespondenceForms, AgreeToSecondOrderInTheStrain) {
  const double H0[9] = {1.0, 0.4, -0.3, 0.2, -0.5, 0.6, 0.1, 0.3, 0.8};
  double relative[2];
  int k = 0;
  for (double eps : {1e-3, 1e-4}) {
    double H[9];
    for (int c = 0; c < 9; ++c) H[c] = eps * H0[c];
    const auto rate = follow(true, H, 20), green = follow(false, H, 20);
    relative[k++] = maxDifference(rate, green) / (kK * eps);
    std::printf("  strain %.0e: max |sigma_rate - sigma_Green| / (K strain) = %.3e\n", eps,
                relative[k - 1]);
  }
  EXPECT_LT(relative[0], 1e-2);                       // O(strain) relative, strain 1e-3
  EXPECT_NEAR(relative[0] / relative[1], 10.0, 1.0);  // O(strain^2) absolute
}

// Simple shear to gamma = 1 (the Green-Naghdi rotation turns by atan(1/2) = 26.6 degrees): the
// rate form converges at first order in dt to Dienes' closed form; the Green strain form gives
// St Venant-Kirchhoff's answer, a different material response.
TEST(CorrespondenceForms, DifferUnderLargeShearWhereTheRateFormFollowsDienes) {
  const double gamma = 1.0, mu = kG, lambda = kK - 2 * kG / 3;
  const double H[9] = {0, gamma, 0, 0, 0, 0, 0, 0, 0};
  const double b = std::atan(gamma / 2);
  const double lc = std::log(std::cos(b));
  const double dienesXX =
      4 * mu * (std::cos(2 * b) * lc + b * std::sin(2 * b) - std::sin(b) * std::sin(b));
  const double dienesXY =
      2 * mu * std::cos(2 * b) * (2 * b - 2 * std::tan(2 * b) * lc - std::tan(b));
  double errors[2];
  int k = 0;
  std::array<double, 9> rate{};
  for (int steps : {100, 200}) {
    rate = follow(true, H, steps);
    errors[k++] = std::max(std::abs(rate[1] - dienesXY), std::abs(rate[0] - dienesXX)) / mu;
    std::printf(
        "  simple shear gamma = 1, %d steps: sigma_xy = %.6f sigma_xx = %.6f (Dienes "
        "%.6f, %.6f), max error / mu = %.3e\n",
        steps, rate[1], rate[0], dienesXY, dienesXX, errors[k - 1]);
  }
  EXPECT_LT(errors[1], 1e-2);
  EXPECT_NEAR(errors[0] / errors[1], 2.0, 0.2);  // first order in dt
  // sigma_yy = -sigma_xx (Dienes) in the rate form; St Venant-Kirchhoff for the Green form.
  EXPECT_NEAR(rate[4], -rate[0], 2 * errors[1] * mu);
  const auto green = follow(false, H, 1);
  const double svkXY = mu * gamma + gamma * (lambda * gamma * gamma / 2 + mu * gamma * gamma);
  EXPECT_NEAR(green[1], svkXY, 1e-10 * mu);
  std::printf("  simple shear gamma = 1: sigma_xy rate form %.4f, Green strain form %.4f\n",
              rate[1], green[1]);
  EXPECT_GT(std::abs(green[1] - rate[1]) / (mu * gamma), 0.5);
}

}  // namespace
}  // namespace peridot
