// Neighbour-search scaling: time of the cell-list search (and of the whole topology build,
// partition included) on cubic grids of 1e4 to 1e6 points with horizon 3.015 x spacing.
// Usage: bench_search_scaling [max_points]   (prints a table; run it on an idle machine)
#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "neighbor/NeighborSearch.hpp"
#include "parallel/Topology.hpp"

using namespace peridot;

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const double maxPoints = argc > 1 ? std::atof(argv[1]) : 1.0e6;
  std::printf("%12s %12s %14s %14s %16s\n", "points", "bonds", "search (s)", "ns/bond",
              "topology (s)");
  for (int n : {22, 47, 100}) {  // 1.06e4, 1.04e5, 1e6 points
    if (static_cast<double>(n) * n * n > maxPoints) break;
    PointCloud cloud;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          cloud.x.insert(cloud.x.end(), {double(i), double(j), double(k)});
          cloud.volume.push_back(1.0);
          cloud.blockId.push_back(1);
          cloud.globalId.push_back(static_cast<long long>(cloud.globalId.size()));
        }
    cloud.blockNames[1] = "block_1";
    std::vector<double> horizon(cloud.size(), 3.015);
    std::vector<std::size_t> queries(cloud.size());
    for (std::size_t q = 0; q < queries.size(); ++q) queries[q] = q;
    NeighborSearchInput in;
    in.x = cloud.x.data();
    in.numPoints = cloud.size();
    in.horizon = horizon.data();
    std::vector<long long> offsets;
    std::vector<std::size_t> neighbors;
    auto t0 = std::chrono::steady_clock::now();
    findNeighbors(in, queries, offsets, neighbors);
    auto t1 = std::chrono::steady_clock::now();
    Topology t = buildTopology(cloud, horizon, TopologyOptions{}, MPI_COMM_WORLD);
    auto t2 = std::chrono::steady_clock::now();
    const double search = std::chrono::duration<double>(t1 - t0).count();
    std::printf("%12zu %12zu %14.3f %14.2f %16.3f\n", cloud.size(), neighbors.size(), search,
                1e9 * search / static_cast<double>(neighbors.size()),
                std::chrono::duration<double>(t2 - t1).count());
    (void)t;
  }
  MPI_Finalize();
  return 0;
}
