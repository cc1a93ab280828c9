#pragma once
// Peridigm's "Critical Stretch": a bond breaks for good once its stretch exceeds the critical
// stretch (tension only).
#include "damage/DamageModel.hpp"
#include "damage/FractureEnergy.hpp"

namespace peridot {

class CriticalStretch : public DamageModel {
 public:
  explicit CriticalStretch(ListReader& params);
  void computeDamage(const ModelState& state, const std::vector<int>& points,
                     float* bondDamage) override;
  double criticalStretch() const { return criticalStretch_.value(); }
  double fusableCriticalStretch() const override { return criticalStretch_.value(); }
  bool bindsToBlock() const override { return criticalStretch_.fromFractureEnergy(); }
  // With `Fracture Energy`, derives the critical stretch from the block's material and horizon.
  void bind(const MaterialModel& material, double horizon, const std::string& blockName,
            std::ostream& log) override;

 private:
  CriticalStretchInput criticalStretch_;
};

}  // namespace peridot
