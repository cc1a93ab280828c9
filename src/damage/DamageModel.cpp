#include "damage/DamageModel.hpp"

#include "core/Error.hpp"

namespace peridot {

std::unique_ptr<DamageModel> createDamageModel(ListReader& params) {
  const std::string model = params.string("Damage Model");
  const auto* entry = DamageRegistry::find(model);
  if (!entry) {
    std::string known;
    for (const auto& n : DamageRegistry::names()) known += (known.empty() ? "\"" : ", \"") + n + "\"";
    throw InputError(params.pathOf("Damage Model"),
                     "unknown damage model \"" + model + "\"; Peridot knows " + known);
  }
  for (const auto& key : params.keys()) {
    bool known = key == "Damage Model" || key == "Verbose";
    for (const auto& doc : entry->parameters) known = known || doc.name == key;
    if (!known) {
      throw InputError(params.pathOf(key), "unknown parameter of damage model \"" + model +
                                               "\" (peridot --help-model \"" + model + "\" lists them)");
    }
  }
  auto damage = entry->create(params);
  params.finish();
  return damage;
}

}  // namespace peridot
