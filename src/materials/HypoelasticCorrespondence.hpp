#pragma once
// Peridigm's hypoelastic correspondence family ("Elastic Hypoelastic Correspondence", "Elastic
// Plastic Hypoelastic Correspondence", "Isotropic Hardening Hypoelastic Correspondence"; theory
// in doc/theory/hypoelastic-correspondence.md). Unlike the correspondence models of
// materials/Correspondence.hpp (a shape tensor and F in the reference configuration, one stress
// per point, hourglass control), this family works in the current configuration with a stress
// per bond, which removes the zero-energy modes without an hourglass force:
//
//   gradient weights  g_ij of materials/GradientOperator.hpp ("Gradient Order Of Accuracy" n)
//                     on the current bonds Y = y_j - y_i, volumes J_j V_j, scaled by "Actual
//                     Horizon" delta (with Peridigm's influence "One" the scale cancels)
//   velocity gradient L_i = sum_j (v_j - v_i) (x) g_ij J_j V_j,  J_i <- J_i (1 + tr L_i dt)
//   bond gradient     L_ij = Lbar + (v_j - v_i - Lbar Y) (x) Y / |Y|^2,  Lbar = (L_i + L_j) / 2
//                     (the same on both ends of the bond, to the last bit)
//   per bond          Flanagan-Taylor step of V_ij, R_ij from L_ij (materials/CorrespondenceRate)
//                     and the model's law on the unrotated stress; sigma_ij = R sigma_u R^T
//   weighted volume   m_i = sum_j (1 - d) J_j V_j
//   nonhomogeneity    N_i = sum_j (1 - d) (1/(2 m_i) + 1/(2 m_j)) J_j V_j sigma_ij (I - Y Y/|Y|^2)
//   force state       T_ij = (1 - d) sigma_ij Y / (m_i |Y|^2) + N_i g_ij
//   force density     f_i = J_i sum_j (T_ij - T_ji) J_j V_j   (J at the start of the step)
//
// A homogeneous stress sigma gives sum_j T_ij (x) Y J_j V_j = sigma exactly (the two terms add
// up to sigma), so the force matches the continuum traction. Point-level V, R, sigma_u, F and
// eps_p are also advanced from L_i, for output only (as Peridigm).
//
// Pull form: point i evaluates both ends of its bonds. T_ji needs m_j, J_j and N_j g_ji =
// (N_j Z_j) Q(-Y / delta) (1 - d) / delta, Z_j the gradient rows of j's moment matrix inverse: m,
// L, J and the 3 x basisSize matrix B = N Z are ghosted, so results do not depend on the rank
// count. B needs the bond stresses of the step: computeForce refreshes its ghosts itself (a
// second exchange), and processes in its first call of an evaluation every point of the model
// (all its blocks). Explicit dynamics only (no tangent), 3D only.
#include <algorithm>
#include <string>
#include <vector>

#include "materials/Correspondence.hpp"
#include "materials/CorrespondenceRate.hpp"
#include "materials/GradientOperator.hpp"
#include "materials/MaterialModel.hpp"

namespace peridot {

class HypoelasticCorrespondence : public MaterialModel {
 public:
  double density() const override { return density_; }
  double bulkModulus() const override { return constants_.bulkModulus; }
  double youngsModulus() const override { return constants_.youngsModulus; }
  double poissonsRatio() const override { return constants_.poissonsRatio; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterInitialize() const override;
  std::vector<std::string> fieldsToSyncAfterPrecompute() const override;
  // Gradient weights, L, m, the step's J and the point-level (output) update.
  void precompute(const ModelState& state, const std::vector<int>& points) override;
  // Bond stresses, N, B (ghosted here), the force, and the commit of the history.
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  std::vector<std::string> outputFields() const override;
  std::vector<std::string> historyNodeFields() const override;
  bool advancesHistory() const override { return true; }
  bool needsVelocity() const override { return true; }
  // One tag per model instance: the ghosted B of a neighbour must come from this very model.
  std::string family() const override { return family_; }
  int gradientOrder() const { return order_; }

  static constexpr const char* kJacobian = "Jacobian_Determinant";
  static constexpr const char* kWeightedVolume = "Weighted_Volume";
  static constexpr const char* kVelocityGradientRows[3] = {
      "Hypoelastic_L_Row_X", "Hypoelastic_L_Row_Y", "Hypoelastic_L_Row_Z"};

 protected:
  HypoelasticCorrespondence(ListReader& params, const std::string& name);
  const std::string& name() const { return name_; }
  // The bond loop with the model's law (one call per evaluation; the law is inlined in it).
  // Law: void operator()(int slot, const double* d, double dt, const double* sigmaN,
  // double* sigma, bool bond) const, slot a bond (bond true) or a point index; writes the
  // unrotated stress at the step's end. The plastic laws keep their eps_p by slot.
  virtual void bondStresses(const ModelState& s) = 0;
  virtual void pointStresses(const ModelState& s, const std::vector<int>& points) = 0;
  virtual void commitLaw(const ModelState&, const std::vector<int>&) {}
  template <class Law>
  void bondStressesWith(const ModelState& s, const Law& law);
  template <class Law>
  void pointStressesWith(const ModelState& s, const std::vector<int>& points, const Law& law);

  ElasticConstants constants_;
  double lame_ = 0.0;
  std::vector<int> points_;  // every owned point of the model (all blocks)
  // Per point: d and the step-start sigma_u (the laws' inputs); per bond: the same.
  double* unrotatedRate_ = nullptr;
  double* unrotated_ = nullptr;
  std::vector<double> bondUnrotatedNew_;  // 9 per bond: this step's sigma_u (committed later)
  std::vector<double> unrotatedNew_;      // 9 per point
  // The step's L_ij is rebuilt per bond from these (rows of L, ghosted).
  std::string name_, family_;
  double density_ = 0.0, actualHorizon_ = 0.0;
  int order_ = 1;
  bool pending_ = false;  // a precompute ran; the next computeForce processes every point
  gradient::Operator op_{1, 3};
  // Per bond (overlap CSR of owned points): weights g (3), this step's sigma_ij (9); the
  // committed V_ij, R_ij, sigma_u,ij (9 each, bond fields saved by checkpoints).
  std::vector<double> g_, bondSigma_, bondRateScratch_;
  std::vector<double>* bondV_[9] = {};
  std::vector<double>* bondR_[9] = {};
  std::vector<double>* bondSigmaU_[9] = {};
  std::vector<double> Z_;  // per owned point: 3 x basisSize rows of M^-1 (GradientOperator::rows)
  std::vector<double> nonhomogeneity_;       // N, 9 per point
  std::vector<double> bondVNew_, bondRNew_;  // 9 per bond
  std::vector<double> jacobianNew_, rotationNew_, stretchNew_, gradientNew_;
  double* jacobian_ = nullptr;
  double* weightedVolume_ = nullptr;
  double* lRow_[3] = {nullptr, nullptr, nullptr};
  std::vector<double*> bColumn_;  // basisSize ghosted 3-vectors: column k of B = N Z
  std::vector<std::string> bNames_;
  double* velocityGradient_ = nullptr;
  double* rotation_ = nullptr;
  double* leftStretch_ = nullptr;
  double* cauchy_ = nullptr;
  double* vonMises_ = nullptr;
  double* deformationGradient_ = nullptr;
  double* greenStrain_ = nullptr;
  void gradientWeights(const ModelState& s, int i, std::string& message);
  void forceLoop(const ModelState& s);
  // V, R of bond b (committed, SoA bond fields) into 9-arrays.
  void gatherBond(const std::vector<double>* const* field, std::int64_t b, double* out) const {
    for (int k = 0; k < 9; ++k) out[k] = (*field[k])[b];
  }
};

// L_ij of bond b of point i (to j), from the ghosted rows of L and the velocities.
inline void bondVelocityGradient(const ModelState& s, double* const* lRow, int i, int j,
                                 double* Lb) {
  double Lbar[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) Lbar[3 * r + c] = 0.5 * (lRow[r][3 * i + c] + lRow[r][3 * j + c]);
  const double Y[3] = {s.y[3 * j] - s.y[3 * i], s.y[3 * j + 1] - s.y[3 * i + 1],
                       s.y[3 * j + 2] - s.y[3 * i + 2]};
  const double YY = Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2];
  if (!(YY > 0)) {  // coincident ends: the bond carries no force; keep its stress finite
    std::copy(Lbar, Lbar + 9, Lb);
    return;
  }
  for (int r = 0; r < 3; ++r) {
    const double dv = s.velocity[3 * j + r] - s.velocity[3 * i + r];
    const double miss =
        (dv - (Lbar[3 * r] * Y[0] + Lbar[3 * r + 1] * Y[1] + Lbar[3 * r + 2] * Y[2])) / YY;
    for (int c = 0; c < 3; ++c) Lb[3 * r + c] = Lbar[3 * r + c] + miss * Y[c];
  }
}

template <class Law>
void HypoelasticCorrespondence::bondStressesWith(const ModelState& s, const Law& law) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points_) {
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      double Lb[9], Vn[9], Rn[9], sigmaN[9], d[9];
      bondVelocityGradient(s, lRow_, i, j, Lb);
      gatherBond(bondV_, b, Vn);
      gatherBond(bondR_, b, Rn);
      gatherBond(bondSigmaU_, b, sigmaN);
      double* Vnew = bondVNew_.data() + 9 * b;
      double* Rnew = bondRNew_.data() + 9 * b;
      correspondence::flanaganTaylorStep(Lb, Vn, Rn, s.dt, Vnew, Rnew, d);
      double* sigmaU = bondUnrotatedNew_.data() + 9 * b;
      law(static_cast<std::size_t>(b), d, s.dt, sigmaN, sigmaU, true);
      double tmp[9];
      correspondence::multiply(Rnew, sigmaU, tmp);
      correspondence::multiplyTransposed(tmp, Rnew, bondSigma_.data() + 9 * b);
    }
  }
}

template <class Law>
void HypoelasticCorrespondence::pointStressesWith(const ModelState& s,
                                                  const std::vector<int>& points, const Law& law) {
  for (int i : points)
    law(static_cast<std::size_t>(i), unrotatedRate_ + 9 * i, s.dt, unrotated_ + 9 * i,
        unrotatedNew_.data() + 9 * i, false);
}

}  // namespace peridot
