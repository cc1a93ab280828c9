// core/ZeroedArray.hpp: an array that reads as zeros and occupies memory only where written.
#include <gtest/gtest.h>

#include <fstream>
#include <utility>

#include "core/ZeroedArray.hpp"

using peridot::ZeroedArray;

namespace {

// Resident pages of this process (/proc/self/statm), -1 where there is no such file.
long residentPages() {
  std::ifstream in("/proc/self/statm");
  long size = 0, resident = -1;
  if (!(in >> size >> resident)) return -1;
  return resident;
}

}  // namespace

TEST(ZeroedArray, ReadsAsZerosAndOccupiesOnlyWrittenPages) {
  const std::size_t n = std::size_t{256} << 20;  // 256 MiB of flags
  const long before = residentPages();
  ZeroedArray<unsigned char> flags(n);
  ASSERT_EQ(flags.size(), n);
  flags[n / 2] = 1;
  flags[n - 1] = 1;
  // Counted before anything reads the untouched pages: whether a read maps the kernel's shared
  // zero page (not counted as this process's) or a fresh page of its own depends on the machine:
  // earlier test machines mapped the zero page, one with kernel 6.18 gives a fresh page.
  const long after = residentPages();
  if (before >= 0 && after >= 0) {
    // Written: 2 pages; a std::vector would have written all 65536 of them.
    EXPECT_LT(after - before, 4096) << "pages resident: " << after - before;
  }
  // A sample of every page's first byte and a few runs: zeros except where written.
  long ones = 0;
  for (std::size_t k = 0; k < n; k += 4096) ones += flags[k];
  for (std::size_t k = 0; k < 100000; ++k) ones += flags[k] + flags[n - 1 - k];
  EXPECT_EQ(ones, 2);  // n / 2 starts a page; n - 1 is read by the second loop
  ZeroedArray<unsigned char> moved = std::move(flags);
  EXPECT_TRUE(flags.empty());
  EXPECT_EQ(flags.data(), nullptr);
  EXPECT_EQ(moved.size(), n);
  EXPECT_EQ(moved[n / 2], 1);
}

TEST(ZeroedArray, EmptyHasNoStorage) {
  ZeroedArray<int> none(0);
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(none.begin(), none.end());
  ZeroedArray<double> some(3);
  for (double v : some) EXPECT_EQ(v, 0.0);
}
