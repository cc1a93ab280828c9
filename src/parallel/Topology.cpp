#include "parallel/Topology.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <algorithm>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "core/Error.hpp"
#include "neighbor/NeighborSearch.hpp"
#include "neighbor/PartialVolume.hpp"
#include "parallel/Partition.hpp"
#include "parallel/PointExchange.hpp"

namespace peridot {

namespace {

// What every rank must agree on before the search: global extent, reach, horizon variation.
struct GlobalFacts {
  double lo[3], hi[3];  // bounding box of all points
  double reach = 0;     // the largest search reach of any point
  bool differentHorizons = false;
  double boxLength[3] = {0, 0, 0};  // periodic box
};

GlobalFacts globalFacts(const PointBatch& points, const TopologyOptions& opt, MPI_Comm comm) {
  GlobalFacts g;
  double mins[5], maxs[5];  // x, y, z, horizon, search reach (only its max is used)
  for (int k = 0; k < 5; ++k) {
    mins[k] = std::numeric_limits<double>::max();
    maxs[k] = std::numeric_limits<double>::lowest();
  }
  for (std::size_t p = 0; p < points.size(); ++p) {
    for (int d = 0; d < 3; ++d) {
      mins[d] = std::min(mins[d], points.x[3 * p + d]);
      maxs[d] = std::max(maxs[d], points.x[3 * p + d]);
    }
    mins[3] = std::min(mins[3], points.horizon[p]);
    maxs[3] = std::max(maxs[3], points.horizon[p]);
    maxs[4] = std::max(maxs[4], searchReach(opt.rule, points.horizon[p]));
  }
  MPI_Allreduce(MPI_IN_PLACE, mins, 5, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, maxs, 5, MPI_DOUBLE, MPI_MAX, comm);
  for (int d = 0; d < 3; ++d) {
    g.lo[d] = mins[d];
    g.hi[d] = maxs[d];
    g.boxLength[d] = opt.periodic.upper[d] - opt.periodic.lower[d];
  }
  g.reach = maxs[4];
  g.differentHorizons = mins[3] != maxs[3];
  return g;
}

// The owned points of this rank and the candidates of their search: the owned points
// themselves, then the halo (points of other ranks, and periodic images, within reach).
struct Neighbourhoods {
  PointBatch owned;
  HaloBatch halo;
  std::vector<long long> offsets;      // per owned point
  std::vector<std::size_t> neighbors;  // candidate indices: owned p is p, halo h is numOwned + h
};

Neighbourhoods search(PointBatch owned, const GlobalFacts& g, const TopologyOptions& opt,
                      const std::vector<int>& codes, int dimension, double thickness,
                      MPI_Comm comm) {
  Neighbourhoods out;
  out.owned = std::move(owned);
  out.halo = exchangeHalo(out.owned, g.reach, codes, g.boxLength, comm);
  const std::size_t numOwned = out.owned.size(), numHalo = out.halo.points.size();
  const std::size_t n = numOwned + numHalo;
  std::vector<double> cx(3 * n), ch(n);
  std::vector<int> cb(n);
  const bool overlap = opt.rule.kind == NeighborhoodRule::Kind::CellOverlap;
  std::vector<double> ce(overlap ? n : 0);
  auto fill = [&](std::size_t k, const PointBatch& from, std::size_t p, int code) {
    double shift[3];
    shiftVector(code, g.boxLength, shift);
    for (int d = 0; d < 3; ++d) cx[3 * k + d] = from.x[3 * p + d] + shift[d];
    ch[k] = from.horizon[p];
    cb[k] = from.blockId[p];
    if (overlap) ce[k] = cellEdge(from.volume[p], dimension, thickness);
  };
  for (std::size_t p = 0; p < numOwned; ++p) {
    for (int d = 0; d < 3; ++d) cx[3 * p + d] = out.owned.x[3 * p + d];
    ch[p] = out.owned.horizon[p];
    cb[p] = out.owned.blockId[p];
    if (overlap) ce[p] = cellEdge(out.owned.volume[p], dimension, thickness);
  }
  for (std::size_t h = 0; h < numHalo; ++h)
    fill(numOwned + h, out.halo.points, h, out.halo.shift[h]);
  std::vector<std::size_t> queries(numOwned);
  std::iota(queries.begin(), queries.end(), std::size_t{0});
  NeighborSearchInput in;
  in.x = cx.data();
  in.numPoints = n;
  in.horizon = ch.data();
  in.blockId = cb.data();
  in.omitBondsBetweenBlocks = opt.omitBondsBetweenBlocks;
  in.rule = opt.rule;
  in.bondFilters = opt.bondFilters;
  in.bondFilterCuts = opt.bondFilterCuts;
  in.unionOfHorizons = opt.rule.kind != NeighborhoodRule::Kind::CellBox && g.differentHorizons;
  in.cellEdge = overlap ? ce.data() : nullptr;
  findNeighbors(in, queries, out.offsets, out.neighbors);
  return out;
}

PointBatch batchOf(const PointCloud& cloud, const std::vector<double>& horizon) {
  PointBatch b;
  b.globalId = cloud.globalId;
  b.x = cloud.x;
  b.volume = cloud.volume;
  b.horizon = horizon;
  b.blockId = cloud.blockId;
  // Set membership per point, from the share's sorted id lists.
  std::vector<std::vector<int>> setsOf(cloud.size());
  std::unordered_map<long long, std::size_t> indexOf;
  indexOf.reserve(2 * cloud.size());
  for (std::size_t p = 0; p < cloud.size(); ++p) indexOf[cloud.globalId[p]] = p;
  for (std::size_t s = 0; s < cloud.pointSets.size(); ++s)
    for (long long gid : cloud.pointSets[s].globalIds) {
      auto it = indexOf.find(gid);
      if (it != indexOf.end()) setsOf[it->second].push_back(static_cast<int>(s));
    }
  b.setOffsets.assign(1, 0);
  for (std::size_t p = 0; p < cloud.size(); ++p) {
    b.setIndex.insert(b.setIndex.end(), setsOf[p].begin(), setsOf[p].end());
    b.setOffsets.push_back(static_cast<int>(b.setIndex.size()));
  }
  return b;
}

}  // namespace

Topology buildTopology(const PointCloud& cloud, const std::vector<double>& horizon,
                       const TopologyOptions& options, MPI_Comm comm) {
  TopologyOptions opt = options;
  Topology t;
  t.comm = comm;
  MPI_Comm_rank(comm, &t.rank);
  MPI_Comm_size(comm, &t.numRanks);
  PointBatch points = batchOf(cloud, horizon);
  if (opt.rule.kind == NeighborhoodRule::Kind::CellOverlap) {
    // Partial volumes: the search reaches half a cell diagonal beyond the horizon.
    opt.rule.dimension = cloud.dimension;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      opt.rule.overlapReach =
          std::max(opt.rule.overlapReach,
                   cellOverlapReach(cellEdge(cloud.volume[i], cloud.dimension, cloud.thickness),
                                    cloud.dimension));
    }
    MPI_Allreduce(MPI_IN_PLACE, &opt.rule.overlapReach, 1, MPI_DOUBLE, MPI_MAX, comm);
  }
  const GlobalFacts facts = globalFacts(points, opt, comm);
  if (opt.rule.kind == NeighborhoodRule::Kind::CellOverlap && facts.differentHorizons) {
    throw InputError("Discretization -> Partial Volumes",
                     "needs one horizon for every point (the blocks' horizons differ)");
  }
  long long shareSize = static_cast<long long>(points.size());
  MPI_Allreduce(&shareSize, &t.globalNumPoints, 1, MPI_LONG_LONG, MPI_SUM, comm);
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

  // Partition, move the points to their owners, search among them and their halo.
  std::vector<int> owner = partitionShare(points.x, {}, comm);
  points = migrate(points, owner, comm);
  Neighbourhoods lists =
      search(std::move(points), facts, opt, codes, cloud.dimension, cloud.thickness, comm);
  if (t.numRanks > 1 && opt.weightByBondCount) {
    // Rebalance with each point weighted by its work (1 + its bonds), then search again.
    std::vector<double> weight(lists.owned.size());
    for (std::size_t p = 0; p < weight.size(); ++p)
      weight[p] = 1.0 + static_cast<double>(lists.offsets[p + 1] - lists.offsets[p]);
    points = std::move(lists.owned);
    lists = Neighbourhoods();  // free the first lists before the second search
    owner = partitionShare(points.x, weight, comm);
    points = migrate(points, owner, comm);
    lists = search(std::move(points), facts, opt, codes, cloud.dimension, cloud.thickness, comm);
  }
  const PointBatch& owned = lists.owned;
  const PointBatch& halo = lists.halo.points;
  const std::vector<int>& haloShift = lists.halo.shift;
  const std::size_t numOwned = owned.size();
  t.numOwned = static_cast<int>(numOwned);

  // A candidate's identity: (global id, shift code).
  auto gidOf = [&](std::size_t c) {
    return c < numOwned ? owned.globalId[c] : halo.globalId[c - numOwned];
  };
  auto codeOf = [&](std::size_t c) { return c < numOwned ? kNoShift : haloShift[c - numOwned]; };
  auto byIdThenShift = [&](std::size_t a, std::size_t b) {
    const long long ga = gidOf(a), gb = gidOf(b);
    return ga != gb ? ga < gb : codeOf(a) < codeOf(b);
  };

  // Space-filling-curve order of the owned points (ties broken by global id).
  std::vector<unsigned long long> key(numOwned);
  for (std::size_t p = 0; p < numOwned; ++p)
    key[p] = mortonKey(&owned.x[3 * p], facts.lo, facts.hi);
  std::vector<std::size_t> order(numOwned);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return key[a] != key[b] ? key[a] < key[b] : owned.globalId[a] < owned.globalId[b];
  });
  key = std::vector<unsigned long long>();

  // Ghosts: the real points behind neighbours owned elsewhere (also of periodic images),
  // sorted by global id; one halo record of each stands for it. Images come last, sorted by
  // (global id, shift).
  std::unordered_map<long long, int> localOfId;  // owned and ghost points
  localOfId.reserve(2 * numOwned);
  for (std::size_t k = 0; k < numOwned; ++k)
    localOfId[owned.globalId[order[k]]] = static_cast<int>(k);
  std::vector<std::size_t> ghosts, images;  // candidate indices
  {
    std::unordered_map<long long, std::size_t> ghostRecord;
    for (std::size_t c : lists.neighbors) {
      if (c < numOwned) continue;
      const long long gid = gidOf(c);
      if (!localOfId.count(gid)) ghostRecord.emplace(gid, c);
      if (codeOf(c) != kNoShift) images.push_back(c);
    }
    for (const auto& kv : ghostRecord) ghosts.push_back(kv.second);
  }
  std::sort(ghosts.begin(), ghosts.end(), byIdThenShift);
  std::sort(images.begin(), images.end(), byIdThenShift);
  images.erase(std::unique(images.begin(), images.end(),
                           [&](std::size_t a, std::size_t b) {
                             return gidOf(a) == gidOf(b) && codeOf(a) == codeOf(b);
                           }),
               images.end());
  t.numGhosts = static_cast<int>(ghosts.size());
  t.numOverlap = t.numOwned + t.numGhosts + static_cast<int>(images.size());
  const std::size_t numOverlap = static_cast<std::size_t>(t.numOverlap);
  t.overlapGlobalId.resize(numOverlap);
  t.referencePosition.resize(3 * numOverlap);
  t.volume.resize(numOverlap);
  t.horizon.resize(numOverlap);
  t.blockId.resize(numOverlap);
  // Overlap point k from candidate c: the unshifted point for owned and ghosts, x + shift for
  // images (the same arithmetic the search used).
  auto setPoint = [&](std::size_t k, std::size_t c, bool applyShift) {
    const PointBatch& from = c < numOwned ? owned : halo;
    const std::size_t p = c < numOwned ? c : c - numOwned;
    double shift[3] = {0, 0, 0};
    if (applyShift) shiftVector(codeOf(c), facts.boxLength, shift);
    for (int d = 0; d < 3; ++d) t.referencePosition[3 * k + d] = from.x[3 * p + d] + shift[d];
    t.overlapGlobalId[k] = from.globalId[p];
    t.volume[k] = from.volume[p];
    t.horizon[k] = from.horizon[p];
    t.blockId[k] = from.blockId[p];
  };
  for (std::size_t k = 0; k < numOwned; ++k) setPoint(k, order[k], false);
  for (std::size_t k = 0; k < ghosts.size(); ++k) {
    setPoint(numOwned + k, ghosts[k], false);
    localOfId[gidOf(ghosts[k])] = static_cast<int>(numOwned + k);
  }
  std::unordered_map<unsigned long long, int> localOfImage;  // gid * 27 + code
  for (std::size_t m = 0; m < images.size(); ++m) {
    const std::size_t k = numOwned + ghosts.size() + m;
    setPoint(k, images[m], true);
    const long long gid = gidOf(images[m]);
    localOfImage[static_cast<unsigned long long>(gid) * 27ull + codeOf(images[m])] =
        static_cast<int>(k);
    t.imageSource.push_back(localOfId.at(gid));
    double shift[3];
    shiftVector(codeOf(images[m]), facts.boxLength, shift);
    t.imageShift.insert(t.imageShift.end(), shift, shift + 3);
  }

  // Bond lists in SFC order of their owners, each sorted by (global id, shift): a fixed
  // summation order whatever the rank count.
  t.bondOffsets.assign(numOwned + 1, 0);
  for (std::size_t k = 0; k < numOwned; ++k)
    t.bondOffsets[k + 1] =
        t.bondOffsets[k] + (lists.offsets[order[k] + 1] - lists.offsets[order[k]]);
  t.neighbors.resize(lists.neighbors.size());
  for (std::size_t k = 0; k < numOwned; ++k) {
    const std::size_t p = order[k];
    auto first = lists.neighbors.begin() + lists.offsets[p],
         last = lists.neighbors.begin() + lists.offsets[p + 1];
    std::sort(first, last, byIdThenShift);
    std::int64_t b = t.bondOffsets[k];
    for (auto it = first; it != last; ++it, ++b) {
      const std::size_t c = *it;
      const long long gid = gidOf(c);
      t.neighbors[b] =
          codeOf(c) == kNoShift
              ? localOfId.at(gid)
              : localOfImage.at(static_cast<unsigned long long>(gid) * 27ull + codeOf(c));
    }
  }

  // Point sets as owned local indices.
  for (const auto& set : cloud.pointSets) t.pointSetNames.push_back(set.name);
  t.ownedPointSets.assign(cloud.pointSets.size(), {});
  for (std::size_t k = 0; k < numOwned; ++k) {
    const std::size_t p = order[k];
    for (int s = owned.setOffsets[p]; s < owned.setOffsets[p + 1]; ++s)
      t.ownedPointSets[owned.setIndex[s]].push_back(static_cast<int>(k));
  }
  lists = Neighbourhoods();

  // One-sided bonds (differing horizons, sphere rules): which end's horizon holds each bond,
  // with the search's own arithmetic so that both ends agree.
  if (opt.rule.kind != NeighborhoodRule::Kind::CellBox && facts.differentHorizons) {
    std::vector<unsigned char> sides(t.neighbors.size(), 3);
    bool oneSided = false;
    const bool strict = opt.rule.kind == NeighborhoodRule::Kind::SphereStrict;
    for (int i = 0; i < t.numOwned; ++i) {
      const double hi2 = t.horizon[i] * t.horizon[i];
      const double* xi = &t.referencePosition[3 * i];
      for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
        const int j = t.neighbors[b];
        double d2 = 0;
        for (int d = 0; d < 3; ++d) {
          const double dx = t.referencePosition[3 * j + d] - xi[d];
          d2 += dx * dx;
        }
        const double hj2 = t.horizon[j] * t.horizon[j];
        const bool own = strict ? d2 < hi2 : d2 <= hi2;
        const bool other = strict ? d2 < hj2 : d2 <= hj2;
        sides[b] = static_cast<unsigned char>((own ? 1 : 0) | (other ? 2 : 0));
        oneSided = oneSided || sides[b] != 3;
      }
    }
    int anyOneSided = oneSided ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &anyOneSided, 1, MPI_INT, MPI_MAX, comm);
    if (anyOneSided) t.bondSides = std::move(sides);
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
  return t;
}

}  // namespace peridot
