#pragma once
// Peridigm's "Critical Stretch": a bond breaks for good once its stretch exceeds the critical
// stretch (tension only).
#include "damage/DamageModel.hpp"

namespace peridot {

class CriticalStretch : public DamageModel {
 public:
  explicit CriticalStretch(ListReader& params);
  void computeDamage(const ModelState& state, const std::vector<int>& points,
                     double* bondDamage) override;
  double criticalStretch() const { return criticalStretch_; }

 private:
  double criticalStretch_ = 0;
};

}  // namespace peridot
