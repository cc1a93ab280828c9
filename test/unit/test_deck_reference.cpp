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

#include "core/Error.hpp"
#include "core/Registry.hpp"
#include "damage/DamageModel.hpp"
#include "deck/Deck.hpp"
#include "deck/OutputVariables.hpp"
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
    if (!entry) {
      // Keys of a model Peridot refuses: the model must be a refused Peridigm model, and its
      // keys are refused with it.
      const auto modelRow = table.find({kindRow, model});
      ASSERT_NE(modelRow, table.end()) << "the table lists keys of \"" << model << "\", unknown";
      EXPECT_EQ(modelRow->second, "not yet") << model;
      EXPECT_EQ(status, "not yet") << where.first << " -> " << where.second;
      continue;
    }
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

// A small valid deck (3^3 points, LPS, Verlet) that each refused entry is put into.
Teuchos::RCP<Teuchos::ParameterList> baseDeck() {
  const std::string yaml =
      "Peridigm:\n"
      "  Discretization:\n    Type: PdQuickGrid\n"
      "    TensorProduct3DMeshGenerator:\n"
      "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
      "      X Length: 3.0\n      Y Length: 3.0\n      Z Length: 3.0\n"
      "      Number Points X: 3\n      Number Points Y: 3\n      Number Points Z: 3\n"
      "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 1.0\n"
      "      Bulk Modulus: 1.0\n      Shear Modulus: 0.6\n"
      "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 1.5\n"
      "  Boundary Conditions:\n    S Node Set: \"1 2\"\n"
      "  Solver:\n    Final Time: 1.0\n    Verlet:\n      Fixed dt: 0.1\n";
  return peridot::parseDeck(yaml, "yaml");
}

// Puts the refused entry (where, key) into `deck`; false if the test does not know the section.
bool inject(Teuchos::ParameterList& deck, const std::string& where, const std::string& key) {
  Teuchos::ParameterList& material = deck.sublist("Materials").sublist("M");
  const std::string materialPrefix = "Materials -> ", damagePrefix = "Damage Models -> ";
  if (where == "Material Model") {
    material.set("Material Model", key);
  } else if (where.rfind(materialPrefix, 0) == 0) {
    material.set("Material Model", where.substr(materialPrefix.size()));
    // The correspondence models require their hourglass coefficient before anything else.
    if (where.find("Correspondence") != std::string::npos)
      material.set("Hourglass Coefficient", 0.02);
    if (key == "Thermal Expansion Coefficient") {
      material.set(key, 1e-5);
    } else {
      material.set(key, true);
    }
  } else if (where == "Damage Model" || where.rfind(damagePrefix, 0) == 0) {
    Teuchos::ParameterList& damage = deck.sublist("Damage Models").sublist("D");
    damage.set("Damage Model", where == "Damage Model" ? key : where.substr(damagePrefix.size()));
    damage.set("Critical Stretch", 0.01);
    if (where != "Damage Model") damage.set(key, 1e-5);
    deck.sublist("Blocks").sublist("B").set("Damage Model", "D");
  } else if (where == "Output Variables") {
    deck.sublist("Output").set("Output Filename", "refused");
    deck.sublist("Output").sublist("Output Variables").set(key, true);
  } else if (where == "top level") {
    if (key == "Multiphysics") {
      deck.set(key, 1);
    } else {
      deck.sublist(key).set("File Name", "x.e");
    }
  } else if (where == "Discretization") {
    deck.sublist("Discretization").set(key, key != "Construct Neighborhood Lists");
  } else if (where == "Discretization -> Type") {
    deck.sublist("Discretization").set("Type", key);
  } else if (where == "Boundary Conditions -> Type") {
    Teuchos::ParameterList& c = deck.sublist("Boundary Conditions").sublist("C");
    c.set("Type", key);
    c.set("Node Set", "S Node Set");
    c.set("Coordinate", "x");
    c.set("Value", "0.0");
  } else if (where == "Solver") {
    // The refused solver replaces Verlet: with both, the deck would fail for having two.
    deck.sublist("Solver").remove("Verlet");
    deck.sublist("Solver").sublist(key).set("Fixed dt", 0.1);
  } else if (where == "Data Loader") {
    deck.sublist(where).set(key, "x");
  } else if (where == "Output") {
    deck.sublist("Output").set("Output Filename", "refused");
    deck.sublist("Output").set(key, true);
  } else {
    return false;
  }
  return true;
}

// The refused model or list that `where` lies inside ("" if none): a material model listed as
// not yet, or a list that is itself a refused key.
std::string refusedParent(const Table& table, const std::string& where) {
  const std::string materials = "Materials -> ";
  if (where.rfind(materials, 0) == 0) {
    const std::string model = where.substr(materials.size());
    const auto row = table.find({"Material Model", model});
    return row != table.end() && row->second == "not yet" ? model : "";
  }
  if (where == "Data Loader") return where;
  const std::string prefix = "Solver -> QuasiStatic -> ";
  if (where.rfind(prefix, 0) == 0) return where.substr(prefix.size());
  return "";
}

// Every Peridigm name the table lists as "not yet", put into a valid deck, stops the reading of
// the deck with an error that names it (as unsupported, or as an unknown parameter).
TEST(DeckReference, EveryRefusedKeyIsNamedInTheError) {
  int refused = 0;
  const Table table = readStatusTable();
  for (const auto& [where, status] : table) {
    if (status != "not yet") continue;
    auto deck = baseDeck();
    ASSERT_TRUE(inject(*deck, where.first, where.second))
        << "no deck for the refused entry " << where.first << " -> " << where.second
        << ": teach inject() its section";
    ++refused;
    try {
      peridot::readRunConfig(*deck);
      ADD_FAILURE() << where.first << " -> " << where.second << " is listed as not yet, but "
                    << "a deck with it is accepted";
    } catch (const peridot::InputError& e) {
      const std::string message = e.what();
      // A key inside a refused model or list is stopped by that model or list: the error
      // names the parent.
      const std::string named = refusedParent(table, where.first).empty()
                                    ? where.second
                                    : refusedParent(table, where.first);
      EXPECT_NE(message.find(named), std::string::npos)
          << where.first << " -> " << where.second << ": the error does not name " << named << ": "
          << message;
      // And says why: the feature is missing, not that the deck is wrong in some other way.
      bool saysMissing = false;
      for (const char* why :
           {"not supported", "unsupported", "unknown", "not yet", "not a known", "not part of"})
        saysMissing = saysMissing || message.find(why) != std::string::npos;
      EXPECT_TRUE(saysMissing) << where.first << " -> " << where.second
                               << ": the error does not say the feature is missing: " << message;
    }
  }
  // The table's size, so the loop cannot silently cover nothing: 50 rows with the keys of the
  // refused models and lists, after Partial_Stress, Nonlinear_Solver_Iterations,
  // Velocity_Gradient, Unrotated_Rate_Of_Deformation, Viscoplastic Needleman Correspondence
  // (with its six keys; its Thermal Expansion Coefficient is a new row), the damage models
  // Johnson Cook and Von Mises Stress, QuasiStatic's Adaptive Load-Stepping (with its five
  // keys), the three hypoelastic correspondence models and Jacobian_Determinant became supported.
  EXPECT_GE(refused, 50);
}

}  // namespace
