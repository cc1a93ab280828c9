#pragma once
// Peridigm's "Time Dependent Critical Stretch": the critical stretch is an expression in the
// time t (RTCompiler dialect), evaluated at the time of each model evaluation; otherwise as
// "Critical Stretch" (tension only, irreversible, optional thermal expansion coefficient).
#include <memory>

#include "damage/DamageModel.hpp"
#include "deck/Expression.hpp"

namespace peridot {

class TimeDependentCriticalStretch : public DamageModel {
 public:
  explicit TimeDependentCriticalStretch(ListReader& params);
  void computeDamage(const ModelState& state, const std::vector<int>& points,
                     float* bondDamage) override;
  bool needsBondLength() const override { return false; }  // breakStretchedBonds computes it
  double criticalStretchAt(double t) const { return criticalStretch_->evaluate(&t); }

 private:
  std::unique_ptr<Expression> criticalStretch_;
  std::string path_;
  double alpha_ = 0.0;
};

}  // namespace peridot
