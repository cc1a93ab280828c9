#include "bc/NodeSets.hpp"

#include <algorithm>
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

// The ids read from `in`, line by line, that `keep` accepts (all ids are range-checked): a
// rank keeps only its own, however long the list.
template <class Keep>
std::vector<long long> readIds(std::istream& in, const std::string& path, const std::string& source,
                               long long numPoints, Keep keep) {
  std::vector<long long> ids;
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    if (line[first] == '#' || line[first] == '/' || line[first] == '*') continue;
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
      char* end = nullptr;
      const long long id = std::strtoll(w.c_str(), &end, 10);
      if (*end != '\0') {
        throw InputError(path, source + ": \"" + w + "\" is not a point id (a positive integer)");
      }
      if (id < 1 || id > numPoints) {
        throw InputError(path, source + ": point id " + w + " is out of range (ids are 1-based, " +
                                   "the discretization has " + std::to_string(numPoints) +
                                   " points)");
      }
      if (keep(id - 1)) ids.push_back(id - 1);
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
  std::vector<int> out;
  for (long long g : setGlobalIds) {
    const int local = owned.find(g);
    if (local >= 0) out.push_back(local);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace peridot
