#pragma once
// Named point sets: those of the mesh and those the deck defines (1-based ids, inline or in a
// file), resolved to the owned points of this rank.
#include <map>
#include <string>
#include <vector>

#include "deck/RunConfig.hpp"
#include "discretization/PointCloud.hpp"

namespace peridot {

// Global (0-based) ids of every named set, mesh sets first; deck sets override nothing: a
// name defined twice is an error.
std::map<std::string, std::vector<long long>> collectNodeSets(
    const PointCloud& cloud, const std::vector<NodeSetSpec>& specs);

// Owned local indices of a set's points, given the owned global ids (local index = position).
std::vector<int> ownedPoints(const std::vector<long long>& setGlobalIds,
                             const std::vector<long long>& ownedGlobalIds);

}  // namespace peridot
