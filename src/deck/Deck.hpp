#pragma once
// Loading a deck (Teuchos XML or YAML) and reading it with checks: every value read through a
// ListReader is type-checked, and finish() rejects any key nobody read, so no deck entry is ever
// silently ignored. Every message names the deck path, e.g.
//   Materials -> My Material -> Bulk Modulus: expected a positive number, got "abc"
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <set>
#include <string>
#include <vector>

namespace peridot {

// Reads `fileName` (.xml, or .yaml/.yml with an optional top-level `Peridigm:` key). An XML
// parameter repeated in one list with the same type and value is accepted, as Peridigm's parser
// (which keeps the last) accepts it, and a sentence saying so is added to `warnings`; a
// repeated parameter with another value or type, or a repeated list, is an error.
Teuchos::RCP<Teuchos::ParameterList> loadDeck(const std::string& fileName,
                                              std::vector<std::string>* warnings = nullptr);

// Parses deck text given in memory ("xml" or "yaml"), e.g. for tests.
Teuchos::RCP<Teuchos::ParameterList> parseDeck(const std::string& text, const std::string& format);

std::string joinPath(const std::string& path, const std::string& key);

class ListReader {
 public:
  ListReader(const Teuchos::ParameterList& list, std::string path);

  const std::string& path() const { return path_; }
  std::string pathOf(const std::string& key) const { return joinPath(path_, key); }
  const Teuchos::ParameterList& list() const { return list_; }
  bool has(const std::string& key) const;
  bool isSublist(const std::string& key) const;

  double number(const std::string& key);
  double number(const std::string& key, double defaultValue);
  double positiveNumber(const std::string& key);
  double positiveNumber(const std::string& key, double defaultValue);
  double nonNegativeNumber(const std::string& key, double defaultValue);
  long long integer(const std::string& key);
  long long integer(const std::string& key, long long defaultValue);
  bool boolean(const std::string& key, bool defaultValue);
  std::string string(const std::string& key);
  std::string string(const std::string& key, const std::string& defaultValue);
  // A string restricted to `choices` (compared exactly); the message lists them.
  std::string choice(const std::string& key, const std::vector<std::string>& choices,
                     const std::string& defaultValue = "");
  // Number or string expression, returned as text (e.g. "Value", "Horizon").
  std::string numberOrExpression(const std::string& key);
  ListReader sublist(const std::string& key);
  // Names of entries (sublists and parameters) in deck order.
  std::vector<std::string> keys() const;

  // Marks a key as understood without reading it (e.g. a key consumed elsewhere).
  void accept(const std::string& key) { used_.insert(key); }
  // Throws InputError for the first key that was never read or accepted.
  void finish() const;

 private:
  void require(const std::string& key) const;
  const Teuchos::ParameterEntry& entry(const std::string& key);
  const Teuchos::ParameterList& list_;
  std::string path_;
  std::set<std::string> used_;
};

// Text of a parameter value for messages ("abc", 12.5, true).
std::string describeEntry(const Teuchos::ParameterEntry& entry);

}  // namespace peridot
