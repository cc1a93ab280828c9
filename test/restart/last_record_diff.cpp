// Test helper for the restart tests: compares the LAST record of two Exodus results bit for bit
// (time, every nodal and element variable of the gold file), since a continued run's file holds
// only the records after its checkpoint. `--nonzero NAME` also requires a variable of the gold
// file to be nonzero somewhere in some record, so that a scene that never reaches contact or damage
// cannot pass unnoticed. Exit status: 0 equal, 1 different, 2 usage or read error.
#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "output/ExodusCompare.hpp"

using peridot::ExodusResults;

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

int compareKind(const char* kind, const std::vector<std::string>& goldNames,
                const std::vector<std::vector<std::vector<double>>>& gold,
                const std::vector<std::string>& resultNames,
                const std::vector<std::vector<std::vector<double>>>& result) {
  int differences = 0;
  for (std::size_t v = 0; v < goldNames.size(); ++v) {
    std::size_t w = 0;
    while (w < resultNames.size() && resultNames[w] != goldNames[v]) ++w;
    if (w == resultNames.size()) {
      std::cout << kind << " variable " << goldNames[v] << " missing from the result\n";
      ++differences;
      continue;
    }
    const auto& g = gold[v].back();
    const auto& r = result[w].back();
    std::size_t bad = 0;
    for (std::size_t k = 0; k < g.size() && k < r.size(); ++k)
      if (!sameBits(g[k], r[k]) && !(std::isnan(g[k]) && std::isnan(r[k]))) {
        if (bad++ == 0)
          std::cout << kind << " " << goldNames[v] << " entry " << k << ": " << r[k] << " vs "
                    << g[k] << "\n";
      }
    if (g.size() != r.size()) ++bad;
    if (bad) std::cout << kind << " " << goldNames[v] << ": " << bad << " entries differ\n";
    differences += bad > 0;
  }
  return differences;
}

double largest(const ExodusResults& f, const std::string& name) {
  double m = 0;
  auto scan = [&](const std::vector<std::string>& names,
                  const std::vector<std::vector<std::vector<double>>>& values) {
    for (std::size_t v = 0; v < names.size(); ++v)
      if (names[v] == name || names[v] == name + "X" || names[v] == name + "Y" ||
          names[v] == name + "Z")
        for (const auto& record : values[v])
          for (double x : record) m = std::max(m, std::fabs(x));
  };
  scan(f.nodalNames, f.nodal);
  scan(f.elementNames, f.element);
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files, nonzero;
  for (int k = 1; k < argc; ++k) {
    if (std::string(argv[k]) == "--nonzero" && k + 1 < argc) {
      nonzero.push_back(argv[++k]);
    } else {
      files.push_back(argv[k]);
    }
  }
  if (files.size() != 2) {
    std::cerr << "usage: last-record-diff [--nonzero NAME]... RESULT.e GOLD.e\n";
    return 2;
  }
  try {
    const ExodusResults result = peridot::readExodusResults(files[0]);
    const ExodusResults gold = peridot::readExodusResults(files[1]);
    if (result.times.empty() || gold.times.empty()) {
      std::cout << "a file has no record\n";
      return 1;
    }
    int differences = 0;
    if (!sameBits(result.times.back(), gold.times.back())) {
      std::cout.precision(17);
      std::cout << "last times differ: " << result.times.back() << " vs " << gold.times.back()
                << "\n";
      ++differences;
    }
    if (result.nodeIds != gold.nodeIds || result.elementIds != gold.elementIds) {
      std::cout << "node or element ids differ\n";
      ++differences;
    }
    differences +=
        compareKind("nodal", gold.nodalNames, gold.nodal, result.nodalNames, result.nodal);
    differences += compareKind("element", gold.elementNames, gold.element, result.elementNames,
                               result.element);
    for (const auto& name : nonzero) {
      const double m = largest(gold, name);
      std::cout << "largest |" << name << "| in the gold file: " << m << "\n";
      if (!(m > 0)) {
        std::cout << name << " is zero everywhere: the scene does not test it\n";
        ++differences;
      }
    }
    std::cout << (differences ? "DIFFERENT" : "last records identical to the bit") << " ("
              << result.times.size() << " and " << gold.times.size() << " records)\n";
    return differences ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
}
