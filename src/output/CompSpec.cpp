#include "output/CompSpec.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "core/Error.hpp"

namespace peridot {

bool sameVariableName(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char p, char q) {
           return std::toupper(static_cast<unsigned char>(p)) ==
                  std::toupper(static_cast<unsigned char>(q));
         });
}

// ----------------------------------------------------------------------------------------------
// Tolerance

double Tolerance::allowed(double a, double b) const {
  if (kind == Kind::Absolute) return value;
  return value * std::max(std::fabs(a), std::fabs(b));
}

bool Tolerance::passes(double a, double b) const {
  if (a == b) return true;  // also the same infinity
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (std::isinf(a) || std::isinf(b)) return false;
  if (std::fabs(a) < floor && std::fabs(b) < floor) return true;
  return std::fabs(a - b) <= allowed(a, b);
}

std::string Tolerance::describe() const {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%s %g", kind == Kind::Absolute ? "absolute" : "relative",
                value);
  std::string text = buffer;
  if (floor > 0.0) {
    std::snprintf(buffer, sizeof buffer, " floor %g", floor);
    text += buffer;
  }
  return text;
}

// ----------------------------------------------------------------------------------------------
// .comp parsing

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

class CompParser {
 public:
  explicit CompParser(const std::string& sourceName) : source_(sourceName) {}

  CompSpec parse(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      ++lineNumber_;
      parseLine(line);
    }
    // A variable listed without a tolerance takes its section's default, else DEFAULT TOLERANCE,
    // wherever in the file those lines are.
    for (auto& [section, inherits] : inherited_) {
      for (std::size_t i = 0; i < inherits.size(); ++i) {
        if (inherits[i]) section->variables[i].second = spec_.sectionDefault(*section);
      }
    }
    return spec_;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(source_ + ", line " + std::to_string(lineNumber_), message);
  }

  double number(const std::string& token, const char* what) const {
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (token.empty() || end == token.c_str() || *end != '\0' || errno == ERANGE ||
        !std::isfinite(v) || v < 0.0) {
      fail(std::string("expected a non-negative number for the ") + what + ", got \"" + token +
           "\"");
    }
    return v;
  }

  // Parses "absolute|relative T [floor F]" from tokens[from..].
  Tolerance tolerance(const std::vector<std::string>& tokens, std::size_t from) const {
    if (from >= tokens.size()) fail("expected a tolerance: absolute|relative <value> [floor <F>]");
    Tolerance t;
    const std::string kind = upper(tokens[from]);
    if (kind == "ABSOLUTE") {
      t.kind = Tolerance::Kind::Absolute;
    } else if (kind == "RELATIVE") {
      t.kind = Tolerance::Kind::Relative;
    } else {
      fail("unsupported tolerance type \"" + tokens[from] + "\" (supported: absolute, relative)");
    }
    if (from + 1 >= tokens.size()) fail("missing the value after \"" + tokens[from] + "\"");
    t.value = number(tokens[from + 1], "tolerance");
    std::size_t next = from + 2;
    if (next < tokens.size() && upper(tokens[next]) == "FLOOR") {
      if (next + 1 >= tokens.size()) fail("missing the value after \"floor\"");
      t.floor = number(tokens[next + 1], "floor");
      next += 2;
    }
    if (next < tokens.size()) fail("unexpected \"" + tokens[next] + "\" after the tolerance");
    return t;
  }

  void parseLine(std::string line) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::vector<std::string> tokens;
    for (std::string w; words >> w;) tokens.push_back(w);
    if (tokens.empty()) return;

    if (line[0] == ' ' || line[0] == '\t') {  // a variable of the current section
      if (section_ == nullptr) {
        fail("indented variable line \"" + tokens[0] +
             "\" outside a NODAL, ELEMENT or GLOBAL VARIABLES section");
      }
      for (const auto& listed : section_->variables) {
        if (sameVariableName(listed.first, tokens[0])) {
          fail("variable \"" + tokens[0] + "\" is listed twice");
        }
      }
      const bool explicitTolerance = tokens.size() > 1;
      section_->variables.emplace_back(tokens[0],
                                       explicitTolerance ? tolerance(tokens, 1) : Tolerance{});
      inherited_[section_].push_back(!explicitTolerance);
      return;
    }

    const std::string first = upper(tokens[0]);
    const std::string second = tokens.size() > 1 ? upper(tokens[1]) : "";
    section_ = nullptr;
    if (first == "DEFAULT" && second == "TOLERANCE") {
      spec_.defaultTolerance = tolerance(tokens, 2);
    } else if (first == "COORDINATES") {
      spec_.coordinates = tolerance(tokens, 1);
    } else if (first == "TIME" && second == "STEPS") {
      spec_.timeSteps = tolerance(tokens, 2);
    } else if (second == "VARIABLES" &&
               (first == "NODAL" || first == "ELEMENT" || first == "GLOBAL")) {
      CompSpec::Section& s = first == "NODAL"     ? spec_.nodal
                             : first == "ELEMENT" ? spec_.element
                                                  : spec_.global;
      if (s.present) fail(first + " VARIABLES appears twice");
      s.present = true;
      if (tokens.size() > 2) s.defaultTolerance = tolerance(tokens, 2);
      section_ = &s;
    } else {
      fail("cannot understand \"" + tokens[0] + (tokens.size() > 1 ? " " + tokens[1] : "") +
           "\" (expected DEFAULT TOLERANCE, COORDINATES, TIME STEPS, NODAL VARIABLES, ELEMENT "
           "VARIABLES, GLOBAL VARIABLES or a tab-indented variable)");
    }
  }

  std::string source_;
  int lineNumber_ = 0;
  CompSpec spec_;
  CompSpec::Section* section_ = nullptr;
  // Per section: which listed variables take the default (no tolerance on their line).
  std::map<CompSpec::Section*, std::vector<bool>> inherited_;
};

}  // namespace

CompSpec parseCompText(const std::string& text, const std::string& sourceName) {
  CompParser parser(sourceName);
  return parser.parse(text);
}

CompSpec parseCompFile(const std::string& fileName) {
  std::ifstream in(fileName, std::ios::binary);
  if (!in) {
    throw InputError("cannot open comparison file \"" + fileName + "\": " + std::strerror(errno));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError("cannot read comparison file \"" + fileName + "\"");
  return parseCompText(text.str(), fileName);
}

}  // namespace peridot
