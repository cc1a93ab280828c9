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

}  // namespace peridot
