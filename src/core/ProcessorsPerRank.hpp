#pragma once
// How many processors each rank may keep busy: one for its own work, and any the node has to
// spare beyond one per rank (a single rank on a multi-core machine). Decided once, at start
// (app/Application.cpp); the set-up's helpers use the spare ones (the neighbour search's
// threads, core/BackgroundFaults.hpp). 1 until decided.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

namespace peridot {

void setProcessorsPerRank(int processors);
int processorsPerRank();

// The threads a set-up pass shares its work among: the rank's processors, at most 8 (the passes
// are bound by memory traffic well before that, and each thread of the search's count keeps
// counts of its own: 4 bytes a point).
int setUpThreads();

// How many of `threads` a pass over `items` takes: at least 1024 items a thread (fewer cost
// more to start than they save), at least one thread.
int threadsFor(int threads, std::size_t items);

// The first rows of `runs` runs of rows [0, rows) with about equal shares of their entries, row r
// holding entries [offsets[r], offsets[r + 1]): runs + 1 values, from 0 to rows.
std::vector<std::size_t> runsOfRows(const std::int64_t* offsets, std::size_t rows, int runs);

// Calls work(t) for t = 0 .. n-1, work(0) on the calling thread and the others on threads of
// their own, and returns when every call has: the first exception any call threw is rethrown
// then. A thread that cannot be started leaves its call to the calling thread.
template <class Work>
void runOnThreads(int n, Work&& work) {
  std::vector<std::exception_ptr> failure(n > 1 ? n : 1);
  std::vector<std::thread> helpers;
  std::vector<int> leftOver;
  for (int t = 1; t < n; ++t) {
    try {
      helpers.emplace_back([&, t] {
        try {
          work(t);
        } catch (...) {
          failure[t] = std::current_exception();
        }
      });
    } catch (...) {
      leftOver.push_back(t);
    }
  }
  leftOver.insert(leftOver.begin(), 0);
  for (int t : leftOver) {
    try {
      work(t);
    } catch (...) {
      failure[t] = std::current_exception();
    }
  }
  for (auto& h : helpers) h.join();
  for (const auto& f : failure)
    if (f) std::rethrow_exception(f);
}

// Calls work(t, first, last) for chunks [first, last) of [0, items), `chunk` items each (the
// last may be shorter), on n threads as runOnThreads does. Chunks go in order to whichever
// thread asks first, so a thread slowed down (by a processor it shares with the page-fault
// helper, or by rows that cost more than others) takes fewer of them instead of finishing last.
// Only for work whose result does not depend on which thread did which chunk.
template <class Work>
void runChunksOnThreads(int n, std::size_t items, std::size_t chunk, Work&& work) {
  chunk = std::max<std::size_t>(chunk, 1);
  std::atomic<std::size_t> nextChunk{0};
  runOnThreads(n, [&](int t) {
    for (;;) {
      const std::size_t first = nextChunk.fetch_add(chunk, std::memory_order_relaxed);
      if (first >= items) return;
      work(t, first, std::min(items, first + chunk));
    }
  });
}

// Calls work(k) for k = 0 .. tasks-1 on n threads, each task going to whichever thread asks
// first (as runChunksOnThreads).
template <class Work>
void runTasksOnThreads(int n, int tasks, Work&& work) {
  runChunksOnThreads(n, static_cast<std::size_t>(std::max(tasks, 0)), 1,
                     [&](int, std::size_t first, std::size_t last) {
                       for (std::size_t k = first; k < last; ++k) work(static_cast<int>(k));
                     });
}

}  // namespace peridot
