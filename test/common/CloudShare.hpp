#pragma once
// Tests build a whole point cloud on every rank; buildTopology takes each rank's share of it.
#include <mpi.h>

#include <algorithm>
#include <vector>

#include "discretization/PointCloud.hpp"
#include "parallel/Topology.hpp"

namespace peridot::testing {

struct CloudShare {
  PointCloud cloud;
  std::vector<double> horizon;
};

// This rank's contiguous slice of a cloud that every rank holds whole.
inline CloudShare shareOf(const PointCloud& whole, const std::vector<double>& horizon,
                          MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const std::size_t n = whole.size(), b = n * rank / size, e = n * (rank + 1) / size;
  CloudShare s;
  s.cloud.x.assign(whole.x.begin() + 3 * b, whole.x.begin() + 3 * e);
  s.cloud.volume.assign(whole.volume.begin() + b, whole.volume.begin() + e);
  s.cloud.blockId.assign(whole.blockId.begin() + b, whole.blockId.begin() + e);
  s.cloud.globalId.assign(whole.globalId.begin() + b, whole.globalId.begin() + e);
  s.cloud.blockNames = whole.blockNames;
  s.cloud.dimension = whole.dimension;
  s.cloud.thickness = whole.thickness;
  s.cloud.globalNumPoints = static_cast<long long>(n);
  for (const auto& set : whole.pointSets) {
    PointSet mine{set.name, {}};
    for (long long g : set.globalIds)
      if (std::find(s.cloud.globalId.begin(), s.cloud.globalId.end(), g) != s.cloud.globalId.end())
        mine.globalIds.push_back(g);
    s.cloud.pointSets.push_back(mine);
  }
  s.horizon.assign(horizon.begin() + b, horizon.begin() + e);
  return s;
}

// buildTopology of a cloud that every rank holds whole, each rank passing its share.
inline Topology topologyOfWhole(const PointCloud& whole, const std::vector<double>& horizon,
                                const TopologyOptions& options, MPI_Comm comm) {
  const CloudShare s = shareOf(whole, horizon, comm);
  return buildTopology(s.cloud, s.horizon, options, comm);
}

}  // namespace peridot::testing
