// Output cost at several rank counts, without the (still replicated) set-up: every rank makes
// its own share of an n^3 lattice directly (slabs along z, as a partitioner would give, owned
// points in a scrambled order, two blocks whose ids interleave, two node sets), then the output
// manager writes R records of Displacement, Velocity (vectors) and Damage (scalar).
//
// Reported (rank 0): time to work out the output order, time of the first write (file, mesh,
// record 1) and of each later record, and the heap bytes the output added on top of the share
// (peak C++ heap, counted by replacing operator new here) on rank 0 and at most on any rank,
// and each rank's peak RSS (VmHWM).
//
//   bench_output_scaling n R file      (e.g. 100 3 /tmp/out_bench -> 1e6 points, /tmp/out_bench.e)
#include <malloc.h>
#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>
#include <string>

#include "output/OutputManager.hpp"

namespace {

std::atomic<long long> heapNow{0}, heapPeak{0};

void* counted(std::size_t size) {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  const long long now = heapNow += static_cast<long long>(malloc_usable_size(p));
  long long peak = heapPeak.load();
  while (now > peak && !heapPeak.compare_exchange_weak(peak, now)) {
  }
  return p;
}

void uncounted(void* p) {
  if (p == nullptr) return;
  heapNow -= static_cast<long long>(malloc_usable_size(p));
  std::free(p);
}

}  // namespace

void* operator new(std::size_t size) { return counted(size); }
void* operator new[](std::size_t size) { return counted(size); }
void operator delete(void* p) noexcept { uncounted(p); }
void operator delete[](void* p) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t) noexcept { uncounted(p); }

namespace {

using namespace peridot;

long long vmHwmKb() {
  std::ifstream in("/proc/self/status");
  std::string key;
  long long value = 0;
  while (in >> key) {
    if (key == "VmHWM:") {
      in >> value;
      return value;
    }
    in.ignore(1 << 20, '\n');
  }
  return 0;
}

class Source : public VariableSource {
 public:
  explicit Source(const Topology& t) : t_(t) {}
  double time = 0;
  void nodeVariable(const std::string& name, std::vector<double>& v) override {
    const int c = components(name);
    v.resize(static_cast<std::size_t>(c) * t_.numOwned);
    for (int i = 0; i < t_.numOwned; ++i)
      for (int d = 0; d < c; ++d)
        v[c * i + d] = std::sin(1e-3 * static_cast<double>(t_.overlapGlobalId[i]) + d) * time;
  }
  void globalVariable(const std::string&, std::vector<double>& v) override { v = {time}; }
  int components(const std::string& name) const override { return name == "Damage" ? 1 : 3; }
  int globalSize(const std::string&) const override { return 1; }

 private:
  const Topology& t_;
};

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  {
    const long long n = argc > 1 ? std::atoll(argv[1]) : 100;
    const int records = argc > 2 ? std::atoi(argv[2]) : 3;
    const std::string stem = argc > 3 ? argv[3] : "/tmp/peridot_output_bench";
    Topology t;
    MPI_Comm_rank(t.comm, &t.rank);
    MPI_Comm_size(t.comm, &t.numRanks);
    t.globalNumPoints = n * n * n;
    std::map<std::string, std::vector<long long>> sets{{"min_x", {}}, {"max_z", {}}};
    std::vector<long long> ids;
    for (long long k = n * t.rank / t.numRanks; k < n * (t.rank + 1) / t.numRanks; ++k)
      for (long long j = 0; j < n; ++j)
        for (long long i = 0; i < n; ++i) ids.push_back(i + n * (j + n * k));
    // Scrambled owned order (a partitioner's curve order is not the id order).
    std::sort(ids.begin(), ids.end(), [](long long a, long long b) {
      const unsigned long long ha = static_cast<unsigned long long>(a) * 0x9E3779B97F4A7C15ULL;
      const unsigned long long hb = static_cast<unsigned long long>(b) * 0x9E3779B97F4A7C15ULL;
      return ha < hb;
    });
    t.numOwned = t.numOverlap = static_cast<int>(ids.size());
    t.overlapGlobalId = ids;
    for (long long g : ids) {
      const long long i = g % n, j = (g / n) % n, k = g / (n * n);
      t.referencePosition.insert(t.referencePosition.end(),
                                 {0.5 * static_cast<double>(i), 0.5 * static_cast<double>(j),
                                  0.5 * static_cast<double>(k)});
      t.blockId.push_back(i < n / 2 ? 1 : 2);
      if (i == 0) sets["min_x"].push_back(g);
      if (k == n - 1) sets["max_z"].push_back(g);
    }
    for (auto& kv : sets) std::sort(kv.second.begin(), kv.second.end());
    RunConfig config;
    OutputConfig out;
    out.fileName = stem;
    out.variables = {"Displacement", "Velocity", "Damage"};
    config.outputs.push_back(out);
    Source source(t);
    Timers timers;
    const std::map<int, std::string> blockNames{{1, "left"}, {2, "right"}};

    MPI_Barrier(t.comm);
    const long long base = heapNow.load();
    heapPeak = base;
    auto now = [] { return std::chrono::steady_clock::now(); };
    auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
    auto t0 = now();
    double setup = 0, first = 0, later = 0;
    {
      OutputManager manager(config, blockNames, 3, sets, t, source, timers);
      MPI_Barrier(t.comm);
      auto t1 = now();
      setup = seconds(t0, t1);
      for (int s = 0; s <= records; ++s) {
        source.time = 0.1 * s;
        auto a = now();
        manager.write(s, source.time);
        MPI_Barrier(t.comm);
        (s == 0 ? first : later) += seconds(a, now());
      }
    }
    const long long extra = heapPeak.load() - base, hwm = vmHwmKb();
    long long maxExtra = 0, maxHwm = 0;
    MPI_Reduce(&extra, &maxExtra, 1, MPI_LONG_LONG, MPI_MAX, 0, t.comm);
    MPI_Reduce(&hwm, &maxHwm, 1, MPI_LONG_LONG, MPI_MAX, 0, t.comm);
    if (t.rank == 0) {
      std::printf(
          "ranks %d points %lld records %d | order %.3f s | first write (file+mesh+record) "
          "%.3f s | later records %.3f s each | output heap peak rank0 %.1f MB, max rank %.1f "
          "MB | VmHWM rank0 %.1f MB, max %.1f MB\n",
          t.numRanks, t.globalNumPoints, records + 1, setup, first,
          records > 0 ? later / records : 0.0, extra / 1e6, maxExtra / 1e6, hwm / 1e3,
          maxHwm / 1e3);
    }
  }
  MPI_Finalize();
  return 0;
}
