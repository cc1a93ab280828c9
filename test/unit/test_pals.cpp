// The position-aware linear solid ("Pals") on small blocks, against the continuum and against
// its own energy:
// * the energy density and the dilatation of homogeneous deformations (dilatation, uniaxial
//   strain, uniaxial stress, simple shear in the three planes) equal the continuum values at
//   EVERY point of a 7x7x7 block, surface, edge and corner points included; LPS ("Elastic")
//   misses them by tens of percent at the surface on the same block (so the check can fail);
// * force balance: the forces sum to zero, and the work of the forces under the deformation's
//   own mode equals the continuum's (the virial sum_i V_i f_i . (E x_i) = -V sigma : E);
// * force = -grad(total energy), by central differences, on a randomly deformed block.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "SerialProblem.hpp"
#include "core/Error.hpp"
#include "damage/DamageModel.hpp"
#include "materials/Pals.hpp"

namespace peridot {
namespace {

using testing::Problem;

const double K = 2.0, G = 1.1;

std::shared_ptr<MaterialModel> material(const std::string& model,
                                        const std::string& dilatationKernel = "One",
                                        const std::string& deviatoricKernel = "One") {
  Teuchos::ParameterList p;
  p.set("Material Model", model);
  p.set("Density", 1.0);
  p.set("Bulk Modulus", K);
  p.set("Shear Modulus", G);
  if (model == "Pals") {
    p.set("Dilatation Influence Function", dilatationKernel);
    p.set("Deviatoric Influence Function", deviatoricKernel);
  }
  ListReader r(p, "Materials -> " + model);
  return createMaterial(r);
}

std::vector<std::array<double, 3>> block(int nx, int ny, int nz) {
  std::vector<std::array<double, 3>> pts;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) pts.push_back({double(i), double(j), double(k)});
  return pts;
}

struct Mode {
  const char* name;
  double H[3][3];  // displacement gradient, y = x + H x
};

// Continuum energy density of the symmetric part of H: K/2 tr^2 + G dev:dev.
double continuumEnergy(const double H[3][3], double sigma[3][3]) {
  double e[3][3], tr = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) e[a][b] = 0.5 * (H[a][b] + H[b][a]);
  for (int a = 0; a < 3; ++a) tr += e[a][a];
  double devdev = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double d = e[a][b] - (a == b ? tr / 3 : 0.0);
      devdev += d * d;
      sigma[a][b] = (a == b ? K * tr : 0.0) + 2 * G * d;
    }
  return 0.5 * K * tr * tr + G * devdev;
}

void deform(Problem& pr, const double H[3][3]) {
  double* y = pr.fields->node("Coordinates", 3);
  const double* x = pr.fields->node("Model_Coordinates", 3);
  for (int p = 0; p < pr.topology.numOverlap; ++p)
    for (int a = 0; a < 3; ++a) {
      y[3 * p + a] = x[3 * p + a];
      for (int b = 0; b < 3; ++b) y[3 * p + a] += H[a][b] * x[3 * p + b];
    }
}

struct Errors {
  double energy = 0, dilatation = 0, momentum = 0, virial = 0;
};

Errors homogeneous(Problem& pr, const Mode& mode) {
  deform(pr, mode.H);
  pr.evaluator->evaluate(0.0);
  double sigma[3][3];
  const double W = continuumEnergy(mode.H, sigma);
  const int n = pr.topology.numOwned;
  std::vector<double> w(pr.topology.numOverlap);
  pr.evaluator->storedEnergyDensity(w.data());
  const double* theta = pr.fields->node("Dilatation", 1);
  const double* f = pr.fields->node("Force_Density", 3);
  const double* x = pr.fields->node("Model_Coordinates", 3);
  const double tr = mode.H[0][0] + mode.H[1][1] + mode.H[2][2];
  Errors err;
  double sum[3] = {0, 0, 0}, virial = 0, fscale = 0, sigmaE = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) sigmaE += sigma[a][b] * mode.H[a][b];
  for (int i = 0; i < n; ++i) {
    err.energy = std::max(err.energy, std::abs(w[i] / W - 1));
    // relative to the strain amplitude (1e-7): shear has no dilatation
    err.dilatation = std::max(err.dilatation, std::abs(theta[i] - tr) / 1e-7);
    for (int a = 0; a < 3; ++a) {
      sum[a] += f[3 * i + a];
      fscale = std::max(fscale, std::abs(f[3 * i + a]));
      double Hx = 0;
      for (int b = 0; b < 3; ++b) Hx += mode.H[a][b] * x[3 * i + b];
      virial += f[3 * i + a] * Hx;  // unit volumes
    }
  }
  err.momentum = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]) / fscale;
  // -dE/dh along y = x + h H x is sum V f.(H x); the continuum's is -V sigma : H.
  err.virial = std::abs(virial / (-double(n) * sigmaE) - 1);
  return err;
}

const double s = 1e-7, g = 1e-7, nu = (3 * K - 2 * G) / (2 * (3 * K + G));
const Mode kModes[] = {
    {"dilatation", {{s, 0, 0}, {0, s, 0}, {0, 0, s}}},
    {"uniaxial strain x", {{s, 0, 0}, {0, 0, 0}, {0, 0, 0}}},
    {"uniaxial strain z", {{0, 0, 0}, {0, 0, 0}, {0, 0, s}}},
    {"uniaxial stress y", {{-nu * s, 0, 0}, {0, s, 0}, {0, 0, -nu* s}}},
    {"simple shear xy", {{0, g, 0}, {0, 0, 0}, {0, 0, 0}}},
    {"simple shear xz", {{0, 0, g}, {0, 0, 0}, {0, 0, 0}}},
    {"simple shear zy", {{0, 0, 0}, {0, 0, 0}, {0, g, 0}}},
    {"shear + dilatation", {{s, g, 0}, {0, s, 0}, {0, 0, s}}},
};

TEST(Pals, HomogeneousDeformationsExactAtEveryPointOfABlock) {
  // The spacing-to-horizon ratio of Peridigm's Pals_Simple_Shear (7x7x7, delta = 3.015 dx).
  const auto pts = block(7, 7, 7);
  for (const char* kernels : {"One/One", "Gaussian/Parabolic Decay"}) {
    const bool gaussian = std::string(kernels) != "One/One";
    Problem pals(
        pts, 3.015,
        material("Pals", gaussian ? "Gaussian" : "One", gaussian ? "Parabolic Decay" : "One"));
    Problem lps(pts, 3.015, material("Elastic"));
    std::printf("  %-26s %-20s %10s %10s %10s %10s\n", kernels, "mode", "energy", "dilatation",
                "momentum", "virial");
    for (const Mode& mode : kModes) {
      const Errors e = homogeneous(pals, mode);
      const Errors l = homogeneous(lps, mode);
      std::printf("  PALS %-21s %-20s %10.2e %10.2e %10.2e %10.2e\n", "", mode.name, e.energy,
                  e.dilatation, e.momentum, e.virial);
      std::printf("  LPS  %-21s %-20s %10.2e %10.2e %10.2e %10.2e\n", "", mode.name, l.energy,
                  l.dilatation, l.momentum, l.virial);
      // Exact up to the second-order terms of the extension |(I + H) xi| - |xi| (strain 1e-6).
      EXPECT_LT(e.energy, 1e-5) << kernels << " " << mode.name;
      EXPECT_LT(e.dilatation, 1e-5) << kernels << " " << mode.name;
      EXPECT_LT(e.momentum, 1e-9) << kernels << " " << mode.name;
      EXPECT_LT(e.virial, 1e-5) << kernels << " " << mode.name;
      // LPS has no surface correction: the same check fails at the surface (except for pure
      // dilatation, which LPS's normalization by m makes exact everywhere).
      if (std::string(mode.name) != "dilatation") {
        EXPECT_GT(l.energy, 0.1) << mode.name;
      }
    }
  }
}

// A deformation outside the six matching ones is not exact at surface points in general: the
// multipliers fix only the diagonal of the deviatoric energy in the matching modes. Shear at
// 45 degrees in a coordinate plane is measured exact on this (mirror-symmetric) lattice block;
// a generic strain is not (printed and asserted, so that doc/theory/pals.md stays true).
TEST(Pals, RotatedShearIsNotAMatchingMode) {
  Problem pals(block(7, 7, 7), 3.015, material("Pals"));
  const Mode rotated = {"45-degree shear", {{g, 0, 0}, {0, -g, 0}, {0, 0, 0}}};
  const Errors r45 = homogeneous(pals, rotated);
  std::printf("  PALS 45-degree shear: worst energy error %.3e\n", r45.energy);
  const Mode generic = {"generic",
                        {{0, 0.3 * g, -0.7 * g}, {0.2 * g, 0, 0.5 * g}, {0, 0.1 * g, 0}}};
  const Errors e = homogeneous(pals, generic);
  std::printf("  PALS generic strain: worst energy error %.3f, virial error %.2e\n", e.energy,
              e.virial);
  EXPECT_GT(e.energy, 1e-3);
}

std::shared_ptr<DamageModel> interfaceAware(double sc) {
  Teuchos::ParameterList p;
  p.set("Damage Model", "Interface Aware");
  p.set("Critical Stretch", sc);
  ListReader r(p, "Damage Models -> D");
  return createDamageModel(r);
}

// Force = -grad(sum_i V_i W_i) by central differences, on a block displaced at random, without
// and with broken bonds (broken by Interface Aware damage first, then held).
TEST(Pals, ForceIsMinusTheGradientOfTheEnergy) {
  for (bool damaged : {false, true}) {
    const auto pts = block(5, 4, 4);
    Problem pr(pts, 2.015, material("Pals", "Gaussian", "One"),
               damaged ? interfaceAware(0.015) : nullptr, PeriodicBox(), 1.0);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-0.02, 0.02);
    double* y = pr.fields->node("Coordinates", 3);
    for (int p = 0; p < pr.topology.numOwned; ++p)
      for (int a = 0; a < 3; ++a) y[3 * p + a] += u(rng);
    const int n = pr.topology.numOwned;
    if (damaged) {
      pr.evaluator->evaluate(0.0);  // breaks the bonds stretched past 0.015, for good
      const auto& d = pr.fields->bondFloat("Bond_Damage");
      const double broken = std::count(d.begin(), d.end(), 1.0f);
      std::printf("  %.0f of %zu bond entries broken\n", broken, d.size());
      EXPECT_GT(broken, 0.05 * d.size());
      EXPECT_LT(broken, 0.9 * d.size());
    }
    auto energy = [&]() {
      pr.evaluator->evaluate(0.0, false);
      std::vector<double> w(pr.topology.numOverlap);
      pr.evaluator->storedEnergyDensity(w.data());
      double E = 0;
      for (int i = 0; i < n; ++i) E += w[i];  // unit volumes
      return E;
    };
    energy();
    const std::vector<double> f(pr.fields->node("Force_Density", 3),
                                pr.fields->node("Force_Density", 3) + 3 * n);
    double worst = 0, scale = 0;
    const double h = 1e-6;
    for (int p : {0, 7, 21, 40, 79}) {
      for (int a = 0; a < 3; ++a) {
        y[3 * p + a] += h;
        const double plus = energy();
        y[3 * p + a] -= 2 * h;
        const double minus = energy();
        y[3 * p + a] += h;
        const double grad = (plus - minus) / (2 * h);
        worst = std::max(worst, std::abs(f[3 * p + a] + grad));
        scale = std::max(scale, std::abs(f[3 * p + a]));
      }
    }
    std::printf("  force vs -dE/dy: worst difference %.2e of the largest force %.2e\n", worst,
                scale);
    EXPECT_GT(scale, 1e-3);
    EXPECT_LT(worst, 1e-6 * scale);
  }
}

// One layer of points (all bonds in z = 0): the out-of-plane multipliers are dropped, as in
// Peridigm, and in-plane dilatation is exact; two points cannot determine six multipliers.
TEST(Pals, OneLayerAndSingularNeighbourhoods) {
  Problem layer(block(6, 6, 1), 2.015, material("Pals"));
  const Mode inPlane = {"in-plane dilatation", {{s, 0, 0}, {0, s, 0}, {0, 0, 0}}};
  deform(layer, inPlane.H);
  layer.evaluator->evaluate(0.0);
  const double* theta = layer.fields->node("Dilatation", 1);
  for (int i = 0; i < layer.topology.numOwned; ++i) EXPECT_NEAR(theta[i] / (2 * s), 1.0, 1e-5);
  try {
    // Two points on a diagonal: every diagonal entry is there, the system has rank one.
    Problem pair({{0, 0, 0}, {1, 1, 1}}, 2.0, material("Pals"));
    (void)pair;
    ADD_FAILURE() << "a two-point neighbourhood was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Pals"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Lagrange multipliers"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace peridot
