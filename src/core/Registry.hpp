#pragma once
// A name -> creator table shared by the factories (materials, damage models, ...). Models
// register themselves from their own .cpp file, so adding a model touches nothing else.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/Error.hpp"
#include "core/Suggest.hpp"
#include "deck/Deck.hpp"
#include "deck/PeridigmVocabulary.hpp"

namespace peridot {

struct ParameterDoc {
  std::string name;
  std::string description;  // type, default, meaning
};

template <class Base>
class Registry {
 public:
  using Creator = std::function<std::unique_ptr<Base>(ListReader&)>;
  struct Entry {
    Creator create;
    std::vector<ParameterDoc> parameters;
    std::string summary;
  };
  static std::map<std::string, Entry>& entries() {
    static std::map<std::string, Entry> table;
    return table;
  }
  static bool add(const std::string& name, Creator create, std::string summary,
                  std::vector<ParameterDoc> parameters) {
    entries()[name] = Entry{std::move(create), std::move(parameters), std::move(summary)};
    return true;
  }
  static const Entry* find(const std::string& name) {
    auto it = entries().find(name);
    return it == entries().end() ? nullptr : &it->second;
  }
  // The entry named by `params.string(kindKey)`, with every key of `params` checked against its
  // documented parameters (plus `extraKeys`): unknown names are errors naming the deck path.
  static const Entry& lookup(ListReader& params, const std::string& kindKey,
                             const std::string& kind, const std::vector<std::string>& extraKeys);
  static std::vector<std::string> names() {
    std::vector<std::string> out;
    for (const auto& kv : entries()) out.push_back(kv.first);
    return out;
  }
};

template <class Base>
const typename Registry<Base>::Entry& Registry<Base>::lookup(
    ListReader& params, const std::string& kindKey, const std::string& kind,
    const std::vector<std::string>& extraKeys) {
  const std::string name = params.string(kindKey);
  const Entry* entry = find(name);
  if (!entry) {
    std::string known;
    for (const auto& n : names()) known += (known.empty() ? "\"" : ", \"") + n + "\"";
    const bool peridigms =
        isIn(peridigmMaterialModels(), name) || isIn(peridigmDamageModels(), name);
    throw InputError(
        params.pathOf(kindKey),
        (peridigms ? "the Peridigm " + kind + " \"" + name + "\" is not supported by Peridot yet"
                   : "unknown " + kind + " \"" + name + "\"" + didYouMean(name, names())) +
            "; Peridot knows " + known);
  }
  // Unknown keys first: a misspelt key must be named as such, not reported as a missing one.
  for (const auto& key : params.keys()) {
    bool known = key == kindKey;
    for (const auto& k : extraKeys) known = known || k == key;
    for (const auto& doc : entry->parameters) known = known || doc.name == key;
    if (!known) {
      throw InputError(params.pathOf(key), "unknown parameter of " + kind + " \"" + name +
                                               "\" (peridot --help-model \"" + name +
                                               "\" lists them)");
    }
  }
  return *entry;
}

}  // namespace peridot
