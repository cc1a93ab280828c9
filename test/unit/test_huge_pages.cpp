// core/HugePages.hpp: asking for large pages leaves an array's contents (and its neighbours'
// bytes in the blocks it shares) as they were, whether or not the kernel grants them; small
// arrays are not asked for.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
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

namespace {

// The VmFlags line of the mapping that holds address p in /proc/self/smaps ("" where none).
std::string vmFlagsAt(const void* p) {
  std::ifstream in("/proc/self/smaps");
  const auto a = reinterpret_cast<std::uintptr_t>(p);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    unsigned long long lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-' && line.find(':') > line.find(' ')) {
      inside = lo <= a && a < hi;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line;
  }
  return "";
}

bool advisedHuge(const void* p) {
  const std::string flags = vmFlagsAt(p);
  return flags.find(" hg") != std::string::npos;
}

}  // namespace

TEST(HugePages, AdviceCoversOnlyTheWholeBlocksInside) {
  constexpr std::size_t kBlock = 2u << 20;
  std::vector<char> storage(9u << 20);
  // A range that starts 1000 bytes into a block and ends 1000 bytes into another.
  const auto base = reinterpret_cast<std::uintptr_t>(storage.data());
  char* begin = storage.data() + ((base + kBlock - 1) / kBlock * kBlock - base) + 1000;
  const std::size_t advised = peridot::adviseHugePages(begin, 3 * kBlock);
  if (advised == 0) GTEST_SKIP() << "no MADV_HUGEPAGE on this system";
  EXPECT_EQ(advised, 2 * kBlock);  // the two whole blocks; not the two it only partly covers
  EXPECT_TRUE(advisedHuge(begin + kBlock));
  EXPECT_EQ(peridot::adviseHugePages(begin, kBlock), 0u);  // no whole block
  EXPECT_EQ(peridot::adviseHugePages(nullptr, 8u << 20), 0u);
}

TEST(HugePages, LargeAllocationsAreAdvisedBeforeTheirFirstTouch) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the sanitizer's operator new replaces the program's";
#else
  std::vector<char> probe(8u << 20);
  if (peridot::adviseHugePages(probe.data(), probe.size()) == 0)
    GTEST_SKIP() << "no MADV_HUGEPAGE on this system";
  if (!peridot::largeAllocationsInHugePages()) GTEST_SKIP() << "PERIDOT_HUGE_PAGES=0";
  // Through operator new (std::vector), as the program's arrays are: the middle of 64 MiB lies in
  // an advised mapping (core/LargeAllocations.cpp).
  std::vector<double> large((64u << 20) / sizeof(double));
  EXPECT_TRUE(advisedHuge(large.data() + large.size() / 2)) << vmFlagsAt(large.data());
#endif
}
