#include "output/ExodusCompare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <unordered_map>

namespace peridot {

// ----------------------------------------------------------------------------------------------
// Comparison

std::size_t CompareReport::valuesCompared() const {
  std::size_t n = 0;
  for (const auto& v : variables) n += v.compared;
  return n;
}

std::size_t CompareReport::failures() const {
  std::size_t n = 0;
  for (const auto& v : variables) n += v.failures;
  return n;
}

namespace {

std::string idList(const std::vector<long long>& ids) {
  std::string text;
  const std::size_t shown = std::min<std::size_t>(ids.size(), 10);
  for (std::size_t i = 0; i < shown; ++i) text += (i ? ", " : "") + std::to_string(ids[i]);
  if (ids.size() > shown) text += ", ... (" + std::to_string(ids.size()) + " in all)";
  return text;
}

// For every gold entry, the index of the result entry with the same id (or -1). Reports count
// mismatches, duplicate ids and ids present on one side only.
std::vector<long long> matchIds(const std::vector<long long>& resultIds,
                                const std::vector<long long>& goldIds, const std::string& what,
                                std::vector<std::string>& problems) {
  if (resultIds.size() != goldIds.size()) {
    problems.push_back("the result has " + std::to_string(resultIds.size()) + " " + what +
                       "s, the gold " + std::to_string(goldIds.size()));
  }
  std::unordered_map<long long, long long> resultIndex;
  std::vector<long long> duplicates;
  for (std::size_t i = 0; i < resultIds.size(); ++i) {
    if (!resultIndex.emplace(resultIds[i], static_cast<long long>(i)).second) {
      duplicates.push_back(resultIds[i]);
    }
  }
  if (!duplicates.empty()) {
    problems.push_back("the result repeats " + what + " ids " + idList(duplicates));
  }
  std::vector<long long> match(goldIds.size(), -1);
  std::vector<long long> missing;
  std::unordered_map<long long, bool> inGold;
  for (std::size_t i = 0; i < goldIds.size(); ++i) {
    inGold[goldIds[i]] = true;
    const auto it = resultIndex.find(goldIds[i]);
    if (it == resultIndex.end()) {
      missing.push_back(goldIds[i]);
    } else {
      match[i] = it->second;
    }
  }
  if (!missing.empty()) {
    problems.push_back("gold " + what + "s missing from the result: ids " + idList(missing));
  }
  std::vector<long long> extra;
  for (long long id : resultIds) {
    if (inGold.count(id) == 0) extra.push_back(id);
  }
  if (!extra.empty()) {
    problems.push_back("result " + what + "s not in the gold: ids " + idList(extra));
  }
  return match;
}

long long findName(const std::vector<std::string>& names, const std::string& name) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<long long>(i);
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (sameVariableName(names[i], name)) return static_cast<long long>(i);
  }
  return -1;
}

class Comparer {
 public:
  Comparer(const CompareOptions& options) : options_(options) {}

  void compare(VariableReport& v, int step, double time, long long id, double result,
               double gold) const {
    ++v.compared;
    if (v.tolerance.passes(result, gold)) return;
    ++v.failures;
    const double diff = std::fabs(result - gold);
    if (std::isnan(diff) || std::isnan(v.maxDifference)) {
      v.maxDifference = std::numeric_limits<double>::quiet_NaN();
    } else {
      v.maxDifference = std::max(v.maxDifference, diff);
    }
    if (v.shown.size() < options_.maxShown) {
      v.shown.push_back(
          Difference{step, time, id, result, gold, diff, v.tolerance.allowed(result, gold)});
    }
  }

 private:
  const CompareOptions& options_;
};

struct Selection {
  std::string name;
  Tolerance tolerance;
};

// The variables of one kind to compare: those the section lists, else all of the gold's; none
// when the .comp file has no section of that kind (exodiff's rule for command files).
std::vector<Selection> select(const CompSpec& spec, const CompSpec::Section& section,
                              const std::vector<std::string>& goldNames) {
  std::vector<Selection> selection;
  if (!section.present) return selection;
  if (!section.variables.empty()) {
    for (const auto& [name, tolerance] : section.variables) selection.push_back({name, tolerance});
  } else {
    for (const auto& name : goldNames) selection.push_back({name, spec.sectionDefault(section)});
  }
  return selection;
}

}  // namespace

CompareReport compareExodusResults(const ExodusResults& result, const ExodusResults& gold,
                                   const CompSpec& spec, const CompareOptions& options) {
  CompareReport report;
  const Comparer comparer(options);
  if (result.dimension != gold.dimension) {
    report.problems.push_back("the result is " + std::to_string(result.dimension) +
                              "-dimensional, the gold " + std::to_string(gold.dimension) +
                              "-dimensional");
  }
  const auto nodeMatch = matchIds(result.nodeIds, gold.nodeIds, "node", report.problems);
  const auto elementMatch =
      matchIds(result.elementIds, gold.elementIds, "element", report.problems);

  // Every point must sit in the block it sits in in the gold.
  {
    std::size_t wrong = 0;
    std::string first;
    for (std::size_t i = 0; i < elementMatch.size(); ++i) {
      if (elementMatch[i] < 0) continue;
      const long long inResult = result.elementBlock[static_cast<std::size_t>(elementMatch[i])];
      if (inResult == gold.elementBlock[i]) continue;
      if (wrong++ == 0) {
        first = "element " + std::to_string(gold.elementIds[i]) + " is in block " +
                std::to_string(inResult) + " in the result, block " +
                std::to_string(gold.elementBlock[i]) + " in the gold";
      }
    }
    if (wrong > 0) {
      report.problems.push_back(std::to_string(wrong) + " element(s) in another block, e.g. " +
                                first);
    }
  }

  const int dims = std::min({result.dimension, gold.dimension, 3});
  static const char* const kAxis[3] = {"X", "Y", "Z"};
  for (int d = 0; d < dims; ++d) {
    VariableReport v;
    v.kind = "coordinate";
    v.name = kAxis[d];
    v.tolerance = spec.coordinateTolerance();
    for (std::size_t i = 0; i < nodeMatch.size(); ++i) {
      if (nodeMatch[i] < 0) continue;
      const auto j = static_cast<std::size_t>(nodeMatch[i]);
      comparer.compare(v, 0, 0.0, gold.nodeIds[i],
                       result.nodeCoordinates[3 * j + static_cast<std::size_t>(d)],
                       gold.nodeCoordinates[3 * i + static_cast<std::size_t>(d)]);
    }
    report.variables.push_back(std::move(v));
  }

  if (result.times.size() != gold.times.size()) {
    report.problems.push_back("the result has " + std::to_string(result.times.size()) +
                              " time steps, the gold " + std::to_string(gold.times.size()) +
                              (std::min(result.times.size(), gold.times.size()) > 0
                                   ? "; the common first steps are compared"
                                   : ""));
  }
  const std::size_t steps = std::min(result.times.size(), gold.times.size());
  {
    VariableReport v;
    v.kind = "time";
    v.name = "TIME";
    v.tolerance = spec.timeTolerance();
    for (std::size_t s = 0; s < steps; ++s) {
      comparer.compare(v, static_cast<int>(s + 1), gold.times[s], 0, result.times[s],
                       gold.times[s]);
    }
    report.variables.push_back(std::move(v));
  }

  struct Kind {
    const char* label;
    const CompSpec::Section& section;
    const std::vector<std::string>& resultNames;
    const std::vector<std::string>& goldNames;
    const std::vector<std::vector<std::vector<double>>>& resultValues;
    const std::vector<std::vector<std::vector<double>>>& goldValues;
    const std::vector<long long>* match;  // null for global variables
    const std::vector<long long>* goldIds;
  };
  const Kind kinds[3] = {
      {"nodal", spec.nodal, result.nodalNames, gold.nodalNames, result.nodal, gold.nodal,
       &nodeMatch, &gold.nodeIds},
      {"element", spec.element, result.elementNames, gold.elementNames, result.element,
       gold.element, &elementMatch, &gold.elementIds},
      {"global", spec.global, result.globalNames, gold.globalNames, result.global, gold.global,
       nullptr, nullptr},
  };
  for (const Kind& kind : kinds) {
    for (const Selection& selected : select(spec, kind.section, kind.goldNames)) {
      const long long g = findName(kind.goldNames, selected.name);
      const long long r = findName(kind.resultNames, selected.name);
      const std::string label = std::string(kind.label) + " variable \"" + selected.name + "\"";
      if (g < 0) {
        report.problems.push_back(label + " is listed in the comparison file but not in the gold");
        continue;
      }
      if (r < 0) {
        report.problems.push_back(label + " is missing from the result");
        continue;
      }
      VariableReport v;
      v.kind = kind.label;
      v.name = kind.goldNames[static_cast<std::size_t>(g)];
      v.tolerance = selected.tolerance;
      const auto& goldSteps = kind.goldValues[static_cast<std::size_t>(g)];
      const auto& resultSteps = kind.resultValues[static_cast<std::size_t>(r)];
      for (std::size_t s = 0; s < steps; ++s) {
        const auto& goldRow = goldSteps[s];
        const auto& resultRow = resultSteps[s];
        if (kind.match == nullptr) {
          comparer.compare(v, static_cast<int>(s + 1), gold.times[s], 0, resultRow[0], goldRow[0]);
          continue;
        }
        for (std::size_t i = 0; i < kind.match->size(); ++i) {
          const long long j = (*kind.match)[i];
          if (j < 0) continue;
          comparer.compare(v, static_cast<int>(s + 1), gold.times[s], (*kind.goldIds)[i],
                           resultRow[static_cast<std::size_t>(j)], goldRow[i]);
        }
      }
      report.variables.push_back(std::move(v));
    }
  }
  return report;
}

void printCompareReport(std::ostream& out, const CompareReport& report, bool quiet) {
  char line[512];
  for (const auto& problem : report.problems) out << "problem: " << problem << "\n";
  std::size_t failedVariables = 0;
  for (const auto& v : report.variables) {
    if (v.failures == 0) continue;
    ++failedVariables;
    if (!quiet) {
      for (const Difference& d : v.shown) {
        std::string where;
        if (d.step > 0) {
          std::snprintf(line, sizeof line, " step %d time %.9g", d.step, d.time);
          where += line;
        }
        if (v.kind != "global" && v.kind != "time") where += " id " + std::to_string(d.id);
        std::snprintf(line, sizeof line, "%s %s%s: result %.16e gold %.16e diff %.3e > tol %.3e\n",
                      v.kind.c_str(), v.name.c_str(), where.c_str(), d.result, d.gold, d.difference,
                      d.allowed);
        out << line;
      }
      if (v.failures > v.shown.size()) {
        out << "  ... " << (v.failures - v.shown.size()) << " more differences in " << v.kind << " "
            << v.name << " not shown\n";
      }
    }
    std::snprintf(line, sizeof line,
                  "%s %s: %zu of %zu values over tolerance (%s), max diff %.3e\n", v.kind.c_str(),
                  v.name.c_str(), v.failures, v.compared, v.tolerance.describe().c_str(),
                  v.maxDifference);
    out << line;
  }
  if (report.passed()) {
    out << "PASSED: " << report.valuesCompared() << " values compared, all within tolerance\n";
  } else {
    out << "FAILED: " << report.failures() << " values over tolerance in " << failedVariables
        << " variables, " << report.problems.size() << " other problems ("
        << report.valuesCompared() << " values compared)\n";
  }
}

}  // namespace peridot
