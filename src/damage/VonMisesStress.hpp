#pragma once
// Peridigm's "Von Mises Stress" damage: a bond's damage is the ramp of `Threshold Damage` and
// `Critical Damage` (defaults 0.99 and 1, Peridigm's) of sigma_vm / `Critical Von Mises Stress`,
// sigma_vm the larger Von_Mises_Stress of its two ends as the material left it at the previous
// evaluation (the damage runs before the force); bond damage never decreases. With both at 1 a
// bond breaks exactly when an end's von Mises stress reaches the critical value. Needs a
// material that computes Von_Mises_Stress (the correspondence models); any other is refused
// when the block is set up.
#include "damage/DamageModel.hpp"
#include "damage/PointDamage.hpp"

namespace peridot {

class VonMisesStress : public DamageModel {
 public:
  explicit VonMisesStress(ListReader& params);
  bool bindsToBlock() const override { return true; }
  void bind(const MaterialModel& material, double horizon, const std::string& blockName,
            std::ostream& log) override;
  void computeDamage(const ModelState& state, const std::vector<int>& points,
                     float* bondDamage) override;
  bool needsBondLength() const override { return false; }
  // The material's Von_Mises_Stress: the first step of a continued run reads it before the
  // material recomputes it.
  std::vector<std::string> historyNodeFields() const override { return {"Von_Mises_Stress"}; }

  // sigma_vm / sigma_c of each point (ghosted), the value the ramp reads.
  static constexpr const char* kStressRatio = "Von_Mises_Stress_Ratio";

 private:
  std::string path_;
  double criticalStress_ = 0.0;
  PointDamageRamp ramp_;
};

}  // namespace peridot
