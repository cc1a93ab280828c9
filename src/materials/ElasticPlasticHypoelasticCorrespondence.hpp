#pragma once
// "Elastic Plastic Hypoelastic Correspondence": the hypoelastic correspondence family
// (materials/HypoelasticCorrespondence.hpp) with J2 plasticity on the unrotated stress of each
// bond: trial sigma_u + dt (lambda tr(d) I + 2 mu d), radial return onto the von Mises surface
// (correspondence::radialReturn), eps_p per bond (Peridigm's Bond_Equivalent_Plastic_Strain)
// and per point (output: Equivalent_Plastic_Strain, Stress_Triaxiality). Perfect plasticity,
// sigma_Y = "Yield Stress"; "Isotropic Hardening Hypoelastic Correspondence" (derived) hardens
// as Peridigm's power law sigma_Y (1 + eps_p / eps_0)^n.
#include <vector>

#include "materials/HypoelasticCorrespondence.hpp"

namespace peridot {

class ElasticPlasticHypoelasticCorrespondence : public HypoelasticCorrespondence {
 public:
  explicit ElasticPlasticHypoelasticCorrespondence(ListReader& params)
      : ElasticPlasticHypoelasticCorrespondence(
            params, "Elastic Plastic Hypoelastic Correspondence", false) {}
  void declareFields(FieldManager& fields) override;
  void initialize(const ModelState& state, const std::vector<int>& points) override;
  std::vector<std::string> outputFields() const override;
  std::vector<std::string> historyNodeFields() const override;

  static constexpr const char* kEquivalentPlasticStrain = "Equivalent_Plastic_Strain";
  static constexpr const char* kStressTriaxiality = "Stress_Triaxiality";
  static constexpr const char* kBondEquivalentPlasticStrain = "Bond_Equivalent_Plastic_Strain";

  // The plastic increment dgamma that returns the trial unrotated stress `sigma` (in place) to
  // the surface sqrt(3/2)|dev sigma| = sigma_Y (1 + (eps_p + dgamma) / eps_0)^n (backward Euler,
  // solved by Newton's method to rounding); n = 0 is perfect plasticity.
  static double powerLawReturn(double mu, double yieldStress, double eps0, double exponent,
                               double eqps, double* sigma);

 protected:
  ElasticPlasticHypoelasticCorrespondence(ListReader& params, const std::string& name,
                                          bool hardening);
  void bondStresses(const ModelState& s) override;
  void pointStresses(const ModelState& s, const std::vector<int>& points) override;
  void commitLaw(const ModelState& s, const std::vector<int>& points) override;

 private:
  double yieldStress_ = 0.0, eps0_ = 1.0, exponent_ = 0.0;
  double* eqps_ = nullptr;
  double* triaxiality_ = nullptr;
  std::vector<double>* bondEqps_ = nullptr;
  std::vector<double> eqpsNew_, bondEqpsNew_;
};

}  // namespace peridot
