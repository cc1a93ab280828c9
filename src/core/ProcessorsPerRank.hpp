#pragma once
// How many processors each rank may keep busy: one for its own work, and any the node has to
// spare beyond one per rank (a single rank on a multi-core machine). Decided once, at start
// (app/Application.cpp); the set-up's helpers use the spare ones (the neighbour search's
// threads, core/BackgroundFaults.hpp). 1 until decided.
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

}  // namespace peridot
