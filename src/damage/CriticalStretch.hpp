#pragma once
// Peridigm's "Critical Stretch": a bond breaks for good once its stretch exceeds the critical
// stretch (tension only).
#include "damage/DamageModel.hpp"

namespace peridot {

class CriticalStretch : public DamageModel {
 public:
  explicit CriticalStretch(ListReader& params);
  void computeDamage(const ModelState& state, const std::vector<int>& points,
                     float* bondDamage) override;
  double criticalStretch() const { return criticalStretch_; }
  double fusableCriticalStretch() const override { return criticalStretch_; }
  bool bindsToBlock() const override { return fractureEnergy_ > 0; }
  // With `Fracture Energy`, derives the critical stretch from the block's material and horizon.
  void bind(const MaterialModel& material, double horizon, const std::string& blockName,
            std::ostream& log) override;

 private:
  double criticalStretch_ = 0;
  double fractureEnergy_ = 0;  // G0, when given instead of the critical stretch
  std::string path_;
};

}  // namespace peridot
