// Energy density of homogeneous deformations in the bulk of a lattice against the continuum
// W = 1/2 sigma : epsilon (3D): pure dilatation and simple shear, for the state-based LPS at
// several Poisson's ratios and for the bond-based models (nu = 1/4).
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstdio>

#include "SerialProblem.hpp"

namespace peridot {
namespace {

using testing::Problem;

std::shared_ptr<MaterialModel> lps(double K, double G, bool shearCorrection = false) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic");
  p.set("Apply Shear Correction Factor", shearCorrection);
  p.set("Density", 1.0);
  p.set("Bulk Modulus", K);
  p.set("Shear Modulus", G);
  ListReader r(p, "Materials -> LPS");
  return createMaterial(r);
}

std::shared_ptr<MaterialModel> bondBased(const std::string& model, double K) {
  Teuchos::ParameterList p;
  p.set("Material Model", model);
  p.set("Density", 1.0);
  p.set("Bulk Modulus", K);
  ListReader r(p, "Materials -> " + model);
  return createMaterial(r);
}

// Energy density at the centre of a periodic lattice under displacement gradient H (y = x + H x).
double centreEnergy(std::shared_ptr<MaterialModel> material, double delta, const double H[3][3]) {
  const int n = 2 * static_cast<int>(std::ceil(delta)) + 3;
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) pts.push_back({double(i), double(j), double(k)});
  PeriodicBox box;  // periodic: every point is in the bulk
  for (int d = 0; d < 3; ++d) {
    box.periodic[d] = true;
    box.lower[d] = -0.5;
    box.upper[d] = n - 0.5;
  }
  Problem pr(pts, delta, material, nullptr, box);
  return pr.energyDensityUnder(H);
}

// LPS: the dilatation energy is exact on any lattice (the dilatation of a homogeneous stretch is
// exactly 3 s at every point). The shear energy is not: on a cubic lattice with delta = 3.015 dx
// it is measured +11% for simple shear along the axes and -16.5% for shear at 45 degrees to
// them (the same at every Poisson's ratio: shear has no dilatation, only G enters); at
// 8.015 dx the axis-aligned error is still +1.2%. Peridigm's shear correction factor makes
// axis-aligned shear exact but the 45-degree case worse (-25%). With the centre-inside rule the
// 1% target for shear is therefore not met on coarse cubic lattices; the figures are printed
// and the asserted facts are the exact ones. Partial volumes meet it: test_partial_volumes.cpp.
TEST(HomogeneousEnergy, LPSDilatationAndShear) {
  const double s = 1e-4, g = 1e-4, E = 1.0;
  const double dil[3][3] = {{s, 0, 0}, {0, s, 0}, {0, 0, s}};
  const double simple[3][3] = {{0, g, 0}, {0, 0, 0}, {0, 0, 0}};    // W = G g^2 / 2
  const double rotated[3][3] = {{g, 0, 0}, {0, -g, 0}, {0, 0, 0}};  // W = 2 G g^2
  std::printf("  delta/dx   nu   correction  dilatation  simple shear  45-degree shear\n");
  for (double nu : {0.1, 0.22, 0.3, 0.45}) {
    const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
    const double delta = 3.015;
    for (bool corrected : {false, true}) {
      const double eDil = centreEnergy(lps(K, G, corrected), delta, dil) / (4.5 * K * s * s) - 1;
      const double eSimple =
          centreEnergy(lps(K, G, corrected), delta, simple) / (0.5 * G * g * g) - 1;
      const double eRotated =
          centreEnergy(lps(K, G, corrected), delta, rotated) / (2 * G * g * g) - 1;
      std::printf("  %8.3f  %4.2f  %10s  %10.2e  %12.2e  %15.2e\n", delta, nu,
                  corrected ? "yes" : "no", eDil, eSimple, eRotated);
      EXPECT_NEAR(eDil, 0.0, 1e-9) << "nu " << nu;
      if (corrected) {
        EXPECT_NEAR(eSimple, 0.0, 1e-6) << "nu " << nu;
      } else {
        EXPECT_GT(eSimple, 0.05);  // the uncorrected coarse-lattice error is real, and recorded
      }
      RecordProperty(std::string(corrected ? "corrected" : "uncorrected") +
                         "_45deg_shear_error_nu" + std::to_string(nu),
                     std::to_string(eRotated));
    }
  }
}

// Bond-based models (nu = 1/4, G = 3K/5): the normalized PMB reproduces the dilatation energy
// exactly; shear is printed.
TEST(HomogeneousEnergy, NormalizedPMBDilatationExactShearReported) {
  const double K = 2.0, s = 1e-4, gamma = 1e-4;
  for (double delta : {3.015, 5.015}) {
    const double dil[3][3] = {{s, 0, 0}, {0, s, 0}, {0, 0, s}};
    const double shear[3][3] = {{0, gamma, 0}, {0, 0, 0}, {0, 0, 0}};
    const double wDil = centreEnergy(bondBased("Normalized PMB", K), delta, dil);
    const double wShear = centreEnergy(bondBased("Normalized PMB", K), delta, shear);
    // Small-strain stretch s is exact here only to first order: (|(1+s)xi| - |xi|)/|xi| = s.
    EXPECT_NEAR(wDil / (4.5 * K * s * s), 1.0, 1e-9);
    std::printf("  normalized PMB delta %.3f: dilatation error %.2e, shear error %.2e\n", delta,
                wDil / (4.5 * K * s * s) - 1, wShear / (0.5 * 0.6 * K * gamma * gamma) - 1);
  }
}

}  // namespace
}  // namespace peridot
