#pragma once
// Peridigm's "Johnson Cook" damage (Johnson and Cook 1985's cumulative damage, without its rate
// and temperature factors, as Peridigm has it): each material point accumulates the damage
// parameter
//   D += Delta eps_p / eps_f,   eps_f = D1 + D2 exp(-D3 sigma*),   sigma* = sigma_m / sigma_eq,
// with Delta eps_p the growth of the material's Equivalent_Plastic_Strain and sigma* the stress
// triaxiality of its Cauchy_Stress (sigma_m the mean stress, sigma_eq the von Mises stress),
// both as the material left them at the previous evaluation (the damage runs before the force).
// D never decreases and stops at 1. A bond's damage is the ramp of `Threshold Damage` and
// `Critical Damage` of the larger D of its two ends (damage/PointDamage.hpp). Peridigm's sign:
// D3 > 0 makes tension (sigma* > 0) lower the failure strain.
//
// History per point: D and the plastic strain it has been integrated to, committed once per
// step (ModelState::commitHistory: a trial takes D to its state without storing it) and saved
// in checkpoints, with the material's Cauchy_Stress that the first continued step reads. Needs a
// material that computes Equivalent_Plastic_Strain and Cauchy_Stress (the plastic correspondence
// models); any other is refused when the block is set up.
#include <cmath>

#include "damage/DamageModel.hpp"
#include "damage/PointDamage.hpp"

namespace peridot {

class JohnsonCook : public DamageModel {
 public:
  explicit JohnsonCook(ListReader& params);
  bool bindsToBlock() const override { return true; }
  void bind(const MaterialModel& material, double horizon, const std::string& blockName,
            std::ostream& log) override;
  void computeDamage(const ModelState& state, const std::vector<int>& points,
                     float* bondDamage) override;
  bool needsBondLength() const override { return false; }
  // With the material's Cauchy_Stress: the next step's triaxiality comes from it, and the
  // material recomputes it only after the damage pass (a continued run would read zeros).
  std::vector<std::string> historyNodeFields() const override {
    return {kCommittedDamageParameter, kIntegratedPlasticStrain, "Cauchy_Stress"};
  }

  // eps_f at triaxiality sigma*.
  double failureStrain(double triaxiality) const {
    return d1_ + d2_ * std::exp(-d3_ * triaxiality);
  }

  // D of this evaluation (ghosted), D committed at the end of the last step, and the
  // Equivalent_Plastic_Strain D has been integrated to.
  static constexpr const char* kDamageParameter = "Damage_Parameter";
  static constexpr const char* kCommittedDamageParameter = "Damage_Parameter_Committed";
  static constexpr const char* kIntegratedPlasticStrain = "Damage_Parameter_Plastic_Strain";

 private:
  std::string path_;
  double d1_ = 0.0, d2_ = 0.0, d3_ = 0.0;
  PointDamageRamp ramp_;
};

}  // namespace peridot
