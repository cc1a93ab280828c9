#pragma once
// A material model from Young's modulus for kernel tests: `mode` is "", "Plane Stress" or
// "Plane Strain"; Poisson's ratio is set only when nu > -1 (bond-based models have their own).
#include <Teuchos_ParameterList.hpp>
#include <memory>
#include <string>

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

}  // namespace testing
}  // namespace peridot
