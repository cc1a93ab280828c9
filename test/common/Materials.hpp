#pragma once
// A material model from Young's modulus for kernel tests: `mode` is "", "Plane Stress" or
// "Plane Strain"; Poisson's ratio is set only when nu > -1 (bond-based models have their own).
#include <Teuchos_ParameterList.hpp>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "damage/CriticalStretch.hpp"
#include "materials/MaterialModel.hpp"

namespace peridot {
namespace testing {

inline std::shared_ptr<MaterialModel> material(const std::string& model, const std::string& mode,
                                               double E, double nu = -1) {
  Teuchos::ParameterList p;
  p.set("Material Model", model);
  p.set("Density", 1.0);
  p.set("Young's Modulus", E);
  if (nu > -1) p.set("Poisson's Ratio", nu);
  if (!mode.empty()) p.set(mode, true);
  ListReader r(p, "Materials -> M");
  return createMaterial(r);
}

// The "Critical Stretch" damage model with critical stretch sc.
inline std::shared_ptr<DamageModel> criticalStretch(double sc) {
  Teuchos::ParameterList p;
  p.set("Critical Stretch", sc);
  ListReader r(p, "Damage Models -> D");
  return std::make_shared<CriticalStretch>(r);
}

// A correspondence model with bulk modulus K and shear modulus G (density 1): `integration` is
// the Stress Integration ("Hypoelastic Rate" or "Total Lagrangian Green Strain"); the yield
// stress and hardening modulus are set when positive (resp. non-negative).
inline std::shared_ptr<MaterialModel> correspondence(const std::string& model, double K, double G,
                                                     double hourglass,
                                                     const std::string& integration,
                                                     double yield = 0.0, double H = -1.0) {
  Teuchos::ParameterList p;
  p.set("Material Model", model);
  p.set("Density", 1.0);
  p.set("Bulk Modulus", K);
  p.set("Shear Modulus", G);
  p.set("Hourglass Coefficient", hourglass);
  p.set("Stress Integration", integration);
  if (yield > 0) p.set("Yield Stress", yield);
  if (H >= 0) p.set("Hardening Modulus", H);
  ListReader r(p, "Materials -> M");
  return createMaterial(r);
}

// The points (i, j, k), 0 <= i, j, k < n, of the unit cubic lattice, k fastest.
inline std::vector<std::array<double, 3>> cubicLattice(int n) {
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) pts.push_back({double(i), double(j), double(k)});
  return pts;
}

// Rotation by angle about the unit axis n (Rodrigues), row-major.
inline void rodriguesRotation(const double n[3], double angle, double R[9]) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) R[3 * a + b] = (a == b ? c : 0.0) + (1 - c) * n[a] * n[b];
  R[1] -= s * n[2];
  R[2] += s * n[1];
  R[3] += s * n[2];
  R[5] -= s * n[0];
  R[6] -= s * n[1];
  R[7] += s * n[0];
}

}  // namespace testing
}  // namespace peridot
