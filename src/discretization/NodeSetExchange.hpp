#pragma once
// Node-set membership for the distributed Exodus reader: the ranks that read slices of the node
// sets send (node, set) to the node's home rank (its node slice), which tells every rank the sets
// of the nodes it asked about. O(entries / P + requests) per rank.
#include <mpi.h>

#include <cstdint>
#include <vector>

#include "discretization/Slicing.hpp"

namespace peridot {

// A node set entry: the node (1-based) and the set's index in the file.
struct NodeInSet {
  int64_t node = 0, set = 0;
  bool operator<(const NodeInSet& o) const { return node != o.node ? node < o.node : set < o.set; }
  bool operator==(const NodeInSet& o) const { return node == o.node && set == o.set; }
};

// The sets of each requested node: sets[start[i] .. start[i + 1]) for the i-th, sorted, unique.
struct NodeSetsOfNodes {
  std::vector<std::size_t> start;
  std::vector<int64_t> sets;
};

// Collective. entries: what this rank read; requests / requestCounts: the nodes other ranks asked
// this rank (their home) about, grouped by asking rank; numRequested: how many sorted, unique
// nodes this rank itself asked about (the answer follows their order).
NodeSetsOfNodes nodeSetsOfRequested(std::vector<NodeInSet> entries, const Slicing& nodes,
                                    const std::vector<int64_t>& requests,
                                    const std::vector<int>& requestCounts, std::size_t numRequested,
                                    MPI_Comm comm);

}  // namespace peridot
