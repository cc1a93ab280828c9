#pragma once
// Peridigm's "Initial Damage": the bonds of the block that cross any of its bond filters
// (`Bond Filters`: Rectangular_Plane, Exodus Mesh, or Disk) start broken (bond damage 1) and stay
// in the neighbour lists, so they count in the node damage; no bond breaks afterwards. A
// `Discretization -> Bond Filters` entry instead removes the bonds from the lists.
#include <vector>

#include "damage/DamageModel.hpp"
#include "discretization/Discretization.hpp"

namespace peridot {

class InitialDamage : public DamageModel {
 public:
  explicit InitialDamage(ListReader& params);
  void initializeDamage(const ModelState& state, const std::vector<int>& points,
                        float* bondDamage) override;
  void computeDamage(const ModelState&, const std::vector<int>&, float*) override {}
  bool needsBondLength() const override { return false; }
  bool initializesDamage() const override { return true; }

 private:
  std::vector<BondFilter> filters_;
};

}  // namespace peridot
