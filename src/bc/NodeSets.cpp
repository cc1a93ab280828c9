#include "bc/NodeSets.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/Error.hpp"
#include "core/InputFile.hpp"

namespace peridot {

namespace {

bool allIntegers(const std::string& s) {
  std::istringstream in(s);
  std::string w;
  bool any = false;
  while (in >> w) {
    any = true;
    char* end = nullptr;
    std::strtoll(w.c_str(), &end, 10);
    if (*end != '\0') return false;
  }
  return any;
}

// The separators of `>>` (the program keeps the classic locale).
bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// The ids read from `in`, line by line, that `keep` accepts (all ids are range-checked): a
// rank keeps only its own, however long the list. The words of a line are read in place (a
// string stream per line cost 0.1 s for a 2 * 10^6-point file).
template <class Keep>
std::vector<long long> readIds(std::istream& in, const std::string& path, const std::string& source,
                               long long numPoints, Keep keep) {
  std::vector<long long> ids;
  std::string line;
  while (std::getline(in, line)) {
    const char* c = line.c_str();
    const char* const end = c + line.size();
    while (c < end && isSpace(*c)) ++c;
    if (c == end || *c == '#' || *c == '/' || *c == '*') continue;
    while (c < end) {
      const char* wordEnd = c;
      while (wordEnd < end && !isSpace(*wordEnd)) ++wordEnd;
      char* parsed = nullptr;
      const long long id = std::strtoll(c, &parsed, 10);
      if (parsed != wordEnd || parsed == c) {
        throw InputError(path, source + ": \"" + std::string(c, wordEnd) +
                                   "\" is not a point id (a positive integer)");
      }
      if (id < 1 || id > numPoints) {
        throw InputError(path, source + ": point id " + std::string(c, wordEnd) +
                                   " is out of range (ids are 1-based, the discretization has " +
                                   std::to_string(numPoints) + " points)");
      }
      if (keep(id - 1)) ids.push_back(id - 1);
      for (c = wordEnd; c < end && isSpace(*c);) ++c;
    }
  }
  return ids;
}

}  // namespace

std::map<std::string, std::vector<long long>> collectNodeSets(
    const Topology& topology, const std::vector<NodeSetSpec>& specs) {
  std::map<std::string, std::vector<long long>> sets;
  // Ids run from 0 to the largest id (Exodus element ids may leave gaps).
  long long maxId = 0, localMax = 0;
  for (int i = 0; i < topology.numOwned; ++i)
    localMax = std::max(localMax, topology.overlapGlobalId[i] + 1);
  MPI_Allreduce(&localMax, &maxId, 1, MPI_LONG_LONG, MPI_MAX, topology.comm);
  const IdIndex owned(topology.overlapGlobalId.data(), static_cast<std::size_t>(topology.numOwned));
  auto isOwned = [&](long long g) { return owned.find(g) >= 0; };
  for (std::size_t s = 0; s < topology.pointSetNames.size(); ++s) {
    std::vector<long long>& ids = sets[topology.pointSetNames[s]];
    for (int i : topology.ownedPointSets[s]) ids.push_back(topology.overlapGlobalId[i]);
    std::sort(ids.begin(), ids.end());
  }
  for (const auto& spec : specs) {
    if (sets.count(spec.name)) {
      throw InputError(spec.path,
                       "a node set named \"" + spec.name + "\" already exists in the mesh");
    }
    std::vector<long long> ids;
    long long listed = 0;  // ids in the set, owned here or not
    auto keep = [&](long long g) {
      ++listed;
      return isOwned(g);
    };
    if (spec.value.find_first_not_of(" \t\r\n") == std::string::npos) {
      throw InputError(spec.path, "the node set is empty");
    }
    if (allIntegers(spec.value)) {
      std::istringstream text(spec.value);
      ids = readIds(text, spec.path, "node set", maxId, keep);
    } else {
      std::string fileName = spec.value;
      fileName.erase(0, fileName.find_first_not_of(" \t"));
      fileName.erase(fileName.find_last_not_of(" \t") + 1);
      const std::string why = whyNotReadableFile(fileName);
      if (!why.empty()) {
        throw InputError(spec.path, "\"" + spec.value +
                                        "\" is neither a list of point ids nor a readable file (" +
                                        why + ")");
      }
      std::ifstream in(fileName);
      if (!in) {
        throw InputError(
            spec.path, "\"" + spec.value + "\" is neither a list of point ids nor a readable file");
      }
      ids = readIds(in, spec.path, "node set file \"" + fileName + "\"", maxId, keep);
    }
    if (listed == 0) throw InputError(spec.path, "the node set is empty");
    if (!std::is_sorted(ids.begin(), ids.end())) std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    sets[spec.name] = ids;
  }
  return sets;
}

std::vector<int> ownedPoints(const std::vector<long long>& setGlobalIds, const IdIndex& owned) {
  // Marked, then collected in order: linear, where a sort of the indices took 0.1 s for a set
  // of 2 * 10^6 points. (The ids are distinct, so are the indices.)
  std::vector<int> out;
  for (long long g : setGlobalIds) {
    const int local = owned.find(g);
    if (local >= 0) out.push_back(local);
  }
  if (out.size() < 64) {
    std::sort(out.begin(), out.end());
    return out;
  }
  const int largest = *std::max_element(out.begin(), out.end());
  std::vector<unsigned char> in(static_cast<std::size_t>(largest) + 1, 0);
  for (int local : out) in[static_cast<std::size_t>(local)] = 1;
  out.clear();
  for (int local = 0; local <= largest; ++local)
    if (in[static_cast<std::size_t>(local)]) out.push_back(local);
  return out;
}

}  // namespace peridot
