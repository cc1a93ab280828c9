#pragma once
// Named point sets: those of the mesh and those the deck defines (1-based ids, inline or in a
// file), resolved to the owned points of this rank.
#include <map>
#include <string>
#include <vector>

#include "core/IdIndex.hpp"
#include "deck/RunConfig.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

// Every named set (mesh sets first; deck sets override nothing: a name defined twice is an
// error) as the global (0-based) ids of its points owned by this rank, sorted. Each rank keeps
// only its owned ids, whatever the size of a set.
std::map<std::string, std::vector<long long>> collectNodeSets(
    const Topology& topology, const std::vector<NodeSetSpec>& specs);

// Owned local indices of a set's points, sorted, each once, given the owned points indexed by
// global id (built once for all the sets).
std::vector<int> ownedPoints(const std::vector<long long>& setGlobalIds, const IdIndex& owned);

}  // namespace peridot
