#include "discretization/NodeSetExchange.hpp"

#include <algorithm>

namespace peridot {

NodeSetsOfNodes nodeSetsOfRequested(std::vector<NodeInSet> entries, const Slicing& nodes,
                                    const std::vector<int64_t>& requests,
                                    const std::vector<int>& requestCounts, std::size_t numRequested,
                                    MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  // The homes learn the sets of their nodes, sorted by node.
  std::sort(entries.begin(), entries.end());  // by node, hence by home
  std::vector<int> counts(static_cast<std::size_t>(size), 0), recvCounts;
  for (const auto& p : entries) ++counts[static_cast<std::size_t>(nodes.home(p.node - 1))];
  std::vector<NodeInSet> homed = exchange(entries, counts, recvCounts, comm);
  entries = {};
  std::sort(homed.begin(), homed.end());
  homed.erase(std::unique(homed.begin(), homed.end()), homed.end());

  // Answer each request in order with (number of sets, the sets).
  std::vector<int64_t> answers;
  std::fill(counts.begin(), counts.end(), 0);
  std::size_t request = 0;
  for (int r = 0; r < size; ++r) {
    const std::size_t before = answers.size();
    for (int i = 0; i < requestCounts[r]; ++i, ++request) {
      const int64_t node = requests[request];
      auto it = std::lower_bound(homed.begin(), homed.end(), NodeInSet{node, 0});
      const std::size_t countAt = answers.size();
      answers.push_back(0);
      for (; it != homed.end() && it->node == node; ++it) {
        answers.push_back(it->set);
        ++answers[countAt];
      }
    }
    counts[r] = static_cast<int>(answers.size() - before);
  }
  homed = {};
  std::vector<int> ignored;
  const std::vector<int64_t> replies = exchange(answers, counts, ignored, comm);
  answers = {};

  // The replies come in the order of the requests (sorted, so grouped by home in rank order).
  NodeSetsOfNodes result;
  result.start.assign(numRequested + 1, 0);
  for (std::size_t i = 0, at = 0; i < numRequested; ++i) {
    const auto n = static_cast<std::size_t>(replies[at]);
    result.sets.insert(result.sets.end(), replies.begin() + static_cast<std::ptrdiff_t>(at + 1),
                       replies.begin() + static_cast<std::ptrdiff_t>(at + 1 + n));
    at += 1 + n;
    result.start[i + 1] = result.sets.size();
  }
  return result;
}

}  // namespace peridot
