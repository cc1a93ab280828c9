// The hypoelastic rate form of the correspondence models (the default "Stress Integration"):
// Flanagan and Taylor's update on its own, then on the 13^3 lattice of test_correspondence.cpp
// driven by prescribed positions and velocities. Golds are independent of the model's code: the
// exact rotation of a constant spin, and the step-by-step hypoelastic recursion of a uniaxial
// stretch written out here by hand (whose limit dt -> 0 is the closed form
// sigma_xx = (lambda + 2 mu) ln(1 + e)).
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstdio>
#include <string>

#include "Materials.hpp"
#include "SerialProblem.hpp"
#include "core/Error.hpp"
#include "materials/Correspondence.hpp"
#include "materials/CorrespondenceRate.hpp"

namespace peridot {
namespace {

using testing::Problem;

const double kK = 2.0, kG = 1.0;
const double kLambda = kK - 2.0 * kG / 3.0;
const int kN = 13;
const long long kCentre = 6 * kN * kN + 6 * kN + 6;

std::shared_ptr<MaterialModel> rateModel(const std::string& model, double yield = 0.0) {
  return testing::correspondence(model, kK, kG, 0.02, "Hypoelastic Rate", yield);
}

std::vector<std::array<double, 3>> lattice(int n) { return testing::cubicLattice(n); }

void rotation(const double n[3], double angle, double R[9]) {
  testing::rodriguesRotation(n, angle, R);
}

// The spin tensor of angular velocity `rate` about n: W y = rate n x y.
void spin(const double n[3], double rate, double W[9]) {
  const double w[9] = {0, -n[2], n[1], n[2], 0, -n[0], -n[1], n[0], 0};
  for (int k = 0; k < 9; ++k) W[k] = rate * w[k];
}

double maxDifference(const double* a, const double* b) {
  double worst = 0;
  for (int k = 0; k < 9; ++k) worst = std::max(worst, std::abs(a[k] - b[k]));
  return worst;
}

const double kAxis[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};

// A constant spin from V = I: R is the exact rotation at every step (the exponential update),
// the rate of deformation is zero, V stays I.
TEST(FlanaganTaylor, ConstantSpinRotatesExactly) {
  const double rate = 0.7, dt = 0.01;
  double W[9], V[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  spin(kAxis, rate, W);
  for (int n = 1; n <= 300; ++n) {
    double Vnew[9], Rnew[9], d[9];
    ASSERT_TRUE(correspondence::flanaganTaylorStep(W, V, R, dt, Vnew, Rnew, d));
    std::copy(Vnew, Vnew + 9, V);
    std::copy(Rnew, Rnew + 9, R);
    const double zero[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    ASSERT_LT(maxDifference(d, zero), 1e-15) << "step " << n;
  }
  double exact[9];
  rotation(kAxis, rate * 300 * dt, exact);  // 2.1 rad
  EXPECT_LT(maxDifference(R, exact), 1e-13);
  const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_LT(maxDifference(V, I), 1e-15);
}

// Pure stretching along x (L = diag(r, 0, 0)) from V = I: no rotation, d = D, V_xx grows by
// (1 + r dt) per step.
TEST(FlanaganTaylor, StretchingDoesNotRotate) {
  const double L[9] = {0.3, 0, 0, 0, 0, 0, 0, 0, 0};
  double V[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  double expected = 1;
  for (int n = 0; n < 10; ++n) {
    double Vnew[9], Rnew[9], d[9];
    correspondence::flanaganTaylorStep(L, V, R, 0.1, Vnew, Rnew, d);
    std::copy(Vnew, Vnew + 9, V);
    std::copy(Rnew, Rnew + 9, R);
    expected *= 1.03;
    EXPECT_LT(maxDifference(d, L), 1e-16);
  }
  const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_LT(maxDifference(R, I), 1e-16);
  EXPECT_NEAR(V[0], expected, 1e-15);
}

void move(Problem& pr, const double F[9], const double Fdot[9], double dt) {
  pr.evaluateAffine(F, Fdot, dt);
}

const double* tensorAt(Problem& pr, const char* name, int components = 9) {
  return pr.fields->node(name, components) + components * pr.local(kCentre);
}

// Uniaxial stretch F = diag(1 + e(t), 1, 1), e = rate t, in n steps; returns the hand recursion's
// sigma_xx and checks every step's sigma, V and outputs against it.
double stretch(Problem& pr, double eFinal, int steps) {
  const double dt = 1.0 / steps, rate = eFinal;
  double sxx = 0, syy = 0, Vxx = 1;
  for (int n = 1; n <= steps; ++n) {
    const double e = rate * n * dt;
    const double F[9] = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1};
    const double Fdot[9] = {rate, 0, 0, 0, 0, 0, 0, 0, 0};
    move(pr, F, Fdot, dt);
    // L = Fdot F^-1 = rate / (1 + e) at the step's end; sigma += dt C:L; V_xx *= 1 + dt L_xx.
    const double Lxx = rate / (1 + e);
    sxx += dt * (kLambda + 2 * kG) * Lxx;
    syy += dt * kLambda * Lxx;
    Vxx *= 1 + dt * Lxx;
    const double sigma[9] = {sxx, 0, 0, 0, syy, 0, 0, 0, syy};
    const double tol = 1e-12 * kK * eFinal + 1e-14 * kK;
    EXPECT_LT(maxDifference(tensorAt(pr, "Cauchy_Stress"), sigma), tol) << "step " << n;
    EXPECT_LT(maxDifference(tensorAt(pr, "Unrotated_Cauchy_Stress"), sigma), tol) << "step " << n;
    const double V[9] = {Vxx, 0, 0, 0, 1, 0, 0, 0, 1};
    EXPECT_LT(maxDifference(tensorAt(pr, "Left_Stretch_Tensor"), V), 1e-13);
    const double L[9] = {Lxx, 0, 0, 0, 0, 0, 0, 0, 0};
    EXPECT_LT(maxDifference(tensorAt(pr, "Velocity_Gradient"), L), 1e-13 * rate);
    EXPECT_LT(maxDifference(tensorAt(pr, "Unrotated_Rate_Of_Deformation"), L), 1e-13 * rate);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(pr.force(kCentre)[a], 0.0, 1e-10 * kK * eFinal);
  }
  return sxx;
}

// The hand recursion to rounding, and its limit: sigma_xx -> (lambda + 2 mu) ln(1 + e) at first
// order in dt (halving dt halves the error).
TEST(ElasticCorrespondenceRate, UniaxialStretchFollowsTheHypoelasticRecursion) {
  const double e = 0.1, exact = (kLambda + 2 * kG) * std::log(1 + e);
  double errors[2];
  int k = 0;
  for (int steps : {50, 100}) {
    Problem pr(lattice(kN), 3.015, rateModel("Elastic Correspondence"));
    const double sxx = stretch(pr, e, steps);
    errors[k++] = std::abs(sxx - exact) / exact;
    std::printf(
        "  uniaxial stretch e = %.2f, %d steps: |sigma_xx / ((lambda + 2 mu) ln(1 + e)) - "
        "1| = %.3e\n",
        e, steps, errors[k - 1]);
  }
  EXPECT_LT(errors[1], 2e-3);
  EXPECT_NEAR(errors[0] / errors[1], 2.0, 0.05);  // first order in dt
}

// Stretch, then spin the stretched body rigidly half a turn and more about (1, 1, 1): sigma_u, V's
// invariants and the von Mises stress do not change, sigma = R sigma_u R^T with R the exact
// rotation, and spinning an unstressed body brings no stress at all.
TEST(ElasticCorrespondenceRate, RigidRotationRotatesTheStressAndAddsNone) {
  Problem pr(lattice(kN), 3.015, rateModel("Elastic Correspondence"));
  const double e = 0.01;
  stretch(pr, e, 20);
  double su[9];
  std::copy(tensorAt(pr, "Unrotated_Cauchy_Stress"), tensorAt(pr, "Unrotated_Cauchy_Stress") + 9,
            su);
  const double vonMises = *tensorAt(pr, "Von_Mises_Stress", 1);
  const double U[9] = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1};
  const double rate = 1.3, dt = 0.02;
  double W[9];
  spin(kAxis, rate, W);
  const int steps = 150;  // 3.9 rad
  double worstUnrotated = 0, worstSigma = 0, worstR = 0;
  for (int n = 1; n <= steps; ++n) {
    double Q[9], F[9], Fdot[9], tmp[9], sigma[9];
    rotation(kAxis, rate * n * dt, Q);
    correspondence::multiply(Q, U, F);
    correspondence::multiply(W, F, Fdot);  // v = W y: a rigid spin of the deformed body
    move(pr, F, Fdot, dt);
    worstUnrotated =
        std::max(worstUnrotated, maxDifference(tensorAt(pr, "Unrotated_Cauchy_Stress"), su));
    correspondence::multiply(Q, su, tmp);
    correspondence::multiplyTransposed(tmp, Q, sigma);
    worstSigma = std::max(worstSigma, maxDifference(tensorAt(pr, "Cauchy_Stress"), sigma));
    worstR = std::max(worstR, maxDifference(tensorAt(pr, "Rotation_Tensor"), Q));
  }
  const double scale = kK * e;
  std::printf(
      "  rigid spin of a stretched body, 3.9 rad: max |sigma_u change| / (K e) = %.2e, "
      "max |sigma - R sigma_u R^T| / (K e) = %.2e, max |R - exact| = %.2e\n",
      worstUnrotated / scale, worstSigma / scale, worstR);
  EXPECT_LT(worstUnrotated / scale, 1e-11);
  EXPECT_LT(worstSigma / scale, 1e-11);
  EXPECT_LT(worstR, 1e-11);
  EXPECT_NEAR(*tensorAt(pr, "Von_Mises_Stress", 1), vonMises, 1e-11 * scale);
  const double* d = tensorAt(pr, "Unrotated_Rate_Of_Deformation");
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(d[k], 0.0, 1e-12 * rate) << k;
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(pr.force(kCentre)[a], 0.0, 1e-10 * scale);

  Problem fresh(lattice(kN), 3.015, rateModel("Elastic Correspondence"));
  double worst = 0;
  for (int n = 1; n <= steps; ++n) {
    double Q[9], Fdot[9];
    rotation(kAxis, rate * n * dt, Q);
    correspondence::multiply(W, Q, Fdot);
    move(fresh, Q, Fdot, dt);
    worst = std::max(worst, std::abs(*tensorAt(fresh, "Von_Mises_Stress", 1)));
  }
  std::printf("  rigid spin of an unstressed body: max von Mises / K = %.2e\n", worst / kK);
  EXPECT_LT(worst / kK, 1e-13);
}

// The rate form's J2 return on a uniaxial stretch past yield: after a plastic step the point is on
// the yield surface, eps_p grows by the scalar return dgamma = (q_trial - sigma_Y) / (3 mu), and
// the mean stress follows the elastic bulk response K ln-strain recursion.
TEST(ElasticPlasticCorrespondenceRate, UniaxialReturnMapping) {
  const double sigmaY = 1e-3;
  Problem pr(lattice(kN), 3.015, rateModel("Elastic Plastic Correspondence", sigmaY));
  const int steps = 40;
  const double eFinal = 5 * sigmaY / (2 * kG), dt = 1.0 / steps, rate = eFinal;
  double p = 0, q = 0, eqps = 0;  // mean stress, signed von Mises along diag(-1/3, -1/3, 2/3)_x
  int plastic = 0;
  for (int n = 1; n <= steps; ++n) {
    const double e = rate * n * dt;
    const double F[9] = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1};
    const double Fdot[9] = {rate, 0, 0, 0, 0, 0, 0, 0, 0};
    move(pr, F, Fdot, dt);
    const double delta = dt * rate / (1 + e);  // d_xx dt
    p += kK * delta;
    q += 2 * kG * delta;
    if (std::abs(q) > sigmaY) {
      eqps += (std::abs(q) - sigmaY) / (3 * kG);
      q = q > 0 ? sigmaY : -sigmaY;
      ++plastic;
    }
    const double sxx = p + 2.0 / 3.0 * q, syy = p - q / 3.0;
    const double* sigma = tensorAt(pr, "Cauchy_Stress");
    EXPECT_NEAR(sigma[0], sxx, 1e-10 * sigmaY) << "step " << n;
    EXPECT_NEAR(sigma[4], syy, 1e-10 * sigmaY) << "step " << n;
    EXPECT_NEAR(*tensorAt(pr, "Equivalent_Plastic_Strain", 1), eqps, 1e-10 * eFinal);
  }
  EXPECT_GT(plastic, 20);
  EXPECT_NEAR(*tensorAt(pr, "Von_Mises_Stress", 1) / sigmaY, 1.0, 1e-9);
}

// An inverted point (det F < 0) has no F^-1 for L and P = J sigma F^-T: the run stops naming it,
// as Peridigm's does, and no tensor holds a NaN.
TEST(ElasticCorrespondenceRate, InvertedPointStopsTheRun) {
  Problem pr(lattice(5), 1.75, rateModel("Elastic Correspondence"));
  const double F[9] = {-1, 0, 0, 0, 1, 0, 0, 0, 1}, Fdot[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  try {
    move(pr, F, Fdot, 0.1);
    FAIL() << "an inverted deformation gradient must stop the run";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("inverted"), std::string::npos) << what;
    EXPECT_NE(what.find("det F = -1"), std::string::npos) << what;
  }
  for (const char* name : {"Cauchy_Stress", "Velocity_Gradient", "Unrotated_Cauchy_Stress"})
    for (int k = 0; k < 9 * pr.topology.numOwned; ++k)
      ASSERT_TRUE(std::isfinite(pr.fields->node(name, 9)[k])) << name;
}

// The deck key: an unknown value is an input error naming both choices; the rate form reads
// velocities and has history (so "Verlet Limit" refuses it), the Green strain form neither.
TEST(ElasticCorrespondenceRate, StressIntegrationKey) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic Correspondence");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", kK);
  p.set("Shear Modulus", kG);
  p.set("Hourglass Coefficient", 0.0);
  p.set("Stress Integration", "Green");
  try {
    ListReader r(p, "Materials -> M");
    createMaterial(r);
    FAIL() << "an unknown Stress Integration was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Stress Integration"), std::string::npos) << what;
    EXPECT_NE(what.find("Total Lagrangian Green Strain"), std::string::npos) << what;
  }
  auto rate = rateModel("Elastic Correspondence");
  EXPECT_TRUE(rate->needsVelocity());
  EXPECT_TRUE(rate->advancesHistory());
  EXPECT_EQ(rate->historyNodeFields().size(), 3u);
  p.set("Stress Integration", "Total Lagrangian Green Strain");
  ListReader r(p, "Materials -> M");
  auto green = createMaterial(r);
  EXPECT_FALSE(green->needsVelocity());
  EXPECT_FALSE(green->advancesHistory());
  EXPECT_TRUE(green->historyNodeFields().empty());
}

}  // namespace
}  // namespace peridot
