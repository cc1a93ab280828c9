#include "contact/ContactConfig.hpp"

#include "core/Error.hpp"
#include "core/Format.hpp"
#include "deck/Expression.hpp"

namespace peridot {

ContactConfig readContactConfig(ListReader c) {
  ContactConfig cc;
  cc.enabled = true;
  cc.path = c.path();
  cc.searchRadius = c.positiveNumber("Search Radius");
  cc.searchFrequency = c.integer("Search Frequency");
  if (cc.searchFrequency < 1) {
    throw InputError(c.pathOf("Search Frequency"),
                     "expected a positive integer (steps between searches)");
  }
  c.boolean("Verbose", false);
  ListReader models = c.sublist("Models");
  const auto names = models.keys();
  if (names.size() != 1) {
    throw InputError(models.path(),
                     "Peridot supports exactly one contact model (Peridigm uses only "
                     "the first); got " +
                         std::to_string(names.size()));
  }
  cc.modelName = names[0];
  ListReader m = models.sublist(cc.modelName);
  const std::string kind =
      m.choice("Contact Model", {"Short Range Force", "Time Dependent Short Range Force"});
  cc.contactRadius = m.positiveNumber("Contact Radius");
  cc.springConstant = m.positiveNumber("Spring Constant");
  if (kind == "Time Dependent Short Range Force") {
    // Peridigm requires the key for this model; its value is an expression in t.
    cc.timeDependentFriction = true;
    cc.frictionPath = m.pathOf("Friction Coefficient");
    cc.frictionExpression = m.numberOrExpression("Friction Coefficient");
    Expression check(cc.frictionExpression, {"t"}, cc.frictionPath);
    (void)check;
  } else {
    cc.frictionCoefficient = m.nonNegativeNumber("Friction Coefficient", 0.0);
  }
  m.finish();
  models.finish();
  if (cc.contactRadius > cc.searchRadius) {
    throw InputError(c.pathOf("Search Radius"), "must be at least the Contact Radius (" +
                                                    formatNumber(cc.contactRadius) + ")");
  }
  ListReader interactions = c.sublist("Interactions");
  for (const auto& name : interactions.keys()) {
    ListReader i = interactions.sublist(name);
    const std::string model = i.string("Contact Model");
    if (model != cc.modelName) {
      throw InputError(i.pathOf("Contact Model"), "unknown contact model \"" + model + "\"");
    }
    if (name == "General Contact") {
      cc.generalContact = true;
    } else if (name == "Self Contact" || i.has("Block")) {
      const std::string b = i.string("Block");
      cc.pairs.insert({b, b});
    } else {
      const std::string a = i.string("First Block"), b = i.string("Second Block");
      cc.pairs.insert(a < b ? std::make_pair(a, b) : std::make_pair(b, a));
    }
    i.finish();
  }
  interactions.finish();
  if (!cc.generalContact && cc.pairs.empty()) {
    throw InputError(interactions.path(), "no interaction is defined");
  }
  c.finish();
  return cc;
}

}  // namespace peridot
