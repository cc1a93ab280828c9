#pragma once
// The `Contact` section: search radius and frequency, the short-range force model and which
// block pairs interact.
#include <set>
#include <string>
#include <utility>

#include "deck/Deck.hpp"

namespace peridot {

struct ContactConfig {
  bool enabled = false;
  double searchRadius = 0;
  long long searchFrequency = 1;
  std::string modelName;
  double contactRadius = 0, springConstant = 0, frictionCoefficient = 0;
  // "Time Dependent Short Range Force": the friction coefficient is this expression in t,
  // evaluated at the time of each force evaluation (frictionCoefficient then holds its value).
  bool timeDependentFriction = false;
  std::string frictionExpression, frictionPath;
  bool generalContact = false;                          // every pair of points, any blocks
  std::set<std::pair<std::string, std::string>> pairs;  // block-name pairs (sorted) otherwise
  std::string path;
  bool interacts(const std::string& a, const std::string& b) const {
    return generalContact || pairs.count(a < b ? std::make_pair(a, b) : std::make_pair(b, a)) > 0;
  }
};

ContactConfig readContactConfig(ListReader contact);

}  // namespace peridot
