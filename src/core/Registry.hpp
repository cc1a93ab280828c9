#pragma once
// A name -> creator table shared by the factories (materials, damage models, ...). Models
// register themselves from their own .cpp file, so adding a model touches nothing else.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "deck/Deck.hpp"

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
  static std::vector<std::string> names() {
    std::vector<std::string> out;
    for (const auto& kv : entries()) out.push_back(kv.first);
    return out;
  }
};

}  // namespace peridot
