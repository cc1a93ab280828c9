// Peak memory of the discretization stage alone: each rank calls buildPointCloud (or, with
// --whole, the serial buildWholePointCloud every rank used to run) on an Exodus or text mesh and
// rank 0 prints every rank's peak resident set size (getrusage ru_maxrss) before and after.
// Usage: mpirun -np P bench_read_rss mesh.g [--text | --gmsh] [--whole]
#include <mpi.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "discretization/Discretization.hpp"

namespace {

long peakKilobytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;  // kilobytes on Linux
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (argc < 2) {
    if (rank == 0) std::fprintf(stderr, "usage: bench_read_rss mesh [--text | --gmsh] [--whole]\n");
    MPI_Finalize();
    return 2;
  }
  bool text = false, whole = false, gmsh = false;
  for (int a = 2; a < argc; ++a) {
    text = text || std::strcmp(argv[a], "--text") == 0;
    gmsh = gmsh || std::strcmp(argv[a], "--gmsh") == 0;
    whole = whole || std::strcmp(argv[a], "--whole") == 0;
  }
  peridot::DiscretizationConfig c;
  c.type = text ? "Text File" : gmsh ? "Gmsh" : "Exodus";
  c.dimension = text ? 3 : 0;
  c.meshFile = argv[1];
  c.meshFilePath = "Discretization -> Input Mesh File";
  const long before = peakKilobytes();
  MPI_Barrier(MPI_COMM_WORLD);
  const double start = MPI_Wtime();
  const peridot::PointCloud cloud =
      whole ? peridot::buildWholePointCloud(c) : peridot::buildPointCloud(c, MPI_COMM_WORLD);
  MPI_Barrier(MPI_COMM_WORLD);
  const double seconds = MPI_Wtime() - start;
  const long mine[3] = {before, peakKilobytes(), static_cast<long>(cloud.size())};
  std::vector<long> all(3 * static_cast<std::size_t>(size));
  MPI_Gather(mine, 3, MPI_LONG, all.data(), 3, MPI_LONG, 0, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf("%s read of %s on %d rank(s): %.2f s\n", whole ? "whole" : "distributed", argv[1],
                size, seconds);
    std::printf("%6s %12s %14s %14s %14s\n", "rank", "points", "peak before", "peak after",
                "read (MiB)");
    long worst = 0;
    for (int r = 0; r < size; ++r) {
      const long* v = &all[3 * static_cast<std::size_t>(r)];
      worst = std::max(worst, v[1] - v[0]);
      std::printf("%6d %12ld %11.1f MiB %11.1f MiB %14.1f\n", r, v[2], v[0] / 1024.0, v[1] / 1024.0,
                  (v[1] - v[0]) / 1024.0);
    }
    std::printf("largest growth of the peak during the read: %.1f MiB\n", worst / 1024.0);
  }
  MPI_Finalize();
  return 0;
}
