#include "core/BackgroundFaults.hpp"

#include <atomic>
#include <cerrno>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

#if defined(__linux__)
#include <pthread.h>
#include <signal.h>
#include <sys/mman.h>
#endif

namespace peridot {

namespace {

#if defined(__linux__)
#ifndef MADV_POPULATE_WRITE
constexpr int MADV_POPULATE_WRITE = 23;  // Linux 5.14
#endif
#endif

// One large page: a step faults at most one (in an advised block) and is as long as a free
// waits for the helper to let go.
constexpr std::uintptr_t kStep = std::uintptr_t{1} << 21;
// Arrays queued at once; more are left to their callers (a set-up has a few dozen).
constexpr int kCapacity = 64;

struct Range {
  char* begin = nullptr;
  std::size_t bytes = 0;
};

struct State {
  std::mutex mutex;
  std::condition_variable work;      // the helper waits for a range
  std::condition_variable released;  // a free waits for the helper to let go of its range
  Range queue[kCapacity];            // a stack: the newest last
  int count = 0;
  char* current = nullptr;  // the range the helper is populating
  std::atomic<bool> dropCurrent{false};
  std::atomic<int> pending{0};  // queued + in flight
  std::atomic<bool> enabled{false};
  std::once_flag started;
};

// Never destroyed: operator delete may still call forgetBackgroundFaults while the program's
// static objects are destroyed at exit, and the helper (detached) may still be waiting.
State& state() {
  static State* s = new State;
  return *s;
}

// Populates r from its end towards its start; stops early when told to drop it, or where the
// kernel refuses (an old kernel, a range no longer mapped): it is only ever a head start.
bool populate(State& s, const Range& r) {
#if defined(__linux__)
  const auto begin = reinterpret_cast<std::uintptr_t>(r.begin);
  std::uintptr_t end = begin + r.bytes;
  while (end > begin && !s.dropCurrent.load(std::memory_order_relaxed)) {
    std::uintptr_t start = (end - 1) & ~(kStep - 1);
    if (start < begin) start = begin;
    // madvise wants a page-aligned start; the page holding `begin` is the caller's anyway.
    const std::uintptr_t pageStart = start & ~std::uintptr_t{4095};
    if (madvise(reinterpret_cast<void*>(pageStart), end - pageStart, MADV_POPULATE_WRITE) != 0)
      return false;
    end = start;
  }
  return true;
#else
  (void)s;
  (void)r;
  return false;
#endif
}

void helperLoop() {
#if defined(__linux__)
  // Signals (a stop request) are the main thread's to take.
  sigset_t all;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, nullptr);
#endif
  State& s = state();
  for (;;) {
    Range r;
    {
      std::unique_lock<std::mutex> lock(s.mutex);
      s.work.wait(lock, [&] { return s.count > 0; });
      r = s.queue[--s.count];
      s.current = r.begin;
      s.dropCurrent.store(false, std::memory_order_relaxed);
    }
    // A kernel without MADV_POPULATE_WRITE refuses at once: nothing more is queued.
    if (!populate(s, r) && errno == EINVAL) s.enabled.store(false);
    {
      std::lock_guard<std::mutex> lock(s.mutex);
      s.current = nullptr;
      s.pending.fetch_sub(1, std::memory_order_release);
    }
    s.released.notify_all();
  }
}

// A child of fork has no helper: it queues nothing and takes nothing back (it never locks the
// mutex, which a parent's thread may have held at the fork).
void forgetHelperInChild() {
  State& s = state();
  s.enabled.store(false);
  s.pending.store(0);
}

}  // namespace

void setBackgroundFaults(bool enabled) { state().enabled.store(enabled); }

bool backgroundFaultsEnabled() { return state().enabled.load(); }

bool faultInBackground(void* data, std::size_t bytes) {
  State& s = state();
  if (data == nullptr || bytes == 0 || !s.enabled.load(std::memory_order_relaxed)) return false;
  bool ok = true;
  std::call_once(s.started, [&] {
    try {
#if defined(__linux__)
      pthread_atfork(nullptr, nullptr, forgetHelperInChild);
#endif
      std::thread(helperLoop).detach();
    } catch (...) {
      ok = false;
    }
  });
  if (!ok) {
    s.enabled.store(false);
    return false;
  }
  {
    std::lock_guard<std::mutex> lock(s.mutex);
    if (s.count == kCapacity) return false;
    s.queue[s.count++] = Range{static_cast<char*>(data), bytes};
    s.pending.fetch_add(1, std::memory_order_relaxed);
  }
  s.work.notify_one();
  return true;
}

void forgetBackgroundFaults(void* data) {
  State& s = state();
  if (data == nullptr || s.pending.load(std::memory_order_acquire) == 0) return;
  std::unique_lock<std::mutex> lock(s.mutex);
  for (int k = 0; k < s.count; ++k)
    if (s.queue[k].begin == data) {
      for (int m = k + 1; m < s.count; ++m) s.queue[m - 1] = s.queue[m];
      --s.count;
      s.pending.fetch_sub(1, std::memory_order_release);
      lock.unlock();
      s.released.notify_all();
      return;
    }
  if (s.current == data) {
    s.dropCurrent.store(true, std::memory_order_relaxed);
    s.released.wait(lock, [&] { return s.current != data; });
  }
}

void waitForBackgroundFaults() {
  State& s = state();
  std::unique_lock<std::mutex> lock(s.mutex);
  s.released.wait(lock, [&] { return s.pending.load() == 0; });
}

}  // namespace peridot
