#pragma once
// Continuum-kinematics-inspired peridynamics (Javili, McBride, Steinmann; paper 004, sections
// 2-3; derivation and checks in doc/theory/cki.md). Besides the bonds (one-neighbour
// interactions, psi1 = C1/2 (l - L)^2 / L), a point i interacts with the triangles (i, j, k) of
// two neighbours mutually within the horizon (psi2 = C2/2 (a - A)^2 / A, a = |dx_ij x dx_ik|) and
// with the tetrahedra (i, j, k, l) of three (psi3 = C3/2 (|v| - |V|)^2 / |V|, v = (dx_ij x
// dx_ik) . dx_il). Stored energy density of point i, with the effective volumes V1 = V_H/N1,
// V2 = V_H^2/N2, V3 = V_H^3/N3 (V_H = beta pi delta^2 or beta 4/3 pi delta^3, beta the
// neighbourhood's fullness):
//   W_i = 1/2 sum_j psi1 V1 + 1/3 sum_(j,k) psi2 V2 + 1/4 sum_(j,k,l) psi3 V3,
// (each interaction shared by its 2, 3 or 4 corners) and the force density is the exact gradient
// f_p = -(1/V_p) d/dy_p sum_i V_i W_i, evaluated in pull form: p visits the bonds, triangles
// and tetrahedra of its own lists and adds the terms of every corner that owns one (their
// geometry is the same; only the weights C V_n V_i of the corners and their damage differ).
// Damage (paper eqs. 3.1, 3.5, 3.6): a bond breaks for good when its stretch exceeds the block's
// critical stretch; a triangle or tetrahedron owned by a corner fails when one of that corner's
// bonds has failed. Point p tracks the bonds j-k between its neighbours itself (per pair, the same
// stretch check from the same positions as j's owner), so no bond damage of ghosts is needed.
#include <cstdint>
#include <vector>

#include "materials/MaterialModel.hpp"
#include "neighbor/InteractionLists.hpp"

namespace peridot {

class ContinuumKinematics : public MaterialModel {
 public:
  explicit ContinuumKinematics(ListReader& params);
  double density() const override { return density_; }
  double bulkModulus() const override { return youngs_ / (3.0 * (1.0 - 2.0 * poisson_)); }
  double youngsModulus() const override { return youngs_; }
  double poissonsRatio() const override { return poisson_; }
  PlaneMode planeMode() const override { return mode_; }
  // The critical-stretch check runs in the force loop: it also breaks the bonds between
  // neighbours that p tracks, from the same stretch.
  bool fusesCriticalStretch() const override { return true; }
  bool requiresFusedCriticalStretch() const override { return true; }
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> fieldsToSyncAfterInitialize() const override { return {kWeights}; }
  void computeForce(const ModelState& state, const std::vector<int>& points) override;
  void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                           double* energyDensity) const override;
  void stiffnessSum(const ModelState& state, const std::vector<int>& points,
                    double* sum) const override;
  std::string family() const override { return "continuum kinematics"; }
  void saveDamageState(std::vector<float>& state) const override { state = edgeDamage_; }
  void restoreDamageState(const std::vector<float>& state) override { edgeDamage_ = state; }
  // f_p reads the positions of p and its neighbours only (its bonds, triangles and tetrahedra
  // are among them): probed by finite differences over the bond pattern.
  TangentReach tangentReach() const override { return TangentReach::Bond; }

  // The interaction constants for horizon delta and dimension 2 or 3 (C2 = 0 in 3D, C3 = 0 in
  // 2D), as this model calibrates them (restricted neighbour sets; doc/theory/cki.md).
  void constants(double delta, int dimension, double& c1, double& c2, double& c3) const;
  // The paper's C2 (eq. 4.1) and C3 (eq. 4.2), calibrated for unrestricted pairs and triples.
  void paperConstants(double delta, int dimension, double& c2, double& c3) const;
  bool oneNeighbor() const { return one_; }
  bool twoNeighbor() const { return two_; }
  bool threeNeighbor() const { return three_; }
  // Interactions per owned point of the lists (pairs stored, triples counted on the fly).
  const InteractionLists& lists() const { return lists_; }
  std::int64_t countTriples(const ModelState& state, int i) const;

  static constexpr const char* kWeights = "CKI_Interaction_Weights";
  // Mean of |xi_j x xi_k| over pairs of the unit disk with |xi_j - xi_k| <= 1, and of
  // |det(xi_j, xi_k, xi_l)| over triples of the unit ball mutually within 1 (doc/theory/cki.md).
  static constexpr double kMeanArea2D = 0.226135;
  static constexpr double kMeanVolume3D = 0.098804;

 private:
  double density_ = 0, youngs_ = 0, poisson_ = 0;
  PlaneMode mode_ = PlaneMode::ThreeD;
  bool one_ = true, two_ = false, three_ = false;
  double* weights_ = nullptr;  // per point: C1 V1 V_i, C2 V2 V_i, C3 V3 V_i
  std::vector<int> points_;    // owned points of every block using this material
  InteractionLists lists_;
  std::vector<float> edgeDamage_;  // per pair (j, k): 1 once the bond j-k has broken
  mutable TripleScan scan_;
  double lambdaExcess(int dimension) const;  // lambda - mu of the (in-plane) elastic tensor
};

}  // namespace peridot
