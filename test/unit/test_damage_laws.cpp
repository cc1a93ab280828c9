// DTT (paper 002) and LSJ-T (paper 001) damage laws and the Linearized LPS material: the
// functions at and between their breakpoints, the bond histories, the symmetry of the two ends
// of a bond, homogeneous energies of the linearized model (3D, plane stress, plane strain) and
// the consistency of its force with its energy.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>

#include "SerialProblem.hpp"
#include "core/Error.hpp"
#include "damage/DTT.hpp"
#include "damage/LSJT.hpp"
#include "materials/LinearizedLPS.hpp"

namespace peridot {
namespace {

using testing::Problem;

std::shared_ptr<DamageModel> dtt(double sc, double f0 = 0.95, double f1 = 1.05) {
  Teuchos::ParameterList p;
  p.set("Damage Model", "DTT");
  p.set("Critical Stretch", sc);
  p.set("S0 Plus Over Critical Stretch", f0);
  p.set("S1 Plus Over Critical Stretch", f1);
  ListReader r(p, "Damage Models -> D");
  return createDamageModel(r);
}

std::shared_ptr<DamageModel> lsjt(double sc) {
  Teuchos::ParameterList p;
  p.set("Damage Model", "LSJ-T");
  p.set("Critical Stretch", sc);
  ListReader r(p, "Damage Models -> D");
  return createDamageModel(r);
}

std::shared_ptr<MaterialModel> linearized(double E, double nu, const std::string& plane = "") {
  Teuchos::ParameterList p;
  p.set("Material Model", "Linearized LPS");
  p.set("Density", 1.0);
  p.set("Young's Modulus", E);
  p.set("Poisson's Ratio", nu);
  if (!plane.empty()) p.set(plane, true);
  ListReader r(p, "Materials -> M");
  return createMaterial(r);
}

std::shared_ptr<MaterialModel> lps(double E, double nu, const std::string& plane = "") {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic");
  p.set("Density", 1.0);
  p.set("Young's Modulus", E);
  p.set("Poisson's Ratio", nu);
  if (!plane.empty()) p.set(plane, true);
  ListReader r(p, "Materials -> M");
  return createMaterial(r);
}

BondLaw smoothLaw() {
  BondLaw law;
  law.kind = BondLaw::Kind::Smooth;
  law.s1Minus = -0.99;
  law.s0Minus = -0.98;
  law.s0Plus = 0.95e-3;
  law.s1Plus = 1.05e-3;
  return law;
}

// ---- F and p (paper 002 eqs. 6 and 14) ----

TEST(DTTForceLaw, ForceScalarAtAndBetweenBreakpoints) {
  const BondLaw law = smoothLaw();
  EXPECT_EQ(law.forceScalar(0.0), 0.0);
  EXPECT_EQ(law.forceScalar(0.5e-3), 0.5e-3);             // linear part
  EXPECT_EQ(law.forceScalar(0.95e-3), 0.95e-3);           // S0+: top of the linear part
  EXPECT_NEAR(law.forceScalar(1.0e-3), 0.475e-3, 1e-18);  // half way down: S0+/2
  EXPECT_NEAR(law.forceScalar(1.05e-3), 0.0, 1e-18);      // S1+
  EXPECT_EQ(law.forceScalar(2e-3), 0.0);
  EXPECT_EQ(law.forceScalar(-0.5), -0.5);
  EXPECT_EQ(law.forceScalar(-0.98), -0.98);            // S0-
  EXPECT_NEAR(law.forceScalar(-0.985), -0.49, 1e-12);  // half way: S0-/2
  EXPECT_NEAR(law.forceScalar(-0.99), 0.0, 1e-15);     // S1-
  EXPECT_EQ(law.forceScalar(-0.995), 0.0);
  // Continuity: no jump anywhere on a fine sweep (the largest step of F is the sweep step over
  // the steepest slope, S0+/(S1+ - S0+) = 9.5).
  double previous = law.forceScalar(-1.0);
  const double step = 1e-7;
  for (double s = -1.0 + step; s < 3e-3; s += step) {
    const double f = law.forceScalar(s);
    ASSERT_LE(std::fabs(f - previous), 98.0 * step + 1e-15) << "s = " << s;
    previous = f;
  }
}

TEST(DTTForceLaw, PotentialIsTheIntegralOfF) {
  const BondLaw law = smoothLaw();
  EXPECT_EQ(law.potential(0.0), 0.0);
  EXPECT_DOUBLE_EQ(law.potential(0.5e-3), 0.125e-6);
  // Beyond S1+ the area under F: the triangle 1/2 S0+ S1+ (by hand).
  EXPECT_NEAR(law.potential(1.05e-3), 0.5 * 0.95e-3 * 1.05e-3, 1e-20);
  EXPECT_NEAR(law.potential(5e-3), 0.5 * 0.95e-3 * 1.05e-3, 1e-20);
  // Below S1-: 1/2 S0- S1-.
  EXPECT_NEAR(law.potential(-0.995), 0.5 * 0.98 * 0.99, 1e-14);
  // p' = F (central differences inside each piece) and p >= 0.
  for (double s : {-0.9875, -0.983, -0.5, 1e-4, 0.9e-3, 0.97e-3, 1.0e-3, 1.04e-3, 2e-3}) {
    const double h = 1e-9 * std::max(1e-3, std::fabs(s));
    const double dp = (law.potential(s + h) - law.potential(s - h)) / (2 * h);
    EXPECT_NEAR(dp, law.forceScalar(s), 1e-6 * std::max(1e-3, std::fabs(s))) << "s = " << s;
    EXPECT_GE(law.potential(s), 0.0);
  }
  // Continuous at the breakpoints.
  for (double s : {-0.99, -0.98, 0.95e-3, 1.05e-3}) {
    EXPECT_NEAR(law.potential(s * (1 + 1e-12)), law.potential(s * (1 - 1e-12)),
                1e-9 * law.potential(s));
  }
}

// ---- mu (paper 002 eq. 6) ----

TEST(DTTDamageFactor, AtAndBetweenBreakpointsNonincreasingContinuous) {
  const double sc = 1e-3;
  auto model = std::dynamic_pointer_cast<DTT>(dtt(sc));
  ASSERT_TRUE(model);
  EXPECT_EQ(model->damageFactor(-0.5), 1.0);
  EXPECT_EQ(model->damageFactor(0.0), 1.0);
  EXPECT_EQ(model->damageFactor(0.9e-3), 1.0);
  EXPECT_EQ(model->damageFactor(0.95e-3), 1.0);
  EXPECT_NEAR(model->damageFactor(1.0e-3), 0.5, 1e-12);
  EXPECT_NEAR(model->damageFactor(1.025e-3), 0.25, 1e-12);
  EXPECT_NEAR(model->damageFactor(1.05e-3), 0.0, 1e-12);  // S1+ = 1.05 x 1e-3 rounded
  EXPECT_EQ(model->damageFactor(1.0), 0.0);
  double previous = 1.0;
  for (double s = 0.0; s < 2e-3; s += 1e-8) {
    const double mu = model->damageFactor(s);
    ASSERT_LE(mu, previous) << s;
    ASSERT_LE(previous - mu, 1e-8 / 0.1e-3 + 1e-12) << s;  // slope 1 / (S1+ - S0+)
    previous = mu;
  }
  const BondLaw law = model->bondLaw();
  EXPECT_EQ(law.kind, BondLaw::Kind::Smooth);
  EXPECT_DOUBLE_EQ(law.s0Plus, 0.95e-3);
  EXPECT_DOUBLE_EQ(law.s1Plus, 1.05e-3);
  EXPECT_EQ(law.s0Minus, -0.98);
  EXPECT_EQ(law.s1Minus, -0.99);
}

TEST(DTTParameters, InvalidThresholdsAreRejected) {
  auto make = [](const std::vector<std::pair<std::string, double>>& keys) {
    Teuchos::ParameterList p;
    p.set("Damage Model", "DTT");
    for (const auto& kv : keys) p.set(kv.first, kv.second);
    ListReader r(p, "Damage Models -> D");
    return createDamageModel(r);
  };
  EXPECT_NO_THROW(make({{"Critical Stretch", 1e-3}}));
  EXPECT_THROW(make({}), InputError);
  EXPECT_THROW(make({{"Critical Stretch", 1e-3}, {"Fracture Energy", 1.0}}), InputError);
  EXPECT_THROW(make({{"Critical Stretch", -1e-3}}), InputError);
  EXPECT_THROW(make({{"Critical Stretch", 1e-3}, {"S0 Plus Over Critical Stretch", 1.1}}),
               InputError);
  EXPECT_THROW(make({{"Critical Stretch", 1e-3}, {"S0 Plus Over Critical Stretch", -0.1}}),
               InputError);
  EXPECT_THROW(make({{"Critical Stretch", 1e-3}, {"S1 Plus Over Critical Stretch", 0.99}}),
               InputError);
  EXPECT_THROW(make({{"Critical Stretch", 1e-3},
                     {"S0 Plus Over Critical Stretch", 1.0},
                     {"S1 Plus Over Critical Stretch", 1.0}}),
               InputError);
  EXPECT_THROW(make({{"Critical Stretch", 1e-3}, {"S0 Minus", 0.1}}), InputError);
  EXPECT_THROW(make({{"Critical Stretch", 1e-3}, {"S0 Minus", -1.0}}), InputError);
  EXPECT_THROW(make({{"Critical Stretch", 1e-3}, {"S1 Minus", -0.97}}), InputError);
  EXPECT_THROW(make({{"Critical Stretch", 1e-3}, {"S1 Minus", -1.0}}), InputError);
  EXPECT_THROW(make({{"Critical Stretch", 1e-3}, {"S1 Plus", 1.0}}), InputError);  // unknown key
  // The degenerate window S0+ = S_c = S1+ is the original PMB rule; it is excluded (S0+ < S1+).
  EXPECT_NO_THROW(make({{"Critical Stretch", 1e-3},
                        {"S0 Plus Over Critical Stretch", 0.0},
                        {"S1 Plus Over Critical Stretch", 3.0},
                        {"S0 Minus", -0.5},
                        {"S1 Minus", -0.6}}));
}

// ---- the DTT bond history ----

// Two points pulled apart along a stretch history that rises into the window, falls back and
// rises again: the bond damage is 1 - mu(S*) with S* the running maximum kept in double, bit for
// bit, never decreases, and moves continuously with the stretch.
TEST(DTTHistory, BondDamageIsOneMinusMuOfTheMaximumStretch) {
  const double sc = 1e-3;
  auto model = dtt(sc);
  auto dttModel = std::dynamic_pointer_cast<DTT>(model);
  Problem pr({{0, 0, 0}, {1, 0, 0}}, 1.5, linearized(1.0, 0.25), model);
  const float* damage = pr.fields->bondFloat("Bond_Damage").data();
  double* y = pr.fields->node("Coordinates", 3);
  const int right = pr.local(1);
  std::vector<double> stretches;
  for (int k = 0; k <= 100; ++k) stretches.push_back(0.9e-3 + 1e-6 * k);  // to 1.0e-3
  for (int k = 0; k <= 100; ++k) stretches.push_back(1.0e-3 - 2e-6 * k);  // back to 0.8e-3
  for (int k = 0; k <= 300; ++k) stretches.push_back(0.8e-3 + 1e-6 * k);  // on to 1.1e-3
  double sStar = -1, previous = 0;
  for (double s : stretches) {
    y[3 * right] = 1.0 + s;
    pr.evaluator->evaluate(1.0);
    sStar = std::max(sStar, s);
    const float expected = static_cast<float>(1.0 - dttModel->damageFactor(sStar));
    // The stretch the kernel forms from the coordinates differs from s by round-off only.
    ASSERT_NEAR(damage[0], expected, 1e-6) << "s = " << s;
    ASSERT_EQ(damage[0], damage[1]) << "the two ends disagree at s = " << s;
    ASSERT_GE(damage[0], previous);
    ASSERT_LE(damage[0] - previous, 2e-6 / 0.1e-3 + 1e-6) << "jump at s = " << s;
    previous = damage[0];
  }
  EXPECT_EQ(damage[0], 1.0f);
  // Half way back down the history the damage stayed at 1 - mu(1e-3) = 0.5.
}

// Keeping S* in double and rounding 1 - mu(S*) to float gives the same bits as keeping the
// running maximum of the rounded 1 - mu(s): the identity that makes the bond damage the history.
TEST(DTTHistory, RunningMaximumOfDamageEqualsDamageOfRunningMaximum) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.8e-3, 1.2e-3);
  const double s0 = 0.95e-3, s1 = 1.05e-3;
  double sStar = -1;
  float d = 0;
  for (int k = 0; k < 200000; ++k) {
    const double s = u(rng);
    sStar = std::max(sStar, s);
    d = std::max(d, static_cast<float>(dttBrokenFraction(s, s0, s1)));
    ASSERT_EQ(d, static_cast<float>(dttBrokenFraction(sStar, s0, s1))) << k;
  }
}

// Every bond of a random cloud with random displacements: both ends hold the same damage, bit for
// bit (they form the same stretch from the same coordinates), and some bonds are partly broken.
TEST(DTTHistory, BothEndsOfEveryBondAgreeBitwise) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(0.0, 4.0), disp(-0.01, 0.01);
  std::vector<std::array<double, 3>> pts;
  for (int k = 0; k < 120; ++k) pts.push_back({pos(rng), pos(rng), pos(rng)});
  const double sc = 4e-3;
  Problem pr(pts, 1.6, linearized(1.0, 0.25), dtt(sc));
  double* y = pr.fields->node("Coordinates", 3);
  for (int step = 0; step < 3; ++step) {
    for (int k = 0; k < 3 * pr.topology.numOwned; ++k) y[k] += disp(rng);
    pr.evaluator->evaluate(1.0);
  }
  const float* damage = pr.fields->bondFloat("Bond_Damage").data();
  const auto& t = pr.topology;
  int partial = 0, checked = 0;
  for (int i = 0; i < t.numOwned; ++i)
    for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
      const int j = t.neighbors[b];
      std::int64_t r = t.bondOffsets[j];
      while (r < t.bondOffsets[j + 1] && t.neighbors[r] != i) ++r;
      ASSERT_LT(r, t.bondOffsets[j + 1]);
      ASSERT_EQ(damage[b], damage[r]) << i << " " << j;
      ++checked;
      if (damage[b] > 0 && damage[b] < 1) ++partial;
    }
  EXPECT_GT(checked, 500);
  EXPECT_GT(partial, 10);  // the window was crossed, or the symmetry proves little
}

// ---- LSJ-T (paper 001 eqs. 19-20) ----

TEST(LSJTFunctions, RateAndDamageFactorAtAndBetweenBreakpoints) {
  const double sc = 2e-3;
  EXPECT_EQ(lsjtOverstretchRate(0.0, sc), 0.0);
  EXPECT_EQ(lsjtOverstretchRate(-1.0, sc), 0.0);
  EXPECT_EQ(lsjtOverstretchRate(0.999 * sc, sc), 0.0);
  EXPECT_EQ(lsjtOverstretchRate(sc, sc), 0.0);  // continuous at S_c
  EXPECT_NEAR(lsjtOverstretchRate(2 * sc, sc), 1.0 / 33.0, 1e-15);
  EXPECT_NEAR(lsjtOverstretchRate(1.05 * sc, sc), 3.125e-7 / (1 + 1.2762815625), 1e-18);
  EXPECT_NEAR(lsjtOverstretchRate(3 * sc, sc), 32.0 / 244.0, 1e-14);
  double previous = 0;
  for (double x = sc; x < 3 * sc; x += 1e-3 * sc) {
    const double j = lsjtOverstretchRate(x, sc);
    ASSERT_GE(j, previous);
    previous = j;
  }
  const double xc = 1e-10;
  EXPECT_EQ(lsjtDamageFactor(-1.0, xc), 1.0);
  EXPECT_EQ(lsjtDamageFactor(0.0, xc), 1.0);
  EXPECT_NEAR(lsjtDamageFactor(1e-6 * xc, xc), 1.0, 1e-11);  // continuous at 0
  EXPECT_NEAR(lsjtDamageFactor(0.5 * xc, xc), std::exp(1.0 - 1.0 / (1.0 - std::pow(0.5, 2.01))),
              1e-15);
  EXPECT_NEAR(lsjtDamageFactor(0.5 * xc, xc), 0.7187294, 1e-7);  // by hand (python)
  EXPECT_LT(lsjtDamageFactor(0.999 * xc, xc), 1e-200);           // continuous at x_c
  EXPECT_EQ(lsjtDamageFactor(xc, xc), 0.0);
  EXPECT_EQ(lsjtDamageFactor(2 * xc, xc), 0.0);
  previous = 1.0;
  for (double x = 0; x < xc; x += 1e-3 * xc) {
    const double h = lsjtDamageFactor(x, xc);
    ASSERT_LE(h, previous);
    previous = h;
  }
}

// The history integral sums dt j_s(eps) over the steps after the first (initial) evaluation,
// persists when the bond relaxes, and the damage follows h of it.
TEST(LSJTHistory, IntegralAccumulatesAndPersists) {
  const double sc = 1e-3, dt = 1e-2;
  auto model = lsjt(sc);
  Problem pr({{0, 0, 0}, {1, 0, 0}}, 1.5, linearized(1.0, 0.25), model);
  double* y = pr.fields->node("Coordinates", 3);
  const float* damage = pr.fields->bondFloat("Bond_Damage").data();
  const int right = pr.local(1);
  const double eps = 1.02 * sc;
  y[3 * right] = 1.0 + eps;
  pr.evaluator->evaluate(dt);  // the initial state: nothing accumulates
  const std::vector<double>& X = pr.fields->bond(LSJT::kHistoryIntegral);
  EXPECT_EQ(X[0], 0.0);
  EXPECT_EQ(damage[0], 0.0f);
  // By hand: j_s(1.02 S_c) = 0.02^5 / (1 + 1.02^5) = 3.2e-9 / 2.1040808032.
  const double rate = 3.2e-9 / 2.1040808032;
  const double xc = 3.125e-7 / 2.2762815625 * dt;
  for (int n = 1; n <= 20; ++n) {
    pr.evaluator->evaluate(dt);
    ASSERT_NEAR(X[0], n * dt * rate, 1e-6 * n * dt * rate) << n;
    ASSERT_EQ(X[0], X[1]) << "the two ends disagree at step " << n;
    ASSERT_EQ(damage[0], damage[1]);
    ASSERT_NEAR(damage[0], 1.0 - lsjtDamageFactor(n * dt * rate, xc), 1e-5) << n;
  }
  // 20 steps at 1.02 S_c: X = 20 x 1.52e-9 dt = 0.222 x_c, mu~ = exp(1 - 1/(1 - 0.222^2.01)).
  EXPECT_NEAR(damage[0], 1.0 - std::exp(1.0 - 1.0 / (1.0 - std::pow(20 * rate / (xc / dt), 2.01))),
              1e-5);
  EXPECT_GT(damage[0], 0.01);
  const double held = X[0];
  const float heldDamage = damage[0];
  y[3 * right] = 1.0 + 0.5 * sc;  // relax: the history stays
  for (int n = 0; n < 10; ++n) pr.evaluator->evaluate(dt);
  EXPECT_EQ(X[0], held);
  EXPECT_EQ(damage[0], heldDamage);
  // One step at 1.1 S_c > 1.05 S_c adds more than x_c: broken for good.
  y[3 * right] = 1.0 + 1.1 * sc;
  pr.evaluator->evaluate(dt);
  EXPECT_EQ(damage[0], 1.0f);
  y[3 * right] = 1.0;
  pr.evaluator->evaluate(dt);
  EXPECT_EQ(damage[0], 1.0f);
  // and the broken bond carries no force
  EXPECT_EQ(pr.force(0)[0], 0.0);
}

// ---- Linearized LPS: homogeneous energies ----

// SerialProblem with a planar evaluator (points in z = 0, volumes with the thickness).
testing::Problem planarProblem(const std::vector<std::array<double, 3>>& points, double horizon,
                               std::shared_ptr<MaterialModel> material, const PeriodicBox& periodic,
                               double volume, double thickness) {
  return testing::Problem(points, horizon, std::move(material), nullptr, periodic, volume, "One",
                          thickness);
}

// A plane-stress material on a 3D discretization is refused.
TEST(LinearizedLPSEnergy, PlaneModeMustMatchTheDiscretization) {
  EXPECT_THROW(Problem({{0, 0, 0}, {1, 0, 0}}, 1.5, linearized(1.0, 0.2, "Plane Stress")),
               InputError);
  EXPECT_THROW(
      planarProblem({{0, 0, 0}, {1, 0, 0}}, 1.5, linearized(1.0, 0.2), PeriodicBox(), 1.0, 1.0),
      InputError);
}

// Energy density at the centre of a periodic lattice (3D, or one layer of a planar lattice with
// cell volume 1 x 1 x thickness) under displacement gradient H.
double centreEnergy(std::shared_ptr<MaterialModel> material, double delta, const double H[3][3],
                    bool planar, double thickness = 1.0) {
  const int n = 2 * static_cast<int>(std::ceil(delta)) + 3;
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < (planar ? 1 : n); ++k) pts.push_back({double(i), double(j), double(k)});
  PeriodicBox box;
  for (int d = 0; d < (planar ? 2 : 3); ++d) {
    box.periodic[d] = true;
    box.lower[d] = -0.5;
    box.upper[d] = n - 0.5;
  }
  if (planar) {
    auto pr = planarProblem(pts, delta, material, box, thickness, thickness);
    return pr.energyDensityUnder(H);
  }
  Problem pr(pts, delta, material, nullptr, box);
  return pr.energyDensityUnder(H);
}

// 3D: the dilatation energy 9 K s^2 / 2 is exact on any lattice; under simple shear and a general
// small strain the linearized model stores what the (nonlinear) LPS stores, to first order in
// the strain — which checks c1 and c2 against Silling's constants.
TEST(LinearizedLPSEnergy, ThreeDDilatationExactAndEqualToLPSForSmallStrains) {
  // The linearized energy is exactly quadratic: a large strain keeps the round-off of
  // eta = (y_j - y_i) - xi small; the comparison with the nonlinear LPS needs a small one.
  const double E = 3.0, s = 1e-3, g = 1e-7;
  const double dil[3][3] = {{s, 0, 0}, {0, s, 0}, {0, 0, s}};
  const double general[3][3] = {{g, 2 * g, -g}, {0.5 * g, -3 * g, g}, {g, 0.3 * g, 2 * g}};
  for (double nu : {0.1, 0.22, 0.25, 0.3, 0.45}) {
    const double K = E / (3 * (1 - 2 * nu));
    const double w = centreEnergy(linearized(E, nu), 3.015, dil, false);
    EXPECT_NEAR(w / (4.5 * K * s * s), 1.0, 1e-9) << "nu " << nu;
    const double wLin = centreEnergy(linearized(E, nu), 3.015, general, false);
    const double wLPS = centreEnergy(lps(E, nu), 3.015, general, false);
    EXPECT_NEAR(wLin / wLPS, 1.0, 1e-5) << "nu " << nu;
  }
}

// 2D: dilatation s I exact; pure shear: the mean of the axis-aligned and the 45-degree modes is
// the isotropic value 2 G g^2 on a square lattice (its fourth moment varies as cos 4 phi).
TEST(LinearizedLPSEnergy, PlaneStressAndPlaneStrainDilatationAndShear) {
  const double E = 72e9, s = 1e-6, g = 1e-6, thickness = 0.25;
  const double dil[3][3] = {{s, 0, 0}, {0, s, 0}, {0, 0, 0}};
  const double axis[3][3] = {{g, 0, 0}, {0, -g, 0}, {0, 0, 0}};
  const double diag[3][3] = {{0, g, 0}, {g, 0, 0}, {0, 0, 0}};
  for (double nu : {0.1, 0.22, 1.0 / 3.0, 0.4}) {
    const double G = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double lambdaStress = E * nu / (1 - nu * nu);
    for (const std::string plane : {"Plane Stress", "Plane Strain"}) {
      const double lam = plane == "Plane Stress" ? lambdaStress : lambda;
      for (double delta : {3.015, 4.015}) {
        const double wDil = centreEnergy(linearized(E, nu, plane), delta, dil, true, thickness);
        EXPECT_NEAR(wDil / (2 * (lam + G) * s * s), 1.0, 1e-9) << plane << " nu " << nu;
        const double wAxis = centreEnergy(linearized(E, nu, plane), delta, axis, true, thickness);
        const double wDiag = centreEnergy(linearized(E, nu, plane), delta, diag, true, thickness);
        EXPECT_NEAR(0.5 * (wAxis + wDiag) / (2 * G * g * g), 1.0, 1e-9) << plane << " nu " << nu;
        // And the two modes do differ (the lattice is not isotropic), so the mean is informative.
        EXPECT_GT(std::fabs(wAxis - wDiag) / (wAxis + wDiag), 1e-3);
        // A general small strain: the same energy as the (nonlinear) 2D LPS of the materials,
        // derived independently (Le et al.), to first order in the strain.
        const double t = 1e-7;
        const double general[3][3] = {{t, 2 * t, 0}, {-0.5 * t, -3 * t, 0}, {0, 0, 0}};
        const double wLin = centreEnergy(linearized(E, nu, plane), delta, general, true, thickness);
        const double wLPS = centreEnergy(lps(E, nu, plane), delta, general, true, thickness);
        EXPECT_NEAR(wLin / wLPS, 1.0, 1e-5) << plane << " nu " << nu;
      }
    }
  }
  // Paper 001's c1 (plane stress) vanishes at nu = 1/3, where the model is bond-based.
  auto m = std::dynamic_pointer_cast<LinearizedLPS>(linearized(E, 1.0 / 3.0, "Plane Stress"));
  EXPECT_NEAR(m->c1(), 0.0, 1e-6);
}

// ---- Fracture energy -> critical stretch (the shared FractureEnergy formulas) ----

TEST(DamageLawFractureEnergy, DTTAndLSJTDeriveTheCriticalStretchPerBlock) {
  const double G0 = 3.8, delta = 1e-3, E = 72e9, nu = 0.22;
  for (const std::string model : {"DTT", "LSJ-T"}) {
    auto make = [&]() {
      Teuchos::ParameterList p;
      p.set("Damage Model", model);
      p.set("Fracture Energy", G0);
      ListReader r(p, "Damage Models -> D");
      return createDamageModel(r);
    };
    auto stretchOf = [](const std::shared_ptr<DamageModel>& d) {
      if (auto m = std::dynamic_pointer_cast<DTT>(d)) return m->criticalStretch();
      return std::dynamic_pointer_cast<LSJT>(d)->criticalStretch();
    };
    std::ostringstream log;
    // Paper 001 eq. (24), LPS-T / LSJ-T in plane stress with omega = (1 - zeta/delta)/zeta.
    auto planeStress = linearized(E, nu, "Plane Stress");
    planeStress->setInfluenceFunction("Conical Over Zeta");
    std::shared_ptr<DamageModel> d = make();
    ASSERT_TRUE(d->bindsToBlock());
    d->bind(*planeStress, delta, "block_1", log);
    const double pi = 3.14159265358979323846;
    EXPECT_NEAR(stretchOf(d), std::sqrt(5 * (1 + nu) * pi * G0 / (12 * E * delta)), 1e-12) << model;
    // The same for the LPS-T material (Elastic), which has the same bond term.
    auto lpsT = lps(E, nu, "Plane Stress");
    lpsT->setInfluenceFunction("Conical Over Zeta");
    std::shared_ptr<DamageModel> d2 = make();
    d2->bind(*lpsT, delta, "block_1", log);
    EXPECT_DOUBLE_EQ(stretchOf(d2), stretchOf(d)) << model;
    // 3D, omega = 1: G0 = pi alpha s^2 J5 with alpha = 15 G / (4 pi J4): s = sqrt(8 G0 / (25 G
    // delta)).
    std::shared_ptr<DamageModel> d3 = make();
    d3->bind(*linearized(E, nu), delta, "block_1", log);
    const double G = E / (2 * (1 + nu));
    EXPECT_NEAR(stretchOf(d3), std::sqrt(8 * G0 / (25 * G * delta)), 1e-12) << model;
    EXPECT_NE(log.str().find("Critical stretch of block block_1"), std::string::npos);
    // A variable horizon has no formula.
    EXPECT_THROW(make()->bind(*linearized(E, nu), -1.0, "block_1", log), InputError);
  }
}

// ---- Linearized LPS: force = -gradient of the stored energy ----

// A random cloud, random displacements, bond damage 0 or 1 at random (where eq. 18's mu^2 on the
// dilatation term equals mu) and the linear or the smooth law: V_k f_k = -dE/du_k with
// E = sum V W, by central differences.
void checkForceIsMinusGradient(const std::function<std::shared_ptr<MaterialModel>()>& makeMaterial,
                               bool binaryDamage, const std::string& name) {
  for (bool smooth : {false, true}) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> pos(0.0, 3.0), disp(-2e-3, 2e-3), unit(0, 1);
    std::vector<std::array<double, 3>> pts;
    for (int k = 0; k < 40; ++k) pts.push_back({pos(rng), pos(rng), pos(rng)});
    // A damage model only to have the bond damage array; its S_c is never reached (linear) or
    // it supplies the smooth law with a window the random stretches cross.
    std::shared_ptr<DamageModel> damage = smooth ? dtt(1e-3, 0.3, 1.5) : dtt(1.0);
    Problem pr(pts, 1.4, makeMaterial(), damage);
    double* y = pr.fields->node("Coordinates", 3);
    for (int k = 0; k < 3 * pr.topology.numOwned; ++k) y[k] += disp(rng);
    pr.evaluator->evaluate(1.0);  // the smooth law sets some damages in (0, 1): round them
    float* d = pr.fields->bondFloat("Bond_Damage").data();
    const auto& t = pr.topology;
    for (int i = 0; i < t.numOwned; ++i)
      for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
        const int j = t.neighbors[b];
        if (j < i) continue;
        const float value = binaryDamage ? (unit(rng) < 0.2 ? 1.0f : 0.0f)
                                         : static_cast<float>(unit(rng) < 0.5 ? 0.0 : unit(rng));
        d[b] = value;
        for (std::int64_t r = t.bondOffsets[j]; r < t.bondOffsets[j + 1]; ++r)
          if (t.neighbors[r] == i) d[r] = value;
      }
    auto material = pr.blocks[0].material;
    ModelState state = pr.evaluator->state();
    state.bondLaw = damage->bondLaw();
    std::vector<int> all = pr.blocks[0].points;
    auto energy = [&]() {
      material->precompute(state, all);
      std::vector<double> w(t.numOwned);
      material->storedEnergyDensity(state, all, w.data());
      double e = 0;
      for (int i = 0; i < t.numOwned; ++i) e += w[i];  // unit volumes
      return e;
    };
    material->precompute(state, all);
    material->computeForce(state, all);
    std::vector<double> f(state.forceDensity, state.forceDensity + 3 * t.numOwned);
    double worst = 0, scale = 0;
    for (int i = 0; i < t.numOwned; i += 3)
      for (int a = 0; a < 3; ++a) {
        const double h = 1e-7, keep = y[3 * i + a];
        y[3 * i + a] = keep + h;
        const double ep = energy();
        y[3 * i + a] = keep - h;
        const double em = energy();
        y[3 * i + a] = keep;
        worst = std::max(worst, std::fabs(-(ep - em) / (2 * h) - f[3 * i + a]));
        scale = std::max(scale, std::fabs(f[3 * i + a]));
      }
    ASSERT_GT(scale, 0.0);
    EXPECT_LT(worst, 1e-6 * scale) << name << ", " << (smooth ? "smooth" : "linear") << " law";
  }
}

TEST(LinearizedLPSForce, IsMinusTheGradientOfTheStoredEnergy) {
  checkForceIsMinusGradient([] { return linearized(2.0, 0.2); }, true, "Linearized LPS");
  // At nu = 1/4 (c1 = 0) eq. 18 is variational for any damage in [0, 1].
  checkForceIsMinusGradient([] { return linearized(2.0, 0.25); }, false, "Linearized LPS nu 1/4");
}

// The same check on the materials branch's smooth-law kernels (PMB, LPS-T), with partial
// damage: the energy balance of Theorem 4 needs force = -grad (stored energy).
TEST(SmoothLawMaterials, ForceIsMinusTheGradientOfTheStoredEnergy) {
  checkForceIsMinusGradient(
      [] {
        Teuchos::ParameterList p;
        p.set("Material Model", "Elastic Bond Based");
        p.set("Density", 1.0);
        p.set("Bulk Modulus", 2.0);
        ListReader r(p, "Materials -> M");
        return createMaterial(r);
      },
      false, "PMB");
  checkForceIsMinusGradient([] { return lps(2.0, 0.25); }, false, "LPS-T nu 1/4");
}

}  // namespace
}  // namespace peridot
