#include "core/ProcessorsPerRank.hpp"

#include <algorithm>
#include <atomic>

namespace peridot {

namespace {
std::atomic<int> processors{1};
}

void setProcessorsPerRank(int n) { processors.store(n < 1 ? 1 : n); }

int processorsPerRank() { return processors.load(); }

int setUpThreads() { return std::min(processors.load(), 8); }

int threadsFor(int threads, std::size_t items) {
  return static_cast<int>(std::max<std::size_t>(
      1, std::min(static_cast<std::size_t>(std::max(threads, 1)), items / 1024)));
}

std::vector<std::size_t> runsOfRows(const std::int64_t* offsets, std::size_t rows, int runs) {
  std::vector<std::size_t> first(static_cast<std::size_t>(runs) + 1, rows);
  first[0] = 0;
  for (int k = 1; k < runs; ++k)
    first[k] = static_cast<std::size_t>(
        std::lower_bound(offsets, offsets + rows, offsets[rows] / runs * k) - offsets);
  return first;
}

}  // namespace peridot
