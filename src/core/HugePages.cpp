#include "core/HugePages.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace peridot {

std::size_t collapseToHugePages(const void* data, std::size_t bytes) {
#if defined(__linux__)
#ifndef MADV_COLLAPSE
  constexpr int MADV_COLLAPSE = 25;  // Linux 6.1 (glibc 2.36's headers predate it)
#endif
  constexpr std::uintptr_t kBlock = std::uintptr_t{1} << 21;
  // Small arrays are left alone: one large page would hold mostly other data.
  if (data == nullptr || bytes < kBlock) return 0;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  // Block by block, so that a block the kernel refuses (part of another mapping) leaves the
  // others collapsed: the blocks the array only partly fills are asked too (a collapse keeps
  // whatever else they hold).
  std::size_t collapsed = 0;
  for (std::uintptr_t b = begin & ~(kBlock - 1); b < begin + bytes; b += kBlock)
    if (madvise(reinterpret_cast<void*>(b), kBlock, MADV_COLLAPSE) == 0) collapsed += kBlock;
  return collapsed;
#else
  (void)data;
  (void)bytes;
  return 0;
#endif
}

std::size_t adviseHugePages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kBlock = std::uintptr_t{1} << 21;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  // Only whole blocks: a block the array shares with other data would take a large page for
  // that data too.
  const std::uintptr_t first = (begin + kBlock - 1) & ~(kBlock - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kBlock - 1);
  if (data == nullptr || last <= first) return 0;
  return madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE) == 0 ? last - first
                                                                                   : 0;
#else
  (void)data;
  (void)bytes;
  return 0;
#endif
}

bool largeAllocationsInHugePages() {
  // Read at the first large allocation (possibly before main); the environment does not change
  // under a run.
  static const bool enabled = [] {
    const char* v = std::getenv("PERIDOT_HUGE_PAGES");
    return v == nullptr || std::strcmp(v, "0") != 0;
  }();
  return enabled;
}

}  // namespace peridot
