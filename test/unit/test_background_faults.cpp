// core/BackgroundFaults.hpp: a queued array becomes resident without its owner touching it, an
// array taken back is left alone from then on, and nothing is queued while the helper is off.
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <memory>
#include <thread>
#include <vector>

#include "core/BackgroundFaults.hpp"

namespace {

// Resident pages of [p, p + bytes) (p page-aligned), by mincore.
std::size_t residentPages(void* p, std::size_t bytes) {
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  std::vector<unsigned char> in((bytes + page - 1) / page);
  if (mincore(p, bytes, in.data()) != 0) return 0;
  std::size_t count = 0;
  for (unsigned char c : in) count += c & 1;
  return count;
}

// Fresh anonymous memory nobody has touched, unmapped at the end of the scope.
struct Fresh {
  explicit Fresh(std::size_t n) : bytes(n) {
    void* p = mmap(nullptr, n, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    data = p == MAP_FAILED ? nullptr : static_cast<char*>(p);
  }
  ~Fresh() {
    if (data) munmap(data, bytes);
  }
  std::size_t pages() const { return bytes / static_cast<std::size_t>(sysconf(_SC_PAGESIZE)); }
  std::size_t bytes;
  char* data = nullptr;
};

// Turns the helper on for a test, and off again.
struct HelperOn {
  HelperOn() { peridot::setBackgroundFaults(true); }
  ~HelperOn() {
    peridot::waitForBackgroundFaults();
    peridot::setBackgroundFaults(false);
  }
};

}  // namespace

TEST(BackgroundFaults, AQueuedArrayBecomesResidentUntouched) {
  Fresh a(32u << 20), b(8u << 20);
  ASSERT_NE(a.data, nullptr);
  ASSERT_NE(b.data, nullptr);
  ASSERT_EQ(residentPages(a.data, a.bytes), 0u);
  {
    HelperOn on;
    if (!peridot::faultInBackground(a.data, a.bytes)) GTEST_SKIP() << "no helper thread";
    // An odd start and length: the pages the range touches at its edges are populated too.
    ASSERT_TRUE(peridot::faultInBackground(b.data + 100, b.bytes - 200));
    peridot::waitForBackgroundFaults();
    if (!peridot::backgroundFaultsEnabled()) GTEST_SKIP() << "no MADV_POPULATE_WRITE here";
  }
  EXPECT_EQ(residentPages(a.data, a.bytes), a.pages());
  EXPECT_EQ(residentPages(b.data, b.bytes), b.pages());
  EXPECT_EQ(a.data[12345], 0);  // populated as zeros, as a first write would find them
}

TEST(BackgroundFaults, NothingIsQueuedWhileOff) {
  Fresh a(8u << 20);
  ASSERT_NE(a.data, nullptr);
  peridot::setBackgroundFaults(false);
  EXPECT_FALSE(peridot::faultInBackground(a.data, a.bytes));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(residentPages(a.data, a.bytes), 0u);
}

TEST(BackgroundFaults, AnArrayTakenBackIsLeftAlone) {
  // Several arrays queued, then taken back at once: from the moment forgetBackgroundFaults
  // returns, none of them gains a page (whatever the helper had done before).
  std::vector<std::unique_ptr<Fresh>> arrays;
  for (int k = 0; k < 6; ++k) {
    arrays.push_back(std::make_unique<Fresh>(64u << 20));
    ASSERT_NE(arrays.back()->data, nullptr);
  }
  HelperOn on;
  for (auto& a : arrays)
    if (!peridot::faultInBackground(a->data, a->bytes)) GTEST_SKIP() << "no helper thread";
  std::vector<std::size_t> resident;
  for (auto& a : arrays) {
    peridot::forgetBackgroundFaults(a->data);
    resident.push_back(residentPages(a->data, a->bytes));
  }
  peridot::waitForBackgroundFaults();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  for (std::size_t k = 0; k < arrays.size(); ++k)
    EXPECT_EQ(residentPages(arrays[k]->data, arrays[k]->bytes), resident[k]) << k;
}

TEST(BackgroundFaults, LargeAllocationsAreQueued) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the sanitizer's operator new replaces the program's";
#else
  // Through operator new, as the program's arrays are (app/LargeAllocations.cpp): 64 MiB that
  // the caller never touches become resident, and a small allocation is not queued.
  HelperOn on;
  constexpr std::size_t n = 64u << 20;
  std::unique_ptr<char[]> large(new char[n]);
  peridot::waitForBackgroundFaults();
  if (!peridot::backgroundFaultsEnabled()) GTEST_SKIP() << "no MADV_POPULATE_WRITE here";
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const auto begin = (reinterpret_cast<std::uintptr_t>(large.get()) + page - 1) / page * page;
  const std::size_t inner = (reinterpret_cast<std::uintptr_t>(large.get()) + n - begin) / page;
  EXPECT_EQ(residentPages(reinterpret_cast<void*>(begin), inner * page), inner);
  // Freed right after its allocation, an array is taken off the queue first (no hang, no fault).
  for (int k = 0; k < 20; ++k) std::unique_ptr<char[]> brief(new char[n]);
#endif
}
