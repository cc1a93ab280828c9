#include "deck/Deck.hpp"

#include <Teuchos_FileInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListCoreHelpers.hpp>
#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/Error.hpp"
#include "core/Format.hpp"
#include "core/InputFile.hpp"
#include "core/Suggest.hpp"
#include "deck/DeckScreen.hpp"

namespace peridot {

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// Parses the whole string as a number; false if anything but blanks is left over.
bool parseNumber(const std::string& text, double& value) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size() && errno == 0 && std::isfinite(value);
}

bool parseInteger(const std::string& text, long long& value) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(t.c_str(), &end, 10);
  return end == t.c_str() + t.size() && errno == 0;
}

// Teuchos reads XML literals leniently ("78oo" as 78, "1.5" as an int 1) and lets a name appear
// twice in a list; check the raw XML first so such decks fail with the deck path.
void checkXmlLiterals(const Teuchos::XMLObject& list, const std::string& path,
                      std::vector<std::string>* warnings) {
  // name -> "type=value" of a parameter ("" for a list), to tell a harmless repetition.
  std::map<std::string, std::string> seen;
  for (int k = 0; k < list.numChildren(); ++k) {
    const Teuchos::XMLObject& child = list.getChild(k);
    if (child.getTag() != "Parameter" && child.getTag() != "ParameterList") continue;
    const std::string name = child.hasAttribute("name") ? child.getAttribute("name") : "";
    const std::string here = joinPath(path, name);
    std::string content;
    if (child.getTag() == "Parameter" && child.hasAttribute("type") && child.hasAttribute("value"))
      content = child.getAttribute("type") + "=" + child.getAttribute("value");
    const auto previous = seen.find(name);
    if (previous != seen.end()) {
      if (content.empty() || previous->second != content) {
        throw InputError(here, "appears twice in the same list" +
                                   std::string(content.empty() || previous->second.empty()
                                                   ? ""
                                                   : " with different values"));
      }
      if (warnings)
        warnings->push_back(here +
                            ": appears twice with the same value; the repetition is "
                            "ignored (Peridigm keeps the last)");
      continue;
    }
    seen[name] = content;
    if (child.getTag() == "ParameterList") {
      checkXmlLiterals(child, here, warnings);
      continue;
    }
    if (!child.hasAttribute("type") || !child.hasAttribute("value")) continue;
    const std::string type = child.getAttribute("type"), value = child.getAttribute("value");
    double d = 0;
    long long i = 0;
    std::string lower = trim(value);
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (type == "double" && !parseNumber(value, d)) {
      throw InputError(here, "expected a number (type \"double\"), got \"" + value + "\"");
    } else if (type == "int" && !parseInteger(value, i)) {
      throw InputError(here, "expected an integer (type \"int\"), got \"" + value + "\"");
    } else if (type == "int" && (i < INT_MIN || i > INT_MAX)) {
      // Teuchos stores type="int" in 32 bits and would wrap the value silently.
      throw InputError(here, "the integer " + trim(value) +
                                 " does not fit type \"int\" (32 bits; largest 2147483647)");
    } else if (type == "bool" && lower != "true" && lower != "false" && lower != "yes" &&
               lower != "no" && lower != "1" && lower != "0") {
      throw InputError(here, "expected true or false (type \"bool\"), got \"" + value + "\"");
    }
  }
}

// YAML decks put everything under a top-level `Peridigm:` key.
Teuchos::RCP<Teuchos::ParameterList> withoutPeridigmWrapper(
    Teuchos::RCP<Teuchos::ParameterList> deck) {
  if (deck->numParams() == 1 && deck->isSublist("Peridigm")) {
    return Teuchos::rcp(new Teuchos::ParameterList(deck->sublist("Peridigm")));
  }
  return deck;
}

}  // namespace

std::string joinPath(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + " -> " + key;
}

std::string describeEntry(const Teuchos::ParameterEntry& e) {
  if (e.isList()) return "a parameter list";
  if (e.isType<std::string>()) return "\"" + Teuchos::getValue<std::string>(e) + "\"";
  std::ostringstream s;
  if (e.isType<double>()) {
    s << formatNumber(Teuchos::getValue<double>(e));
  } else if (e.isType<int>()) {
    s << Teuchos::getValue<int>(e);
  } else if (e.isType<long long>()) {
    s << Teuchos::getValue<long long>(e);
  } else if (e.isType<bool>()) {
    s << (Teuchos::getValue<bool>(e) ? "true" : "false");
  } else {
    s << "a value of type " << e.getAny(false).typeName();
  }
  return s.str();
}

Teuchos::RCP<Teuchos::ParameterList> loadDeck(const std::string& fileName,
                                              std::vector<std::string>* warnings) {
  const std::string why = whyNotReadableFile(fileName);
  if (!why.empty()) throw InputError("cannot open deck file \"" + fileName + "\": " + why);
  std::ifstream probe(fileName);
  if (!probe) throw InputError("cannot open deck file \"" + fileName + "\"");
  const bool yaml = endsWith(fileName, ".yaml") || endsWith(fileName, ".yml");
  const bool xml = endsWith(fileName, ".xml");
  if (!yaml && !xml) {
    throw InputError("deck file \"" + fileName + "\" must end in .xml, .yaml or .yml");
  }
  std::string text;
  {
    std::ostringstream all;
    all << probe.rdbuf();
    text = all.str();
  }
  screenDeckText(text, yaml, fileName);
  Teuchos::RCP<Teuchos::ParameterList> deck;
  if (xml) {
    Teuchos::XMLObject root;
    try {
      root = Teuchos::FileInputSource(fileName).getObject();
    } catch (const std::exception&) {
      root = Teuchos::XMLObject();  // the parse below reports the syntax error
    }
    if (!root.isEmpty()) checkXmlLiterals(root, "", warnings);
  }
  try {
    deck = yaml ? Teuchos::getParametersFromYamlFile(fileName)
                : Teuchos::getParametersFromXmlFile(fileName);
  } catch (const std::exception& e) {
    std::string what = e.what();
    if (yaml) {
      const std::string words = explainYamlFailure(what, text);
      if (!words.empty())
        throw InputError("cannot parse deck file \"" + fileName + "\" as YAML: " + words);
    }
    // Teuchos prefixes its messages with source locations; keep the lines that say where in
    // the deck the problem is, and the last informative line.
    std::istringstream lines(what);
    std::string line, last, where;
    while (std::getline(lines, line)) {
      const std::string t = trim(line);
      if (t.empty() || t.find(".cpp") != std::string::npos || t.find(".hpp") != std::string::npos)
        continue;
      if (where.empty() && t.find("line ") != std::string::npos) where = t;
      last = t;
    }
    if (!where.empty() && where != last) last = where + "; " + last;
    throw InputError("cannot parse deck file \"" + fileName + "\" as " + (yaml ? "YAML" : "XML") +
                     ": " + last);
  }
  return withoutPeridigmWrapper(deck);
}

Teuchos::RCP<Teuchos::ParameterList> parseDeck(const std::string& text, const std::string& format) {
  Teuchos::RCP<Teuchos::ParameterList> deck;
  try {
    deck = format == "yaml" ? Teuchos::getParametersFromYamlString(text)
                            : Teuchos::getParametersFromXmlString(text);
  } catch (const std::exception& e) {
    throw InputError(std::string("cannot parse deck text: ") + e.what());
  }
  return withoutPeridigmWrapper(deck);
}

ListReader::ListReader(const Teuchos::ParameterList& list, std::string path)
    : list_(list), path_(std::move(path)) {}

bool ListReader::has(const std::string& key) const { return list_.isParameter(key); }

bool ListReader::isSublist(const std::string& key) const { return list_.isSublist(key); }

void ListReader::require(const std::string& key) const {
  if (!list_.isParameter(key)) throw InputError(pathOf(key), "required parameter is missing");
}

const Teuchos::ParameterEntry& ListReader::entry(const std::string& key) {
  require(key);
  used_.insert(key);
  return *list_.getEntryPtr(key);
}

double ListReader::number(const std::string& key) {
  const auto& e = entry(key);
  if (e.isType<double>()) {
    const double v = Teuchos::getValue<double>(e);
    if (!std::isfinite(v)) throw InputError(pathOf(key), "expected a finite number");
    return v;
  }
  if (e.isType<int>()) return Teuchos::getValue<int>(e);
  if (e.isType<long long>()) return static_cast<double>(Teuchos::getValue<long long>(e));
  double v = 0.0;
  if (e.isType<std::string>() && parseNumber(Teuchos::getValue<std::string>(e), v)) return v;
  throw InputError(pathOf(key), "expected a number, got " + describeEntry(e));
}

double ListReader::number(const std::string& key, double defaultValue) {
  return has(key) ? number(key) : defaultValue;
}

double ListReader::positiveNumber(const std::string& key) {
  const auto& e = entry(key);
  double v = 0.0;
  bool ok = false;
  if (e.isType<double>()) {
    v = Teuchos::getValue<double>(e);
    ok = true;
  } else if (e.isType<int>()) {
    v = Teuchos::getValue<int>(e);
    ok = true;
  } else if (e.isType<long long>()) {
    v = static_cast<double>(Teuchos::getValue<long long>(e));
    ok = true;
  } else if (e.isType<std::string>()) {
    ok = parseNumber(Teuchos::getValue<std::string>(e), v);
  }
  if (!ok || !(v > 0.0) || !std::isfinite(v)) {
    throw InputError(pathOf(key), "expected a positive number, got " + describeEntry(e));
  }
  return v;
}

double ListReader::positiveNumber(const std::string& key, double defaultValue) {
  return has(key) ? positiveNumber(key) : defaultValue;
}

double ListReader::nonNegativeNumber(const std::string& key, double defaultValue) {
  if (!has(key)) return defaultValue;
  const double v = number(key);
  if (v < 0.0) {
    throw InputError(pathOf(key), "expected a non-negative number, got " +
                                      describeEntry(*list_.getEntryPtr(key)));
  }
  return v;
}

long long ListReader::integer(const std::string& key) {
  const auto& e = entry(key);
  if (e.isType<int>()) return Teuchos::getValue<int>(e);
  if (e.isType<long long>()) return Teuchos::getValue<long long>(e);
  double v = 0.0;
  const bool parsed =
      (e.isType<double>() && ((v = Teuchos::getValue<double>(e)), true)) ||
      (e.isType<std::string>() && parseNumber(Teuchos::getValue<std::string>(e), v));
  if (parsed && std::floor(v) == v && std::fabs(v) < 9e15) return static_cast<long long>(v);
  throw InputError(pathOf(key), "expected an integer, got " + describeEntry(e));
}

long long ListReader::integer(const std::string& key, long long defaultValue) {
  return has(key) ? integer(key) : defaultValue;
}

bool ListReader::boolean(const std::string& key, bool defaultValue) {
  if (!has(key)) return defaultValue;
  const auto& e = entry(key);
  if (e.isType<bool>()) return Teuchos::getValue<bool>(e);
  if (e.isType<std::string>()) {
    const std::string s = trim(Teuchos::getValue<std::string>(e));
    if (s == "true" || s == "True" || s == "TRUE" || s == "1") return true;
    if (s == "false" || s == "False" || s == "FALSE" || s == "0") return false;
  }
  if (e.isType<int>()) {
    const int v = Teuchos::getValue<int>(e);
    if (v == 0 || v == 1) return v == 1;
  }
  throw InputError(pathOf(key), "expected true or false, got " + describeEntry(e));
}

std::string ListReader::string(const std::string& key) {
  const auto& e = entry(key);
  if (!e.isType<std::string>()) {
    throw InputError(pathOf(key), "expected a string, got " + describeEntry(e));
  }
  return Teuchos::getValue<std::string>(e);
}

std::string ListReader::string(const std::string& key, const std::string& defaultValue) {
  return has(key) ? string(key) : defaultValue;
}

std::string ListReader::choice(const std::string& key, const std::vector<std::string>& choices,
                               const std::string& defaultValue) {
  if (!has(key) && !defaultValue.empty()) return defaultValue;
  const std::string v = string(key);
  for (const auto& c : choices)
    if (v == c) return v;
  std::string list;
  for (std::size_t i = 0; i < choices.size(); ++i) list += (i ? ", \"" : "\"") + choices[i] + "\"";
  throw InputError(pathOf(key), "unknown value \"" + v + "\"" + didYouMean(v, choices) +
                                    "; expected one of " + list);
}

std::string ListReader::numberOrExpression(const std::string& key) {
  const auto& e = entry(key);
  if (e.isType<std::string>()) return Teuchos::getValue<std::string>(e);
  if (e.isType<double>() || e.isType<int>() || e.isType<long long>()) return describeEntry(e);
  throw InputError(pathOf(key), "expected a number or an expression, got " + describeEntry(e));
}

ListReader ListReader::sublist(const std::string& key) {
  if (!list_.isParameter(key)) throw InputError(pathOf(key), "required list is missing");
  if (!list_.isSublist(key)) {
    throw InputError(pathOf(key),
                     "expected a parameter list, got " + describeEntry(*list_.getEntryPtr(key)));
  }
  used_.insert(key);
  return ListReader(list_.sublist(key), pathOf(key));
}

std::vector<std::string> ListReader::keys() const {
  std::vector<std::string> out;
  for (auto it = list_.begin(); it != list_.end(); ++it) out.push_back(list_.name(it));
  return out;
}

void ListReader::finish() const {
  for (auto it = list_.begin(); it != list_.end(); ++it) {
    const std::string& key = list_.name(it);
    if (!used_.count(key)) {
      throw InputError(pathOf(key),
                       std::string("unknown ") + (list_.entry(it).isList() ? "list" : "parameter") +
                           " (not part of Peridot's deck vocabulary; see doc/deck-reference.md)");
    }
  }
}

}  // namespace peridot
