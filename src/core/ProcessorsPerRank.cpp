#include "core/ProcessorsPerRank.hpp"

#include <atomic>

namespace peridot {

namespace {
std::atomic<int> processors{1};
}

void setProcessorsPerRank(int n) { processors.store(n < 1 ? 1 : n); }

int processorsPerRank() { return processors.load(); }

}  // namespace peridot
