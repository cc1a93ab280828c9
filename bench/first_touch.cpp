// What the first write of fresh memory costs on this machine, against writing it again: the
// figure behind the set-up's helper thread (core/BackgroundFaults.hpp, bench/RESULTS.md).
//
//   bench_first_touch GB [threads] [pause_s]
//
// Maps GB of anonymous memory in 2 MiB pages where the kernel gives them (MADV_HUGEPAGE), has
// `threads` threads fault it in (MADV_POPULATE_WRITE, each its own slice), then writes it all
// once more from one thread, and prints both rates. It does this twice, `pause_s` seconds apart
// (default 5): a VM whose host takes freed memory back (a balloon's free page reporting) shows
// the first-touch rate again after the pause, one that keeps it shows the second faster.
#include <sys/mman.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23
#endif

namespace {

double seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void round(std::size_t bytes, int threads) {
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) {
    std::perror("mmap");
    std::exit(1);
  }
  char* data = static_cast<char*>(p);
  madvise(data, bytes, MADV_HUGEPAGE);
  const std::size_t slice =
      bytes / static_cast<std::size_t>(threads) & ~((std::size_t{2} << 20) - 1);
  const double t0 = seconds();
  std::vector<std::thread> workers;
  bool refused = false;
  for (int t = 0; t < threads; ++t) {
    const std::size_t begin = slice * static_cast<std::size_t>(t);
    const std::size_t end = t + 1 == threads ? bytes : begin + slice;
    workers.emplace_back([&, begin, end] {
      if (madvise(data + begin, end - begin, MADV_POPULATE_WRITE) != 0) refused = true;
    });
  }
  for (auto& w : workers) w.join();
  const double t1 = seconds();
  std::memset(data, 1, bytes);
  const double t2 = seconds();
  const double gb = static_cast<double>(bytes) / 1e9;
  std::printf("first touch (%d thread%s): %.2f GB/s%s   written again: %.2f GB/s\n", threads,
              threads == 1 ? "" : "s", gb / (t1 - t0), refused ? " (populate refused)" : "",
              gb / (t2 - t1));
  munmap(data, bytes);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_first_touch GB [threads] [pause_s]\n");
    return 2;
  }
  const auto bytes = static_cast<std::size_t>(std::atof(argv[1]) * 1e9) & ~std::size_t{4095};
  const int threads = argc > 2 ? std::max(1, std::atoi(argv[2])) : 1;
  const double pause = argc > 3 ? std::atof(argv[3]) : 5.0;
  round(bytes, threads);
  std::this_thread::sleep_for(std::chrono::duration<double>(pause));
  round(bytes, threads);
  return 0;
}
