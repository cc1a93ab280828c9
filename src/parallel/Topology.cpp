#include "parallel/Topology.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "core/Error.hpp"
#include "neighbor/NeighborSearch.hpp"
#include "neighbor/PartialVolume.hpp"
#include "parallel/Partition.hpp"

namespace peridot {

namespace {

// A candidate neighbour: a cloud point, possibly shifted to one of its periodic images. The
// shift code c in 0..26 stands for (c % 3 - 1, c / 3 % 3 - 1, c / 9 - 1) box lengths.
constexpr int kNoShift = 13;
inline unsigned long long packed(std::size_t index, int code) { return index * 27ull + code; }
inline std::size_t indexOf(unsigned long long key) { return static_cast<std::size_t>(key / 27); }
inline int codeOf(unsigned long long key) { return static_cast<int>(key % 27); }
inline void shiftVector(int code, const PeriodicBox& box, double* shift) {
  const int s[3] = {code % 3 - 1, code / 3 % 3 - 1, code / 9 - 1};
  for (int d = 0; d < 3; ++d) shift[d] = s[d] * (box.upper[d] - box.lower[d]);
}

struct LocalLists {
  std::vector<std::size_t> owned;      // cloud indices, SFC order
  std::vector<long long> offsets;      // per owned point
  std::vector<std::size_t> neighbors;  // packed (cloud index, shift code)
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
  const bool unionOfHorizons = opt.rule.kind != NeighborhoodRule::Kind::CellBox &&
                               std::adjacent_find(horizon.begin(), horizon.end(),
                                                  std::not_equal_to<double>()) != horizon.end();
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      gLo[d] = std::min(gLo[d], cloud.x[3 * i + d]);
      gHi[d] = std::max(gHi[d], cloud.x[3 * i + d]);
    }
    // With differing horizons a neighbour may reach an owned point from its own horizon.
    if (unionOfHorizons) reach = std::max(reach, searchReach(opt.rule, horizon[i]));
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

  // Candidates: the points, and their periodic images, that can be within reach of an owned
  // point.
  std::vector<unsigned long long> candidates;
  std::vector<double> cx;
  std::vector<int> codes = {kNoShift};
  if (opt.periodic.any()) {
    codes.clear();
    for (int c = 0; c < 27; ++c) {
      const int s[3] = {c % 3 - 1, c / 3 % 3 - 1, c / 9 - 1};
      bool allowed = true;
      for (int d = 0; d < 3; ++d) allowed = allowed && (s[d] == 0 || opt.periodic.periodic[d]);
      if (allowed) codes.push_back(c);
    }
  }
  for (int code : codes) {
    double shift[3] = {0, 0, 0};
    shiftVector(code, opt.periodic, shift);
    for (std::size_t i = 0; i < n; ++i) {
      bool inside = true;
      for (int d = 0; d < 3 && inside; ++d) {
        const double xd = cloud.x[3 * i + d] + shift[d];
        inside = xd >= lo[d] - reach && xd <= hi[d] + reach;
      }
      if (!inside) continue;
      candidates.push_back(packed(i, code));
      for (int d = 0; d < 3; ++d) cx.push_back(cloud.x[3 * i + d] + shift[d]);
    }
  }
  std::vector<double> ch(candidates.size());
  std::vector<int> cb(candidates.size());
  const bool overlap = opt.rule.kind == NeighborhoodRule::Kind::CellOverlap;
  std::vector<double> ce(overlap ? candidates.size() : 0);
  std::unordered_map<std::size_t, std::size_t> candidateOf;
  candidateOf.reserve(out.owned.size() * 2);
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const std::size_t i = indexOf(candidates[k]);
    ch[k] = horizon[i];
    cb[k] = cloud.blockId[i];
    if (overlap) ce[k] = cellEdge(cloud.volume[i], cloud.dimension, cloud.thickness);
    if (owner[i] == rank && codeOf(candidates[k]) == kNoShift) candidateOf[i] = k;
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
  in.unionOfHorizons = unionOfHorizons;
  in.cellEdge = overlap ? ce.data() : nullptr;
  // Candidate indices become packed keys in place: one 8-byte word per bond at the peak.
  findNeighbors(in, queries, out.offsets, out.neighbors);
  for (auto& k : out.neighbors) k = candidates[k];
  return out;
}

Topology buildFromReplicated(const PointCloud& cloud, const std::vector<double>& horizon,
                             const TopologyOptions& options, MPI_Comm comm) {
  TopologyOptions opt = options;
  if (opt.rule.kind == NeighborhoodRule::Kind::CellOverlap) {
    // Partial volumes: the search reaches half a cell diagonal beyond the horizon.
    if (std::adjacent_find(horizon.begin(), horizon.end(), std::not_equal_to<double>()) !=
        horizon.end()) {
      throw InputError("Discretization -> Partial Volumes",
                       "needs one horizon for every point (the blocks' horizons differ)");
    }
    opt.rule.dimension = cloud.dimension;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      opt.rule.overlapReach =
          std::max(opt.rule.overlapReach,
                   cellOverlapReach(cellEdge(cloud.volume[i], cloud.dimension, cloud.thickness),
                                    cloud.dimension));
    }
  }
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
    lists = LocalLists();  // free the first lists before the second search
    owner = partitionPoints(cloud.x, weight, comm);
    lists = searchOwned(cloud, horizon, owner, t.rank, opt);
  }

  t.numOwned = static_cast<int>(lists.owned.size());
  t.overlapCloudIndex = lists.owned;
  // Ghosts: neighbours owned elsewhere, and the real points behind periodic images, sorted by
  // global id. Images come last, sorted by (global id, shift).
  std::vector<std::size_t> ghosts;
  std::vector<unsigned long long> images;
  for (std::size_t key : lists.neighbors) {
    const std::size_t j = indexOf(key);
    if (owner[j] != t.rank) ghosts.push_back(j);
    if (codeOf(key) != kNoShift) images.push_back(key);
  }
  auto byId = [&](std::size_t a, std::size_t b) { return cloud.globalId[a] < cloud.globalId[b]; };
  std::sort(ghosts.begin(), ghosts.end(), byId);
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  auto byIdThenShift = [&](unsigned long long a, unsigned long long b) {
    const long long ga = cloud.globalId[indexOf(a)], gb = cloud.globalId[indexOf(b)];
    return ga != gb ? ga < gb : codeOf(a) < codeOf(b);
  };
  std::sort(images.begin(), images.end(), byIdThenShift);
  images.erase(std::unique(images.begin(), images.end()), images.end());
  t.overlapCloudIndex.insert(t.overlapCloudIndex.end(), ghosts.begin(), ghosts.end());
  t.numGhosts = static_cast<int>(ghosts.size());
  std::vector<int> localOf(n, -1);
  for (std::size_t k = 0; k < t.overlapCloudIndex.size(); ++k)
    localOf[t.overlapCloudIndex[k]] = static_cast<int>(k);
  std::unordered_map<unsigned long long, int> localOfImage;
  for (unsigned long long key : images) {
    localOfImage[key] = static_cast<int>(t.overlapCloudIndex.size());
    t.overlapCloudIndex.push_back(indexOf(key));
    t.imageSource.push_back(localOf[indexOf(key)]);
    double shift[3];
    shiftVector(codeOf(key), opt.periodic, shift);
    t.imageShift.insert(t.imageShift.end(), shift, shift + 3);
  }
  t.numOverlap = static_cast<int>(t.overlapCloudIndex.size());
  t.overlapGlobalId.resize(t.numOverlap);
  for (int k = 0; k < t.numOverlap; ++k)
    t.overlapGlobalId[k] = cloud.globalId[t.overlapCloudIndex[k]];

  t.bondOffsets.assign(t.numOwned + 1, 0);
  std::vector<std::size_t>& sorted = lists.neighbors;  // sorted in place
  t.neighbors.resize(lists.neighbors.size());
  for (int i = 0; i < t.numOwned; ++i) {
    const long long b = lists.offsets[i], e = lists.offsets[i + 1];
    t.bondOffsets[i + 1] = e;
    // Fixed summation order: by global id (then image), whatever the rank count.
    std::sort(sorted.begin() + b, sorted.begin() + e, byIdThenShift);
    for (long long k = b; k < e; ++k) {
      const unsigned long long key = sorted[k];
      t.neighbors[k] = codeOf(key) == kNoShift ? localOf[indexOf(key)] : localOfImage.at(key);
    }
  }
  lists = LocalLists();

  // One-sided bonds (differing horizons, sphere rules): which end's horizon holds each bond,
  // with the search's own arithmetic so that both ends agree.
  if (opt.rule.kind != NeighborhoodRule::Kind::CellBox &&
      std::adjacent_find(horizon.begin(), horizon.end(), std::not_equal_to<double>()) !=
          horizon.end()) {
    std::vector<unsigned char> sides(t.neighbors.size(), 3);
    bool oneSided = false;
    const bool strict = opt.rule.kind == NeighborhoodRule::Kind::SphereStrict;
    for (int i = 0; i < t.numOwned; ++i) {
      const double hi2 = horizon[t.overlapCloudIndex[i]] * horizon[t.overlapCloudIndex[i]];
      const double* xi = &cloud.x[3 * t.overlapCloudIndex[i]];
      for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
        const int j = t.neighbors[b];
        const std::size_t cj = t.overlapCloudIndex[j];
        const double* shift = t.shiftOf(j);
        double d2 = 0;
        for (int d = 0; d < 3; ++d) {
          const double dx = (cloud.x[3 * cj + d] + shift[d]) - xi[d];
          d2 += dx * dx;
        }
        const double hj2 = horizon[cj] * horizon[cj];
        const bool own = strict ? d2 < hi2 : d2 <= hi2;
        const bool other = strict ? d2 < hj2 : d2 <= hj2;
        sides[b] = static_cast<unsigned char>((own ? 1 : 0) | (other ? 2 : 0));
        oneSided = oneSided || sides[b] != 3;
      }
    }
    if (oneSided) t.bondSides = std::move(sides);
  }
  long long localBonds = static_cast<long long>(t.neighbors.size());
  MPI_Allreduce(&localBonds, &t.globalNumBonds, 1, MPI_LONG_LONG, MPI_SUM, comm);

  auto teuchosComm = Teuchos::rcp(new Teuchos::MpiComm<int>(comm));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  std::vector<GlobalOrdinal> ids(t.overlapGlobalId.begin(), t.overlapGlobalId.begin() + t.numOwned);
  std::vector<GlobalOrdinal> ghostIds(t.overlapGlobalId.begin() + t.numOwned,
                                      t.overlapGlobalId.begin() + t.numOwned + t.numGhosts);
  auto makeMap = [&](const std::vector<GlobalOrdinal>& gids) {
    return Teuchos::rcp(new Map(invalid,
                                Teuchos::ArrayView<const GlobalOrdinal>(gids.data(), gids.size()),
                                0, teuchosComm));
  };
  auto expand3 = [](const std::vector<GlobalOrdinal>& gids) {
    std::vector<GlobalOrdinal> out(3 * gids.size());
    for (std::size_t k = 0; k < gids.size(); ++k)
      for (int d = 0; d < 3; ++d) out[3 * k + d] = 3 * gids[k] + d;
    return out;
  };
  t.ownedMap = makeMap(ids);
  t.ghostMap = makeMap(ghostIds);
  t.ownedMap3 = makeMap(expand3(ids));
  t.ghostMap3 = makeMap(expand3(ghostIds));
  t.ghostImport = Teuchos::rcp(new Import(t.ownedMap, t.ghostMap));
  t.ghostImport3 = Teuchos::rcp(new Import(t.ownedMap3, t.ghostMap3));
  t.referencePosition.resize(3 * static_cast<std::size_t>(t.numOverlap));
  t.volume.resize(t.numOverlap);
  t.horizon.resize(t.numOverlap);
  t.blockId.resize(t.numOverlap);
  for (int k = 0; k < t.numOverlap; ++k) {
    const std::size_t p = t.overlapCloudIndex[k];
    const double* shift = t.shiftOf(k);
    for (int d = 0; d < 3; ++d) t.referencePosition[3 * k + d] = cloud.x[3 * p + d] + shift[d];
    t.volume[k] = cloud.volume[p];
    t.horizon[k] = horizon[p];
    t.blockId[k] = cloud.blockId[p];
  }
  for (const auto& set : cloud.pointSets) {
    t.pointSetNames.push_back(set.name);
    std::vector<int> owned;
    for (int i = 0; i < t.numOwned; ++i)
      if (std::binary_search(set.globalIds.begin(), set.globalIds.end(), t.overlapGlobalId[i]))
        owned.push_back(i);
    t.ownedPointSets.push_back(std::move(owned));
  }
  return t;
}

}  // namespace

// TODO(distributed set-up): gathers the shares into one cloud on every rank.
Topology buildTopology(const PointCloud& share, const std::vector<double>& shareHorizon,
                       const TopologyOptions& options, MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  const int n = static_cast<int>(share.size());
  std::vector<int> counts(size), displs(size, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  const int total = displs[size - 1] + counts[size - 1];
  PointCloud cloud;
  cloud.blockNames = share.blockNames;
  cloud.dimension = share.dimension;
  cloud.thickness = share.thickness;
  cloud.globalNumPoints = total;
  cloud.volume.resize(total);
  cloud.blockId.resize(total);
  cloud.globalId.resize(total);
  std::vector<double> horizon(total);
  MPI_Allgatherv(share.volume.data(), n, MPI_DOUBLE, cloud.volume.data(), counts.data(),
                 displs.data(), MPI_DOUBLE, comm);
  MPI_Allgatherv(shareHorizon.data(), n, MPI_DOUBLE, horizon.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, comm);
  MPI_Allgatherv(share.blockId.data(), n, MPI_INT, cloud.blockId.data(), counts.data(),
                 displs.data(), MPI_INT, comm);
  MPI_Allgatherv(share.globalId.data(), n, MPI_LONG_LONG, cloud.globalId.data(), counts.data(),
                 displs.data(), MPI_LONG_LONG, comm);
  std::vector<int> counts3(size), displs3(size);
  for (int r = 0; r < size; ++r) counts3[r] = 3 * counts[r], displs3[r] = 3 * displs[r];
  cloud.x.resize(3 * static_cast<std::size_t>(total));
  MPI_Allgatherv(share.x.data(), 3 * n, MPI_DOUBLE, cloud.x.data(), counts3.data(), displs3.data(),
                 MPI_DOUBLE, comm);
  for (const auto& set : share.pointSets) {
    const int m = static_cast<int>(set.globalIds.size());
    std::vector<int> c(size), dsp(size, 0);
    MPI_Allgather(&m, 1, MPI_INT, c.data(), 1, MPI_INT, comm);
    for (int r = 1; r < size; ++r) dsp[r] = dsp[r - 1] + c[r - 1];
    PointSet all{set.name, std::vector<long long>(dsp[size - 1] + c[size - 1])};
    MPI_Allgatherv(set.globalIds.data(), m, MPI_LONG_LONG, all.globalIds.data(), c.data(),
                   dsp.data(), MPI_LONG_LONG, comm);
    std::sort(all.globalIds.begin(), all.globalIds.end());
    cloud.pointSets.push_back(std::move(all));
  }
  Topology t = buildFromReplicated(cloud, horizon, options, comm);
  t.overlapCloudIndex.clear();
  return t;
}

}  // namespace peridot
