#pragma once
// The command files (.comp) of SEACAS exodiff, the subset Peridigm's regression tests use:
// tolerances per quantity and the variables to compare (output/ExodusCompare.hpp compares under
// them).
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

// Whether two variable names are the same name: case-insensitively, as exodiff matches them.
bool sameVariableName(const std::string& a, const std::string& b);

}  // namespace peridot
