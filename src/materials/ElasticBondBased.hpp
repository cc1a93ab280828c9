#pragma once
// Prototype micro-elastic brittle (PMB) bond-based material, Peridigm's "Elastic Bond Based":
// pairwise force c s omega (1-d) along the deformed bond, micromodulus c = 18K/(pi delta^4).
#include "materials/MaterialModel.hpp"

namespace peridot {

class ElasticBondBased : public MaterialModel {
 public:
  explicit ElasticBondBased(ListReader& params);
  double density() const override { return density_; }
  double bulkModulus() const override { return bulkModulus_; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterInitialize() const override { return {kMicromodulus}; }
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  std::string family() const override { return "bond-based"; }

  static constexpr const char* kMicromodulus = "PMB_Micromodulus";

 private:
  double density_ = 0, bulkModulus_ = 0;
  double* micromodulus_ = nullptr;  // per point: 18K/(pi delta_i^4)
};

}  // namespace peridot
