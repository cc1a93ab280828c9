#include "output/ExodusCompare.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>
#include <unordered_map>

#include "core/Error.hpp"
#include "discretization/ExodusMeshReader.hpp"

namespace peridot {

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

bool sameName(const std::string& a, const std::string& b) { return upper(a) == upper(b); }

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
        if (sameName(listed.first, tokens[0])) {
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

// ----------------------------------------------------------------------------------------------
// Reading a result file

namespace {

class ResultReader {
 public:
  explicit ResultReader(const std::string& fileName)
      : fileName_(fileName), file_(fileName, "file", "") {}

  ExodusResults read();

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError("Exodus file \"" + fileName_ + "\": " + message);
  }
  void check(int status, const char* call) const {
    if (status < 0) {
      fail(std::string(call) + " failed (" + exodusLastError() +
           "); the file may be truncated or corrupt");
    }
  }
  std::vector<std::string> variableNames(ex_entity_type type) const;

  std::string fileName_;
  ExodusInputFile file_;
};

std::vector<std::string> ResultReader::variableNames(ex_entity_type type) const {
  int count = 0;
  check(ex_get_variable_param(file_.id(), type, &count), "ex_get_variable_param");
  std::vector<std::string> names(static_cast<std::size_t>(std::max(count, 0)));
  if (count <= 0) return names;
  constexpr std::size_t kBufferSize = 257;  // the longest netCDF name plus the terminator
  std::vector<std::vector<char>> buffers(names.size(), std::vector<char>(kBufferSize, '\0'));
  std::vector<char*> pointers(names.size());
  for (std::size_t i = 0; i < names.size(); ++i) pointers[i] = buffers[i].data();
  check(ex_get_variable_names(file_.id(), type, count, pointers.data()), "ex_get_variable_names");
  for (std::size_t i = 0; i < names.size(); ++i) {
    buffers[i].back() = '\0';
    std::string name = buffers[i].data();
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
    names[i] = name;
  }
  return names;
}

ExodusResults ResultReader::read() {
  const int exoid = file_.id();
  ExodusResults r;
  r.fileName = fileName_;
  ex_init_params init{};
  check(ex_get_init_ext(exoid, &init), "ex_get_init_ext");
  if (init.num_dim < 1 || init.num_dim > 3 || init.num_nodes < 0 || init.num_elem < 0 ||
      init.num_elem_blk < 0) {
    fail("implausible sizes in the header; the file may be corrupt");
  }
  r.dimension = static_cast<int>(init.num_dim);
  const auto numNodes = static_cast<std::size_t>(init.num_nodes);
  const auto numElements = static_cast<std::size_t>(init.num_elem);

  const int64_t numSteps = ex_inquire_int(exoid, EX_INQ_TIME);
  if (numSteps < 0) fail("cannot read the number of time steps (" + exodusLastError() + ")");
  r.times.resize(static_cast<std::size_t>(numSteps));
  if (numSteps > 0) check(ex_get_all_times(exoid, r.times.data()), "ex_get_all_times");

  std::vector<int64_t> ids(numNodes);
  if (numNodes > 0) {
    check(ex_get_id_map(exoid, EX_NODE_MAP, ids.data()), "ex_get_id_map");
    std::vector<double> c[3];
    for (int d = 0; d < 3; ++d) c[d].assign(numNodes, 0.0);
    check(ex_get_coord(exoid, c[0].data(), r.dimension > 1 ? c[1].data() : nullptr,
                       r.dimension > 2 ? c[2].data() : nullptr),
          "ex_get_coord");
    r.nodeCoordinates.resize(3 * numNodes);
    for (std::size_t n = 0; n < numNodes; ++n) {
      for (int d = 0; d < 3; ++d) r.nodeCoordinates[3 * n + static_cast<std::size_t>(d)] = c[d][n];
    }
  }
  r.nodeIds.assign(ids.begin(), ids.end());

  ids.assign(numElements, 0);
  if (numElements > 0) check(ex_get_id_map(exoid, EX_ELEM_MAP, ids.data()), "ex_get_id_map");
  r.elementIds.assign(ids.begin(), ids.end());

  const auto numBlocks = static_cast<std::size_t>(init.num_elem_blk);
  std::vector<int64_t> blockIds(numBlocks);
  std::vector<std::size_t> blockStart(numBlocks + 1, 0);
  if (numBlocks > 0) check(ex_get_ids(exoid, EX_ELEM_BLOCK, blockIds.data()), "ex_get_ids");
  for (std::size_t b = 0; b < numBlocks; ++b) {
    ex_block param{};
    param.id = blockIds[b];
    param.type = EX_ELEM_BLOCK;
    check(ex_get_block_param(exoid, &param), "ex_get_block_param");
    if (param.num_entry < 0 ||
        blockStart[b] + static_cast<std::size_t>(param.num_entry) > numElements) {
      fail("element block " + std::to_string(blockIds[b]) + " has an inconsistent size");
    }
    blockStart[b + 1] = blockStart[b] + static_cast<std::size_t>(param.num_entry);
    r.elementBlock.insert(r.elementBlock.end(), static_cast<std::size_t>(param.num_entry),
                          static_cast<long long>(blockIds[b]));
  }
  if (blockStart[numBlocks] != numElements) {
    fail("the element blocks hold " + std::to_string(blockStart[numBlocks]) +
         " elements but the header declares " + std::to_string(numElements));
  }

  r.nodalNames = variableNames(EX_NODAL);
  r.elementNames = variableNames(EX_ELEM_BLOCK);
  r.globalNames = variableNames(EX_GLOBAL);
  const auto steps = static_cast<std::size_t>(numSteps);

  r.nodal.assign(r.nodalNames.size(), std::vector<std::vector<double>>(steps));
  for (std::size_t v = 0; v < r.nodalNames.size(); ++v) {
    for (std::size_t s = 0; s < steps; ++s) {
      auto& values = r.nodal[v][s];
      values.assign(numNodes, 0.0);
      if (numNodes == 0) continue;
      check(ex_get_var(exoid, static_cast<int>(s + 1), EX_NODAL, static_cast<int>(v + 1), 1,
                       static_cast<int64_t>(numNodes), values.data()),
            "ex_get_var (nodal)");
    }
  }

  const std::size_t numElementVars = r.elementNames.size();
  std::vector<int> truth(numBlocks * numElementVars, 1);
  if (numElementVars > 0 && numBlocks > 0) {
    check(ex_get_truth_table(exoid, EX_ELEM_BLOCK, static_cast<int>(numBlocks),
                             static_cast<int>(numElementVars), truth.data()),
          "ex_get_truth_table");
  }
  r.element.assign(numElementVars, std::vector<std::vector<double>>(steps));
  for (std::size_t v = 0; v < numElementVars; ++v) {
    for (std::size_t s = 0; s < steps; ++s) {
      auto& values = r.element[v][s];
      values.assign(numElements, std::numeric_limits<double>::quiet_NaN());
      for (std::size_t b = 0; b < numBlocks; ++b) {
        const std::size_t count = blockStart[b + 1] - blockStart[b];
        if (count == 0 || truth[b * numElementVars + v] == 0) continue;
        check(ex_get_var(exoid, static_cast<int>(s + 1), EX_ELEM_BLOCK, static_cast<int>(v + 1),
                         blockIds[b], static_cast<int64_t>(count), values.data() + blockStart[b]),
              "ex_get_var (element)");
      }
    }
  }

  const std::size_t numGlobals = r.globalNames.size();
  r.global.assign(numGlobals, std::vector<std::vector<double>>(steps, std::vector<double>(1)));
  std::vector<double> row(numGlobals);
  for (std::size_t s = 0; s < steps && numGlobals > 0; ++s) {
    check(
        ex_get_glob_vars(exoid, static_cast<int>(s + 1), static_cast<int>(numGlobals), row.data()),
        "ex_get_glob_vars");
    for (std::size_t v = 0; v < numGlobals; ++v) r.global[v][s][0] = row[v];
  }
  return r;
}

}  // namespace

ExodusResults readExodusResults(const std::string& fileName) {
  ResultReader reader(fileName);
  return reader.read();
}

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
    if (sameName(names[i], name)) return static_cast<long long>(i);
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
