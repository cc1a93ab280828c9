// Ordinary state-based plasticity ("Elastic Plastic", "Elastic Plastic Hardening") under imposed
// homogeneous deformations of a slab (periodic in x and y, free in z): the stress is measured
// as the force that the lower half exerts on the upper half across the mid plane, from the
// model's nodal forces only. Golds: (1) a hand computation of the same lattice (the lattice
// sums of the model's formulas, enumerated here from the integer bond vectors, and a scalar
// return mapping along the one deviatoric direction of the path), asserted tightly; (2) the
// continuum J2 response (radial return, sigma_Y), printed and tabulated in
// doc/verification.md (the difference is the lattice's quadrature error).
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstdio>

#include "SerialProblem.hpp"
#include "materials/ElasticPlastic.hpp"

namespace peridot {
namespace {

using testing::Problem;

const double kPi = 3.14159265358979323846;
const double kDelta = 3.015;
const int kN = 9, kNz = 20;  // slab: 9 x 9 periodic columns, 20 layers (bulk within 2 delta)

std::shared_ptr<MaterialModel> plastic(double K, double G, double sigmaY, double H = -1.0,
                                       bool disable = false) {
  Teuchos::ParameterList p;
  p.set("Material Model", H >= 0 ? "Elastic Plastic Hardening" : "Elastic Plastic");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", K);
  p.set("Shear Modulus", G);
  p.set("Yield Stress", sigmaY);
  if (H >= 0) p.set("Hardening Modulus", H);
  if (disable) p.set("Disable Plasticity", true);
  ListReader r(p, "Materials -> EP");
  return createMaterial(r);
}

std::shared_ptr<MaterialModel> lps(double K, double G) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", K);
  p.set("Shear Modulus", G);
  ListReader r(p, "Materials -> LPS");
  return createMaterial(r);
}

std::unique_ptr<Problem> slab(std::shared_ptr<MaterialModel> m) {
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
  return std::make_unique<Problem>(pts, kDelta, m, nullptr, box);
}

// One step: y = x + H x on every point (images included), precompute, ghost refresh of what
// the model lists (periodic images are copies of their sources), force. Returns the traction
// (sigma_xz, sigma_yz, sigma_zz) across the plane z = (kNz - 1) / 2.
std::array<double, 3> step(Problem& pr, const double H[3][3]) {
  double* y = pr.fields->node("Coordinates", 3);
  const double* x = pr.fields->node("Model_Coordinates", 3);
  for (int p = 0; p < pr.topology.numOverlap; ++p)
    for (int a = 0; a < 3; ++a) {
      y[3 * p + a] = x[3 * p + a];
      for (int b = 0; b < 3; ++b) y[3 * p + a] += H[a][b] * x[3 * p + b];
    }
  const ModelState& s = pr.evaluator->state();
  for (auto& b : pr.blocks) {
    b.material->precompute(s, b.points);
    for (const auto& f : b.material->fieldsToSyncAfterPrecompute()) pr.fields->refreshGhosts(f);
    b.material->computeForce(s, b.points);
  }
  std::array<double, 3> F = {0, 0, 0};
  for (int i = 0; i < pr.topology.numOwned; ++i)
    if (x[3 * i + 2] > 0.5 * (kNz - 1))
      for (int d = 0; d < 3; ++d) F[d] += s.forceDensity[3 * i + d];  // unit volumes
  for (double& f : F) f = -f / (kN * kN);
  return F;
}

// Lattice sums of the model's formulas over the integer bond vectors |xi| <= delta, for the
// deviatoric direction g(xi) = zeta n.D.n of a path (D deviatoric, unit amplitude):
// m = sum zeta^2, S = sum g^2, Q = sum g zeta n_a n_b (the measured stress component ab).
struct LatticeSums {
  double m = 0, S = 0, Q = 0;
};
LatticeSums latticeSums(const double D[3][3], int a, int b) {
  LatticeSums L;
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
        const double g = zeta * nDn;
        L.m += z2;
        L.S += g * g;
        L.Q += g * zeta * n[a] * n[b];
      }
  return L;
}

// Continuum: m = 4 pi delta^5 / 5 and the integrals of the same sums over the ball.
LatticeSums continuumSums(const double D[3][3], int a, int b) {
  // integral over the unit sphere of (n.D.n)^2 = 8 pi / 15 D:D; of (n.D.n) n_a n_b = 8 pi/15 D_ab
  double DD = 0;
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) DD += D[p][q] * D[p][q];
  const double radial = std::pow(kDelta, 5) / 5;
  LatticeSums L;
  L.m = 4 * kPi * std::pow(kDelta, 5) / 5;
  L.S = radial * 8 * kPi / 15 * DD;
  L.Q = radial * 8 * kPi / 15 * D[a][b];
  return L;
}

// The scalar model along the path's deviatoric direction: the deviatoric force state is
// alpha (eps - p) g(xi); yield |t_d|^2 / 2 = alpha^2 (eps - p)^2 S / 2 <= psi_0 + H lambda; a
// plastic step solves 2 (1 + alpha x)^2 (psi + H x) = |t_d trial|^2 by bisection.
struct ScalarPlasticity {
  double alpha, S, Q, psi0, H;
  double p = 0, lambda = 0;
  double stress(double eps) {  // deviatoric stress component, after the step
    const double trial = alpha * (eps - p) * std::sqrt(S);
    const double psi = psi0 + H * lambda;
    double x = 0;
    if (trial * trial / 2 > psi) {
      double lo = 0, hi = 1;
      auto g = [&](double v) { return 2 * (1 + alpha * v) * (1 + alpha * v) * (psi + H * v); };
      while (g(hi) < trial * trial) hi *= 2;
      for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (g(mid) < trial * trial ? lo : hi) = mid;
      }
      x = 0.5 * (lo + hi);
    }
    const double scale = 1 / (1 + alpha * x);
    const double tdAmplitude = scale * alpha * (eps - p);  // t_d = amplitude g(xi)
    p += x * tdAmplitude;
    lambda += x;
    return tdAmplitude * Q;
  }
};

struct PathResult {
  double maxError = 0, peak = 0, maxContinuumError = 0;
  bool lambdaMonotone = true;
};

// Loads along `dir` (displacement gradient of unit amplitude) to +5 epsY, to -5 epsY and back
// to 0; compares component (a, b) of the measured traction with both golds.
PathResult runPath(std::shared_ptr<MaterialModel> m, const double dir[3][3], int a, int b, double K,
                   double G, double sigmaY, double H, double epsY, const char* name) {
  auto pr = slab(m);
  // The deviatoric direction D of the strain sym(dir) and its trace.
  double E[3][3], tr = 0;
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) E[p][q] = 0.5 * (dir[p][q] + dir[q][p]);
  for (int p = 0; p < 3; ++p) tr += E[p][p];
  double D[3][3];
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) D[p][q] = E[p][q] - (p == q ? tr / 3 : 0.0);
  const double psi0 = 25 * sigmaY * sigmaY / (8 * kPi * std::pow(kDelta, 5));
  const LatticeSums Ld = latticeSums(D, a, b), Lc = continuumSums(D, a, b);
  ScalarPlasticity lattice{15 * G / Ld.m, Ld.S, Ld.Q, psi0, H >= 0 ? H : 0.0};
  ScalarPlasticity continuum{15 * G / Lc.m, Lc.S, Lc.Q, psi0, H >= 0 ? H : 0.0};
  const double isoFactor = (a == b ? 1.0 : 0.0) * K * tr;  // K theta in sigma_aa
  std::vector<double> path;
  const int n = 20;
  for (int k = 1; k <= n; ++k) path.push_back(5 * epsY * k / n);
  for (int k = 1; k <= 2 * n; ++k) path.push_back(5 * epsY * (1 - 1.0 * k / n));
  for (int k = 1; k <= n; ++k) path.push_back(-5 * epsY * (1 - 1.0 * k / n));
  PathResult r;
  std::vector<double> lambdaBefore(pr->topology.numOwned, 0.0);
  const double* lambda = pr->fields->node("Lambda", 1);
  std::printf("  %s: strain, measured, lattice gold, continuum J2\n", name);
  int k = 0;
  for (double eps : path) {
    double Hm[3][3];
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) Hm[p][q] = eps * dir[p][q];
    const double measured = step(*pr, Hm)[a];
    const double gold = isoFactor * eps + lattice.stress(eps);
    const double cont = isoFactor * eps + continuum.stress(eps);
    r.maxError = std::max(r.maxError, std::abs(measured - gold));
    r.maxContinuumError = std::max(r.maxContinuumError, std::abs(measured - cont));
    r.peak = std::max(r.peak, std::abs(cont));
    for (int i = 0; i < pr->topology.numOwned; ++i) {
      if (lambda[i] < lambdaBefore[i]) r.lambdaMonotone = false;
      lambdaBefore[i] = lambda[i];
    }
    if (k++ % 10 == 0) std::printf("    %+.3e  %+.6e  %+.6e  %+.6e\n", eps, measured, gold, cont);
  }
  std::printf(
      "  %s: max |measured - lattice gold| / peak = %.2e, |measured - continuum| / peak "
      "= %.2e\n",
      name, r.maxError / r.peak, r.maxContinuumError / r.peak);
  return r;
}

// nu = 1/4; yield strain ~ 1e-7: the golds are small-strain (linear in the displacement
// gradient), and the measured traction differs from them at O(strain) relative (finite bond
// rotations and stretches: 1.5e-5 at a yield strain of 1e-5), which must stay below the 1e-6
// asserted; rounding of the bond extensions (1e-16 x |x| ~ 1e-15 against 1e-7) stays far below.
const double kK = 5.0 / 3.0, kG = 1.0, kSigmaY = 1e-7;

TEST(ElasticPlastic, UniaxialStrainLoadUnloadPastYield) {
  const double dir[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 1}};
  const double epsY = kSigmaY / (2 * kG);  // continuum uniaxial-strain yield: 2 G eps = sigma_Y
  const auto r =
      runPath(plastic(kK, kG, kSigmaY), dir, 2, 2, kK, kG, kSigmaY, -1, epsY, "EP uniaxial strain");
  EXPECT_LT(r.maxError / r.peak, 1e-6);
  EXPECT_TRUE(r.lambdaMonotone);
  RecordProperty("continuum_error", std::to_string(r.maxContinuumError / r.peak));
}

TEST(ElasticPlastic, SimpleShearLoadUnloadPastYield) {
  const double dir[3][3] = {{0, 0, 1}, {0, 0, 0}, {0, 0, 0}};  // y_x = x + gamma z
  const double gammaY = kSigmaY / std::sqrt(3.0) / kG;         // tau_Y = sigma_Y / sqrt 3
  const auto r =
      runPath(plastic(kK, kG, kSigmaY), dir, 0, 2, kK, kG, kSigmaY, -1, gammaY, "EP shear");
  EXPECT_LT(r.maxError / r.peak, 1e-6);
  EXPECT_TRUE(r.lambdaMonotone);
}

TEST(ElasticPlastic, DilatationNeverYields) {
  const double dir[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  auto pr = slab(plastic(kK, kG, kSigmaY));
  const double s = 1e3 * kSigmaY;  // far past any deviatoric yield strain
  double Hm[3][3] = {{s, 0, 0}, {0, s, 0}, {0, 0, s}};
  (void)dir;
  const double measured = step(*pr, Hm)[2];
  EXPECT_NEAR(measured / (3 * kK * s), 1.0, 1e-3);  // sigma_zz = K theta, theta = 3 s (1 + O(s))
  const double* lambda = pr->fields->node("Lambda", 1);
  for (int i = 0; i < pr->topology.numOwned; ++i) EXPECT_EQ(lambda[i], 0.0) << i;
}

TEST(ElasticPlasticHardening, UniaxialStrainLoadUnloadPastYield) {
  const double dir[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 1}};
  const double epsY = kSigmaY / (2 * kG);
  // H in psi per unit Lambda: Lambda grows by ~1/alpha = m / (15 G) ~ 40 per multiple of the
  // yield strain here, so psi_0 / 50 about doubles the yield value along the path.
  const double psi0 = 25 * kSigmaY * kSigmaY / (8 * kPi * std::pow(kDelta, 5));
  const double H = psi0 / 50;
  const auto r = runPath(plastic(kK, kG, kSigmaY, H), dir, 2, 2, kK, kG, kSigmaY, H, epsY,
                         "EPH uniaxial strain");
  EXPECT_LT(r.maxError / r.peak, 1e-6);
  EXPECT_TRUE(r.lambdaMonotone);
}

// With plasticity disabled the model is the LPS with omega = 1: a second code path ("Elastic")
// gives the same forces for an arbitrary (non-homogeneous) deformation.
TEST(ElasticPlastic, DisabledPlasticityIsTheLPS) {
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) pts.push_back({double(i), double(j), double(k)});
  Problem a(pts, kDelta, plastic(kK, kG, kSigmaY, -1, true));
  Problem b(pts, kDelta, lps(kK, kG));
  for (Problem* pr : {&a, &b}) {
    for (int g = 0; g < 216; ++g)
      pr->move(g, 1e-3 * std::sin(g * 1.3), 1e-3 * std::cos(g * 0.7), 1e-3 * std::sin(g * 2.1));
    pr->evaluator->evaluate(1.0);
  }
  double worst = 0, scale = 0;
  for (int g = 0; g < 216; ++g)
    for (int d = 0; d < 3; ++d) {
      worst = std::max(worst, std::abs(a.force(g)[d] - b.force(g)[d]));
      scale = std::max(scale, std::abs(b.force(g)[d]));
    }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(worst / scale, 1e-12);
}

// The return mapping puts the deviatoric force state on the (hardened) yield surface:
// |t_trial|^2 / (2 (1 + alpha x)^2) = psi + H x.
TEST(ElasticPlasticHardening, ReturnMappingConsistency) {
  for (double H : {0.0, 0.3, 5.0, 1e3})
    for (double ratio : {1.0001, 1.5, 10.0}) {
      const double psi = 2.0, alpha = 0.7, norm = ratio * std::sqrt(2 * psi);
      const double x = plasticMultiplierIncrement(norm, psi, alpha, H);
      EXPECT_GT(x, 0.0);
      const double onSurface = norm * norm / (2 * (1 + alpha * x) * (1 + alpha * x));
      EXPECT_NEAR(onSurface / (psi + H * x), 1.0, 1e-12) << "H " << H << " ratio " << ratio;
    }
}

// Force = -grad(energy) in the elastic range (the stored energy is the potential there).
TEST(ElasticPlastic, ForceIsMinusEnergyGradientWhileElastic) {
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) pts.push_back({double(i), double(j), double(k)});
  Problem pr(pts, kDelta, plastic(kK, kG, 1.0));  // yield far away
  for (int g = 0; g < 216; ++g)
    pr.move(g, 1e-4 * std::sin(g * 1.3), 1e-4 * std::cos(g * 0.7), 1e-4 * std::sin(g * 2.1));
  auto energy = [&]() {
    for (auto& b : pr.blocks) b.material->precompute(pr.evaluator->state(), b.points);
    std::vector<double> w(pr.topology.numOverlap);
    pr.evaluator->storedEnergyDensity(w.data());
    double total = 0;
    for (int i = 0; i < pr.topology.numOwned; ++i) total += w[i];  // unit volumes
    return total;
  };
  pr.evaluator->evaluate(1.0);
  const long long probe = 3 * 36 + 2 * 6 + 3;  // an interior point
  const double f[3] = {pr.force(probe)[0], pr.force(probe)[1], pr.force(probe)[2]};
  const double h = 1e-7;
  for (int d = 0; d < 3; ++d) {
    double dm[3] = {0, 0, 0};
    dm[d] = h;
    pr.move(probe, dm[0], dm[1], dm[2]);
    const double up = energy();
    pr.move(probe, -2 * dm[0], -2 * dm[1], -2 * dm[2]);
    const double down = energy();
    pr.move(probe, dm[0], dm[1], dm[2]);
    EXPECT_NEAR(-(up - down) / (2 * h), f[d], 1e-6 * std::abs(f[d]) + 1e-12) << d;
  }
}

TEST(ElasticPlastic, Keys) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic Plastic");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", 1.0);
  p.set("Shear Modulus", 1.0);
  ListReader r(p, "Materials -> EP");
  EXPECT_THROW(createMaterial(r), InputError);  // Yield Stress is required
  p.set("Yield Stress", 1.0);
  p.set("Apply Shear Correction Factor", true);  // not in Peridigm's Elastic Plastic
  ListReader r2(p, "Materials -> EP");
  EXPECT_THROW(createMaterial(r2), InputError);
  Teuchos::ParameterList q;
  q.set("Material Model", "Multiphysics Elastic");
  ListReader r3(q, "Materials -> C");
  try {
    createMaterial(r3);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not supported"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace peridot
