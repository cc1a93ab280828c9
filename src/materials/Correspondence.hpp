#pragma once
// The machinery shared by the non-ordinary correspondence models (Silling 2007, "Peridynamic
// states and constitutive modeling", section 15; theory and checks in
// doc/theory/correspondence.md):
//
//   shape tensor         K_i = sum_j w_ij xi (x) xi V_j            (w = omega (1 - d))
//   deformation gradient F_i = [sum_j w_ij Y (x) xi V_j] K_i^-1    (exact for any affine motion)
//   force state          T_i<xi> = w_ij P_i K_i^-1 xi              (P: first Piola-Kirchhoff)
//   hourglass control    Peridigm's form: a bond spring on the part of Y that F_i does not
//                        explain, T^hg = (1 - d) C_hg ((Y - F_i xi) . Y) / (|xi| |Y|) Y with
//                        C_hg = 18 c_hg K / (pi delta^4), c_hg = "Hourglass Coefficient"
//
// Two ways to integrate the stress ("Stress Integration"):
//   "Hypoelastic Rate" (default, as Peridigm): each step, the velocity gradient L = Fdot F^-1,
//     Flanagan and Taylor's update of V and R and the unrotated rate of deformation d = R^T D R
//     (materials/CorrespondenceRate.hpp); the model advances the unrotated Cauchy stress
//     sigma_u by d dt; sigma = R sigma_u R^T and P = J sigma F^-T. sigma_u, R and V are history
//     (committed once per step, saved in checkpoints).
//   "Total Lagrangian Green Strain" (Peridot extension): the second Piola-Kirchhoff stress S of
//     a point from its Green strain E = (F^T F - I) / 2, P = F S; R and V from F's polar
//     decomposition.
// A model derived from CorrespondenceMaterial supplies only its constitutive law (one for each
// form) and commits its history once per step. Everything else — the bond loops, the
// singular-shape-tensor diagnostics, the output tensors — lives here.
//
// Pull form: point i adds both ends' force states of each bond, f_i = sum_j [T_i<xi> -
// T_j<-xi>] V_j = sum_j (w_ij A_i + w_ji A_j) xi V_j with A = P K^-1; A and F are ghosted after
// precompute, so the result does not depend on the rank count.
//
// A shape tensor is singular when the point has fewer than three non-coplanar intact bonds.
// Peridigm stops the run there ("failed to compute shape tensor ... Is the horizon too
// small?"); so does Peridot, collectively, naming the point, its position, and its bond count,
// at set-up (InputError) or after bonds broke (RunError). Never a NaN. A point whose bonds have
// all broken is the exception: it is cut loose (zero stress and force state), not an error.
#include <string>
#include <vector>

#include "materials/MaterialModel.hpp"

namespace peridot {

namespace correspondence {

// 3x3 tensors, row-major (a[3 r + c]), as Peridigm orders its full-tensor output (XX XY XZ YX..).
// c = a b
void multiply(const double* a, const double* b, double* c);
// c = a b^T
void multiplyTransposed(const double* a, const double* b, double* c);
double determinant(const double* a);
// inverse of a; false (and zeros) when det(a) is 0 or the matrix is ill-conditioned relative to
// its own scale: |det a| <= tolerance * (|a|_F / sqrt 3)^3.
bool invert(const double* a, double* inverse, double tolerance = 1e-10);
// Rotation R of the polar decomposition F = R U (det F > 0), by Higham's iteration
// R <- (R + R^-T) / 2; false when F is singular or inverted.
bool polarRotation(const double* F, double* R);
// sqrt(3/2 s:s), s the deviator of the symmetric part of a.
double vonMises(const double* a);

// Shape tensor inverse and deformation gradient of point i from the current coordinates `y`
// (one pass over its bonds, weights omega (1 - d) on its own side). Returns false when the shape
// tensor is singular (Kinv and F are then zero). `useDamage` false ignores the bond damage
// (Peridigm's Deformation_Gradient compute). In a planar run F is the in-plane F with F_zz = 1.
// With `velocitySums`, the same pass also sums M = sum_j w (v_j - v_i) (x) xi V_j from
// `s.velocity` (the rate form's Fdot = M K^-1).
bool shapeTensorAndDeformationGradient(const ModelState& s, int i, double* Kinv, double* F,
                                       bool useDamage = true, double* velocitySums = nullptr);

// True when damage has broken every bond on the point's own side (a point cut loose by ductile
// damage): its singular shape tensor is then no error, the point carries no stress.
bool detached(const ModelState& s, int i);

// "point <id> at (x, y, z) (N intact bonds of M)": the diagnostics' description of a point.
std::string describePoint(const ModelState& s, int i);

}  // namespace correspondence

class CorrespondenceMaterial : public MaterialModel {
 public:
  enum class StressIntegration { HypoelasticRate, GreenStrain };
  double density() const override { return density_; }
  double bulkModulus() const override { return constants_.bulkModulus; }
  double youngsModulus() const override { return constants_.youngsModulus; }
  double poissonsRatio() const override { return constants_.poissonsRatio; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterPrecompute() const override {
    return {kDeformationGradientRows[0], kDeformationGradientRows[1], kDeformationGradientRows[2],
            kForceTensorRows[0],         kForceTensorRows[1],         kForceTensorRows[2]};
  }
  // Shape tensor, F, the stress of the model (trial history only), P K^-1 and the outputs.
  void precompute(const ModelState& state, const std::vector<int>& points) override;
  // Force density (and Hourglass_Force_Density) of the points; then commits the model's history.
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  std::vector<std::string> outputFields() const override;
  // The rate form's history: the unrotated Cauchy stress, R and V.
  std::vector<std::string> historyNodeFields() const override;
  bool advancesHistory() const override { return rateForm(); }
  bool needsVelocity() const override { return rateForm(); }
  bool rateForm() const { return integration_ == StressIntegration::HypoelasticRate; }
  std::string family() const override { return "correspondence"; }
  // f_i reads A and F of its neighbours (their families): probed by finite differences.
  TangentReach tangentReach() const override { return TangentReach::Family; }
  // K and F use the same weights, so F is exact for affine motion whatever omega is.
  bool acceptsInfluenceFunction(const std::string&) const override { return true; }

  static constexpr const char* kShapeTensorInverse = "Shape_Tensor_Inverse";
  static constexpr const char* kDeformationGradient = "Deformation_Gradient";
  static constexpr const char* kCauchyStress = "Cauchy_Stress";
  static constexpr const char* kUnrotatedCauchyStress = "Unrotated_Cauchy_Stress";
  static constexpr const char* kVonMisesStress = "Von_Mises_Stress";
  static constexpr const char* kHourglassForceDensity = "Hourglass_Force_Density";
  // The polar decomposition F = R U = V R.
  static constexpr const char* kRotationTensor = "Rotation_Tensor";
  static constexpr const char* kLeftStretchTensor = "Left_Stretch_Tensor";
  // The rate form's kinematics (zero with the Green strain): L and d = R^T sym(L) R.
  static constexpr const char* kVelocityGradient = "Velocity_Gradient";
  static constexpr const char* kUnrotatedRateOfDeformation = "Unrotated_Rate_Of_Deformation";
  // Per point, ghosted, by rows (ghost refreshes move 1- or 3-component fields): F, and
  // A = P K^-1, the tensor that maps a bond xi to the force state.
  static constexpr const char* kDeformationGradientRows[3] = {
      "Correspondence_F_Row_X", "Correspondence_F_Row_Y", "Correspondence_F_Row_Z"};
  static constexpr const char* kForceTensorRows[3] = {
      "Correspondence_A_Row_X", "Correspondence_A_Row_Y", "Correspondence_A_Row_Z"};

 protected:
  CorrespondenceMaterial(ListReader& params, const std::string& name);
  // The model's second Piola-Kirchhoff stress S of owned point i from its Green strain E (both
  // symmetric 3x3, row-major). Called from precompute, which may be repeated: keep the
  // step's new history in scratch space and commit it in commitHistory.
  virtual void secondPiolaKirchhoff(int i, const double* E, double* S) = 0;
  virtual void commitHistory(const std::vector<int>&) {}
  // A point cut loose by damage (correspondence::detached) skips the constitutive update: its
  // step-end history is the committed one. The base holds the rate form's sigma_u, R and V; a
  // model with its own history holds it too (and calls this).
  virtual void holdHistory(int i);
  // The rate form: the unrotated Cauchy stress of owned point i at the end of a step of size dt
  // from its value sigmaN at the start and the unrotated rate of deformation d (symmetric).
  // Called from precompute, like secondPiolaKirchhoff. Default: the linear hypoelastic law
  // sigma = sigmaN + dt (lambda tr(d) I + 2 mu d).
  virtual void unrotatedCauchyStress(int i, const double* d, double dt, const double* sigmaN,
                                     double* sigma);
  // Recoverable energy density of point i at Green strain E (no hourglass term).
  virtual double energyDensity(int i, const double* E) const;
  // The St Venant-Kirchhoff stress S = lambda tr(E) I + 2 mu E.
  void elasticStress(const double* E, double* S) const;
  const std::string& name() const { return name_; }
  StressIntegration integration_ = StressIntegration::HypoelasticRate;

  ElasticConstants constants_;
  double lame_ = 0.0;  // lambda

 private:
  std::string name_;
  double density_ = 0.0, hourglassCoefficient_ = 0.0;
  double* shapeTensorInverse_ = nullptr;
  double* deformationGradient_ = nullptr;
  double* cauchy_ = nullptr;
  double* unrotated_ = nullptr;
  double* vonMises_ = nullptr;
  double* hourglass_ = nullptr;
  double* rotation_ = nullptr;
  double* leftStretch_ = nullptr;
  double* velocityGradient_ = nullptr;
  double* unrotatedRate_ = nullptr;
  // The rate form's step-end sigma_u, R, V from the last precompute (9 per overlap point),
  // committed by computeForce.
  std::vector<double> unrotatedNew_, rotationNew_, leftStretchNew_;
  // P of owned point i: from the Green strain, or the rate form's step; false when the rate
  // form meets an inverted or singular F (P zero, `message` set).
  void greenStress(int i, const double* F, double* P);
  bool rateStress(const ModelState& s, int i, const double* F, const double* Kinv, const double* M,
                  double* P);
  template <bool kDamage, bool kSides, bool kInfluence>
  void forceLoop(const ModelState& state, const std::vector<int>& points);
  std::vector<double> hourglassConstant_;  // per overlap point: 18 c_hg K / (pi delta^4)
  double* fRow_[3] = {nullptr, nullptr, nullptr};
  double* aRow_[3] = {nullptr, nullptr, nullptr};
};

}  // namespace peridot
