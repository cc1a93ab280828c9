#include "damage/DamageModel.hpp"

#include "core/Error.hpp"

namespace peridot {

std::unique_ptr<DamageModel> createDamageModel(ListReader& params) {
  // A Peridigm model Peridot lacks is named as such by the registry (deck/PeridigmVocabulary).
  const auto& entry = DamageRegistry::lookup(params, "Damage Model", "damage model", {"Verbose"});
  auto damage = entry.create(params);
  params.finish();
  return damage;
}

}  // namespace peridot
