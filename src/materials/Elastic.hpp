#pragma once
// Linear peridynamic solid (LPS, ordinary state-based), Peridigm's "Elastic": weighted volume
// m, dilatation theta and deviatoric extension e^d; scalar force state
//   t = (1 - d) omega (3 K theta / m |xi| + 15 G / m e^d).
#include "materials/MaterialModel.hpp"

namespace peridot {

class Elastic : public MaterialModel {
 public:
  explicit Elastic(ListReader& params);
  double density() const override { return density_; }
  double bulkModulus() const override { return constants_.bulkModulus; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterInitialize() const override {
    return {kWeightedVolume, kAlpha, kBeta, kBulkModulus};
  }
  std::vector<std::string> fieldsToSyncAfterPrecompute() const override { return {kDilatation}; }
  void precompute(const ModelState& state, const std::vector<int>& points) override;
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  std::vector<std::string> outputFields() const override { return {kWeightedVolume, kDilatation}; }
  std::string family() const override { return "LPS"; }
  bool acceptsInfluenceFunction(const std::string&) const override { return true; }

  static constexpr const char* kWeightedVolume = "Weighted_Volume";
  static constexpr const char* kDilatation = "Dilatation";
  static constexpr const char* kBulkModulus = "LPS_Bulk_Modulus";
  // Per-point constants of the force state: alpha = 15 G / m, beta = 3 K / m - alpha / 3.
  static constexpr const char* kAlpha = "LPS_Alpha";
  static constexpr const char* kBeta = "LPS_Beta";

 private:
  double density_ = 0;
  ElasticConstants constants_;
  bool shearCorrection_ = false;
  double* weightedVolume_ = nullptr;
  double* dilatation_ = nullptr;
  double* bulk_ = nullptr;  // per point, so bonds across blocks see each end's constants
  double* alpha_ = nullptr;
  double* beta_ = nullptr;
};

}  // namespace peridot
