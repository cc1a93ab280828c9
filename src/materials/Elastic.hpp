#pragma once
// Linear peridynamic solid (LPS, ordinary state-based), Peridigm's "Elastic": weighted volume
// m, dilatation theta and deviatoric extension e^d; scalar force state
//   t = (1 - d) omega (3 K theta / m |xi| + 15 G / m e^d)          (3D)
// and its plane stress / plane strain forms (Le, Chan and Schwartz 2014): theta = c/m sum omega
// zeta e V with c = 2(1-2nu)/(1-nu) or 2, alpha = 8 G / m. With a smooth bond law, LPS-T (paper
// 001 eq. 15): t = (1 - d) omega zeta (beta theta + alpha F(s)), beta = B c / m - alpha / c.
#include "materials/MaterialModel.hpp"

namespace peridot {

class Elastic : public MaterialModel {
 public:
  explicit Elastic(ListReader& params);
  double density() const override { return density_; }
  double bulkModulus() const override { return constants_.bulkModulus; }
  double youngsModulus() const override { return constants_.youngsModulus; }
  double poissonsRatio() const override { return constants_.poissonsRatio; }
  double thermalExpansionCoefficient() const override { return thermalExpansion_; }
  PlaneMode planeMode() const override { return mode_; }
  bool acceptsSmoothBondLaw() const override { return true; }
  // The critical stretch breaks bonds in the dilatation loop: one pass over the bonds less.
  bool fusesCriticalStretch() const override { return true; }
  bool breaksInPrecompute() const override { return true; }
  // Both loops walk each bond once over a half list (materials/HalfLps.hpp), omega per pair
  // included; the partial stress pass, per block, keeps the full lists.
  bool computesOverHalfBondList() const override { return !partialStress_; }
  bool halfBondListTakesInfluence() const override { return true; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterInitialize() const override {
    return {kWeightedVolume, kAlpha, kBeta, kBulkModulus};
  }
  std::vector<std::string> fieldsToSyncAfterPrecompute() const override { return {kDilatation}; }
  void precompute(const ModelState& state, const std::vector<int>& points) override;
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  TangentReach tangentReach() const override { return TangentReach::Family; }
  bool hasAnalyticTangent() const override { return analyticTangent_; }
  void addStiffness(const ModelState& state, const std::vector<int>& points,
                    TangentBlocks& K) const override;
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  std::vector<std::string> outputFields() const override {
    if (partialStress_) return {kWeightedVolume, kDilatation, kPartialStress};
    return {kWeightedVolume, kDilatation};
  }
  std::string family() const override { return "LPS"; }
  bool acceptsInfluenceFunction(const std::string&) const override { return true; }

  static constexpr const char* kWeightedVolume = "Weighted_Volume";
  static constexpr const char* kDilatation = "Dilatation";
  static constexpr const char* kBulkModulus = "LPS_Bulk_Modulus";
  // Per-point constants of the force state: alpha = 15 G / m, beta = 3 K / m - alpha / 3.
  static constexpr const char* kAlpha = "LPS_Alpha";
  static constexpr const char* kBeta = "LPS_Beta";
  // Compute Partial Stress: Peridigm's partial stress tensor per point (9, row-major).
  static constexpr const char* kPartialStress = "Partial_Stress";

 private:
  bool analyticTangent_ = true;
  // The bond loops, instantiated per option (influence array, bond damage, one-sided bonds,
  // smooth law) so that their bodies have no branch and vectorize.
  // kThermal: extensions less the thermal part, e = |Y| - |xi| - alpha Delta T |xi| (each end's
  // own thermal strain, state.thermalStrain), as Peridigm forms them.
  template <bool kInfluence, bool kDamage, bool kSides, bool kThermal, bool kBreak>
  void dilatationLoop(const ModelState& state, const std::vector<int>& points);
  template <bool kSmooth, bool kInfluence, bool kDamage, bool kSides, bool kThermal>
  void forceLoop(const ModelState& state, const std::vector<int>& points) const;
  void partialStressLoop(const ModelState& state, const std::vector<int>& points) const;
  void smoothEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const;
  PlaneMode mode_ = PlaneMode::ThreeD;
  // theta = thetaFactor / m sum omega zeta e V (3 in 3D, 2 r in 2D); the dilatation energy
  // 1/2 dilatationModulus theta^2 (K in 3D, kappa / r^2 in 2D); alpha = deviatoricFactor G / m.
  double thetaFactor_ = 3.0, dilatationModulus_ = 0.0, deviatoricFactor_ = 15.0;
  double density_ = 0;
  double thermalExpansion_ = 0;  // alpha
  ElasticConstants constants_;
  bool shearCorrection_ = false;
  double* weightedVolume_ = nullptr;
  double* dilatation_ = nullptr;
  double* bulk_ = nullptr;  // per point (the dilatation modulus), each end's constants
  double* alpha_ = nullptr;
  double* beta_ = nullptr;
  std::vector<double> thetaBeta_;  // theta beta per overlap point, filled by computeForce
  bool partialStress_ = false;
  double* partialStressField_ = nullptr;
};

}  // namespace peridot
