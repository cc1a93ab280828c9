#pragma once
// Comparison of an Exodus result file with a gold file under a SEACAS exodiff-style command file
// (.comp), the subset Peridigm's regression tests use. The peridot-diff tool is a thin main
// around these pieces.
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "output/CompSpec.hpp"
#include "output/ExodusResults.hpp"

namespace peridot {

// One value over tolerance.
struct Difference {
  int step = 0;       // 1-based time step (record) number; 0 for coordinates
  double time = 0.0;  // the gold time of that step
  long long id = 0;   // node or element id; 0 for global variables and times
  double result = 0.0;
  double gold = 0.0;
  double difference = 0.0;  // |result - gold| (NaN when one is NaN)
  double allowed = 0.0;     // the tolerance's allowed |difference| for this pair
};

// The outcome for one compared quantity.
struct VariableReport {
  std::string kind;  // "coordinate", "time", "nodal", "element", "global"
  std::string name;
  Tolerance tolerance;
  std::size_t compared = 0;       // values compared
  std::size_t failures = 0;       // values over tolerance (all counted)
  double maxDifference = 0.0;     // largest |difference| among the failures
  std::vector<Difference> shown;  // the first failures, at most CompareOptions::maxShown
};

struct CompareOptions {
  std::size_t maxShown = 50;  // differences kept (and printed) per variable
};

struct CompareReport {
  std::vector<std::string> problems;  // structural mismatches: ids, step counts, missing variables
  std::vector<VariableReport> variables;
  std::size_t valuesCompared() const;
  std::size_t failures() const;  // values over tolerance, all variables
  bool passed() const { return problems.empty() && failures() == 0; }
};

// Compares result with gold under spec. Points are matched by id (node number map for nodal
// variables and coordinates, element number map for element variables, whatever the block order);
// time steps by index; global variables by name. Names match case-insensitively.
CompareReport compareExodusResults(const ExodusResults& result, const ExodusResults& gold,
                                   const CompSpec& spec, const CompareOptions& options = {});

// Writes the problems, the shown differences (unless quiet) and a final summary line.
void printCompareReport(std::ostream& out, const CompareReport& report, bool quiet);

}  // namespace peridot
