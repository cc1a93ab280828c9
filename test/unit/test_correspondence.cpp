// The correspondence models ("Elastic Correspondence", "Elastic Plastic Correspondence",
// "Isotropic Hardening Correspondence") with "Stress Integration: Total Lagrangian Green Strain"
// (the rate form, the default, is checked in test_correspondence_rate.cpp and
// test_correspondence_forms.cpp) on a 13^3 unit lattice (horizon 3.015) whose centre is
// two horizons from every face. Golds are independent of the model's code: the deformation
// gradient imposed; the Cauchy stress of a St Venant-Kirchhoff solid written out here from the
// closed forms of each homogeneous deformation (and the linear-elastic limit at small strain);
// the uniaxial-strain J2 response from a scalar return mapping along its one deviatoric
// direction; a central finite difference of the total energy for the force; momentum balance.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "Materials.hpp"
#include "SerialProblem.hpp"
#include "core/Error.hpp"
#include "damage/DamageModel.hpp"
#include "materials/Correspondence.hpp"
#include "materials/ElasticPlasticCorrespondence.hpp"

namespace peridot {
namespace {

using testing::Problem;

const double kK = 2.0, kG = 1.0;  // lambda = K - 2G/3 = 4/3
const double kLambda = kK - 2.0 * kG / 3.0;
const int kN = 13;
const long long kCentre = 6 * kN * kN + 6 * kN + 6;

std::shared_ptr<MaterialModel> correspondenceModel(const std::string& model, double hourglass,
                                                   double yield = 0.0, double H = -1.0) {
  return testing::correspondence(model, kK, kG, hourglass, "Total Lagrangian Green Strain", yield,
                                 H);
}

std::vector<std::array<double, 3>> lattice(int n) { return testing::cubicLattice(n); }

// y = F x at every point, then one model evaluation (precompute, ghosts, force).
void deform(Problem& pr, const double F[9]) {
  double* y = pr.fields->node("Coordinates", 3);
  const double* x = pr.fields->node("Model_Coordinates", 3);
  for (int p = 0; p < pr.topology.numOverlap; ++p)
    for (int a = 0; a < 3; ++a)
      y[3 * p + a] =
          F[3 * a] * x[3 * p] + F[3 * a + 1] * x[3 * p + 1] + F[3 * a + 2] * x[3 * p + 2];
  pr.evaluator->evaluate(1.0);
}

const double* nodeTensor(Problem& pr, const char* name, int components, long long g) {
  return pr.fields->node(name, components) + components * pr.local(g);
}

// Also prints the largest difference relative to `scale` (tabulated in doc/verification.md).
void expectTensorNear(const double* actual, const double* expected, double tolerance,
                      const std::string& what, double scale = 0.0) {
  double worst = 0;
  for (int k = 0; k < 9; ++k) {
    EXPECT_NEAR(actual[k], expected[k], tolerance) << what << " component " << k;
    worst = std::max(worst, std::abs(actual[k] - expected[k]));
  }
  if (scale > 0) std::printf("  %s: max |error| / scale = %.2e\n", what.c_str(), worst / scale);
}

void rotation(const double n[3], double angle, double R[9]) {
  testing::rodriguesRotation(n, angle, R);
}

class ElasticCorrespondenceLattice : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    problem_ = new Problem(lattice(kN), 3.015, correspondenceModel("Elastic Correspondence", 0.05));
  }
  static void TearDownTestSuite() {
    delete problem_;
    problem_ = nullptr;
  }
  static Problem* problem_;
};
Problem* ElasticCorrespondenceLattice::problem_ = nullptr;

// Uniaxial strain F = diag(1 + e, 1, 1): E_xx = e + e^2/2 =: g, S = diag(lambda + 2 mu, lambda,
// lambda) g, sigma = F S F^T / J: sigma_xx = (1 + e)(lambda + 2 mu) g, sigma_yy = lambda g / (1 +
// e).
TEST_F(ElasticCorrespondenceLattice, UniaxialStrainMatchesClosedForm) {
  Problem& pr = *problem_;
  for (double e : {1e-6, 0.05}) {
    const double F[9] = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1};
    deform(pr, F);
    const double g = e + 0.5 * e * e;
    const double sigma[9] = {(1 + e) * (kLambda + 2 * kG) * g,
                             0,
                             0,
                             0,
                             kLambda * g / (1 + e),
                             0,
                             0,
                             0,
                             kLambda * g / (1 + e)};
    const double scale = (kLambda + 2 * kG) * e;
    expectTensorNear(nodeTensor(pr, "Deformation_Gradient", 9, kCentre), F, 1e-12, "uniaxial F",
                     1.0);
    // F's lattice sums round at ~1e-15, so the stress carries ~1e-15 K besides its relative error.
    expectTensorNear(nodeTensor(pr, "Cauchy_Stress", 9, kCentre), sigma, 1e-10 * scale + 1e-13 * kK,
                     "uniaxial strain e = " + std::to_string(e) + " sigma", scale);
    if (e < 1e-5) {  // the linear-elastic limit: sigma_xx = (lambda + 2 mu) e, sigma_yy = lambda e
      const double* s = nodeTensor(pr, "Cauchy_Stress", 9, kCentre);
      EXPECT_NEAR(s[0] / ((kLambda + 2 * kG) * e), 1.0, 1e-5);
      EXPECT_NEAR(s[4] / (kLambda * e), 1.0, 1e-5);
    }
    const double* f = pr.force(kCentre);
    const double* h = nodeTensor(pr, "Hourglass_Force_Density", 3, kCentre);
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(f[d], 0.0, 1e-9 * scale) << "bulk force, e = " << e;
      EXPECT_NEAR(h[d], 0.0, 1e-9 * scale) << "hourglass force of an affine motion";
    }
  }
}

// Dilatation F = (1 + e) I: E = g I, S = 3 K g I, sigma = S / (1 + e).
TEST_F(ElasticCorrespondenceLattice, DilatationMatchesClosedForm) {
  Problem& pr = *problem_;
  const double e = 0.02, g = e + 0.5 * e * e;
  const double F[9] = {1 + e, 0, 0, 0, 1 + e, 0, 0, 0, 1 + e};
  deform(pr, F);
  const double p = 3 * kK * g / (1 + e);
  const double sigma[9] = {p, 0, 0, 0, p, 0, 0, 0, p};
  expectTensorNear(nodeTensor(pr, "Cauchy_Stress", 9, kCentre), sigma, 1e-10 * p,
                   "dilatation sigma", p);
  EXPECT_NEAR(*nodeTensor(pr, "Von_Mises_Stress", 1, kCentre), 0.0, 1e-10 * p);
}

// Simple shear F = I + gamma e_x (x) e_y: E = [[0, g/2, 0], [g/2, g^2/2, 0], [0, 0, 0]],
// S = lambda g^2/2 I + 2 mu E, J = 1, sigma = F S F^T, written out by components.
TEST_F(ElasticCorrespondenceLattice, SimpleShearMatchesClosedForm) {
  Problem& pr = *problem_;
  const double c = 0.03, mu = kG, l = kLambda;
  const double F[9] = {1, c, 0, 0, 1, 0, 0, 0, 1};
  deform(pr, F);
  const double t = l * c * c / 2;  // lambda tr E
  const double Sxx = t, Sxy = mu * c, Syy = t + mu * c * c, Szz = t;
  // F S: row x = S_x + c S_y, row y = S_y; sigma = (F S) F^T: column x gains c times column y.
  const double FSxx = Sxx + c * Sxy, FSxy = Sxy + c * Syy;
  const double sigma[9] = {FSxx + c * FSxy, FSxy, 0, Sxy + c * Syy, Syy, 0, 0, 0, Szz};
  expectTensorNear(nodeTensor(pr, "Cauchy_Stress", 9, kCentre), sigma, 1e-10 * mu * c,
                   "simple shear sigma", mu * c);
  // Linear limit: sigma_xy = mu gamma to O(gamma^2).
  EXPECT_NEAR(nodeTensor(pr, "Cauchy_Stress", 9, kCentre)[1] / (mu * c), 1.0, 2 * c * c);
}

// A rigid rotation is stress free (the point of the Green strain), F = R exactly; stretch then
// rotation: the unrotated Cauchy stress is the uniaxial one and the Cauchy stress is rotated.
TEST_F(ElasticCorrespondenceLattice, RotationIsStressFreeAndUnrotatedStressIsFrameFree) {
  Problem& pr = *problem_;
  const double n[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  double R[9];
  rotation(n, 0.5, R);
  deform(pr, R);
  const double zero[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  expectTensorNear(nodeTensor(pr, "Deformation_Gradient", 9, kCentre), R, 1e-12, "rotation F", 1.0);
  expectTensorNear(nodeTensor(pr, "Cauchy_Stress", 9, kCentre), zero, 1e-12, "rotation sigma", kG);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(pr.force(kCentre)[d], 0.0, 1e-10);

  const double e = 0.01, g = e + 0.5 * e * e;
  const double U[9] = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1};
  double F[9];
  correspondence::multiply(R, U, F);
  deform(pr, F);
  const double su[9] = {(1 + e) * (kLambda + 2 * kG) * g,
                        0,
                        0,
                        0,
                        kLambda * g / (1 + e),
                        0,
                        0,
                        0,
                        kLambda * g / (1 + e)};
  const double tol = 1e-10 * kK * e;
  expectTensorNear(nodeTensor(pr, "Unrotated_Cauchy_Stress", 9, kCentre), su, tol,
                   "stretch + rotation R^T sigma R", kK * e);
  double tmp[9], sigma[9];
  correspondence::multiply(R, su, tmp);
  correspondence::multiplyTransposed(tmp, R, sigma);  // R su R^T
  expectTensorNear(nodeTensor(pr, "Cauchy_Stress", 9, kCentre), sigma, tol, "sigma");
  // The polar decomposition: R, and V = F R^T = R U R^T.
  expectTensorNear(nodeTensor(pr, "Rotation_Tensor", 9, kCentre), R, 1e-12, "R");
  double V[9];
  correspondence::multiply(R, U, tmp);
  correspondence::multiplyTransposed(tmp, R, V);
  expectTensorNear(nodeTensor(pr, "Left_Stretch_Tensor", 9, kCentre), V, 1e-12, "V");
}

// A non-affine motion: moving the centre alone brings a hourglass force that pulls it back.
TEST_F(ElasticCorrespondenceLattice, HourglassForceRestoresANonAffineMode) {
  Problem& pr = *problem_;
  const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  deform(pr, I);
  pr.move(kCentre, 1e-3, 0, 0);
  pr.evaluator->evaluate(1.0);
  const double* h = nodeTensor(pr, "Hourglass_Force_Density", 3, kCentre);
  EXPECT_LT(h[0], 0.0);
  EXPECT_NEAR(h[1], 0.0, 1e-12);
  EXPECT_NEAR(h[2], 0.0, 1e-12);
  pr.move(kCentre, -1e-3, 0, 0);
}

// Momentum balance under an arbitrary motion, hourglass forces included: sum f V = 0.
TEST(ElasticCorrespondence, ConservesLinearMomentum) {
  Problem pr(lattice(6), 1.75, correspondenceModel("Elastic Correspondence", 0.05));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  double* y = pr.fields->node("Coordinates", 3);
  for (int k = 0; k < 3 * pr.topology.numOverlap; ++k) y[k] += u(rng);
  pr.evaluator->evaluate(1.0);
  double sum[3] = {0, 0, 0}, magnitude = 0;
  for (int i = 0; i < pr.topology.numOwned; ++i)
    for (int d = 0; d < 3; ++d) {
      sum[d] += pr.fields->node("Force_Density", 3)[3 * i + d];
      magnitude += std::abs(pr.fields->node("Force_Density", 3)[3 * i + d]);
    }
  ASSERT_GT(magnitude, 0.0);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(sum[d] / magnitude, 0.0, 1e-13);
}

// Without hourglass control the model is hyperelastic: f_p V_p = -d/dy_p sum_i W(F_i) V_i.
TEST(ElasticCorrespondence, ForceIsMinusTheEnergyGradient) {
  Problem pr(lattice(6), 1.75, correspondenceModel("Elastic Correspondence", 0.0));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  double* y = pr.fields->node("Coordinates", 3);
  for (int k = 0; k < 3 * pr.topology.numOverlap; ++k) y[k] += u(rng);
  auto energy = [&]() {
    for (auto& b : pr.blocks) b.material->precompute(pr.evaluator->state(), b.points);
    std::vector<double> w(pr.topology.numOverlap);
    pr.evaluator->storedEnergyDensity(w.data());
    double total = 0;
    for (int i = 0; i < pr.topology.numOwned; ++i) total += w[i];  // unit volumes
    return total;
  };
  pr.evaluator->evaluate(1.0);
  std::vector<double> f(pr.fields->node("Force_Density", 3),
                        pr.fields->node("Force_Density", 3) + 3 * pr.topology.numOwned);
  const double h = 1e-6;
  double worst = 0, largest = 0;
  for (long long g : {0LL, 43LL, 86LL, 129LL, 215LL}) {
    const int p = pr.local(g);
    for (int d = 0; d < 3; ++d) {
      y[3 * p + d] += h;
      const double plus = energy();
      y[3 * p + d] -= 2 * h;
      const double minus = energy();
      y[3 * p + d] += h;
      const double gradient = (plus - minus) / (2 * h);
      worst = std::max(worst, std::abs(f[3 * p + d] + gradient));
      largest = std::max(largest, std::abs(f[3 * p + d]));
    }
  }
  ASSERT_GT(largest, 1e-3);
  EXPECT_LT(worst / largest, 1e-6) << worst << " of " << largest;
}

// Fewer than three non-coplanar neighbours: a clear set-up error, as Peridigm stops there.
TEST(ElasticCorrespondence, CoplanarNeighbourhoodIsAClearError) {
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) pts.push_back({double(i), double(j), 0.0});  // one plane
  try {
    Problem pr(pts, 1.5, correspondenceModel("Elastic Correspondence", 0.0));
    FAIL() << "a planar cloud's shape tensors are singular";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("shape tensor"), std::string::npos) << what;
    EXPECT_NE(what.find("three non-coplanar"), std::string::npos) << what;
    EXPECT_NE(what.find("point 1 at (0, 0, 0)"), std::string::npos) << what;
  }
}

// Bonds broken until a point's shape tensor is singular: the run stops with the point named,
// and nothing computed so far holds a NaN.
TEST(ElasticCorrespondence, ShapeTensorSingularAfterBondBreakageStopsTheRun) {
  Teuchos::ParameterList p;
  p.set("Damage Model", "Critical Stretch");
  p.set("Critical Stretch", 0.5);
  ListReader r(p, "Damage Models -> CS");
  std::shared_ptr<DamageModel> damage = createDamageModel(r);
  Problem pr(lattice(5), 1.75, correspondenceModel("Elastic Correspondence", 0.05), damage);
  pr.evaluator->evaluate(1.0);  // intact: fine
  // Break every bond of point 62 (the centre) except those along x.
  const int c = pr.local(62);
  float* d = pr.fields->bondFloat("Bond_Damage").data();
  const double* x = pr.fields->node("Model_Coordinates", 3);
  for (auto b = pr.topology.bondOffsets[c]; b < pr.topology.bondOffsets[c + 1]; ++b) {
    const int j = pr.topology.neighbors[b];
    if (x[3 * j + 1] != x[3 * c + 1] || x[3 * j + 2] != x[3 * c + 2]) d[b] = 1.0f;
  }
  try {
    for (auto& b : pr.blocks) b.material->precompute(pr.evaluator->state(), b.points);
    FAIL() << "a singular shape tensor must stop the run";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("point 63 at (2, 2, 2) (2 intact bonds of"), std::string::npos) << what;
    EXPECT_NE(what.find("became singular"), std::string::npos) << what;
  }
  for (const char* name : {"Deformation_Gradient", "Cauchy_Stress", "Shape_Tensor_Inverse"})
    for (int k = 0; k < 9 * pr.topology.numOwned; ++k)
      ASSERT_TRUE(std::isfinite(pr.fields->node(name, 9)[k])) << name;
  for (const char* name :
       {"Correspondence_A_Row_X", "Correspondence_A_Row_Y", "Correspondence_A_Row_Z"})
    for (int k = 0; k < 3 * pr.topology.numOwned; ++k)
      ASSERT_TRUE(std::isfinite(pr.fields->node(name, 3)[k])) << name;
}

// Uniaxial strain E_xx = g(t) loaded past yield, unloaded and reloaded in compression. With
// E^p = p diag(1, -1/2, -1/2), the trial deviator is 2 mu (g - 3p/2) (2/3) diag(1, -1/2, -1/2),
// its von Mises value 2 mu |g - 3p/2|, and the return dgamma = (2 mu |a| - sigma_y) / (3 mu +
// H) moves p by dgamma sign(a) and eps_p by dgamma: S_xx = lambda g + 2 mu (g - p).
void checkUniaxialPlasticity(const std::string& model, double H) {
  const double sigmaY = 1e-3;
  // H < 0: the perfectly plastic model, which has no "Hardening Modulus".
  Problem pr(lattice(kN), 3.015, correspondenceModel(model, 0.02, sigmaY, H));
  H = std::max(H, 0.0);
  const double yieldStrain = sigmaY / (2 * kG);
  double p = 0, eqps = 0, lastEqps = 0;
  int plasticSteps = 0;
  const int steps = 60;
  for (int n = 1; n <= steps; ++n) {
    // 0 -> 5 yield strains (n = 20) -> -5 (n = 60)
    const double e = n <= 20 ? 5 * yieldStrain * n / 20.0 : 5 * yieldStrain * (40 - n) / 20.0;
    const double F[9] = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1};
    deform(pr, F);
    const double g = e + 0.5 * e * e;
    const double a = g - 1.5 * p;
    const double yieldNow = sigmaY + H * eqps;
    if (2 * kG * std::abs(a) > yieldNow) {
      const double dgamma = (2 * kG * std::abs(a) - yieldNow) / (3 * kG + H);
      p += a > 0 ? dgamma : -dgamma;
      eqps += dgamma;
      ++plasticSteps;
    }
    const double SxxGold = kLambda * g + 2 * kG * (g - p);
    // S from the Cauchy output: S = J F^-1 sigma F^-T, here S_xx = sigma_xx / (1 + e).
    const double* sigma = nodeTensor(pr, "Cauchy_Stress", 9, kCentre);
    const double Sxx = sigma[0] / (1 + e), Syy = sigma[4] * (1 + e), Szz = sigma[8] * (1 + e);
    EXPECT_NEAR(Sxx, SxxGold, 1e-9 * sigmaY) << "step " << n;
    const double eq = *nodeTensor(pr, "Equivalent_Plastic_Strain", 1, kCentre);
    EXPECT_NEAR(eq, eqps, 1e-9 * yieldStrain) << "step " << n;
    EXPECT_GE(eq, lastEqps) << "plastic strain decreased at step " << n;
    lastEqps = eq;
    // On the yield surface after a plastic step: sqrt(3/2) |dev S| = sigma_Y + H eps_p.
    const double vm = std::abs(Sxx - 0.5 * (Syy + Szz));  // uniaxial: von Mises = |Sxx - Syy|
    if (2 * kG * std::abs(a) > yieldNow)
      EXPECT_NEAR(vm / (sigmaY + H * eq), 1.0, 1e-9) << "step " << n;
    else
      EXPECT_LE(vm, sigmaY + H * eq + 1e-12) << "step " << n;
  }
  EXPECT_GT(plasticSteps, 20);  // both ways past yield
  EXPECT_GT(eqps, 5 * yieldStrain);
}

TEST(ElasticPlasticCorrespondence, UniaxialStrainReturnMappingFollowsClosedForm) {
  checkUniaxialPlasticity("Elastic Plastic Correspondence", -1.0);
}

TEST(IsotropicHardeningCorrespondence, UniaxialStrainReturnMappingFollowsClosedForm) {
  checkUniaxialPlasticity("Isotropic Hardening Correspondence", 0.3);
}

TEST(IsotropicHardeningCorrespondence, FlawLowersTheYieldStressAroundItsCentre) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Isotropic Hardening Correspondence");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", kK);
  p.set("Shear Modulus", kG);
  p.set("Hourglass Coefficient", 0.0);
  p.set("Yield Stress", 2.0);
  p.set("Hardening Modulus", 0.0);
  p.set("Enable Flaw", true);
  p.set("Flaw Location X", 1.0);
  p.set("Flaw Location Y", 0.0);
  p.set("Flaw Location Z", 0.0);
  p.set("Flaw Size", 0.5);
  p.set("Flaw Magnitude", 0.25);
  ListReader r(p, "Materials -> M");
  auto m = createMaterial(r);
  auto* plastic = dynamic_cast<ElasticPlasticCorrespondence*>(m.get());
  ASSERT_NE(plastic, nullptr);
  const double centre[3] = {1, 0, 0}, away[3] = {1, 0.5, 0};
  EXPECT_DOUBLE_EQ(plastic->yieldStressAt(centre), 1.5);
  EXPECT_DOUBLE_EQ(plastic->yieldStressAt(away), 2.0 * (1 - 0.25 * std::exp(-1.0)));
}

TEST(ElasticCorrespondence, HourglassCoefficientIsRequired) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic Correspondence");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", kK);
  p.set("Shear Modulus", kG);
  ListReader r(p, "Materials -> M");
  try {
    createMaterial(r);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Hourglass Coefficient"), std::string::npos);
  }
}

}  // namespace
}  // namespace peridot
