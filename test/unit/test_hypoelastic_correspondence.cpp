// Peridigm's hypoelastic correspondence family (materials/HypoelasticCorrespondence.hpp) under
// homogeneous motions y = F x, v = Fdot x prescribed at every point. Golds are independent of the
// model's code: the step-by-step hypoelastic recursion written out by hand (uniaxial stretch,
// dilatation), the small-strain shear modulus, the continuum traction sigma . (J F^-T e_x) A on a
// cut through a lattice periodic in y and z, the scalar J2 return, and zero stress under a rigid
// spin.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "Materials.hpp"
#include "SerialProblem.hpp"
#include "core/Error.hpp"
#include "materials/Correspondence.hpp"

namespace peridot {
namespace {

using testing::Problem;

const double kK = 2.0, kG = 1.0;
const double kLambda = kK - 2.0 * kG / 3.0;
const int kN = 9;  // odd: the lattice is symmetric about its centre point
const long long kCentre = 4 * kN * kN + 4 * kN + 4;

std::shared_ptr<MaterialModel> hypo(const std::string& model, int order = 1, double yield = 0.0,
                                    double eps0 = 0.0, double n = -1) {
  Teuchos::ParameterList p;
  p.set("Material Model", model);
  p.set("Density", 1.0);
  p.set("Bulk Modulus", kK);
  p.set("Shear Modulus", kG);
  p.set("Actual Horizon", 3.015);
  p.set("Gradient Order Of Accuracy", order);
  if (yield > 0) p.set("Yield Stress", yield);
  if (eps0 > 0) p.set("Hardening Characteristic Strain", eps0);
  if (n >= 0) p.set("Hardening Exponent", n);
  ListReader r(p, "Materials -> M");
  return createMaterial(r);
}

const double* at(Problem& pr, const char* name, long long g = kCentre, int components = 9) {
  return pr.fields->node(name, components) + components * pr.local(g);
}

double maxForce(Problem& pr) {
  double worst = 0;
  for (int i = 0; i < pr.topology.numOwned; ++i)
    for (int a = 0; a < 3; ++a)
      worst = std::max(worst, std::abs(pr.fields->nodeField("Force_Density").data[3 * i + a]));
  return worst;
}

// Uniaxial stretch F = diag(1 + e(t), 1, 1) in `steps` steps at the lattice's centre: sigma
// follows sigma += dt C : L, L_xx = rate / (1 + e), to rounding, for gradient orders 1 and 2;
// the force at the centre vanishes; J follows J *= 1 + dt L_xx.
TEST(ElasticHypoelasticCorrespondence, UniaxialStretchFollowsTheHypoelasticRecursion) {
  for (int order : {1, 2}) {
    Problem pr(testing::cubicLattice(kN), 3.015, hypo("Elastic Hypoelastic Correspondence", order));
    const int steps = 50;
    const double eFinal = 0.05, dt = 1.0 / steps, rate = eFinal;
    double sxx = 0, syy = 0, J = 1, worst = 0;
    for (int n = 1; n <= steps; ++n) {
      const double e = rate * n * dt;
      const double F[9] = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1};
      const double Fdot[9] = {rate, 0, 0, 0, 0, 0, 0, 0, 0};
      pr.evaluateAffine(F, Fdot, dt);
      const double Lxx = rate / (1 + e);
      sxx += dt * (kLambda + 2 * kG) * Lxx;
      syy += dt * kLambda * Lxx;
      J *= 1 + dt * Lxx;
      const double* sigma = at(pr, "Cauchy_Stress");
      worst = std::max({worst, std::abs(sigma[0] - sxx), std::abs(sigma[4] - syy)});
      ASSERT_NEAR(sigma[0], sxx, 1e-11 * kK) << "order " << order << " step " << n;
      ASSERT_NEAR(sigma[4], syy, 1e-11 * kK);
      ASSERT_NEAR(sigma[8], syy, 1e-11 * kK);
      ASSERT_NEAR(sigma[1], 0.0, 1e-11 * kK);
      ASSERT_NEAR(*at(pr, "Jacobian_Determinant", kCentre, 1), J, 1e-13);
      for (int a = 0; a < 3; ++a) ASSERT_NEAR(pr.force(kCentre)[a], 0.0, 1e-10 * kK * eFinal);
    }
    std::printf(
        "  order %d: max |sigma - recursion| / K = %.2e; sigma_xx = %.6f vs (lambda + 2 mu) ln(1 "
        "+ e) = %.6f\n",
        order, worst / kK, at(pr, "Cauchy_Stress")[0], (kLambda + 2 * kG) * std::log(1 + eFinal));
  }
}

// Dilatation F = (1 + e) I: the mean stress follows sigma += 3 K dt L_xx, no deviator.
TEST(ElasticHypoelasticCorrespondence, DilatationFollowsTheBulkRecursion) {
  Problem pr(testing::cubicLattice(kN), 3.015, hypo("Elastic Hypoelastic Correspondence", 2));
  const int steps = 20;
  const double eFinal = 0.01, dt = 1.0 / steps, rate = eFinal;
  double p = 0;
  for (int n = 1; n <= steps; ++n) {
    const double e = rate * n * dt;
    const double F[9] = {1 + e, 0, 0, 0, 1 + e, 0, 0, 0, 1 + e};
    const double Fdot[9] = {rate, 0, 0, 0, rate, 0, 0, 0, rate};
    pr.evaluateAffine(F, Fdot, dt);
    p += dt * 3 * kK * rate / (1 + e);
  }
  const double* sigma = at(pr, "Cauchy_Stress");
  std::printf("  dilatation: sigma_xx - recursion = %.2e K\n", (sigma[0] - p) / kK);
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(sigma[k], k % 4 == 0 ? p : 0.0, 1e-12 * kK) << k;
  EXPECT_NEAR(*at(pr, "Von_Mises_Stress", kCentre, 1), 0.0, 1e-12 * kK);
}

// A small simple shear gamma: sigma_xy = mu gamma to O(gamma^2), the normal stresses O(gamma^2).
TEST(ElasticHypoelasticCorrespondence, SmallShearGivesTheShearModulus) {
  Problem pr(testing::cubicLattice(kN), 3.015, hypo("Elastic Hypoelastic Correspondence"));
  const double gamma = 1e-4;
  const int steps = 10;
  for (int n = 1; n <= steps; ++n) {
    const double g = gamma * n / steps;
    const double F[9] = {1, g, 0, 0, 1, 0, 0, 0, 1};
    const double Fdot[9] = {0, gamma, 0, 0, 0, 0, 0, 0, 0};
    pr.evaluateAffine(F, Fdot, 1.0 / steps);
  }
  const double* sigma = at(pr, "Cauchy_Stress");
  std::printf("  shear 1e-4: sigma_xy / (mu gamma) - 1 = %.2e, sigma_xx / (mu gamma) = %.2e\n",
              sigma[1] / (kG * gamma) - 1, sigma[0] / (kG * gamma));
  EXPECT_NEAR(sigma[1] / (kG * gamma), 1.0, 2 * gamma);
  EXPECT_NEAR(sigma[3] / (kG * gamma), 1.0, 2 * gamma);
  EXPECT_NEAR(sigma[0], 0.0, 2 * kG * gamma * gamma);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(pr.force(kCentre)[a], 0.0, 1e-9 * kG * gamma);
}

// The continuum traction: on a lattice periodic in y and z, the force on all points beyond a cut
// x = c is what the stress transmits across it, -J sigma F^-T e_x A (A the reference area of the
// cut, J the model's Jacobian at the start of the step). Exact to rounding: the bond term and N add
// up to sigma.
TEST(ElasticHypoelasticCorrespondence, ForceAcrossACutIsTheTraction) {
  const int nx = 19, ny = 7;
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < ny; ++k) pts.push_back({double(i), double(j), double(k)});
  PeriodicBox box;
  box.periodic[1] = box.periodic[2] = true;
  box.lower[1] = box.lower[2] = -0.5;
  box.upper[1] = box.upper[2] = ny - 0.5;
  for (int order : {1, 2}) {
    Problem pr(pts, 3.015, hypo("Elastic Hypoelastic Correspondence", order), nullptr, box);
    // Stretch along x and shear v_y = gamma x together, 10 steps. F e_y = e_y and F e_z = e_z:
    // the periodic images (shifted by the reference period in y and z) and their velocities
    // (copies) then follow the homogeneous motion exactly.
    const int steps = 10;
    const double Fend[9] = {1.02, 0, 0, 0.03, 1, 0, -0.01, 0, 1};
    for (int n = 1; n <= steps; ++n) {
      double F[9], Fdot[9];
      for (int k = 0; k < 9; ++k) {
        const double I = k % 4 == 0 ? 1.0 : 0.0;
        F[k] = I + (Fend[k] - I) * n / steps;
        Fdot[k] = Fend[k] - I;
      }
      pr.evaluateAffine(F, Fdot, 1.0 / steps);
    }
    const long long inside = 9 * ny * ny + 3 * ny + 3;  // a point far from the x faces
    const double* sigma = at(pr, "Cauchy_Stress", inside);
    // The force weighs volumes by J at the start of the last step (as Peridigm's).
    const double* L = at(pr, "Velocity_Gradient", inside);
    const double J =
        *at(pr, "Jacobian_Determinant", inside, 1) / (1 + (L[0] + L[4] + L[8]) / steps);
    double Finv[9];
    ASSERT_TRUE(correspondence::invert(Fend, Finv));
    // F^-T e_x = first row of F^-1, as a column
    double expected[3];
    for (int a = 0; a < 3; ++a)
      expected[a] =
          -J * ny * ny *
          (sigma[3 * a] * Finv[0] + sigma[3 * a + 1] * Finv[1] + sigma[3 * a + 2] * Finv[2]);
    double total[3] = {0, 0, 0};
    for (int i = 0; i < pr.topology.numOwned; ++i) {
      const long long g = pr.topology.overlapGlobalId[i];
      if (g / (ny * ny) < 10) continue;  // x index >= 10: beyond the cut between 9 and 10
      for (int a = 0; a < 3; ++a) total[a] += pr.fields->nodeField("Force_Density").data[3 * i + a];
    }
    std::printf(
        "  order %d: force beyond the cut (%.8f, %.8f, %.8f), traction (%.8f, %.8f, %.8f)\n", order,
        total[0], total[1], total[2], expected[0], expected[1], expected[2]);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(total[a], expected[a], 1e-10 * std::abs(expected[0]));
  }
}

// A rigid spin of an unstressed body, 2 rad: no stress at any point, no force.
TEST(ElasticHypoelasticCorrespondence, RigidRotationGivesNoStress) {
  Problem pr(testing::cubicLattice(9), 3.015, hypo("Elastic Hypoelastic Correspondence", 2));
  const double axis[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  const double rate = 1.0, dt = 0.02;
  const double w[9] = {0, -axis[2], axis[1], axis[2], 0, -axis[0], -axis[1], axis[0], 0};
  double worst = 0;
  for (int n = 1; n <= 100; ++n) {
    double Q[9], Fdot[9], W[9];
    testing::rodriguesRotation(axis, rate * n * dt, Q);
    for (int k = 0; k < 9; ++k) W[k] = rate * w[k];
    correspondence::multiply(W, Q, Fdot);
    pr.evaluateAffine(Q, Fdot, dt);
    for (int i = 0; i < pr.topology.numOwned; ++i)
      worst = std::max(worst, pr.fields->node("Von_Mises_Stress", 1)[i]);
  }
  std::printf("  rigid spin, 2 rad: max von Mises / K = %.2e, max |f| / K = %.2e\n", worst / kK,
              maxForce(pr) / kK);
  EXPECT_LT(worst / kK, 1e-12);
  EXPECT_LT(maxForce(pr) / kK, 1e-11);
}

// Uniaxial stretch past yield and back: on the surface while loading plastically (von Mises =
// sigma_Y to rounding), eps_p never decreasing and equal to the scalar return's sum of
// (q_trial - sigma_Y) / (3 mu), unloading with the elastic slope lambda + 2 mu.
TEST(ElasticPlasticHypoelasticCorrespondence, LoadingAndUnloadingPastYield) {
  const double sigmaY = 1e-3;
  Problem pr(testing::cubicLattice(kN), 3.015,
             hypo("Elastic Plastic Hypoelastic Correspondence", 1, sigmaY));
  const int steps = 60;
  const double ePeak = 4 * sigmaY / (2 * kG), dt = 1.0 / steps;
  double p = 0, q = 0, eqps = 0, e = 0, lastEqps = 0, lastSxx = 0;
  int plastic = 0, unloading = 0;
  for (int n = 1; n <= steps; ++n) {
    const double rate = n <= 40 ? ePeak / (40 * dt) : -ePeak / (40 * dt);
    const double eNew = e + rate * dt;
    const double F[9] = {1 + eNew, 0, 0, 0, 1, 0, 0, 0, 1};
    const double Fdot[9] = {rate, 0, 0, 0, 0, 0, 0, 0, 0};
    pr.evaluateAffine(F, Fdot, dt);
    const double delta = dt * rate / (1 + eNew);
    p += kK * delta;
    q += 2 * kG * delta;
    bool yielded = false;
    if (std::abs(q) > sigmaY) {
      eqps += (std::abs(q) - sigmaY) / (3 * kG);
      q = q > 0 ? sigmaY : -sigmaY;
      yielded = true;
      ++plastic;
    }
    const double* sigma = at(pr, "Cauchy_Stress");
    const double now = *at(pr, "Equivalent_Plastic_Strain", kCentre, 1);
    ASSERT_NEAR(sigma[0], p + 2.0 / 3.0 * q, 1e-10 * sigmaY) << "step " << n;
    ASSERT_NEAR(now, eqps, 1e-10 * ePeak) << "step " << n;
    ASSERT_GE(now, lastEqps);
    if (yielded) {
      ASSERT_NEAR(*at(pr, "Von_Mises_Stress", kCentre, 1) / sigmaY, 1.0, 1e-10);
    }
    if (n > 41 && !yielded) {
      // the elastic unloading slope d sigma_xx / d ln(1 + e) = lambda + 2 mu
      const double slope = (sigma[0] - lastSxx) / (rate * dt / (1 + eNew));
      ASSERT_NEAR(slope / (kLambda + 2 * kG), 1.0, 1e-8);
      ++unloading;
    }
    lastEqps = now;
    lastSxx = sigma[0];
    e = eNew;
  }
  std::printf("  %d plastic steps, %d elastic unloading steps, final eps_p %.4e\n", plastic,
              unloading, lastEqps);
  EXPECT_GT(plastic, 20);
  EXPECT_GT(unloading, 10);
}

// Power-law hardening: after plastic steps the von Mises stress is sigma_Y (1 + eps_p / eps_0)^n
// to rounding.
TEST(IsotropicHardeningHypoelasticCorrespondence, StressStaysOnTheHardenedSurface) {
  const double sigmaY = 1e-3, eps0 = 1e-3, n = 0.3;
  Problem pr(testing::cubicLattice(kN), 3.015,
             hypo("Isotropic Hardening Hypoelastic Correspondence", 1, sigmaY, eps0, n));
  const int steps = 40;
  const double eFinal = 6 * sigmaY / (2 * kG), dt = 1.0 / steps, rate = eFinal;
  double lastEqps = 0;
  for (int s = 1; s <= steps; ++s) {
    const double e = rate * s * dt;
    const double F[9] = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1};
    const double Fdot[9] = {rate, 0, 0, 0, 0, 0, 0, 0, 0};
    pr.evaluateAffine(F, Fdot, dt);
    const double eqps = *at(pr, "Equivalent_Plastic_Strain", kCentre, 1);
    ASSERT_GE(eqps, lastEqps);
    if (eqps > lastEqps) {
      const double surface = sigmaY * std::pow(1 + eqps / eps0, n);
      ASSERT_NEAR(*at(pr, "Von_Mises_Stress", kCentre, 1) / surface, 1.0, 1e-12) << s;
    }
    lastEqps = eqps;
  }
  EXPECT_GT(lastEqps, 0.5 * eFinal);
}

// Bad input: Actual Horizon is required, the order is 1..4, Peridigm's refused keys are refused.
TEST(HypoelasticCorrespondence, BadInputIsAnError) {
  const auto make = [](const std::string& key, const Teuchos::ParameterEntry* value,
                       bool dropHorizon) {
    Teuchos::ParameterList p;
    p.set("Material Model", "Elastic Hypoelastic Correspondence");
    p.set("Density", 1.0);
    p.set("Bulk Modulus", kK);
    p.set("Shear Modulus", kG);
    if (!dropHorizon) p.set("Actual Horizon", 3.0);
    if (value) p.setEntry(key, *value);
    ListReader r(p, "Materials -> M");
    return createMaterial(r);
  };
  EXPECT_THROW(make("", nullptr, true), InputError);
  const Teuchos::ParameterEntry zero(0), five(5), yes(true), alpha(1e-5);
  EXPECT_THROW(make("Gradient Order Of Accuracy", &zero, false), InputError);
  EXPECT_THROW(make("Gradient Order Of Accuracy", &five, false), InputError);
  EXPECT_THROW(make("Apply Automatic Differentiation Jacobian", &yes, false), InputError);
  EXPECT_THROW(make("Apply Shear Correction Factor", &yes, false), InputError);
  EXPECT_THROW(make("Thermal Expansion Coefficient", &alpha, false), InputError);
  EXPECT_NO_THROW(make("", nullptr, false));
}

}  // namespace
}  // namespace peridot
