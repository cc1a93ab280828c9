#pragma once
// Comparison of an Exodus result file with a gold file under a SEACAS exodiff-style command file
// (.comp), the subset Peridigm's regression tests use. The peridot-diff tool is a thin main
// around these pieces.
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace peridot {

// One tolerance: absolute |a-b| <= value, or relative |a-b| <= value * max(|a|,|b|); pairs with
// both |a| and |b| below floor are not compared.
struct Tolerance {
  enum class Kind { Absolute, Relative };
  Kind kind = Kind::Relative;
  double value = 1.0e-6;
  double floor = 0.0;

  // The largest |a-b| allowed for this pair.
  double allowed(double a, double b) const;
  // True when a and b agree: identical (including both NaN, or the same infinity), below the
  // floor, or |a-b| <= allowed(a, b).
  bool passes(double a, double b) const;
  std::string describe() const;  // "absolute 1e-09", "relative 1e-06 floor 1e-12"
};

// A parsed .comp file.
//   DEFAULT TOLERANCE absolute 1.0E-9         what everything not given otherwise uses
//   COORDINATES absolute 1.0E-12
//   TIME STEPS absolute 1.0E-14
//   NODAL VARIABLES absolute 1.0E-12          (section default optional)
//   <TAB>DisplacementX absolute 1.0E-9        (tolerance optional: the section default)
//   ELEMENT VARIABLES ... / GLOBAL VARIABLES ...
// Keywords are case-insensitive; '#' starts a comment. When a section lists variables only those
// are compared; otherwise every variable of that kind in the gold file, with the section default.
// A kind with no section at all is not compared, as with exodiff's command files.
// Without DEFAULT TOLERANCE the default is exodiff's: relative 1e-6.
struct CompSpec {
  struct Section {
    bool present = false;
    std::optional<Tolerance> defaultTolerance;
    std::vector<std::pair<std::string, Tolerance>> variables;  // in file order
  };
  Tolerance defaultTolerance;
  std::optional<Tolerance> coordinates;
  std::optional<Tolerance> timeSteps;
  Section nodal;
  Section element;
  Section global;

  Tolerance coordinateTolerance() const { return coordinates.value_or(defaultTolerance); }
  Tolerance timeTolerance() const { return timeSteps.value_or(defaultTolerance); }
  Tolerance sectionDefault(const Section& s) const {
    return s.defaultTolerance.value_or(defaultTolerance);
  }
};

// Parses .comp text; sourceName (the file name) prefixes error messages. Throws InputError with
// the line number on anything it does not understand.
CompSpec parseCompText(const std::string& text, const std::string& sourceName);
// Reads and parses a .comp file; throws InputError when it cannot be read or parsed.
CompSpec parseCompFile(const std::string& fileName);

// Everything in an Exodus result file that the comparison looks at.
struct ExodusResults {
  std::string fileName;
  int dimension = 3;
  std::vector<double> times;            // one per time step (record)
  std::vector<long long> nodeIds;       // node number map (1..n when absent)
  std::vector<double> nodeCoordinates;  // 3 per node (0 beyond the file's dimension)
  std::vector<long long> elementIds;    // element number map, file order (blocks concatenated)
  std::vector<long long> elementBlock;  // block id of each element, file order
  std::vector<std::string> nodalNames, elementNames, globalNames;
  // values[variable][step][entry]; entries in node / element file order, one entry for globals.
  // An element variable a block does not carry (truth table) is NaN on that block's elements.
  std::vector<std::vector<std::vector<double>>> nodal, element, global;
};

// Reads the whole file. Throws InputError (naming the file) when it cannot be opened, is
// truncated or corrupt.
ExodusResults readExodusResults(const std::string& fileName);

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
