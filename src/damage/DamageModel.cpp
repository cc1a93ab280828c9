#include "damage/DamageModel.hpp"

#include "core/Error.hpp"

namespace peridot {

std::unique_ptr<DamageModel> createDamageModel(ListReader& params) {
  // Peridigm's damage models that Peridot does not have: named as unsupported, not unknown.
  static const char* const unsupported[] = {"Time Dependent Critical Stretch", "Interface Aware",
                                            "Initial Damage", "Johnson Cook", "Von Mises Stress"};
  if (params.has("Damage Model")) {
    const std::string name = params.string("Damage Model");
    for (const char* u : unsupported)
      if (name == u && !DamageRegistry::find(name))
        throw InputError(params.pathOf("Damage Model"),
                         "Peridigm's damage model \"" + name + "\" is not supported by Peridot");
  }
  const auto& entry = DamageRegistry::lookup(params, "Damage Model", "damage model", {"Verbose"});
  auto damage = entry.create(params);
  params.finish();
  return damage;
}

}  // namespace peridot
