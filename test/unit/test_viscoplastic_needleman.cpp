// "Viscoplastic Needleman Correspondence" on a 7^3 lattice driven by prescribed homogeneous
// motions (every point's F and velocity gradient are then exact, so every point follows the
// continuum law). Golds are computed here, independently of the model's code:
//  - the continuum law under uniaxial stretch as an ODE in the mean stress p, the signed von
//    Mises stress q (deviator q diag(2/3, -1/3, -1/3)) and eps_p, integrated by RK4 on a grid
//    10^3 times finer than the model's steps:
//      p' = K D,  q' = 2 mu D - 3 mu sign(q) epsdot_p,  D = edot / (1 + e),
//      epsdot_p = epsdot_0 (|q| / g(eps_p))^(1/m) where |q| >= sigma_Y, else 0;
//  - the model's time-discrete scheme as a scalar recursion (backward Euler, d_xx dt = De / (1 +
//    e_n+1); test/common/NeedlemanGold.hpp), its return solved for the new stress by bisection
//    (the model solves for the plastic increment by Newton).
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "Materials.hpp"
#include "NeedlemanGold.hpp"
#include "SerialProblem.hpp"
#include "core/Error.hpp"
#include "materials/Correspondence.hpp"
#include "materials/ViscoplasticNeedlemanCorrespondence.hpp"

namespace peridot {
namespace {

using testing::Problem;

const double kK = 2.0, kG = 1.0;
const double kLambda = kK - 2.0 * kG / 3.0;
const int kN = 7;
const long long kCentre = 3 * kN * kN + 3 * kN + 3;
const double kHorizon = 2.015;

using Law = testing::NeedlemanLaw;
using testing::Uniaxial;

double hardening(const Law& l, double e) { return testing::needlemanHardening(l, e); }

Teuchos::ParameterList deck(const Law& l) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Viscoplastic Needleman Correspondence");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", kK);
  p.set("Shear Modulus", kG);
  p.set("Hourglass Coefficient", 0.02);
  p.set("Yield Stress", l.sigmaY);
  p.set("Strain Hardening Exponent", l.N);
  p.set("Rate Hardening Exponent", l.m);
  p.set("Reference Strain Rate", l.rate0);
  p.set("Reference Strain 0", l.eps0);
  p.set("Reference Strain 1", l.eps1);
  return p;
}

std::shared_ptr<MaterialModel> model(const Law& l) {
  Teuchos::ParameterList p = deck(l);
  ListReader r(p, "Materials -> M");
  return createMaterial(r);
}

const double* at(Problem& pr, const char* name, int components = 9) {
  return pr.fields->node(name, components) + components * pr.local(kCentre);
}

// Uniaxial stretch F = diag(1 + e, 1, 1) to e at the end of step n, moving at edot.
void stretchTo(Problem& pr, double e, double edot, double dt) {
  const double F[9] = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1};
  const double Fdot[9] = {edot, 0, 0, 0, 0, 0, 0, 0, 0};
  pr.evaluateAffine(F, Fdot, dt);
}

bool discreteStep(const Law& l, Uniaxial& u, double delta, double dt) {
  return testing::needlemanStep(l, kK, kG, u, delta, dt);
}

// The continuum ODE by RK4 from t0 to t1 in `substeps` steps along e(t) = e0 + edot (t - t0).
void integrateODE(const Law& l, Uniaxial& u, double e0, double edot, double t0, double t1,
                  int substeps) {
  auto rhs = [&](double t, const double y[3], double out[3]) {
    const double D = edot / (1 + e0 + edot * (t - t0));
    const double qa = std::abs(y[1]);
    const double flow =
        qa >= l.sigmaY ? l.rate0 * std::pow(qa / hardening(l, y[2]), 1.0 / l.m) : 0.0;
    out[0] = kK * D;
    out[1] = 2 * kG * D - 3 * kG * (y[1] > 0 ? flow : -flow);
    out[2] = flow;
  };
  double y[3] = {u.p, u.q, u.eqps};
  const double h = (t1 - t0) / substeps;
  for (int s = 0; s < substeps; ++s) {
    const double t = t0 + s * h;
    double k1[3], k2[3], k3[3], k4[3], z[3];
    rhs(t, y, k1);
    for (int a = 0; a < 3; ++a) z[a] = y[a] + 0.5 * h * k1[a];
    rhs(t + 0.5 * h, z, k2);
    for (int a = 0; a < 3; ++a) z[a] = y[a] + 0.5 * h * k2[a];
    rhs(t + 0.5 * h, z, k3);
    for (int a = 0; a < 3; ++a) z[a] = y[a] + h * k3[a];
    rhs(t + h, z, k4);
    for (int a = 0; a < 3; ++a) y[a] += h / 6 * (k1[a] + 2 * k2[a] + 2 * k3[a] + k4[a]);
  }
  u.p = y[0];
  u.q = y[1];
  u.eqps = y[2];
}

struct StretchResult {
  double worstDiscrete = 0;  // max |sigma_xx - discrete gold| over the steps, / sigma_Y
  double worstODE = 0;       // max |sigma_xx - ODE| over the steps, / sigma_Y
  double finalODE = 0;       // |sigma_xx - ODE| at the end, / sigma_Y
  double finalQ = 0, finalEqps = 0, odeQ = 0, odeEqps = 0;
  int plastic = 0;
};

// Stretch to eFinal at rate edot in `steps` model steps; every step against both golds.
StretchResult stretch(const Law& l, double eFinal, double edot, int steps) {
  Problem pr(testing::cubicLattice(kN), kHorizon, model(l));
  const double T = eFinal / edot, dt = T / steps;
  Uniaxial discrete, ode;
  StretchResult r;
  for (int n = 1; n <= steps; ++n) {
    const double e = edot * n * dt, ePrevious = edot * (n - 1) * dt;
    stretchTo(pr, e, edot, dt);
    r.plastic += discreteStep(l, discrete, dt * edot / (1 + e), dt);
    integrateODE(l, ode, ePrevious, edot, (n - 1) * dt, n * dt, 1000);
    const double* sigma = at(pr, "Cauchy_Stress");
    const double eq = *at(pr, "Equivalent_Plastic_Strain", 1);
    EXPECT_NEAR(sigma[0], discrete.axial(), 1e-10 * l.sigmaY) << "step " << n;
    EXPECT_NEAR(sigma[4], discrete.lateral(), 1e-10 * l.sigmaY) << "step " << n;
    EXPECT_NEAR(eq, discrete.eqps, 1e-10 * l.sigmaY / kG) << "step " << n;
    r.worstDiscrete = std::max(r.worstDiscrete, std::abs(sigma[0] - discrete.axial()) / l.sigmaY);
    r.worstODE = std::max(r.worstODE, std::abs(sigma[0] - ode.axial()) / l.sigmaY);
    if (n == steps) {
      r.finalODE = std::abs(sigma[0] - ode.axial()) / l.sigmaY;
      r.finalQ = sigma[0] - sigma[4];
      r.finalEqps = eq;
      r.odeQ = ode.q;
      r.odeEqps = ode.eqps;
    }
  }
  return r;
}

// Uniaxial stretch to 5 yield strains at two strain rates 100 apart: every step matches the
// discrete recursion to rounding, and the continuum ODE at first order in dt (halving dt halves
// the difference); the faster stretch ends on a flow stress higher by the rate factor, ~100^m.
TEST(ViscoplasticNeedlemanCorrespondence, UniaxialStretchAtTwoRatesFollowsTheFlowRule) {
  const Law l;
  const double eFinal = 5 * l.sigmaY / (2 * kG);
  double finalQ[2], odeQ[2];
  int k = 0;
  for (double edot : {2.5e-3, 0.25}) {
    const StretchResult coarse = stretch(l, eFinal, edot, 100);
    const StretchResult fine = stretch(l, eFinal, edot, 200);
    std::printf(
        "  Needleman uniaxial stretch, edot %.3g: q/sigma_Y %.6f (ODE %.6f), eps_p %.6e (ODE "
        "%.6e); |sigma_xx - ODE| / sigma_Y at the end %.3e at 100 steps, %.3e at 200 (ratio "
        "%.3f), max over the path %.3e, %.3e; max |sigma_xx - discrete| / sigma_Y %.1e\n",
        edot, fine.finalQ / l.sigmaY, fine.odeQ / l.sigmaY, fine.finalEqps, fine.odeEqps,
        coarse.finalODE, fine.finalODE, coarse.finalODE / fine.finalODE, coarse.worstODE,
        fine.worstODE, std::max(coarse.worstDiscrete, fine.worstDiscrete));
    EXPECT_GT(fine.plastic, 150);
    EXPECT_LT(fine.finalODE, 1e-4);
    EXPECT_NEAR(coarse.finalODE / fine.finalODE, 2.0, 0.05);  // first order in dt
    // The largest difference is at the yield point, where the flow rate jumps from 0 to
    // epsdot_0 within a step; it falls at first order too, more slowly at these step counts.
    EXPECT_LT(fine.worstODE, 5e-3);
    EXPECT_LT(fine.worstODE, 0.7 * coarse.worstODE);
    EXPECT_NEAR(fine.finalEqps / fine.odeEqps, 1.0, 5e-3);
    finalQ[k] = fine.finalQ;
    odeQ[k++] = fine.odeQ;
  }
  // Rate dependence: the flow stress at 100 times the rate is higher by about 100^m = 1.259
  // (less the hardening the slower run gains from its larger plastic strain).
  const double modelRatio = finalQ[1] / finalQ[0], odeRatio = odeQ[1] / odeQ[0];
  std::printf("  q(fast) / q(slow): model %.5f, ODE %.5f, 100^m = %.5f\n", modelRatio, odeRatio,
              std::pow(100.0, l.m));
  EXPECT_GT(odeRatio, 1.15);
  EXPECT_NEAR(modelRatio / odeRatio, 1.0, 2e-3);
}

// Loaded past yield, unloaded and reloaded in compression past the reverse yield: every step
// matches the discrete recursion; eps_p never decreases; while the trial stress is below sigma_Y
// the step is exactly elastic (eps_p unchanged, d sigma_xx / (d_xx dt) = lambda + 2 mu).
TEST(ViscoplasticNeedlemanCorrespondence, LoadUnloadReverseYield) {
  const Law l;
  Problem pr(testing::cubicLattice(kN), kHorizon, model(l));
  const double eMax = 5 * l.sigmaY / (2 * kG), edot = 2.5e-3, T = eMax / edot;
  const int steps = 120;  // 0 -> eMax (n = 40) -> -eMax (n = 120)
  const double dt = 3 * T / steps;
  Uniaxial gold;
  double lastEqps = 0, lastSxx = 0, worstSlope = 0;
  int plastic = 0, elasticUnloading = 0, reversePlastic = 0;
  auto strain = [&](int n) { return n <= 40 ? edot * n * dt : eMax - edot * (n - 40) * dt; };
  for (int n = 1; n <= steps; ++n) {
    const bool loading = n <= 40;
    const double e = strain(n), ePrevious = strain(n - 1);
    stretchTo(pr, e, loading ? edot : -edot, dt);
    const double delta = (e - ePrevious) / (1 + e);
    const bool flowed = discreteStep(l, gold, delta, dt);
    plastic += flowed;
    if (!loading && flowed && gold.q < 0) ++reversePlastic;
    const double* sigma = at(pr, "Cauchy_Stress");
    const double eq = *at(pr, "Equivalent_Plastic_Strain", 1);
    EXPECT_NEAR(sigma[0], gold.axial(), 1e-10 * l.sigmaY) << "step " << n;
    EXPECT_NEAR(eq, gold.eqps, 1e-10 * l.sigmaY / kG) << "step " << n;
    EXPECT_GE(eq, lastEqps) << "plastic strain decreased at step " << n;
    if (!flowed && !loading) {
      ++elasticUnloading;
      EXPECT_EQ(eq, lastEqps) << "step " << n;
      const double slope = (sigma[0] - lastSxx) / delta;
      worstSlope = std::max(worstSlope, std::abs(slope / (kLambda + 2 * kG) - 1));
    }
    lastEqps = eq;
    lastSxx = sigma[0];
  }
  std::printf(
      "  Needleman load/unload/reverse: %d plastic steps (%d in reverse), %d elastic unloading "
      "steps, max |slope / (lambda + 2 mu) - 1| = %.2e, final eps_p %.6e\n",
      plastic, reversePlastic, elasticUnloading, worstSlope, lastEqps);
  EXPECT_GT(elasticUnloading, 10);
  EXPECT_GT(reversePlastic, 20);
  EXPECT_LT(worstSlope, 1e-9);
}

// m = 0: rate-independent J2 plasticity with the hardening curve g. After every plastic step the
// von Mises stress is g(eps_p); with N = 0 and eps_1 -> infinity, g = sigma_Y and the model is
// "Elastic Plastic Correspondence" step for step.
TEST(ViscoplasticNeedlemanCorrespondence, RateIndependentLimit) {
  Law l;
  l.m = 0;
  {
    Problem pr(testing::cubicLattice(kN), kHorizon, model(l));
    const double edot = 2.5e-3, dt = 0.02;
    int plastic = 0;
    double last = 0;
    for (int n = 1; n <= 100; ++n) {
      const double e = edot * n * dt;
      stretchTo(pr, e, edot, dt);
      const double eq = *at(pr, "Equivalent_Plastic_Strain", 1);
      const double vm = *at(pr, "Von_Mises_Stress", 1);
      if (eq > last) {
        ++plastic;
        EXPECT_NEAR(vm / hardening(l, eq), 1.0, 1e-12) << "step " << n;
      }
      last = eq;
    }
    // Once softening takes g below sigma_Y, Peridigm's gate keeps a point elastic until its
    // trial stress is back at sigma_Y: fewer plastic steps than steps past yield.
    EXPECT_GT(plastic, 30);
  }
  l.N = 0;
  l.eps1 = 1e30;
  Problem needleman(testing::cubicLattice(kN), kHorizon, model(l));
  Problem perfect(testing::cubicLattice(kN), kHorizon,
                  testing::correspondence("Elastic Plastic Correspondence", kK, kG, 0.02,
                                          "Hypoelastic Rate", l.sigmaY));
  const double edot = 2.5e-3, dt = 0.02;
  double worst = 0, worstEqps = 0, eqps = 0;
  for (int n = 1; n <= 150; ++n) {
    const double e = n <= 100 ? edot * n * dt : edot * (200 - n) * dt;
    const double rate = n <= 100 ? edot : -edot;
    stretchTo(needleman, e, rate, dt);
    stretchTo(perfect, e, rate, dt);
    for (int k = 0; k < 9; ++k)
      worst = std::max(
          worst, std::abs(at(needleman, "Cauchy_Stress")[k] - at(perfect, "Cauchy_Stress")[k]));
    eqps = *at(perfect, "Equivalent_Plastic_Strain", 1);
    worstEqps =
        std::max(worstEqps, std::abs(*at(needleman, "Equivalent_Plastic_Strain", 1) - eqps));
  }
  std::printf(
      "  m = 0, N = 0 against Elastic Plastic Correspondence: max |sigma diff| / sigma_Y "
      "%.2e, max |eps_p diff| / eps_p %.2e\n",
      worst / l.sigmaY, worstEqps / eqps);
  EXPECT_GT(eqps, 1e-3);
  EXPECT_LT(worst / l.sigmaY, 1e-12);
  EXPECT_LT(worstEqps / eqps, 1e-12);
}

// After every plastic step the point is on the rate-dependent flow surface: its von Mises stress
// is g(eps_p) ((eps_p - eps_p,n) / (epsdot_0 dt))^m, for rate sensitivities from 0.005 to 2 and
// stretching rates from 10^-3 to 10^3 times the reference rate.
TEST(ViscoplasticNeedlemanCorrespondence, StressOnTheRateDependentSurface) {
  for (double m : {0.005, 0.05, 0.5, 2.0})
    for (double edot : {1e-6, 1e-3, 1.0}) {
      Law l;
      l.m = m;
      Problem pr(testing::cubicLattice(kN), kHorizon, model(l));
      const double eFinal = 5e-3, steps = 50, dt = eFinal / edot / steps;
      double last = 0, worst = 0;
      int plastic = 0;
      for (int n = 1; n <= steps; ++n) {
        stretchTo(pr, edot * n * dt, edot, dt);
        const double eq = *at(pr, "Equivalent_Plastic_Strain", 1);
        const double vm = *at(pr, "Von_Mises_Stress", 1);
        ASSERT_TRUE(std::isfinite(vm) && std::isfinite(eq));
        if (eq > last) {
          ++plastic;
          const double Y = hardening(l, eq) * std::pow((eq - last) / (l.rate0 * dt), m);
          worst = std::max(worst, std::abs(vm / Y - 1));
        }
        last = eq;
      }
      EXPECT_GT(plastic, 2) << "m " << m << " edot " << edot;
      EXPECT_LT(worst, 1e-10) << "m " << m << " edot " << edot;
    }
}

// The scalar return on its own, far from the lattice runs: a trial stress 10^3 times the flow
// stress with m = 0.005 (the explicit first guess overflows), a tiny overstress with m = 2, and
// strong softening (eps_p >> eps_1): the root satisfies the consistency condition to rounding,
// in a few Newton iterations.
TEST(ViscoplasticNeedlemanCorrespondence, ScalarReturnConvergesEverywhere) {
  struct Case {
    double m, q, eqps, dt;
  };
  const Case cases[] = {{0.005, 1.0, 0.0, 1e-3},       {0.005, 1.001e-3, 0.0, 1e-3},
                        {2.0, 1.0000001e-3, 0.0, 1.0}, {2.0, 10.0, 0.0, 1e-9},
                        {0.1, 2e-3, 0.5, 1e-2},        {0.05, 5e-4, 0.02, 1.0}};
  for (const Case& c : cases) {
    Law l;
    l.m = c.m;
    auto m = model(l);
    auto* v = dynamic_cast<ViscoplasticNeedlemanCorrespondence*>(m.get());
    ASSERT_NE(v, nullptr);
    int iterations = 0;
    const double de = v->plasticIncrement(c.q, c.eqps, l.sigmaY, c.dt, &iterations);
    const double Y = hardening(l, c.eqps + de) * std::pow(de / (l.rate0 * c.dt), c.m);
    std::printf("  m %.3g q %.4g eps_p %.3g dt %.3g: Deps %.6e in %d iterations, residual %.2e\n",
                c.m, c.q, c.eqps, c.dt, de, iterations, (c.q - 3 * kG * de - Y) / c.q);
    EXPECT_GT(de, 0);
    // To rounding in q (the relative residual in Y itself is limited by the cancellation in
    // q - 3 mu Deps where nearly all of q flows away).
    EXPECT_LT(std::abs(c.q - 3 * kG * de - Y) / c.q, 1e-14);
    EXPECT_LE(iterations, 20);  // bisection alone would take ~50
  }
}

// A rigid spin of an unstressed body brings no stress and no plastic strain. A body stretched
// past yield and then held relaxes (its stress flows down towards sigma_Y); spinning it while it
// relaxes changes nothing in the unrotated frame: sigma_u and eps_p follow the held body's, and
// sigma = R sigma_u R^T.
TEST(ViscoplasticNeedlemanCorrespondence, RigidRotationAddsNoStress) {
  const Law l;
  const double axis[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  const double rate = 1.3, dt = 0.02;
  double W[9];
  const double w[9] = {0, -axis[2], axis[1], axis[2], 0, -axis[0], -axis[1], axis[0], 0};
  for (int k = 0; k < 9; ++k) W[k] = rate * w[k];
  const int steps = 150;  // 3.9 rad
  {
    Problem fresh(testing::cubicLattice(kN), kHorizon, model(l));
    double worst = 0;
    for (int n = 1; n <= steps; ++n) {
      double Q[9], Fdot[9];
      testing::rodriguesRotation(axis, rate * n * dt, Q);
      correspondence::multiply(W, Q, Fdot);
      fresh.evaluateAffine(Q, Fdot, dt);
      for (int k = 0; k < 9; ++k) worst = std::max(worst, std::abs(at(fresh, "Cauchy_Stress")[k]));
      ASSERT_EQ(*at(fresh, "Equivalent_Plastic_Strain", 1), 0.0) << "step " << n;
    }
    std::printf("  rigid spin of an unstressed body: max |sigma| / K = %.2e\n", worst / kK);
    EXPECT_LT(worst / kK, 1e-13);
  }
  Problem spun(testing::cubicLattice(kN), kHorizon, model(l));
  Problem held(testing::cubicLattice(kN), kHorizon, model(l));
  const double e = 5 * l.sigmaY / (2 * kG), edot = 2.5e-3, loadSteps = 40;
  const double loadDt = e / edot / loadSteps;
  for (int n = 1; n <= loadSteps; ++n) {
    stretchTo(spun, edot * n * loadDt, edot, loadDt);
    stretchTo(held, edot * n * loadDt, edot, loadDt);
  }
  const double eqpsLoaded = *at(held, "Equivalent_Plastic_Strain", 1);
  const double U[9] = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1}, zero[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  double worstU = 0, worstSigma = 0, worstEqps = 0;
  for (int n = 1; n <= steps; ++n) {
    double Q[9], F[9], Fdot[9], tmp[9], sigma[9];
    testing::rodriguesRotation(axis, rate * n * dt, Q);
    correspondence::multiply(Q, U, F);
    correspondence::multiply(W, F, Fdot);
    spun.evaluateAffine(F, Fdot, dt);
    held.evaluateAffine(U, zero, dt);
    const double* su = at(held, "Unrotated_Cauchy_Stress");
    for (int k = 0; k < 9; ++k)
      worstU = std::max(worstU, std::abs(at(spun, "Unrotated_Cauchy_Stress")[k] - su[k]));
    correspondence::multiply(Q, su, tmp);
    correspondence::multiplyTransposed(tmp, Q, sigma);
    for (int k = 0; k < 9; ++k)
      worstSigma = std::max(worstSigma, std::abs(at(spun, "Cauchy_Stress")[k] - sigma[k]));
    worstEqps = std::max(worstEqps, std::abs(*at(spun, "Equivalent_Plastic_Strain", 1) -
                                             *at(held, "Equivalent_Plastic_Strain", 1)));
  }
  const double relaxed = *at(held, "Equivalent_Plastic_Strain", 1) - eqpsLoaded;
  std::printf(
      "  stretched body relaxing while spun 3.9 rad: eps_p grew by %.3e while held; max "
      "|sigma_u spun - held| / sigma_Y %.2e, |sigma - R sigma_u R^T| / sigma_Y %.2e, |eps_p "
      "diff| %.2e\n",
      relaxed, worstU / l.sigmaY, worstSigma / l.sigmaY, worstEqps);
  EXPECT_GT(relaxed, 1e-5);  // it does relax: the comparison is not of two frozen states
  EXPECT_LT(worstU / l.sigmaY, 1e-9);
  EXPECT_LT(worstSigma / l.sigmaY, 1e-9);
  EXPECT_LT(worstEqps / relaxed, 1e-9);
}

TEST(ViscoplasticNeedlemanCorrespondence, Keys) {
  const Law l;
  auto m = model(l);
  EXPECT_TRUE(m->advancesHistory());
  EXPECT_TRUE(m->needsVelocity());
  const auto history = m->historyNodeFields();
  EXPECT_NE(std::find(history.begin(), history.end(), "Equivalent_Plastic_Strain"), history.end());
  const auto outputs = m->outputFields();
  EXPECT_NE(std::find(outputs.begin(), outputs.end(), "Equivalent_Plastic_Strain"), outputs.end());
  auto refused = [&](Teuchos::ParameterList p, const std::string& needle) {
    try {
      ListReader r(p, "Materials -> M");
      createMaterial(r);
      ADD_FAILURE() << "accepted; expected an error naming " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  for (const char* key : {"Yield Stress", "Strain Hardening Exponent", "Rate Hardening Exponent",
                          "Reference Strain Rate", "Reference Strain 0", "Reference Strain 1"}) {
    Teuchos::ParameterList p = deck(l);
    p.remove(key);
    refused(p, key);  // all required, as in Peridigm
  }
  for (const char* key : {"Rate Hardening Exponent", "Strain Hardening Exponent"}) {
    Teuchos::ParameterList p = deck(l);
    p.set(key, -0.1);
    refused(p, key);
  }
  for (const char* key : {"Reference Strain Rate", "Reference Strain 0", "Reference Strain 1"}) {
    Teuchos::ParameterList p = deck(l);
    p.set(key, 0.0);
    refused(p, key);
  }
  Teuchos::ParameterList green = deck(l);
  green.set("Stress Integration", "Total Lagrangian Green Strain");
  refused(green, "Stress Integration");
  Teuchos::ParameterList flaw = deck(l);
  flaw.set("Enable Flaw", true);
  refused(flaw, "Flaw Location X");
  flaw.set("Flaw Location X", 1.0);
  flaw.set("Flaw Location Y", 0.0);
  flaw.set("Flaw Location Z", 0.0);
  flaw.set("Flaw Size", 0.5);
  flaw.set("Flaw Magnitude", 0.25);
  ListReader r(flaw, "Materials -> M");
  auto withFlaw = createMaterial(r);
  auto* v = dynamic_cast<ViscoplasticNeedlemanCorrespondence*>(withFlaw.get());
  ASSERT_NE(v, nullptr);
  const double centre[3] = {1, 0, 0}, away[3] = {1, 0.5, 0};
  EXPECT_DOUBLE_EQ(v->yieldStressAt(centre), 0.75 * l.sigmaY);
  EXPECT_DOUBLE_EQ(v->yieldStressAt(away), l.sigmaY * (1 - 0.25 * std::exp(-1.0)));
  Teuchos::ParameterList hardeningModulus = deck(l);
  hardeningModulus.set("Hardening Modulus", 0.1);  // Isotropic Hardening's key, not this model's
  refused(hardeningModulus, "Hardening Modulus");
}

}  // namespace
}  // namespace peridot
