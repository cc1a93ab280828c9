// doc/deck-reference.md's "Peridigm key status" table against the code: every registered model
// parameter, model and output variable is listed, nothing listed as supported or extension is
// missing from the code, and every Peridigm name Peridot refuses is listed as "not yet". The
// table cannot drift from the models' own parameter lists.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "core/Registry.hpp"
#include "damage/DamageModel.hpp"
#include "deck/PeridigmVocabulary.hpp"
#include "deck/RunConfig.hpp"
#include "materials/MaterialModel.hpp"

namespace {

using Table = std::map<std::pair<std::string, std::string>, std::string>;  // (where, key) -> status

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

Table readStatusTable() {
  std::ifstream in(std::string(PERIDOT_TEST_DIR) + "/../doc/deck-reference.md");
  EXPECT_TRUE(in.good());
  Table table;
  std::string line;
  bool inSection = false;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) inSection = line == "## Peridigm key status";
    if (!inSection || line.rfind("| ", 0) != 0 || line.rfind("| Where", 0) == 0) continue;
    std::vector<std::string> cells;
    std::stringstream cellsIn(line.substr(1));
    std::string cell;
    while (std::getline(cellsIn, cell, '|')) cells.push_back(trim(cell));
    if (cells.size() < 3) continue;
    std::string key = cells[1];
    if (key.size() >= 2 && key.front() == '`' && key.back() == '`')
      key = key.substr(1, key.size() - 2);
    EXPECT_TRUE(cells[2] == "supported" || cells[2] == "extension" || cells[2] == "not yet")
        << line;
    EXPECT_TRUE(table.emplace(std::make_pair(cells[0], key), cells[2]).second) << "twice: " << line;
  }
  return table;
}

template <class Base>
void checkModels(const Table& table, const std::string& kindRow, const std::string& prefix,
                 const std::vector<std::string>& peridigmNames) {
  using R = peridot::Registry<Base>;
  for (const auto& name : R::names()) {
    const auto row = table.find({kindRow, name});
    ASSERT_NE(row, table.end()) << kindRow << " \"" << name << "\" is registered, not in the table";
    EXPECT_EQ(row->second, peridot::isIn(peridigmNames, name) ? "supported" : "extension") << name;
    for (const auto& p : R::find(name)->parameters) {
      EXPECT_TRUE(table.count({prefix + name, p.name}))
          << "registered parameter " << prefix << name << " -> " << p.name << " not in the table";
    }
  }
  for (const auto& name : peridigmNames) {
    const auto row = table.find({kindRow, name});
    ASSERT_NE(row, table.end()) << "Peridigm's " << kindRow << " \"" << name << "\" not listed";
    if (!R::find(name)) {
      EXPECT_EQ(row->second, "not yet") << name;
    }
  }
  for (const auto& [where, status] : table) {
    if (where.first.rfind(prefix, 0) != 0) continue;
    const std::string model = where.first.substr(prefix.size());
    const auto* entry = R::find(model);
    ASSERT_NE(entry, nullptr) << "the table lists keys of \"" << model << "\", not registered";
    bool registered = false;
    for (const auto& p : entry->parameters) registered = registered || p.name == where.second;
    EXPECT_TRUE(registered) << where.first << " -> " << where.second
                            << " is in the table but not a registered parameter";
  }
}

TEST(DeckReference, MaterialModelsAndTheirKeysMatchTheRegistry) {
  checkModels<peridot::MaterialModel>(readStatusTable(), "Material Model", "Materials -> ",
                                      peridot::peridigmMaterialModels());
}

TEST(DeckReference, DamageModelsAndTheirKeysMatchTheRegistry) {
  checkModels<peridot::DamageModel>(readStatusTable(), "Damage Model", "Damage Models -> ",
                                    peridot::peridigmDamageModels());
}

TEST(DeckReference, OutputVariablesMatchTheCode) {
  const Table table = readStatusTable();
  for (const auto& v : peridot::knownOutputVariables()) {
    const auto row = table.find({"Output Variables", v.name});
    ASSERT_NE(row, table.end()) << v.name << " is an output variable, not in the table";
    EXPECT_NE(row->second, "not yet") << v.name;
  }
  for (const auto& v : peridot::peridigmOutputVariablesNotYet()) {
    const auto row = table.find({"Output Variables", v});
    ASSERT_NE(row, table.end()) << v << " (Peridigm, refused) not in the table";
    EXPECT_EQ(row->second, "not yet") << v;
  }
  for (const auto& [where, status] : table) {
    if (where.first != "Output Variables") continue;
    const bool known = peridot::findOutputVariable(where.second) != nullptr;
    EXPECT_EQ(known, status != "not yet") << where.second << " listed as " << status;
  }
}

}  // namespace
