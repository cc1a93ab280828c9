#pragma once
// "Elastic Plastic Correspondence": the correspondence kinematics (materials/Correspondence.hpp)
// with J2 plasticity on the Green strain, in the reference frame: E = E^e + E^p, S = lambda
// tr(E^e) I + 2 mu E^e, yield f = sqrt(3/2) |dev S| - (sigma_Y + H eps_p) <= 0, radial return
// (backward Euler, exact for linear hardening):
//   dgamma = f_trial / (3 mu + H),  n = dev S_trial / |dev S_trial|,
//   S = S_trial - 2 mu sqrt(3/2) dgamma n,  E^p += sqrt(3/2) dgamma n,  eps_p += dgamma.
// The stress after a plastic step lies on the yield surface to rounding, and eps_p never
// decreases. History per point: E^p (9) and eps_p (Equivalent_Plastic_Strain), saved in
// checkpoints. "Isotropic Hardening Correspondence" (derived) adds H and Peridigm's flaw;
// "Viscoplastic Needleman Correspondence" (derived) keeps the flaw and replaces the return.
//
// That is the "Total Lagrangian Green Strain" form. The default, "Hypoelastic Rate" (as
// Peridigm), makes the same radial return on the unrotated Cauchy stress: trial sigma_u + dt C:d,
// q its von Mises stress, dgamma = (q - sigma_Y - H eps_p) / (3 mu + H), the deviator scaled by
// 1 - 3 mu dgamma / q, eps_p += dgamma; history eps_p and the base's sigma_u, R, V. For small
// elastic strains the two forms agree to first order (doc/theory/correspondence.md).
#include <vector>

#include "materials/Correspondence.hpp"

namespace peridot {

class ElasticPlasticCorrespondence : public CorrespondenceMaterial {
 public:
  explicit ElasticPlasticCorrespondence(ListReader& params)
      : ElasticPlasticCorrespondence(params, "Elastic Plastic Correspondence", false, false) {}
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> outputFields() const override;
  std::vector<std::string> historyNodeFields() const override;
  bool advancesHistory() const override { return true; }

  static constexpr const char* kEquivalentPlasticStrain = "Equivalent_Plastic_Strain";
  static constexpr const char* kPlasticStrain = "Plastic_Green_Strain";

  // The yield stress of a point at reference position x (the flaw lowers it near its centre).
  double yieldStressAt(const double* x) const;

 protected:
  // `hardening`: read "Hardening Modulus"; `flaw`: read Peridigm's "Enable Flaw" and its keys.
  ElasticPlasticCorrespondence(ListReader& params, const std::string& name, bool hardening,
                               bool flaw);
  void secondPiolaKirchhoff(int i, const double* E, double* S) override;
  void unrotatedCauchyStress(int i, const double* d, double dt, const double* sigmaN,
                             double* sigma) override;
  void commitHistory(const std::vector<int>& points) override;
  void holdHistory(int i) override;
  double energyDensity(int i, const double* E) const override;
  // The deviator of the stress S and its squared norm dev:dev (the trial state of the returns).
  static double deviator(const double* S, double* dev);

  double* eqps_ = nullptr;  // committed eps_p
  // This step's eps_p from the last precompute, committed by computeForce; the yield stress
  // sigma_Y(x) of each point (the flaw's, or sigma_Y).
  std::vector<double> eqpsNew_, yield_;

 private:
  double yieldStress_ = 0.0, hardeningModulus_ = 0.0;
  bool flaw_ = false;
  double flawLocation_[3] = {0, 0, 0}, flawSize_ = 1.0, flawMagnitude_ = 0.0;
  double* plasticStrain_ = nullptr;       // committed E^p, 9 per point (Green strain form only)
  std::vector<double> plasticStrainNew_;  // this step's E^p (Green strain form only)
};

}  // namespace peridot
