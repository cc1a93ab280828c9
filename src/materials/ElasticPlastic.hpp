#pragma once
// Ordinary state-based elastic-plastic solid (Mitchell 2011), Peridigm's "Elastic Plastic": the
// LPS split into an isotropic part t_i = 3 K theta / m zeta and a deviatoric part
// t_d = alpha (e^d - e^dp), with the deviatoric plastic extension e^dp a bond history state.
// Yield function on the deviatoric force state: f = |t_d|^2 / 2 - psi, |t_d|^2 = sum t_d^2 V,
// psi = 25 sigma_Y^2 / (8 pi delta^5) (uniaxial yield at sigma_Y for a continuum
// neighbourhood). Return mapping: t_d = t_d^trial / (1 + alpha dLambda),
// e^dp += dLambda t_d, Lambda += dLambda. With a hardening modulus H ("Elastic Plastic
// Hardening", derived class) psi grows to psi + H Lambda and dLambda solves the backward-Euler
// consistency condition |t_d^trial|^2 / (2 (1 + alpha dLambda)^2) = psi + H (Lambda + dLambda).
//
// Pull form: a point computes the force state of both ends of each bond, so it keeps, next to
// its own e^dp on (i, j), a copy of j's e^dp on (j, i), updated by the same operations on the
// same operands as j's own (j's theta, return scale and dLambda are ghosted after precompute):
// the two copies stay bit-identical and the results do not depend on the rank count.
#include "materials/MaterialModel.hpp"

namespace peridot {

// Plastic multiplier increment of the hardening return mapping: the positive root of
// 2 (1 + alpha x)^2 (psi + H x) = norm^2 (psi: the yield value at the step's start, including
// H Lambda_n). With H = 0 the closed form (norm / sqrt(2 psi) - 1) / alpha. Requires
// norm^2 / 2 > psi > 0.
double plasticMultiplierIncrement(double norm, double psi, double alpha, double H);

class ElasticPlastic : public MaterialModel {
 public:
  explicit ElasticPlastic(ListReader& params) : ElasticPlastic(params, false) {}
  double density() const override { return density_; }
  double bulkModulus() const override { return constants_.bulkModulus; }
  double youngsModulus() const override { return constants_.youngsModulus; }
  double poissonsRatio() const override { return constants_.poissonsRatio; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterInitialize() const override { return {kModuli}; }
  std::vector<std::string> fieldsToSyncAfterPrecompute() const override { return {kReturn}; }
  void precompute(const ModelState& state, const std::vector<int>& points) override;
  // Also advances the plastic history by one step (e^dp, Lambda) when the state commits.
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  // The recoverable part: 1/2 K theta^2 + alpha/2 sum (1 - d) (e^d - e^dp)^2 V.
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  std::vector<std::string> outputFields() const override {
    return {kWeightedVolume, kDilatation, kLambda};
  }
  std::vector<std::string> historyNodeFields() const override { return {kLambda}; }
  bool advancesHistory() const override { return true; }
  std::string family() const override { return "elastic-plastic state-based"; }
  // The neighbours' dilatation and return enter f_i: probed by finite differences.
  TangentReach tangentReach() const override { return TangentReach::Family; }

  static constexpr const char* kWeightedVolume = "Weighted_Volume";
  static constexpr const char* kDilatation = "Dilatation";
  static constexpr const char* kLambda = "Lambda";
  // Bond history: own e^dp on (i, j), and the copy of the neighbour's e^dp on (j, i).
  static constexpr const char* kPlasticExtension = "Deviatoric_Plastic_Extension";
  static constexpr const char* kNeighborPlasticExtension =
      "Deviatoric_Plastic_Extension_Of_Neighbor";
  // Per point, ghosted: {alpha, 3 K / m, yield value psi_0} after initialize and
  // {theta, return scale 1 / (1 + alpha dLambda), dLambda} after precompute.
  static constexpr const char* kModuli = "Elastic_Plastic_Moduli";
  static constexpr const char* kReturn = "Elastic_Plastic_Return";

 protected:
  ElasticPlastic(ListReader& params, bool hardening);
  double hardeningModulus_ = 0.0;
  bool shearCorrection_ = false;

 private:
  template <bool kDamage, bool kSides>
  void precomputeLoop(const ModelState& state, const std::vector<int>& points);
  template <bool kDamage, bool kSides, bool kCommit>
  void forceLoop(const ModelState& state, const std::vector<int>& points);
  std::string name_;
  double density_ = 0, yieldStress_ = 0;
  bool plasticityDisabled_ = false;
  ElasticConstants constants_;
  double* weightedVolume_ = nullptr;
  double* dilatation_ = nullptr;
  double* lambda_ = nullptr;
  double* moduli_ = nullptr;
  double* return_ = nullptr;
};

}  // namespace peridot
