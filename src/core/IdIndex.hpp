#pragma once
// Points looked up by global id. Where a rank's ids are dense (their range at most a few times
// their count: one rank, or a partition of a mesh numbered along an axis) a table over the
// range answers in one load; otherwise a sorted copy of the ids answers by binary search. At
// 2 * 10^6 points the hash map this replaces took 0.1-0.3 s of the set-up at each node set.
// Memory: O(points of the rank) either way.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace peridot {

class IdIndex {
 public:
  // ids[k] for local k in [0, n); an id listed twice keeps its first index.
  IdIndex(const long long* ids, std::size_t n) {
    if (n == 0) return;
    const auto [lo, hi] = std::minmax_element(ids, ids + n);
    if (*lo >= 0 &&
        static_cast<unsigned long long>(*hi - *lo) < 4 * static_cast<unsigned long long>(n)) {
      first_ = *lo;
      table_.assign(static_cast<std::size_t>(*hi - *lo) + 1, -1);
      for (std::size_t k = n; k-- > 0;)
        table_[static_cast<std::size_t>(ids[k] - first_)] = static_cast<int>(k);
      return;
    }
    byId_.resize(n);
    for (std::size_t k = 0; k < n; ++k) byId_[k] = {ids[k], static_cast<int>(k)};
    std::sort(byId_.begin(), byId_.end());
  }

  // The local index of `id`, or -1.
  int find(long long id) const {
    if (!table_.empty()) {
      const long long at = id - first_;
      return at >= 0 && at < static_cast<long long>(table_.size())
                 ? table_[static_cast<std::size_t>(at)]
                 : -1;
    }
    auto it = std::lower_bound(byId_.begin(), byId_.end(), std::pair<long long, int>{id, -1});
    return it != byId_.end() && it->first == id ? it->second : -1;
  }

  // visit(id, local) for every indexed id, in ascending id order.
  template <class Visit>
  void forEachInOrder(Visit visit) const {
    for (std::size_t k = 0; k < table_.size(); ++k)
      if (table_[k] >= 0) visit(first_ + static_cast<long long>(k), table_[k]);
    for (std::size_t k = 0; k < byId_.size(); ++k)
      if (k == 0 || byId_[k - 1].first != byId_[k].first) visit(byId_[k].first, byId_[k].second);
  }

 private:
  long long first_ = 0;
  std::vector<int> table_;                       // dense: local index of id first_ + k, or -1
  std::vector<std::pair<long long, int>> byId_;  // sparse: (id, local), sorted
};

}  // namespace peridot
