// "Viscoelastic" (ordinary state-based standard linear solid) under imposed homogeneous
// deformations of a slab (periodic in x and y, free in z): ramp then hold (stress relaxation).
// The stress is the force the lower half exerts on the upper half across the mid plane. Golds:
// the closed-form relaxation of the standard linear solid, tau b' + b = eps(t), with the
// lattice's moduli (lattice sums of the formulas over the integer bond vectors; asserted) and
// with the continuum moduli G, K (printed; doc/verification.md).
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstdio>

#include "SerialProblem.hpp"

namespace peridot {
namespace {

using testing::Problem;

const double kDelta = 3.015;
const int kN = 9, kNz = 20;
const double kK = 5.0 / 3.0, kG = 1.0, kLambdaI = 0.6, kTau = 2.0;

std::shared_ptr<MaterialModel> viscoelastic() {
  Teuchos::ParameterList p;
  p.set("Material Model", "Viscoelastic");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", kK);
  p.set("Shear Modulus", kG);
  p.set("lambda_i", kLambdaI);
  p.set("tau b", kTau);
  ListReader r(p, "Materials -> VE");
  return createMaterial(r);
}

std::unique_ptr<Problem> slab() {
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j)
      for (int k = 0; k < kNz; ++k) pts.push_back({double(i), double(j), double(k)});
  PeriodicBox box;
  for (int d = 0; d < 2; ++d) {
    box.periodic[d] = true;
    box.lower[d] = -0.5;
    box.upper[d] = kN - 0.5;
  }
  return std::make_unique<Problem>(pts, kDelta, viscoelastic(), nullptr, box);
}

// One step of dt at y = x + H x; returns the traction (sigma_xz, sigma_yz, sigma_zz) across the
// mid plane.
std::array<double, 3> step(Problem& pr, const double H[3][3], double dt) {
  double* y = pr.fields->node("Coordinates", 3);
  const double* x = pr.fields->node("Model_Coordinates", 3);
  for (int p = 0; p < pr.topology.numOverlap; ++p)
    for (int a = 0; a < 3; ++a) {
      y[3 * p + a] = x[3 * p + a];
      for (int b = 0; b < 3; ++b) y[3 * p + a] += H[a][b] * x[3 * p + b];
    }
  ModelState s = pr.evaluator->state();
  s.dt = dt;
  for (auto& b : pr.blocks) {
    b.material->precompute(s, b.points);
    for (const auto& f : b.material->fieldsToSyncAfterPrecompute()) pr.fields->refreshGhosts(f);
    b.material->computeForce(s, b.points);
  }
  std::array<double, 3> F = {0, 0, 0};
  for (int i = 0; i < pr.topology.numOwned; ++i)
    if (x[3 * i + 2] > 0.5 * (kNz - 1))
      for (int d = 0; d < 3; ++d) F[d] += s.forceDensity[3 * i + d];
  for (double& f : F) f = -f / (kN * kN);
  return F;
}

// Lattice: m = sum zeta^2 and Q = sum g zeta n_a n_b with g = zeta n.D.n (D the path's
// deviatoric direction); the deviatoric stress component is (15 G / m) Q times the amplitude.
double latticeDeviatoricModulus(const double D[3][3], int a, int b) {
  double m = 0, Q = 0;
  const int r = static_cast<int>(kDelta);
  for (int i = -r; i <= r; ++i)
    for (int j = -r; j <= r; ++j)
      for (int k = -r; k <= r; ++k) {
        const double z2 = i * i + j * j + k * k;
        if (z2 == 0 || z2 > kDelta * kDelta) continue;
        const double zeta = std::sqrt(z2), n[3] = {i / zeta, j / zeta, k / zeta};
        double nDn = 0;
        for (int p = 0; p < 3; ++p)
          for (int q = 0; q < 3; ++q) nDn += n[p] * D[p][q] * n[q];
        m += z2;
        Q += zeta * nDn * zeta * n[a] * n[b];
      }
  return 15 * kG / m * Q;
}

// The back strain of tau b' + b = eps for eps = rate t up to tRamp, then held.
double backStrain(double t, double rate, double tRamp) {
  if (t <= tRamp) return rate * (t - kTau * (1 - std::exp(-t / kTau)));
  const double eps0 = rate * tRamp, bRamp = backStrain(tRamp, rate, tRamp);
  return eps0 + (bRamp - eps0) * std::exp(-(t - tRamp) / kTau);
}

struct Case {
  const char* name;
  double dir[3][3];
  int a, b;
  double continuumModulus;  // deviatoric modulus of the measured component in the continuum
  double iso;               // K tr(dir) if the component is normal
};

TEST(Viscoelastic, RelaxationAfterARamp) {
  const Case cases[] = {
      {"simple shear", {{0, 0, 1}, {0, 0, 0}, {0, 0, 0}}, 0, 2, kG, 0.0},
      {"uniaxial strain", {{0, 0, 0}, {0, 0, 0}, {0, 0, 1}}, 2, 2, 4 * kG / 3, kK},
      {"dilatation", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 2, 2, 0.0, 3 * kK},
  };
  const double dt = 0.1 * kTau, tRamp = 1.0 * kTau, amplitude = 1e-7, rate = amplitude / tRamp;
  for (const Case& c : cases) {
    double E[3][3], tr = 0;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) E[p][q] = 0.5 * (c.dir[p][q] + c.dir[q][p]);
    for (int p = 0; p < 3; ++p) tr += E[p][p];
    double D[3][3];
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) D[p][q] = E[p][q] - (p == q ? tr / 3 : 0.0);
    const double latticeModulus = latticeDeviatoricModulus(D, c.a, c.b);
    auto pr = slab();
    double worst = 0, worstContinuum = 0, peak = 0, first = 0, last = 0;
    for (int n = 0; n <= 60; ++n) {
      const double t = n * dt;
      const double eps = t < tRamp ? rate * t : amplitude;
      double H[3][3];
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) H[p][q] = eps * c.dir[p][q];
      const double measured = step(*pr, H, dt)[c.a];
      const double relaxing = eps - kLambdaI * backStrain(t, rate, tRamp);
      const double gold = c.iso * eps + latticeModulus * relaxing;
      const double continuum = c.iso * eps + c.continuumModulus * relaxing;
      worst = std::max(worst, std::abs(measured - gold));
      worstContinuum = std::max(worstContinuum, std::abs(measured - continuum));
      peak = std::max(peak, std::abs(gold));
      if (n == 10) first = measured;
      last = measured;
    }
    std::printf(
        "  %s: |measured - lattice closed form| / peak %.2e, vs continuum %.2e; "
        "relaxed/peak %.4f\n",
        c.name, worst / peak, worstContinuum / peak, last / first);
    EXPECT_LT(worst / peak, 1e-6) << c.name;
    if (c.continuumModulus > 0) {
      EXPECT_LT(last, 0.9 * first) << c.name;  // it does relax
    } else {
      EXPECT_NEAR(last / first, 1.0, 1e-9) << c.name;  // no volumetric relaxation
    }
  }
}

TEST(Viscoelastic, Keys) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Viscoelastic");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", 1.0);
  p.set("Shear Modulus", 1.0);
  p.set("tau b", 1.0);
  ListReader r(p, "Materials -> VE");
  EXPECT_THROW(createMaterial(r), InputError);  // lambda_i is required
  p.set("lambda_i", 1.5);
  ListReader r2(p, "Materials -> VE");
  EXPECT_THROW(createMaterial(r2), InputError);  // outside [0, 1]
  p.set("lambda_i", 0.5);
  p.set("Apply Shear Correction Factor", false);
  ListReader r3(p, "Materials -> VE");
  EXPECT_THROW(createMaterial(r3), InputError);  // refused, as by Peridigm
}

}  // namespace
}  // namespace peridot
