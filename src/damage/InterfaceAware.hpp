#pragma once
// Peridigm's "Interface Aware" damage: critical stretch for bi-material interfaces. Each point
// of the block carries the model's critical stretch s_c in the node field "Critical_Stretch"
// (ghosted); a bond i -> j breaks for good when its stretch exceeds min(s_c, s_c of j). A
// neighbour whose Critical_Stretch is 0 (a point of a block without this model) never lets the
// bond break. A point left with two or fewer intact bonds has all of them broken (Peridigm
// takes it out of the linear system; see doc/deck-reference.md). The stretch is measured from
// the thermally expanded length with the model's `Thermal Expansion Coefficient`, as Critical
// Stretch does.
#include "damage/DamageModel.hpp"

namespace peridot {

class InterfaceAware : public DamageModel {
 public:
  explicit InterfaceAware(ListReader& params);
  void initializeDamage(const ModelState& state, const std::vector<int>& points,
                        float* bondDamage) override;
  void computeDamage(const ModelState& state, const std::vector<int>& points,
                     float* bondDamage) override;

  static constexpr const char* kCriticalStretch = "Critical_Stretch";

 private:
  double criticalStretch_ = 0.0;
  double alpha_ = 0.0;
};

}  // namespace peridot
