#pragma once
// Names Peridigm's decks use that Peridot does not (yet) implement, so that a deck using one
// gets an error naming it as an unsupported Peridigm feature rather than as a typo. From
// Peridigm 1.5's factories and compute classes (shared/peridigm-reference.md, sections 1.1, 1.2
// and 1.7). doc/deck-reference.md's key status table is checked against these and against the
// models' registered parameters (test_deck_reference.cpp).
#include <string>
#include <vector>

namespace peridot {

// Peridigm's material models (`Material Model`), all of them, supported or not.
const std::vector<std::string>& peridigmMaterialModels();
// Peridigm's damage models (`Damage Model`).
const std::vector<std::string>& peridigmDamageModels();
// Output variables and compute classes Peridigm decks request that Peridot lacks.
const std::vector<std::string>& peridigmOutputVariablesNotYet();

// True when `name` is in `list`.
bool isIn(const std::vector<std::string>& list, const std::string& name);

}  // namespace peridot
