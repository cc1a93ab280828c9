#pragma once
// Interface of a damage model: updates the bond damage (0 intact .. 1 broken) of a block's
// owned points before the material computes forces.
#include <memory>
#include <string>
#include <vector>

#include "core/Registry.hpp"
#include "materials/MaterialModel.hpp"

namespace peridot {

class DamageModel {
 public:
  virtual ~DamageModel() = default;
  virtual void computeDamage(const ModelState& state, const std::vector<int>& points,
                             double* bondDamage) = 0;
};

using DamageRegistry = Registry<DamageModel>;

std::unique_ptr<DamageModel> createDamageModel(ListReader& params);

}  // namespace peridot

#define PERIDOT_REGISTER_DAMAGE(DeckName, Class, Summary, Params)                           \
  namespace {                                                                                \
  const bool kRegistered##Class = ::peridot::DamageRegistry::add(                            \
      DeckName, [](::peridot::ListReader& p) { return std::make_unique<Class>(p); }, Summary, \
      Params);                                                                               \
  }
