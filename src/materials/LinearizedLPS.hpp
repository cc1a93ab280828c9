#pragma once
// Linearized LPS (paper 001, eqs. 17-19; the elastic part of Lipton, Said and Jha's model):
// the linear peridynamic solid written with the linearized bond strain eps = xi.eta/|xi|^2 and
// forces along the reference bond xi/|xi|:
//   theta_i = (kappa / m_i) sum_j omega |xi|^2 eps mu V_j,
//   t_i<xi> = [ (c1 / m_i) mu theta_i + c2_i F(eps) ] mu omega |xi|,
// mu = 1 - bond damage (LSJ-T's h of its history integral), F the block's bond law (eps, or
// DTT's smooth F). 3D: kappa = 3, c1 = 3 (lambda - G), c2 = 15 G / m. Plane strain: kappa = 2,
// c1 = 2 (lambda - G), c2 = 8 G / m. Plane stress: kappa = 2 (1 - 2 nu) / (1 - nu),
// c1 = E (1 - 3 nu) / ((1 + nu)(2 nu - 1)), c2 = 8 G / m. Derivation in doc/theory/damage.md.
#include "materials/MaterialModel.hpp"

namespace peridot {

class LinearizedLPS : public MaterialModel {
 public:
  explicit LinearizedLPS(ListReader& params);
  double density() const override { return density_; }
  double bulkModulus() const override { return constants_.bulkModulus; }
  double youngsModulus() const override { return constants_.youngsModulus; }
  double poissonsRatio() const override { return constants_.poissonsRatio; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterInitialize() const override {
    return {kWeightedVolume, kAlpha, kBeta};
  }
  std::vector<std::string> fieldsToSyncAfterPrecompute() const override { return {kDilatation}; }
  void precompute(const ModelState& state, const std::vector<int>& points) override;
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  std::vector<std::string> outputFields() const override { return {kWeightedVolume, kDilatation}; }
  std::string family() const override { return "linearized LPS"; }
  // No analytic tangent: probed by finite differences over the family pattern.
  TangentReach tangentReach() const override { return TangentReach::Family; }
  PlaneMode planeMode() const override { return mode_; }
  bool acceptsInfluenceFunction(const std::string&) const override { return true; }
  bool acceptsSmoothBondLaw() const override { return true; }
  // The block's LSJ-T update, or DTT's damage, runs in the dilatation loop (one walk over the
  // bonds less a step): each point's dilatation reads only its own bonds' damage.
  bool breaksInPrecompute() const override { return true; }
  bool fusesLsjtUpdate() const override { return true; }
  bool fusesSmoothBreak() const override { return true; }

  // kappa, c1 and m_i c2_i of the header comment, for the material's constants and mode.
  double kappa() const { return kappa_; }
  double c1() const { return c1_; }
  double c2TimesWeightedVolume() const { return c2m_; }

  static constexpr const char* kWeightedVolume = "Weighted_Volume";
  static constexpr const char* kDilatation = "Dilatation";
  // Per point: alpha = c2 (bond strain), beta = c1 / m (dilatation).
  static constexpr const char* kAlpha = "Linearized_LPS_Alpha";
  static constexpr const char* kBeta = "Linearized_LPS_Beta";

 private:
  // Which damage update the dilatation loop applies to each bond before it enters the sum.
  enum class Fused { None, Lsjt, Dtt };
  template <Fused kFused>
  void dilatationLoop(const ModelState& state, const std::vector<int>& points);

  double density_ = 0;
  ElasticConstants constants_;
  PlaneMode mode_ = PlaneMode::ThreeD;
  double kappa_ = 3, c1_ = 0, c2m_ = 0;
  double* weightedVolume_ = nullptr;
  double* dilatation_ = nullptr;
  double* alpha_ = nullptr;
  double* beta_ = nullptr;
  std::vector<double> scratch_;  // one point's xi.eta, strains and LSJ-T integrals (fused)
};

}  // namespace peridot
