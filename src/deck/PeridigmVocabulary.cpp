#include "deck/PeridigmVocabulary.hpp"

#include <algorithm>

namespace peridot {

const std::vector<std::string>& peridigmMaterialModels() {
  static const std::vector<std::string> names = {
      "Elastic",
      "Elastic Bond Based",
      "Elastic Plastic",
      "Elastic Plastic Hardening",
      "Viscoelastic",
      "Pals",
      "Linear LPS Partial Volume",
      "Elastic Partial Volume",
      "Elastic Correspondence",
      "Elastic Plastic Correspondence",
      "Isotropic Hardening Correspondence",
      "Viscoplastic Needleman Correspondence",
      "Elastic Hypoelastic Correspondence",
      "Elastic Plastic Hypoelastic Correspondence",
      "Isotropic Hardening Hypoelastic Correspondence",
      "Elastic Bond Associated Correspondence",
      "Elastic Plastic Bond Associated Correspondence",
      "Isotropic Hardening Bond Associated Correspondence",
      "Multiphysics Elastic",
      "Diffusion",
      "Vector Poisson",
      "LCM",
  };
  return names;
}

const std::vector<std::string>& peridigmDamageModels() {
  static const std::vector<std::string> names = {
      "Critical Stretch", "Time Dependent Critical Stretch",
      "Interface Aware",  "Initial Damage",
      "Johnson Cook",     "Von Mises Stress",
  };
  return names;
}

const std::vector<std::string>& peridigmOutputVariablesNotYet() {
  static const std::vector<std::string> names = {
      "Normalized_Weighted_Volume",  // Pals' debugging field (never computed by Peridigm)
      "Surface_Correction_Factor",
      "Concentration",
      "Flux_Divergence",
      "Fluid_Pressure_U",
      "Flux_Density",
      "OBC_Functional",
      "JIntegral",
      "Bond_Visualization",
  };
  return names;
}

bool isIn(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

}  // namespace peridot
