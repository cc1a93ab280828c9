#include "parallel/Topology.hpp"

#include <Teuchos_DefaultMpiComm.hpp>

#include <algorithm>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "neighbor/NeighborSearch.hpp"
#include "parallel/Partition.hpp"

namespace peridot {

namespace {

struct LocalLists {
  std::vector<std::size_t> owned;       // cloud indices, SFC order
  std::vector<long long> offsets;       // per owned point
  std::vector<std::size_t> neighbors;   // cloud indices
};

LocalLists searchOwned(const PointCloud& cloud, const std::vector<double>& horizon,
                       const std::vector<int>& owner, int rank, const TopologyOptions& opt) {
  const std::size_t n = cloud.size();
  LocalLists out;
  double gLo[3], gHi[3], lo[3], hi[3];
  for (int d = 0; d < 3; ++d) {
    gLo[d] = lo[d] = std::numeric_limits<double>::max();
    gHi[d] = hi[d] = std::numeric_limits<double>::lowest();
  }
  double reach = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      gLo[d] = std::min(gLo[d], cloud.x[3 * i + d]);
      gHi[d] = std::max(gHi[d], cloud.x[3 * i + d]);
    }
    if (owner[i] != rank) continue;
    out.owned.push_back(i);
    reach = std::max(reach, searchReach(opt.rule, horizon[i]));
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], cloud.x[3 * i + d]);
      hi[d] = std::max(hi[d], cloud.x[3 * i + d]);
    }
  }
  // Space-filling-curve order of the owned points (ties broken by global id).
  std::vector<unsigned long long> key(n, 0);
  for (std::size_t i : out.owned) key[i] = mortonKey(&cloud.x[3 * i], gLo, gHi);
  std::sort(out.owned.begin(), out.owned.end(), [&](std::size_t a, std::size_t b) {
    return key[a] != key[b] ? key[a] < key[b] : cloud.globalId[a] < cloud.globalId[b];
  });

  // Candidates: the points that can be within reach of an owned point.
  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < n; ++i) {
    bool inside = true;
    for (int d = 0; d < 3 && inside; ++d)
      inside = cloud.x[3 * i + d] >= lo[d] - reach && cloud.x[3 * i + d] <= hi[d] + reach;
    if (inside) candidates.push_back(i);
  }
  std::vector<double> cx(3 * candidates.size()), ch(candidates.size());
  std::vector<int> cb(candidates.size());
  std::unordered_map<std::size_t, std::size_t> candidateOf;
  candidateOf.reserve(out.owned.size() * 2);
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const std::size_t i = candidates[k];
    for (int d = 0; d < 3; ++d) cx[3 * k + d] = cloud.x[3 * i + d];
    ch[k] = horizon[i];
    cb[k] = cloud.blockId[i];
    if (owner[i] == rank) candidateOf[i] = k;
  }
  std::vector<std::size_t> queries;
  queries.reserve(out.owned.size());
  for (std::size_t i : out.owned) queries.push_back(candidateOf[i]);
  NeighborSearchInput in;
  in.x = cx.data();
  in.numPoints = candidates.size();
  in.horizon = ch.data();
  in.blockId = cb.data();
  in.omitBondsBetweenBlocks = opt.omitBondsBetweenBlocks;
  in.rule = opt.rule;
  in.bondFilters = opt.bondFilters;
  findNeighbors(in, queries, out.offsets, out.neighbors);
  for (auto& j : out.neighbors) j = candidates[j];
  return out;
}

}  // namespace

Topology buildTopology(const PointCloud& cloud, const std::vector<double>& horizon,
                       const TopologyOptions& opt, MPI_Comm comm) {
  Topology t;
  t.comm = comm;
  MPI_Comm_rank(comm, &t.rank);
  MPI_Comm_size(comm, &t.numRanks);
  const std::size_t n = cloud.size();
  t.globalNumPoints = static_cast<long long>(n);

  std::vector<int> owner = partitionPoints(cloud.x, {}, comm);
  LocalLists lists = searchOwned(cloud, horizon, owner, t.rank, opt);
  if (t.numRanks > 1 && opt.weightByBondCount) {
    // Rebalance with each point weighted by its work (1 + its bonds), then search again.
    std::vector<double> weight(n, 0.0);
    for (std::size_t k = 0; k < lists.owned.size(); ++k)
      weight[lists.owned[k]] = 1.0 + static_cast<double>(lists.offsets[k + 1] - lists.offsets[k]);
    MPI_Allreduce(MPI_IN_PLACE, weight.data(), static_cast<int>(n), MPI_DOUBLE, MPI_SUM, comm);
    owner = partitionPoints(cloud.x, weight, comm);
    lists = searchOwned(cloud, horizon, owner, t.rank, opt);
  }

  t.numOwned = static_cast<int>(lists.owned.size());
  t.overlapCloudIndex = lists.owned;
  // Ghosts: neighbours owned elsewhere, sorted by global id.
  std::vector<std::size_t> ghosts;
  for (std::size_t j : lists.neighbors)
    if (owner[j] != t.rank) ghosts.push_back(j);
  std::sort(ghosts.begin(), ghosts.end(), [&](std::size_t a, std::size_t b) {
    return cloud.globalId[a] < cloud.globalId[b];
  });
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  t.overlapCloudIndex.insert(t.overlapCloudIndex.end(), ghosts.begin(), ghosts.end());
  t.numOverlap = static_cast<int>(t.overlapCloudIndex.size());
  t.overlapGlobalId.resize(t.numOverlap);
  std::vector<int> localOf(n, -1);
  for (int k = 0; k < t.numOverlap; ++k) {
    t.overlapGlobalId[k] = cloud.globalId[t.overlapCloudIndex[k]];
    localOf[t.overlapCloudIndex[k]] = k;
  }

  t.bondOffsets.assign(t.numOwned + 1, 0);
  t.neighbors.resize(lists.neighbors.size());
  for (int i = 0; i < t.numOwned; ++i) {
    const long long b = lists.offsets[i], e = lists.offsets[i + 1];
    t.bondOffsets[i + 1] = e;
    for (long long k = b; k < e; ++k) t.neighbors[k] = localOf[lists.neighbors[k]];
    // Fixed summation order: by global id, whatever the rank count.
    std::sort(t.neighbors.begin() + b, t.neighbors.begin() + e,
              [&](int a, int c) { return t.overlapGlobalId[a] < t.overlapGlobalId[c]; });
  }
  long long localBonds = static_cast<long long>(t.neighbors.size());
  MPI_Allreduce(&localBonds, &t.globalNumBonds, 1, MPI_LONG_LONG, MPI_SUM, comm);

  auto teuchosComm = Teuchos::rcp(new Teuchos::MpiComm<int>(comm));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  std::vector<GlobalOrdinal> ids(t.overlapGlobalId.begin(), t.overlapGlobalId.begin() + t.numOwned);
  std::vector<GlobalOrdinal> ghostIds(t.overlapGlobalId.begin() + t.numOwned, t.overlapGlobalId.end());
  auto makeMap = [&](const std::vector<GlobalOrdinal>& gids) {
    return Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(gids), 0, teuchosComm));
  };
  auto expand3 = [](const std::vector<GlobalOrdinal>& gids) {
    std::vector<GlobalOrdinal> out(3 * gids.size());
    for (std::size_t k = 0; k < gids.size(); ++k)
      for (int d = 0; d < 3; ++d) out[3 * k + d] = 3 * gids[k] + d;
    return out;
  };
  t.ownedMap = makeMap(ids);
  t.ghostMap = makeMap(ghostIds);
  t.overlapMap = makeMap(t.overlapGlobalId);
  t.ownedMap3 = makeMap(expand3(ids));
  t.ghostMap3 = makeMap(expand3(ghostIds));
  t.ghostImport = Teuchos::rcp(new Import(t.ownedMap, t.ghostMap));
  t.ghostImport3 = Teuchos::rcp(new Import(t.ownedMap3, t.ghostMap3));
  return t;
}

}  // namespace peridot
