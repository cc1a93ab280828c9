// The program's operator new, so that every large array (bond lists, node fields, the search's
// grids) is page-faulted in 2 MiB pages. The set-up of a large run writes a few GB of fresh
// memory; on the VM we measure on, a 4 KiB fault costs more than clearing its page, and at
// 128^3 the faults took half of the set-up (bench/RESULTS.md). In 2 MiB pages there are 512
// times fewer, and the bond loops' address translations hit more often. An allocation of at
// least kLargeAllocation bytes is advised (MADV_HUGEPAGE) before the caller first touches it; a
// smaller one, or any with PERIDOT_HUGE_PAGES=0 in the environment, is plain malloc. Every form
// allocates with malloc (or posix_memalign) and frees with free. Where the application turned
// it on, each large allocation is also handed to the helper that faults it in ahead of its use
// (core/BackgroundFaults.hpp), and taken back from it before it is freed.
//
// Linked into `peridot` and the unit tests only: a bench program counts its allocations with an
// operator new of its own. Not in sanitizer builds, whose runtime replaces operator new to check
// its uses.
#include <cstddef>
#include <cstdlib>
#include <new>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "core/BackgroundFaults.hpp"
#include "core/HugePages.hpp"

#if !defined(__SANITIZE_ADDRESS__)

namespace {

// Two large pages: below that, the whole blocks inside an allocation are few or none.
constexpr std::size_t kLargeAllocation = std::size_t{4} << 20;

// Aligned as new-expressions ask (at least malloc's own alignment).
void* allocate(std::size_t bytes, std::size_t alignment = 0) noexcept {
  if (bytes == 0) bytes = 1;
  void* p = nullptr;
  if (alignment <= alignof(std::max_align_t)) {
    p = std::malloc(bytes);
  } else if (posix_memalign(&p, alignment, bytes) != 0) {
    p = nullptr;
  }
  if (p != nullptr && bytes >= kLargeAllocation) {
    if (peridot::largeAllocationsInHugePages()) peridot::adviseHugePages(p, bytes);
    peridot::faultInBackground(p, bytes);
  }
  return p;
}

void release(void* p) noexcept {
#if defined(__GLIBC__)
  // Only a large block can be queued; the size is in the block's header, which free reads too.
  if (p != nullptr && malloc_usable_size(p) >= kLargeAllocation) peridot::forgetBackgroundFaults(p);
#else
  peridot::forgetBackgroundFaults(p);
#endif
  std::free(p);
}

void* allocateOrThrow(std::size_t bytes, std::size_t alignment = 0) {
  for (;;) {
    if (void* p = allocate(bytes, alignment)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

void* allocateOrNull(std::size_t bytes, std::size_t alignment = 0) noexcept {
  try {
    return allocateOrThrow(bytes, alignment);
  } catch (...) {
    return nullptr;
  }
}

}  // namespace

// Every form a new-expression may call, the aligned ones too (the node fields' storage takes
// the aligned form: fields/FieldManager.hpp).
void* operator new(std::size_t bytes) { return allocateOrThrow(bytes); }
void* operator new[](std::size_t bytes) { return allocateOrThrow(bytes); }
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
  return allocateOrNull(bytes);
}
void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept {
  return allocateOrNull(bytes);
}
void* operator new(std::size_t bytes, std::align_val_t a) {
  return allocateOrThrow(bytes, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t bytes, std::align_val_t a) {
  return allocateOrThrow(bytes, static_cast<std::size_t>(a));
}
void* operator new(std::size_t bytes, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocateOrNull(bytes, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t bytes, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocateOrNull(bytes, static_cast<std::size_t>(a));
}
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }

#endif
