#pragma once
// Position-aware linear solid (PALS; Mitchell, Silling and Littlewood 2015, as Peridigm's
// "Pals"): an ordinary state-based linear solid whose two influence functions are corrected at
// each point by Lagrange multipliers, so that the dilatation of every homogeneous small strain
// and the deviatoric energy of six matching deformations are those of the continuum at every
// point, surface points included. At point i, for a bond xi (doc/theory/pals.md):
//   omega_i(xi) = omega_0(|xi|) + xi . Lambda_i . xi        (Lambda_i symmetric: 6 multipliers)
//   sigma_i(xi) = sigma_0(|xi|) + sum_k tau_ik g_k(xi)^2      (g_k: 6 matching extensions)
//   theta_i = sum_j (1 - d) omega_i |xi| e V_j,   e^d = e - theta_i |xi| / 3,
//   W_i = K/2 theta_i^2 + G sum_j (1 - d) sigma_i (e^d)^2 V_j,
//   t_i<xi> = (1 - d) (p_i omega_i |xi| + 2 G sigma_i e^d),
//   p_i = K theta_i - (2 G / 3) sum_j (1 - d) sigma_i |xi| e^d V_j.
#include "materials/MaterialModel.hpp"

namespace peridot {

class Pals : public MaterialModel {
 public:
  static constexpr int kMultipliers = 6;
  // The influence functions omega_0 and sigma_0 Peridigm offers (zeta = |xi|, delta the horizon).
  enum class Kernel { One, ParabolicDecay, Gaussian };

  explicit Pals(ListReader& params);
  double density() const override { return density_; }
  double bulkModulus() const override { return constants_.bulkModulus; }
  double youngsModulus() const override { return constants_.youngsModulus; }
  double poissonsRatio() const override { return constants_.poissonsRatio; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterInitialize() const override;
  std::vector<std::string> fieldsToSyncAfterPrecompute() const override {
    return {kDilatation, kPressure};
  }
  void precompute(const ModelState& state, const std::vector<int>& points) override;
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  TangentReach tangentReach() const override { return TangentReach::Family; }
  bool hasAnalyticTangent() const override { return true; }
  void addStiffness(const ModelState& state, const std::vector<int>& points,
                    TangentBlocks& K) const override;
  std::vector<std::string> outputFields() const override;
  std::string family() const override { return "PALS"; }

  static double kernel(Kernel k, double zeta, double delta);
  // Name of the n-th (1-based) multiplier field, as Peridigm outputs it.
  static std::string dilatationMultiplierName(int n);
  static std::string deviatoricMultiplierName(int n);

  static constexpr const char* kWeightedVolume = "Weighted_Volume";
  static constexpr const char* kDilatation = "Dilatation";
  static constexpr const char* kPressure = "Pals_Pressure";
  static constexpr const char* kDilatationNormalization = "Dilatation_Normalization";
  static constexpr const char* kDeviatoricNormalization = "Deviatoric_Normalization";

 private:
  // Solves the two 6x6 systems of point i; returns an error message ("" on success).
  std::string computeMultipliers(const ModelState& s, int i);
  // omega and sigma of every bond of `points`, at both ends (the far end's from its ghosted
  // multipliers), stored per bond entry once the multipliers are known everywhere.
  void tabulateInfluence(const ModelState& s, const std::vector<int>& points);
  double omegaAt(const ModelState& s, int point, const double xi[3]) const;
  double sigmaAt(const ModelState& s, int point, const double xi[3]) const;

  double density_ = 0;
  ElasticConstants constants_;
  Kernel dilatationKernel_ = Kernel::One, deviatoricKernel_ = Kernel::One;
  double* weightedVolume_ = nullptr;
  double* dilatation_ = nullptr;
  double* pressure_ = nullptr;
  double* dilatationNormalization_ = nullptr;
  double* deviatoricNormalization_ = nullptr;
  double* lambda_[kMultipliers] = {};  // dilatation multipliers, per point
  double* tau_[kMultipliers] = {};     // deviatoric multipliers, per point
  // Per bond entry: omega and sigma of the owner (i) and of the far end (j, on the reversed bond).
  std::vector<double> omegaOwn_, sigmaOwn_, omegaFar_, sigmaFar_;
  std::vector<unsigned char> tabulated_;  // per owned point
};

}  // namespace peridot
