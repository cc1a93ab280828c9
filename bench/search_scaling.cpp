// Neighbour-search scaling: the per-query search (findNeighbors, what contact uses), the two
// passes of the topology's search by candidate (countNeighbors, fillNeighbors: lists come out
// sorted), and the whole topology build, on cubic lattices of 1e4 to 1e6 points with horizon
// 3.015 x spacing. Times are CPU seconds of this process (the machine is shared).
// Usage: bench_search_scaling [max_points] [min_points] [repeats]: the lattices of min_points to
// max_points; with min_points given the per-query search (seconds at 1e6 points) is skipped and
// the two passes run `repeats` times (the smallest time is printed).
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "LatticeScene.hpp"
#include "neighbor/NeighborSearch.hpp"
#include "parallel/Topology.hpp"

using namespace peridot;

namespace {
double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const double maxPoints = argc > 1 ? std::atof(argv[1]) : 1.0e6;
  const double minPoints = argc > 2 ? std::atof(argv[2]) : 0.0;
  const bool perQuerySearch = argc <= 2;
  const int repeats = argc > 3 ? std::max(1, std::atoi(argv[3])) : 1;
  std::printf("%10s %11s | %9s %8s | %9s %9s %8s | %9s\n", "points", "bonds", "per-query",
              "ns/bond", "count", "fill", "ns/bond", "topology");
  for (int n : {22, 47, 100, 128}) {  // 1.06e4, 1.04e5, 1e6, 2.1e6 points
    if (static_cast<double>(n) * n * n > maxPoints) break;
    if (static_cast<double>(n) * n * n < minPoints) continue;
    PointCloud cloud = bench::unitLattice(n);
    std::vector<double> horizon(cloud.size(), bench::kLatticeHorizon);
    std::vector<std::size_t> queries(cloud.size());
    for (std::size_t q = 0; q < queries.size(); ++q) queries[q] = q;
    NeighborSearchInput in;
    in.x = cloud.x.data();
    in.numPoints = cloud.size();
    in.horizon = horizon.data();
    std::size_t bonds = 0;
    double perQuery = 0;
    if (perQuerySearch) {
      std::vector<long long> offsets;
      std::vector<std::size_t> neighbors;
      const double t0 = cpuSeconds();
      findNeighbors(in, queries, offsets, neighbors);
      perQuery = cpuSeconds() - t0;
      bonds = neighbors.size();
    }
    double count = 1e300, fill = 1e300;
    for (int r = 0; r < repeats; ++r) {
      std::vector<int> counts;
      const double t1 = cpuSeconds();
      countNeighbors(in, queries, counts);
      count = std::min(count, cpuSeconds() - t1);
      std::vector<std::int64_t> begin(queries.size() + 1, 0);
      for (std::size_t q = 0; q < queries.size(); ++q) begin[q + 1] = begin[q] + counts[q];
      std::vector<int> lists(static_cast<std::size_t>(begin.back()));
      const double t3 = cpuSeconds();
      fillNeighbors(in, queries, begin, counts, lists.data());
      fill = std::min(fill, cpuSeconds() - t3);
      bonds = lists.size();
    }
    const double t4 = cpuSeconds();
    Topology t = buildTopology(cloud, horizon, TopologyOptions{}, MPI_COMM_WORLD);
    const double t5 = cpuSeconds();
    const double nb = static_cast<double>(bonds);
    std::printf("%10zu %11zu | %9.3f %8.2f | %9.3f %9.3f %8.2f | %9.3f\n", cloud.size(), bonds,
                perQuery, 1e9 * perQuery / nb, count, fill, 1e9 * (count + fill) / nb, t5 - t4);
    (void)t;
  }
  MPI_Finalize();
  return 0;
}
