#pragma once
// Prototype micro-elastic brittle (PMB) bond-based material, Peridigm's "Elastic Bond Based":
// pairwise force c s omega (1-d) along the deformed bond (or c F(s) omega (1-d) with a smooth
// bond law), micromodulus c from the dilatation energy: 3D 18K/(pi delta^4) for omega = 1,
// 9K/(2 pi J3) in general; plane stress / strain 4 kappa/(pi t J2), J_k the influence moments.
#include "materials/MaterialModel.hpp"

namespace peridot {

class ElasticBondBased : public MaterialModel {
 public:
  explicit ElasticBondBased(ListReader& params);
  double density() const override { return density_; }
  double bulkModulus() const override { return bulkModulus_; }
  double youngsModulus() const override {
    return 3.0 * bulkModulus_ * (1.0 - 2.0 * poissonsRatio());
  }
  double poissonsRatio() const override { return bondBasedPoissonsRatio(mode_); }
  double thermalExpansionCoefficient() const override { return thermalExpansion_; }
  PlaneMode planeMode() const override { return mode_; }
  bool acceptsPlaneModeIn3D() const override { return true; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterInitialize() const override { return {kMicromodulus}; }
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  TangentReach tangentReach() const override { return TangentReach::Bond; }
  bool hasAnalyticTangent() const override { return true; }
  void addStiffness(const ModelState& state, const std::vector<int>& points,
                    TangentBlocks& K) const override;
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  void stiffnessSum(const ModelState& state, const std::vector<int>& points,
                    double* sum) const override;
  std::string family() const override { return "bond-based"; }
  // Influence functions whose moments J_k have a closed form (the micromodulus needs them).
  bool acceptsInfluenceFunction(const std::string& name) const override {
    return name == "One" || name == "Conical" || name == "Conical Over Zeta";
  }
  bool acceptsSmoothBondLaw() const override { return true; }
  bool fusesCriticalStretch() const override { return true; }
  bool fusesSmoothBreak() const override { return true; }
  // The pair loops compute |xi| from the reference coordinates and read either damage form.
  bool needsBondLength() const override { return false; }
  bool acceptsBrokenBondFlags() const override { return true; }
  bool computesOverHalfBondList() const override { return true; }

  static constexpr const char* kMicromodulus = "PMB_Micromodulus";

 private:
  double density_ = 0, bulkModulus_ = 0, height_ = 0;
  double thermalExpansion_ = 0;  // alpha (a Peridot extension: Peridigm's PMB has none)
  PlaneMode mode_ = PlaneMode::ThreeD;
  double* micromodulus_ = nullptr;  // per point
};

}  // namespace peridot
