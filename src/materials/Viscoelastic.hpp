#pragma once
// Ordinary state-based standard linear solid (Mitchell), Peridigm's "Viscoelastic": the LPS
// (omega = 1) whose deviatoric force state relaxes through one Maxwell branch,
//   t_d = alpha [ (1 - lambda_i) e^d + lambda_i (e^d - e^b) ],   tau_b de^b/dt = e^d - e^b,
// e^b the deviatoric back extension, a bond history state integrated exactly over each step for
// an e^d linear in time: e^b_{n+1} = e^d_n (1 - D) + e^b_n D + beta (e^d_{n+1} - e^d_n),
// D = exp(-dt / tau_b), beta = 1 - (tau_b / dt)(1 - D). The isotropic part is elastic.
//
// Pull form: each bond entry keeps the owner's e^d_n and e^b and copies of the neighbour's on
// the reversed bond, advanced by the same operations on the same operands (the neighbour's theta
// is ghosted), so the results do not depend on the rank count.
#include "materials/MaterialModel.hpp"

namespace peridot {

class Viscoelastic : public MaterialModel {
 public:
  explicit Viscoelastic(ListReader& params);
  double density() const override { return density_; }
  bool advancesHistory() const override { return true; }
  double bulkModulus() const override { return constants_.bulkModulus; }
  double youngsModulus() const override { return constants_.youngsModulus; }
  double poissonsRatio() const override { return constants_.poissonsRatio; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterInitialize() const override {
    return {kWeightedVolume};
  }
  std::vector<std::string> fieldsToSyncAfterPrecompute() const override { return {kDilatation}; }
  void precompute(const ModelState& state, const std::vector<int>& points) override;
  // Also advances the back extension by one step of state.dt when the state commits.
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  // The free energy 1/2 K theta^2 + alpha/2 sum (1 - d) [(1 - lambda_i) e^d^2 +
  // lambda_i (e^d - e^b)^2] V.
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  std::vector<std::string> outputFields() const override { return {kWeightedVolume, kDilatation}; }
  std::string family() const override { return "viscoelastic state-based"; }
  TangentReach tangentReach() const override { return TangentReach::Family; }

  static constexpr const char* kWeightedVolume = "Weighted_Volume";
  static constexpr const char* kDilatation = "Dilatation";
  // Bond history: {e^d_n, e^b} of the owner on (i, j) and of the neighbour on (j, i).
  static constexpr const char* kBackExtension = "Deviatoric_Back_Extension";
  static constexpr const char* kDeviatoricExtension = "Deviatoric_Extension_Previous_Step";
  static constexpr const char* kNeighborBackExtension = "Deviatoric_Back_Extension_Of_Neighbor";
  static constexpr const char* kNeighborDeviatoricExtension =
      "Deviatoric_Extension_Previous_Step_Of_Neighbor";

 private:
  template <bool kCommit>
  void withDamageAndSides(const ModelState& state, const std::vector<int>& points);
  template <bool kDamage, bool kSides, bool kCommit>
  void forceLoop(const ModelState& state, const std::vector<int>& points);
  double density_ = 0, lambdaI_ = 0, tauB_ = 0;
  ElasticConstants constants_;
  double* weightedVolume_ = nullptr;
  double* dilatation_ = nullptr;
};

}  // namespace peridot
