#pragma once
// The bond-associated correspondence models (Peridigm's "Elastic / Elastic Plastic / Isotropic
// Hardening Bond Associated Correspondence"; theory and checks in
// doc/theory/bond-associated-correspondence.md). A stress per bond, not per point, from the
// bond's own deformation gradient F_b (materials/BondAssociatedKinematics.hpp): a deformation
// that stretches a bond differently from what the two ends' gradients predict (the zero-energy
// modes of plain correspondence) stresses that bond, so no hourglass control is needed.
//
// Per bond, the rate form of materials/CorrespondenceRate.hpp: L_b = Fdot_b F_b^-1, Flanagan and
// Taylor's update of the bond's V_b and R_b, d_b = R_b^T D_b R_b, the unrotated Cauchy stress
// sigma_u += dt (lambda tr(d) I + 2 mu d) with (plastic models) the J2 return of
// materials/J2Return.hpp, sigma_b = R_b sigma_u R_b^T, P_b = J_b sigma_b F_b^-T. The bond history
// (sigma_u, R, V, eps_p) is kept per bond entry, as Peridigm keeps it.
//
// Force state (Peridigm's), with phi_ij the gradient weights of "Gradient Order Of Accuracy" n
// (n = 1: phi_ij = w_ij K_i^-1 xi; n > 1: materials/GradientOperator.hpp on the reference bonds,
// which also give F_i = I + sum_j (u_j - u_i) (x) phi_ij V_j and Fdot_i likewise):
//   T_i<xi> = w_ij P_b xi / (m_i |xi|^2) + S_i phi_ij,
//   S_i = sum_j w_ij (1/(2 m_i) + 1/(2 m_j)) P_b (I - xi (x) xi / |xi|^2) V_j,
// so that sum_j T_i<xi> (x) xi V_j = P for a homogeneous deformation (the correspondence
// condition: sum_j phi_ij (x) xi V_j = I at any order). Pull form: f_i = sum_j [T_i<xi> -
// T_j<-xi>] V_j; for n = 1
//   = sum_j [ (w_ij / m_i + w_ji / m_j) P_b xi / |xi|^2 + (w_ij B_i + w_ji B_j) xi ] V_j,
// B = S K^-1; for n > 1 phi_ij = w_ij Zs_i q(xi) (q the monomials of xi, Zs the rows of the
// moment matrix's inverse rescaled by the horizon powers) and B = S Zs, 3 x dim q per point:
//   = sum_j [ (w_ij / m_i + w_ji / m_j) P_b xi / |xi|^2 + w_ij B_i q(xi) - w_ji B_j q(-xi) ] V_j,
// with P_b computed again by i's owner (the same bits as j's: F_b, L_b and the
// bond's history are the same from both ends). Three passes: (1) point F, Fdot, 1/m, ghosted
// inside precompute; (2) the bonds' stresses and B_i, ghosted after precompute; (3) the force.
//
// Point-level outputs (Cauchy_Stress, Von_Mises_Stress, Equivalent_Plastic_Strain, ...) come,
// as in Peridigm, from the same constitutive update driven by the point's own F and Fdot (for
// visualisation; the force uses the bonds' stresses only).
#include <string>
#include <vector>

#include "materials/GradientOperator.hpp"
#include "materials/J2Return.hpp"
#include "materials/MaterialModel.hpp"

namespace peridot {

class BondAssociatedCorrespondence : public MaterialModel {
 public:
  double density() const override { return density_; }
  double bulkModulus() const override { return constants_.bulkModulus; }
  double youngsModulus() const override { return constants_.youngsModulus; }
  double poissonsRatio() const override { return constants_.poissonsRatio; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterPrecompute() const override;
  void precompute(const ModelState& state, const std::vector<int>& points) override;
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  std::vector<std::string> outputFields() const override;
  std::vector<std::string> historyNodeFields() const override;
  bool advancesHistory() const override { return true; }
  bool needsVelocity() const override { return true; }
  // Not bonded to plain correspondence points, nor to bond-associated points of another gradient
  // order: the force reads the far end's B (whose layout is the order's) and 1/m.
  std::string family() const override;
  // f_i reads B_j, which reads the stresses of j's bonds, which read F of j's neighbours: three
  // bonds deep, beyond the probed tangent's reach. Explicit dynamics only (Peridigm has no
  // implicit tangent for these models either).
  TangentReach tangentReach() const override { return TangentReach::None; }
  bool acceptsInfluenceFunction(const std::string&) const override { return true; }
  bool plastic() const { return plastic_; }
  int gradientOrder() const { return order_; }

  static constexpr const char* kShapeTensorInverse = "Shape_Tensor_Inverse";
  static constexpr const char* kDeformationGradient = "Deformation_Gradient";
  static constexpr const char* kCauchyStress = "Cauchy_Stress";
  static constexpr const char* kUnrotatedCauchyStress = "Unrotated_Cauchy_Stress";
  static constexpr const char* kVonMisesStress = "Von_Mises_Stress";
  static constexpr const char* kRotationTensor = "Rotation_Tensor";
  static constexpr const char* kLeftStretchTensor = "Left_Stretch_Tensor";
  static constexpr const char* kVelocityGradient = "Velocity_Gradient";
  static constexpr const char* kUnrotatedRateOfDeformation = "Unrotated_Rate_Of_Deformation";
  static constexpr const char* kWeightedVolume = "Weighted_Volume";
  static constexpr const char* kEquivalentPlasticStrain = "Equivalent_Plastic_Strain";
  static constexpr const char* kStressTriaxiality = "Stress_Triaxiality";
  // Bond fields (one value per bond entry), Peridigm's names: the bond's history and, for the
  // plastic models, its von Mises stress and triaxiality (what ductile damage models read).
  static constexpr const char* kBondUnrotatedCauchyStress[9] = {
      "Unrotated_Cauchy_Stress_XX", "Unrotated_Cauchy_Stress_XY", "Unrotated_Cauchy_Stress_XZ",
      "Unrotated_Cauchy_Stress_YX", "Unrotated_Cauchy_Stress_YY", "Unrotated_Cauchy_Stress_YZ",
      "Unrotated_Cauchy_Stress_ZX", "Unrotated_Cauchy_Stress_ZY", "Unrotated_Cauchy_Stress_ZZ"};
  static constexpr const char* kBondRotationTensor[9] = {
      "Rotation_Tensor_XX", "Rotation_Tensor_XY", "Rotation_Tensor_XZ",
      "Rotation_Tensor_YX", "Rotation_Tensor_YY", "Rotation_Tensor_YZ",
      "Rotation_Tensor_ZX", "Rotation_Tensor_ZY", "Rotation_Tensor_ZZ"};
  static constexpr const char* kBondLeftStretchTensor[9] = {
      "Left_Stretch_Tensor_XX", "Left_Stretch_Tensor_XY", "Left_Stretch_Tensor_XZ",
      "Left_Stretch_Tensor_YX", "Left_Stretch_Tensor_YY", "Left_Stretch_Tensor_YZ",
      "Left_Stretch_Tensor_ZX", "Left_Stretch_Tensor_ZY", "Left_Stretch_Tensor_ZZ"};
  static constexpr const char* kBondEquivalentPlasticStrain = "Bond_Equivalent_Plastic_Strain";
  static constexpr const char* kBondVonMisesStress = "Bond_Von_Mises_Stress";
  static constexpr const char* kBondStressTriaxiality = "Bond_Stress_Triaxiality";
  // Ghosted point tensors, by rows: F, Fdot (inside precompute), B = S K^-1 (after it).
  static constexpr const char* kDeformationGradientRows[3] = {
      "BondAssociated_F_Row_X", "BondAssociated_F_Row_Y", "BondAssociated_F_Row_Z"};
  static constexpr const char* kDeformationRateRows[3] = {
      "BondAssociated_Fdot_Row_X", "BondAssociated_Fdot_Row_Y", "BondAssociated_Fdot_Row_Z"};
  static constexpr const char* kStressIntegralRows[3] = {
      "BondAssociated_B_Row_X", "BondAssociated_B_Row_Y", "BondAssociated_B_Row_Z"};
  static constexpr const char* kInverseWeightedVolume = "BondAssociated_Inverse_Weighted_Volume";
  // Gradient order n > 1: column k of B = S Zs, one ghosted 3-vector per monomial.
  static constexpr const char* kStressIntegralColumnPrefix = "BondAssociated_B_Column_";

 protected:
  BondAssociatedCorrespondence(ListReader& params, const std::string& name);
  // Makes the model J2-plastic with this hardening curve (derived constructors).
  void setPlasticity(const correspondence::Hardening& hardening);

 private:
  std::string name_;
  double density_ = 0.0, lame_ = 0.0;
  ElasticConstants constants_;
  bool plastic_ = false;
  correspondence::Hardening hardening_;
  // "Gradient Order Of Accuracy" n; for n > 1 the gradient operator, the parity (-1)^degree of
  // each monomial (q(-xi) = parity q(xi)), each owned point's rescaled rows Zs (3 x dim q: the
  // weight of bond xi is w Zs q(xi), q the monomials of xi itself), the ghosted columns of B,
  // and the scratch of one point's bonds.
  int order_ = 1;
  gradient::Operator op_{1, 3};
  std::vector<double> parity_, scaledRows_;
  std::vector<double*> bColumn_;
  std::vector<std::string> bColumnNames_;
  std::vector<double> bondXi_, bondWeight_, bondVolume_, bondPhi_;
  // Point outputs and point history (sigma_u, R, V, eps_p: outputs only, see above).
  double *shapeTensorInverse_ = nullptr, *deformationGradient_ = nullptr, *cauchy_ = nullptr,
         *unrotated_ = nullptr, *vonMises_ = nullptr, *rotation_ = nullptr, *leftStretch_ = nullptr,
         *velocityGradient_ = nullptr, *unrotatedRate_ = nullptr, *weightedVolume_ = nullptr,
         *eqps_ = nullptr, *triaxiality_ = nullptr, *inverseWeightedVolume_ = nullptr;
  double* fRow_[3] = {nullptr, nullptr, nullptr};
  double* fdotRow_[3] = {nullptr, nullptr, nullptr};
  double* bRow_[3] = {nullptr, nullptr, nullptr};
  // Bond history, committed (one array per component, Peridigm's layout) ...
  double* bondSigma_[9] = {};
  double* bondRotation_[9] = {};
  double* bondStretch_[9] = {};
  double* bondEqps_ = nullptr;
  double* bondVonMises_ = nullptr;
  double* bondTriaxiality_ = nullptr;
  // ... and this step's from the last precompute, in the same layout (component k of bond entry
  // b at [k][b]: the commit is a contiguous copy per point), committed by computeForce.
  std::vector<double> bondSigmaNew_[9], bondRotationNew_[9], bondStretchNew_[9], bondEqpsNew_;
  // P_b xi / |xi|^2 of every bond entry, from precompute for the force.
  std::vector<double> bondTraction_;
  // The point history's step-end values, committed by computeForce.
  std::vector<double> unrotatedNew_, rotationNew_, stretchNew_, eqpsNew_;

  // The constitutive update of one stress point (bond or point): sigma from sigmaN and d over
  // dt; returns the new eps_p.
  double updateStress(const double* d, double dt, const double* sigmaN, double eqpsN,
                      double* sigma) const;
  // Pass 1 for owned point i: F, Fdot, 1/m and the point outputs; false if K (or, for n > 1,
  // the moment matrix) is singular.
  bool pointKinematics(const ModelState& s, int i, std::string& message);
  // For n > 1: the gradient weights phi_ij of owned point i's bonds into bondPhi_, and its Zs;
  // false when the moment matrix is singular.
  bool higherOrderWeights(const ModelState& s, int i);
  // For n > 1: F_i = I + sum_j (u_j - u_i) (x) phi_ij V_j and M = sum_j (v_j - v_i) (x) phi_ij
  // V_j (= Fdot_i), from the weights of the last higherOrderWeights(i).
  void higherOrderGradients(const ModelState& s, int i, double* F, double* Fdot) const;
  // Pass 3 (the force), for n = 1 (one vectorisable pass) and n > 1.
  void firstOrderForce(const ModelState& s, const std::vector<int>& points) const;
  void higherOrderForce(const ModelState& s, const std::vector<int>& points) const;
  // Pass 2 for owned point i: its bonds' stresses, B_i.
  void bondStresses(const ModelState& s, int i, std::string& message);
};

}  // namespace peridot
