// core/HugePages.hpp: asking for large pages leaves an array's contents (and its neighbours'
// bytes in the blocks it shares) as they were, whether or not the kernel grants them; small
// arrays are not asked for.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "core/HugePages.hpp"

using peridot::collapseToHugePages;

namespace {

// The process's anonymous memory in large pages (kB), from /proc/self/smaps_rollup; -1 where
// there is no such file.
long anonHugeKiloBytes() {
  std::ifstream in("/proc/self/smaps_rollup");
  if (!in) return -1;
  std::string key;
  long value = 0;
  while (in >> key) {
    if (key == "AnonHugePages:") {
      in >> value;
      return value;
    }
    in.ignore(1 << 20, '\n');
  }
  return -1;
}

}  // namespace

TEST(HugePages, ContentsAreKeptAndSmallArraysLeftAlone) {
  // 5 MiB of values with a guard on each side, offset so that the array starts and ends inside
  // blocks it shares with the guards.
  const std::size_t n = (5u << 20) / sizeof(double);
  std::vector<double> storage(n + 2 * 4096);
  for (std::size_t i = 0; i < storage.size(); ++i) storage[i] = 0.5 * static_cast<double>(i) - 3;
  const std::vector<double> before = storage;
  const long hugeBefore = anonHugeKiloBytes();
  const std::size_t collapsed = collapseToHugePages(storage.data() + 4096, n * sizeof(double));
  EXPECT_EQ(storage, before);
  EXPECT_EQ(collapsed % (2u << 20), 0u);
  EXPECT_LE(collapsed, 4u * (2u << 20));  // the blocks the array touches, at most
  if (collapsed > 0 && hugeBefore >= 0) {
    // What it reports granted is there (unless the kernel split pages since, which it does
    // only under memory pressure).
    EXPECT_GE(anonHugeKiloBytes() - hugeBefore, static_cast<long>(collapsed / 1024) / 2);
  }
  std::vector<double> small(1000, 1.0);
  EXPECT_EQ(collapseToHugePages(small.data(), small.size() * sizeof(double)), 0u);
  EXPECT_EQ(collapseToHugePages(nullptr, 8u << 20), 0u);
}
