// Plane stress / plane strain materials, influence functions and the smooth (DTT) bond law, on
// planar lattices (z = 0, volume = area x thickness): homogeneous energies against the continuum
// W = 1/2 sigma : eps, forces by hand, p' = F, and the stored energy of a smooth-law run against
// its force by finite differences.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include "Materials.hpp"
#include "PlanarProblem.hpp"
#include "SerialProblem.hpp"
#include "core/Error.hpp"
#include "damage/CriticalStretch.hpp"
#include "damage/FractureEnergy.hpp"

namespace peridot {
namespace {

using testing::PlanarProblem;
const double kPi = 3.14159265358979323846;

using testing::material;

// In-plane continuum energy density of the in-plane strain eps (2x2) of an isotropic material.
double continuumEnergy(const std::string& mode, double E, double nu, const double eps[2][2]) {
  const double mu = E / (2 * (1 + nu));
  const double lambda = mode == "Plane Stress" ? E * nu / (1 - nu * nu)  // with sigma_zz = 0
                                               : E * nu / ((1 + nu) * (1 - 2 * nu));  // eps_zz = 0
  const double tr = eps[0][0] + eps[1][1];
  double ee = 0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) ee += eps[a][b] * eps[a][b];
  return 0.5 * lambda * tr * tr + mu * ee;
}

// Energy density at a point of a periodic square lattice (spacing 1) under y = x + H x.
double latticeEnergy(std::shared_ptr<MaterialModel> m, double delta, const double H[2][2],
                     double thickness = 0.5, const std::string& influence = "One") {
  const int n = 2 * static_cast<int>(std::ceil(delta)) + 3;
  std::vector<std::array<double, 2>> pts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) pts.push_back({double(i), double(j)});
  PeriodicBox box;
  for (int d = 0; d < 2; ++d) {
    box.periodic[d] = true;
    box.lower[d] = -0.5;
    box.upper[d] = n - 0.5;
  }
  PlanarProblem pr(pts, delta, m, thickness, 1.0, nullptr, box, influence);
  const double H3[3][3] = {{H[0][0], H[0][1], 0}, {H[1][0], H[1][1], 0}, {0, 0, 0}};
  return pr.energyDensityUnder(H3);
}

// LPS in 2D. Dilatation: exact on any lattice (theta is the same discrete sum as m). Simple
// shear: the quadrature error of the square lattice, the same at every nu and in both modes
// (shear has no dilatation), not monotone in delta: measured -3.5% (delta/dx 3.015), -4.7%
// (4.015), +8.7% (5.015), +3.4% (6.015), +2.2% (8.015), +4.8% (10.015), -0.5% (12.015); shear at
// 45 degrees has the opposite error. The 1% goal is not met by these lattices with the centre
// rule (partial volumes meet it: test_partial_volumes.cpp); asserted: below 10% (the measured
// bound), and exact with the shear correction (one in-plane mode, 1e-6).
TEST(PlanarLPS, DilatationExactShearMeasured) {
  const double E = 2.0, s = 1e-4, g = 1e-4;
  const double dil[2][2] = {{s, 0}, {0, s}}, shear[2][2] = {{0, g}, {0, 0}};
  const double epsDil[2][2] = {{s, 0}, {0, s}}, epsShear[2][2] = {{0, g / 2}, {g / 2, 0}};
  std::printf("  mode          nu    delta  dilatation  simple shear  corrected shear\n");
  for (const std::string mode : {"Plane Stress", "Plane Strain"}) {
    for (double nu : {0.1, 0.22, 0.3, 0.45}) {
      for (double delta : {3.015, 5.015}) {
        const double eDil = latticeEnergy(material("Elastic", mode, E, nu), delta, dil) /
                                continuumEnergy(mode, E, nu, epsDil) -
                            1;
        const double eShear = latticeEnergy(material("Elastic", mode, E, nu), delta, shear) /
                                  continuumEnergy(mode, E, nu, epsShear) -
                              1;
        Teuchos::ParameterList p;
        p.set("Material Model", "Elastic");
        p.set("Density", 1.0);
        p.set("Young's Modulus", E);
        p.set("Poisson's Ratio", nu);
        p.set(mode, true);
        p.set("Apply Shear Correction Factor", true);
        ListReader r(p, "Materials -> M");
        const double eCorrected = latticeEnergy(createMaterial(r), delta, shear) /
                                      continuumEnergy(mode, E, nu, epsShear) -
                                  1;
        std::printf("  %-12s  %4.2f  %5.3f  %10.2e  %12.2e  %15.2e\n", mode.c_str(), nu, delta,
                    eDil, eShear, eCorrected);
        EXPECT_NEAR(eDil, 0.0, 1e-9) << mode << " nu " << nu;
        EXPECT_NEAR(eCorrected, 0.0, 1e-6) << mode << " nu " << nu;
        EXPECT_LT(std::fabs(eShear), 0.10) << mode << " nu " << nu << " delta " << delta;
        EXPECT_GT(std::fabs(eShear), 0.01);  // the lattice error is real (and recorded)
      }
    }
  }
}

// Bond-based models at their fixed nu (1/3 plane stress, 1/4 plane strain). Normalized PMB:
// dilatation exact to round-off in both modes, omega = 1 or conical. Conical PMB: the quadrature
// error shrinks steadily with delta, for dilatation and shear alike (measured dilatation / shear:
// -4.2% / -7.2% at 3.015, -0.34% / -0.48% at 8.015, -0.14% / -0.20% at 12.015): the shear
// modulus of the model tends to the continuum's, which checks the fixed Poisson's ratios.
// PMB with omega = 1 oscillates (+2.5%, -4.8%, +4.0%, ..., -4.1% at 12.015 for dilatation).
TEST(PlanarBondBased, NormalizedExactConicalPMBConverges) {
  const double E = 3.0, s = 1e-4, g = 1e-4;
  const double dil[2][2] = {{s, 0}, {0, s}}, shear[2][2] = {{0, g}, {0, 0}};
  const double epsDil[2][2] = {{s, 0}, {0, s}}, epsShear[2][2] = {{0, g / 2}, {g / 2, 0}};
  for (const std::string mode : {"Plane Stress", "Plane Strain"}) {
    const double nu = mode == "Plane Stress" ? 1.0 / 3.0 : 0.25;
    for (const std::string influence : {"One", "Conical"}) {
      for (double delta : {3.015, 4.015}) {
        const double e =
            latticeEnergy(material("Normalized PMB", mode, E), delta, dil, 0.5, influence) /
                continuumEnergy(mode, E, nu, epsDil) -
            1;
        EXPECT_NEAR(e, 0.0, 1e-9) << mode << " " << influence << " " << delta;
      }
    }
    double previousDil = 1, previousShear = 1;
    for (double delta : {3.015, 8.015, 12.015}) {
      const double eDil =
          latticeEnergy(material("Elastic Bond Based", mode, E), delta, dil, 0.5, "Conical") /
              continuumEnergy(mode, E, nu, epsDil) -
          1;
      const double eShear =
          latticeEnergy(material("Elastic Bond Based", mode, E), delta, shear, 0.5, "Conical") /
              continuumEnergy(mode, E, nu, epsShear) -
          1;
      std::printf("  conical PMB %s delta %.3f: dilatation %.2e shear %.2e\n", mode.c_str(), delta,
                  eDil, eShear);
      EXPECT_LT(std::fabs(eDil), 0.5 * previousDil);
      EXPECT_LT(std::fabs(eShear), 0.7 * previousShear);
      previousDil = std::fabs(eDil);
      previousShear = std::fabs(eShear);
    }
    EXPECT_LT(previousDil, 0.002);
    EXPECT_LT(previousShear, 0.0025);
    const double ePmb = latticeEnergy(material("Elastic Bond Based", mode, E), 3.015, dil) /
                            continuumEnergy(mode, E, nu, epsDil) -
                        1;
    EXPECT_LT(std::fabs(ePmb), 0.05);
  }
}

// Conical PMB in 3D: c = 90 K / (pi delta^4); the lattice energy of a dilatation approaches
// 9 K s^2 / 2.
TEST(PlanarBondBased, ConicalPMB3DDilatationEnergy) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic Bond Based");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", 2.0);
  ListReader r(p, "Materials -> M");
  std::shared_ptr<MaterialModel> m = createMaterial(r);
  const double delta = 4.015, s = 1e-4;
  const int n = 2 * 5 + 3;
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) pts.push_back({double(i), double(j), double(k)});
  PeriodicBox box;
  for (int d = 0; d < 3; ++d) {
    box.periodic[d] = true;
    box.lower[d] = -0.5;
    box.upper[d] = n - 0.5;
  }
  // SerialProblem builds with omega = 1; build the conical problem by hand here.
  testing::Problem pr(pts, delta, m, nullptr, box);  // omega = 1 first, for comparison
  double* y = pr.fields->node("Coordinates", 3);
  for (int k = 0; k < 3 * pr.topology.numOverlap; ++k) y[k] *= 1 + s;
  std::vector<double> w(pr.topology.numOverlap);
  pr.evaluator->storedEnergyDensity(w.data());
  const double eOne = w[0] / (4.5 * 2.0 * s * s) - 1;
  // Conical: a fresh evaluator on the same topology and fields.
  std::vector<Block> blocks = pr.blocks;
  ModelEvaluator conical(pr.topology, *pr.fields, blocks, "Conical", pr.timers);
  for (int k = 0; k < 3 * pr.topology.numOverlap; ++k) y[k] /= 1 + s;
  conical.initialize();
  for (int k = 0; k < 3 * pr.topology.numOverlap; ++k) y[k] *= 1 + s;
  conical.storedEnergyDensity(w.data());
  const double eConical = w[0] / (4.5 * 2.0 * s * s) - 1;
  std::printf("  3D PMB delta 4.015: dilatation error omega=1 %.2e, conical %.2e\n", eOne,
              eConical);
  EXPECT_LT(std::fabs(eConical), 0.03);
  EXPECT_GT(std::fabs(eConical), 1e-6);  // a quadrature error, not an identity
}

// Two points in plane stress / strain, by hand: PMB c = 12 kappa / (pi t delta^3) (plane stress
// 9E/(pi t delta^3)), conical 48 kappa (1 - zeta/delta) / (pi t delta^3); the pair force
// c s V_j. LPS: t_ij = t_ji = 4 kappa s / zeta (e^d = 0), force 8 kappa s V_j / (zeta^2 V_j).
TEST(PlanarForces, TwoPointsByHand) {
  const double E = 5.0, delta = 1.7, t = 0.3, s = 0.01, area = 0.8, V = area * t;
  for (const std::string mode : {"Plane Stress", "Plane Strain"}) {
    const double nu = mode == "Plane Stress" ? 1.0 / 3.0 : 0.25;
    const double kappa =
        mode == "Plane Stress" ? E / (2 * (1 - nu)) : E / (2 * (1 + nu) * (1 - 2 * nu));
    if (mode == "Plane Stress") {
      EXPECT_NEAR(12 * kappa, 9 * E, 1e-12);
    }
    for (const std::string influence : {"One", "Conical"}) {
      PlanarProblem pr({{0, 0}, {1, 0}}, delta, material("Elastic Bond Based", mode, E), t, area,
                       nullptr, PeriodicBox(), influence);
      pr.move(1, s, 0);
      pr.evaluator->evaluate(1.0);
      const double c = influence == "One"
                           ? 12 * kappa / (kPi * t * std::pow(delta, 3))
                           : 48 * kappa * (1 - 1 / delta) / (kPi * t * std::pow(delta, 3));
      EXPECT_NEAR(pr.force(0)[0], c * s * V, 1e-12 * c) << mode << " " << influence;
      EXPECT_NEAR(pr.force(1)[0], -c * s * V, 1e-12 * c);
      EXPECT_EQ(pr.force(0)[1], 0.0);
    }
    for (double nuLps : {0.1, 0.3}) {
      const double k2 =
          mode == "Plane Stress" ? E / (2 * (1 - nuLps)) : E / (2 * (1 + nuLps) * (1 - 2 * nuLps));
      PlanarProblem pr({{0, 0}, {2, 0}}, 2.5, material("Elastic", mode, E, nuLps), t, area);
      pr.move(1, 2 * s, 0);
      pr.evaluator->evaluate(1.0);
      EXPECT_NEAR(pr.force(0)[0], 8 * k2 * s / 2.0, 1e-12) << mode << " nu " << nuLps;
      EXPECT_NEAR(pr.force(1)[0], -8 * k2 * s / 2.0, 1e-12);
    }
  }
}

// Three points, LPS in 2D, against the textbook 2D form written independently of the code's
// (3D-volumetric) dilatation variable: theta2 = 2/m sum zeta e V, t = 2 kappa theta2 zeta / m +
// 8 G / m (e - theta2 zeta / 2).
TEST(PlanarForces, LPSThreePointsByHand) {
  const double E = 7.0, nu = 0.2, t = 0.5, V = t;
  const double G = E / (2 * (1 + nu));
  const double X[3][2] = {{0, 0}, {1, 0}, {0, 1}}, Y[3][2] = {{0, 0}, {1.02, 0.05}, {-0.01, 1}};
  for (const std::string mode : {"Plane Stress", "Plane Strain"}) {
    const double kappa =
        mode == "Plane Stress" ? E / (2 * (1 - nu)) : E / (2 * (1 + nu) * (1 - 2 * nu));
    PlanarProblem pr({{0, 0}, {1, 0}, {0, 1}}, 2.0, material("Elastic", mode, E, nu), t);
    pr.move(1, 0.02, 0.05);
    pr.move(2, -0.01, 0.0);
    pr.evaluator->evaluate(1.0);
    auto len = [](const double* a, const double* b) {
      return std::hypot(b[0] - a[0], b[1] - a[1]);
    };
    double m[3] = {0, 0, 0}, theta[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (i != j) m[i] += std::pow(len(X[i], X[j]), 2) * V;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (i != j)
          theta[i] += 2 / m[i] * len(X[i], X[j]) * (len(Y[i], Y[j]) - len(X[i], X[j])) * V;
    auto ts = [&](int i, int j) {
      const double z = len(X[i], X[j]), e = len(Y[i], Y[j]) - z;
      return 2 * kappa * theta[i] * z / m[i] + 8 * G / m[i] * (e - theta[i] * z / 2);
    };
    for (int i = 0; i < 3; ++i) {
      double f[2] = {0, 0};
      for (int j = 0; j < 3; ++j) {
        if (i == j) continue;
        const double l = len(Y[i], Y[j]);
        for (int d = 0; d < 2; ++d) f[d] += (ts(i, j) + ts(j, i)) * (Y[j][d] - Y[i][d]) / l * V;
      }
      EXPECT_NEAR(pr.force(i)[0], f[0], 1e-11) << mode << " point " << i;
      EXPECT_NEAR(pr.force(i)[1], f[1], 1e-11) << mode << " point " << i;
    }
  }
}

// p' = F for the smooth law, through all of its pieces, by central differences.
TEST(SmoothBondLaw, PotentialDerivativeIsTheForceScalar) {
  BondLaw law;
  law.kind = BondLaw::Kind::Smooth;
  law.s0Plus = 0.0095;
  law.s1Plus = 0.0105;
  const double h = 1e-7;
  for (double s = -1.2; s < 0.02; s += 0.000731) {
    const double dp = (law.potential(s + h) - law.potential(s - h)) / (2 * h);
    EXPECT_NEAR(dp, law.forceScalar(s), 1e-6) << "s " << s;
  }
  EXPECT_EQ(law.potential(0.0), 0.0);
  EXPECT_EQ(law.forceScalar(0.02), 0.0);
}

// A damage model for tests: a fixed fractional damage, the same on both entries of a pair, and
// a smooth bond law with a narrow window, so that stretches of the test reach all its pieces.
class FixedSmoothDamage : public DamageModel {
 public:
  explicit FixedSmoothDamage(bool smooth) : smooth_(smooth) {}
  void computeDamage(const ModelState& s, const std::vector<int>& points, float* d) override {
    for (int i : points)
      for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
        const long long a = s.topology->overlapGlobalId[i],
                        c = s.topology->overlapGlobalId[s.topology->neighbors[b]];
        d[b] = static_cast<float>(((a + c) % 3) * 0.25);  // 0, 0.25 or 0.5, symmetric in (a, c)
      }
  }
  BondLaw bondLaw() const override {
    BondLaw law;
    if (!smooth_) return law;
    law.kind = BondLaw::Kind::Smooth;
    law.s0Plus = 0.004;
    law.s1Plus = 0.012;
    return law;
  }

 private:
  bool smooth_;
};

// The stored energy of a smooth-law run is the potential of its force: f_i = -(1/V_i) dE/dy_i,
// E = sum_i W_i V_i, checked by central differences on a perturbed planar cloud whose bond
// stretches span the linear, softening and broken pieces of F (PMB, normalized PMB, LPS-T).
TEST(SmoothBondLaw, StoredEnergyIsThePotentialOfTheForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.012, 0.012);
  std::vector<std::array<double, 2>> pts;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) pts.push_back({double(i), double(j)});
  std::vector<std::array<double, 2>> moves;
  for (std::size_t k = 0; k < pts.size(); ++k) moves.push_back({jitter(rng), jitter(rng)});
  const double t = 0.4, V = t;
  struct Case {
    std::string model, mode, influence;
    double nu;
  };
  for (const Case& c : {Case{"Elastic Bond Based", "Plane Stress", "Conical", -1},
                        Case{"Normalized PMB", "Plane Strain", "One", -1},
                        Case{"Elastic", "Plane Stress", "Conical Over Zeta", 0.22},
                        Case{"Elastic", "Plane Strain", "One", 0.3}}) {
    PlanarProblem pr(pts, 2.2, material(c.model, c.mode, 10.0, c.nu), t, 1.0,
                     std::make_shared<FixedSmoothDamage>(true), PeriodicBox(), c.influence);
    for (std::size_t k = 0; k < pts.size(); ++k) pr.move(k, moves[k][0], moves[k][1]);
    auto energy = [&]() {
      pr.evaluator->evaluate(1.0);  // damage (fixed), dilatation, force
      std::vector<double> w(pr.topology.numOverlap);
      pr.evaluator->storedEnergyDensity(w.data());
      double total = 0;
      for (int i = 0; i < pr.topology.numOwned; ++i) total += w[i] * V;
      return total;
    };
    energy();
    std::vector<double> f(pr.fields->nodeField("Force_Density").data,
                          pr.fields->nodeField("Force_Density").data + 3 * pr.topology.numOwned);
    const double h = 1e-7;
    double worst = 0, scale = 0;
    for (long long g : {0LL, 6LL, 12LL, 18LL, 24LL}) {
      for (int d = 0; d < 2; ++d) {
        pr.move(g, d == 0 ? h : 0, d == 1 ? h : 0);
        const double ePlus = energy();
        pr.move(g, d == 0 ? -2 * h : 0, d == 1 ? -2 * h : 0);
        const double eMinus = energy();
        pr.move(g, d == 0 ? h : 0, d == 1 ? h : 0);
        const double fd = -(ePlus - eMinus) / (2 * h) / V;
        worst = std::max(worst, std::fabs(fd - f[3 * pr.local(g) + d]));
        scale = std::max(scale, std::fabs(f[3 * pr.local(g) + d]));
      }
    }
    std::printf("  %s %s %s: max |f_fd - f| = %.2e (max |f| %.2e)\n", c.model.c_str(),
                c.mode.c_str(), c.influence.c_str(), worst, scale);
    EXPECT_GT(scale, 1e-3);
    EXPECT_LT(worst, 1e-5 * scale) << c.model << " " << c.mode;
  }
}

// With a smooth law whose window lies beyond every stretch of the scene, F(s) = s: the smooth
// instantiation gives the linear forces (the LPS-T deviatoric term differs from Peridigm's
// (1 - d)^2 only under damage, absent here).
TEST(SmoothBondLaw, SmoothEqualsLinearInsideTheLinearRange) {
  std::vector<std::array<double, 2>> pts = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  for (const std::string model : {"Elastic Bond Based", "Normalized PMB", "Elastic"}) {
    std::vector<double> forces[2];
    for (int smooth = 0; smooth < 2; ++smooth) {
      class Law : public DamageModel {
       public:
        explicit Law(bool smooth) : smooth_(smooth) {}
        void computeDamage(const ModelState&, const std::vector<int>&, float*) override {}
        BondLaw bondLaw() const override {
          BondLaw law;
          if (smooth_) {
            law.kind = BondLaw::Kind::Smooth;
            law.s0Plus = 0.5;
            law.s1Plus = 0.6;
          }
          return law;
        }
        bool smooth_;
      };
      PlanarProblem pr(pts, 1.6,
                       material(model, "Plane Strain", 4.0, model == "Elastic" ? 0.3 : -1), 0.2,
                       1.0, std::make_shared<Law>(smooth == 1));
      pr.move(1, 0.03, -0.01);
      pr.move(3, -0.02, 0.04);
      pr.evaluator->evaluate(1.0);
      for (int i = 0; i < 4; ++i)
        for (int d = 0; d < 2; ++d) forces[smooth].push_back(pr.force(i)[d]);
    }
    for (std::size_t k = 0; k < forces[0].size(); ++k)
      EXPECT_NEAR(forces[1][k], forces[0][k], 1e-13 * (1 + std::fabs(forces[0][k]))) << model;
  }
}

// A plane material in a 3D run (and the reverse) is refused at initialization.
TEST(PlanarMaterials, DimensionMismatchIsAnInputError) {
  EXPECT_THROW(testing::Problem({{0, 0, 0}, {1, 0, 0}}, 1.5,
                                material("Elastic Bond Based", "Plane Stress", 1.0)),
               InputError);
  EXPECT_THROW(PlanarProblem({{0, 0}, {1, 0}}, 1.5, material("Elastic", "", 1.0, 0.2), 1.0),
               InputError);
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic");
  p.set("Density", 1.0);
  p.set("Young's Modulus", 1.0);
  p.set("Poisson's Ratio", 0.2);
  p.set("Plane Stress", true);
  p.set("Plane Strain", true);
  ListReader r(p, "Materials -> M");
  EXPECT_THROW(createMaterial(r), InputError);
}

// Fracture energy -> critical stretch: the papers' closed forms where they are right, and the
// derivation itself checked by counting: the energy of the bonds crossing a line of a fine
// lattice, all at s_c, per unit crack area, must be G0 (paper 000 eq. 22 would give G0/2).
TEST(FractureEnergy, PapersFormulasAndCrossingBondEnergy) {
  const double E = 72e9, G0 = 3.8, delta = 1e-3;
  std::string formula;
  auto ps = material("Elastic Bond Based", "Plane Stress", E);
  // Paper 001 eq. 22 (conical PMB, plane stress) and omega = 1 (Ha and Bobaru): 4 pi G0/(9 E d).
  EXPECT_NEAR(criticalStretchFromFractureEnergy(*ps, delta, G0, "Conical", formula),
              std::sqrt(5 * kPi * G0 / (9 * E * delta)), 1e-15);
  EXPECT_NEAR(criticalStretchFromFractureEnergy(*ps, delta, G0, "One", formula),
              std::sqrt(4 * kPi * G0 / (9 * E * delta)), 1e-15);
  // Paper 001 eq. 24 (LPS-T, its omega = (1 - zeta/delta)/zeta), any nu.
  for (double nu : {0.22, 0.3}) {
    auto lpsT = material("Elastic", "Plane Stress", E, nu);
    EXPECT_NEAR(criticalStretchFromFractureEnergy(*lpsT, delta, G0, "Conical Over Zeta", formula),
                std::sqrt(5 * (1 + nu) * kPi * G0 / (12 * E * delta)), 1e-15);
  }
  EXPECT_THROW(criticalStretchFromFractureEnergy(*ps, delta, G0, "Gaussian", formula), InputError);

  // Counting on a lattice: spacing h = 1, delta = 6.015, thickness t; crack line y = 0 between
  // the rows y = -1/2 and y = +1/2, periodic in x (one column of i per unit length).
  const double d = 6.015, t = 0.7, Eg = 10.0, Gc = 2.0;
  struct Case {
    std::string model, mode, influence;
  };
  for (const Case& c : {Case{"Elastic Bond Based", "Plane Stress", "Conical"},
                        Case{"Elastic Bond Based", "Plane Strain", "One"},
                        Case{"Normalized PMB", "Plane Strain", "One"},
                        Case{"Normalized PMB", "Plane Stress", "Conical"}}) {
    auto m = material(c.model, c.mode, Eg);
    const double sc = criticalStretchFromFractureEnergy(*m, d, Gc, c.influence, formula);
    const double nu = c.mode == "Plane Stress" ? 1.0 / 3.0 : 0.25;
    const double kappa =
        c.mode == "Plane Stress" ? Eg / (2 * (1 - nu)) : Eg / (2 * (1 + nu) * (1 - 2 * nu));
    const int R = static_cast<int>(std::ceil(d));
    // Constants as the models compute them in the bulk (the lattice sum for normalized PMB).
    auto omega = [&](double z) { return c.influence == "One" ? 1.0 : 1.0 - z / d; };
    double sumOmegaV = 0;
    for (int a = -R; a <= R; ++a)
      for (int b = -R; b <= R; ++b) {
        const double z = std::hypot(a, b);
        if ((a || b) && z <= d) sumOmegaV += omega(z) * t;
      }
    const double J2 = c.influence == "One" ? d * d * d / 3 : d * d * d / 12;
    const double cPmb = 4 * kappa / (kPi * t * J2), cNorm = 8 * kappa / sumOmegaV;
    double energy = 0;  // per unit length of crack: i in the column x = 0, all rows above
    for (int iy = 0; iy < R; ++iy)
      for (int a = -R; a <= R; ++a)
        for (int jy = -R; jy < 0; ++jy) {
          const double z = std::hypot(a, iy - jy);
          if (z > d) continue;
          // Pair energy (both ends) per V_i V_j: 1/2 c omega s^2 zeta (PMB), 1/2 c omega s^2.
          const double w = c.model == "Normalized PMB" ? 0.5 * cNorm * omega(z) * sc * sc
                                                       : 0.5 * cPmb * omega(z) * sc * sc * z;
          energy += w * t * t;
        }
    const double G = energy / t;
    std::printf("  %s %s %s: crossing-bond energy / G0 = %.4f\n", c.model.c_str(), c.mode.c_str(),
                c.influence.c_str(), G / Gc);
    EXPECT_NEAR(G / Gc, 1.0, 0.05) << c.model << " " << c.mode << " " << c.influence;
  }
}

// CriticalStretch::bind logs the value and the formula, and records the influence function it
// assumed so that a run with another one is refused.
TEST(FractureEnergy, BindUsesTheMaterialsInfluenceFunction) {
  Teuchos::ParameterList p;
  p.set("Damage Model", "Critical Stretch");
  p.set("Fracture Energy", 3.8);
  ListReader r(p, "Damage Models -> CS");
  auto damage = createDamageModel(r);
  auto m = material("Elastic Bond Based", "Plane Stress", 72e9);
  m->setInfluenceFunction("Conical");
  std::ostringstream log;
  damage->bind(*m, 1e-3, "plate", log);
  EXPECT_NEAR(static_cast<CriticalStretch&>(*damage).criticalStretch(),
              std::sqrt(5 * kPi * 3.8 / (9 * 72e9 * 1e-3)), 1e-15);
  EXPECT_NE(log.str().find("plate"), std::string::npos);
  EXPECT_NE(log.str().find("Conical"), std::string::npos);
  // The run uses omega = 1: refused.
  EXPECT_THROW(PlanarProblem({{0, 0}, {1, 0}}, 1.5, m, 1.0), InputError);
  // With the influence function it assumed: accepted.
  EXPECT_NO_THROW(
      PlanarProblem({{0, 0}, {1, 0}}, 1.5, m, 1.0, 1.0, nullptr, PeriodicBox(), "Conical"));
}

}  // namespace
}  // namespace peridot
