#pragma once
// Normalized PMB (Ganzenmueller, Hiermaier and May; paper 000, eqs. 13-17): the micromodulus of
// each point comes from the same Riemann sum that integrates the forces, c_i = 18 K / sum_j
// omega V_j (3D) or 8 kappa / sum_j omega V_j (plane stress / strain, kappa the in-plane bulk
// modulus), so that a homogeneous dilatation gives exactly W = 9 K s^2 / 2 (3D) or 2 kappa s^2
// (2D) at every point, surface and mixed particle sizes or horizons included. Pair constant
// c_ij = (c_i + c_j) / 2; force density on i: sum_j c_ij omega F(s_ij) / |xi_ij| e_ij V_j;
// energy density W_i = 1/2 sum_j c_ij omega p(s_ij) V_j (F = s, p = s^2/2 for the linear law).
#include "materials/MaterialModel.hpp"

namespace peridot {

class NormalizedPMB : public MaterialModel {
 public:
  explicit NormalizedPMB(ListReader& params);
  double density() const override { return density_; }
  double bulkModulus() const override { return bulkModulus_; }
  double youngsModulus() const override {
    return 3.0 * bulkModulus_ * (1.0 - 2.0 * poissonsRatio());
  }
  double poissonsRatio() const override { return bondBasedPoissonsRatio(mode_); }
  PlaneMode planeMode() const override { return mode_; }
  // The normalization is a discrete sum: any influence function is consistent.
  bool acceptsInfluenceFunction(const std::string&) const override { return true; }
  bool acceptsSmoothBondLaw() const override { return true; }
  bool fusesCriticalStretch() const override { return true; }
  bool fusesSmoothBreak() const override { return true; }
  // The pair loops compute |xi| from the reference coordinates and read either damage form.
  bool needsBondLength() const override { return false; }
  bool acceptsBrokenBondFlags() const override { return true; }
  bool computesOverHalfBondList() const override { return true; }
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
  std::string family() const override { return "normalized PMB"; }

  static constexpr const char* kMicromodulus = "Normalized_PMB_Micromodulus";

 private:
  double density_ = 0, bulkModulus_ = 0;
  PlaneMode mode_ = PlaneMode::ThreeD;
  double* micromodulus_ = nullptr;
};

}  // namespace peridot
