#include "parallel/Topology.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <algorithm>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "core/Error.hpp"
#include "core/ProcessorsPerRank.hpp"
#include "neighbor/NeighborSearch.hpp"
#include "neighbor/PartialVolume.hpp"
#include "parallel/Partition.hpp"
#include "parallel/PointExchange.hpp"

namespace peridot {

namespace {

Teuchos::RCP<const Map> nonContiguousMap(const std::vector<GlobalOrdinal>& gids,
                                         const Teuchos::RCP<const Teuchos::Comm<int>>& comm) {
  return Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                              Teuchos::ArrayView<const GlobalOrdinal>(gids.data(), gids.size()), 0,
                              comm));
}

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

// The owned points of this rank and the candidates of their search (the owned points and the
// halo: points of other ranks, and periodic images, within reach), the candidates numbered in
// identity order -- global id, then periodic shift code -- which is the order every bond list
// must have: the search then writes each list in order (fillNeighbors), with no sort.
struct Candidates {
  PointBatch owned;
  HaloBatch halo;
  std::vector<std::size_t> source;   // per candidate: owned p is p, halo h is numOwned + h
  std::vector<std::size_t> queries;  // per owned point p: its candidate index
  std::vector<double> x, horizon, edge;
  std::vector<int> blockId;

  long long globalId(std::size_t c) const {
    const std::size_t s = source[c], numOwned = owned.size();
    return s < numOwned ? owned.globalId[s] : halo.points.globalId[s - numOwned];
  }
  int code(std::size_t c) const {
    const std::size_t s = source[c], numOwned = owned.size();
    return s < numOwned ? kNoShift : halo.shift[s - numOwned];
  }
  bool isOwned(std::size_t c) const { return source[c] < owned.size(); }
};

Candidates gatherCandidates(PointBatch owned, const GlobalFacts& g, const TopologyOptions& opt,
                            const std::vector<int>& codes, int dimension, double thickness,
                            MPI_Comm comm) {
  Candidates out;
  out.owned = std::move(owned);
  out.halo = exchangeHalo(out.owned, g.reach, codes, g.boxLength, comm);
  const std::size_t numOwned = out.owned.size(), numHalo = out.halo.points.size();
  const std::size_t n = numOwned + numHalo;
  // Identity order. The owned points usually arrive sorted (one rank: the reader's order), so
  // the sort is skipped when it has nothing to do.
  struct Identity {
    long long id;
    int code;
    std::size_t source;
    bool operator<(const Identity& o) const { return id != o.id ? id < o.id : code < o.code; }
  };
  std::vector<Identity> identity(n);
  for (std::size_t p = 0; p < numOwned; ++p) identity[p] = {out.owned.globalId[p], kNoShift, p};
  for (std::size_t h = 0; h < numHalo; ++h)
    identity[numOwned + h] = {out.halo.points.globalId[h], out.halo.shift[h], numOwned + h};
  if (!std::is_sorted(identity.begin(), identity.end()))
    std::stable_sort(identity.begin(), identity.end());
  out.source.resize(n);
  out.queries.resize(numOwned);
  for (std::size_t c = 0; c < n; ++c) {
    out.source[c] = identity[c].source;
    if (identity[c].source < numOwned) out.queries[identity[c].source] = c;
  }
  identity = std::vector<Identity>();
  out.x.resize(3 * n);
  out.horizon.resize(n);
  out.blockId.resize(n);
  const bool overlap = opt.rule.kind == NeighborhoodRule::Kind::CellOverlap;
  out.edge.resize(overlap ? n : 0);
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t s = out.source[c];
    const bool isOwned = s < numOwned;
    const PointBatch& from = isOwned ? out.owned : out.halo.points;
    const std::size_t p = isOwned ? s : s - numOwned;
    if (isOwned) {
      for (int d = 0; d < 3; ++d) out.x[3 * c + d] = from.x[3 * p + d];
    } else {
      double shift[3];
      shiftVector(out.halo.shift[p], g.boxLength, shift);
      for (int d = 0; d < 3; ++d) out.x[3 * c + d] = from.x[3 * p + d] + shift[d];
    }
    out.horizon[c] = from.horizon[p];
    out.blockId[c] = from.blockId[p];
    if (overlap) out.edge[c] = cellEdge(from.volume[p], dimension, thickness);
  }
  return out;
}

NeighborSearchInput searchInput(const Candidates& c, const GlobalFacts& g,
                                const TopologyOptions& opt) {
  NeighborSearchInput in;
  in.x = c.x.data();
  in.numPoints = c.horizon.size();
  in.horizon = c.horizon.data();
  in.blockId = c.blockId.data();
  in.omitBondsBetweenBlocks = opt.omitBondsBetweenBlocks;
  in.rule = opt.rule;
  in.bondFilters = opt.bondFilters;
  in.unionOfHorizons = opt.rule.kind != NeighborhoodRule::Kind::CellBox && g.differentHorizons;
  in.cellEdge = c.edge.empty() ? nullptr : c.edge.data();
  in.threads = opt.searchThreads;
  return in;
}

// The cloud's points as a batch: its arrays are moved, not copied (at 128^3 a copy is ~100 MB
// of fresh pages), so the cloud keeps only its sets, dimension and thickness.
PointBatch batchOf(PointCloud& cloud, std::vector<double>& horizon) {
  PointBatch b;
  // Set membership per point, from the share's sorted id lists.
  std::vector<std::vector<int>> setsOf(cloud.pointSets.empty() ? 0 : cloud.size());
  if (!cloud.pointSets.empty()) {
    std::unordered_map<long long, std::size_t> indexOf;
    indexOf.reserve(2 * cloud.size());
    for (std::size_t p = 0; p < cloud.size(); ++p) indexOf[cloud.globalId[p]] = p;
    for (std::size_t s = 0; s < cloud.pointSets.size(); ++s)
      for (long long gid : cloud.pointSets[s].globalIds) {
        auto it = indexOf.find(gid);
        if (it != indexOf.end()) setsOf[it->second].push_back(static_cast<int>(s));
      }
  }
  b.setOffsets.assign(cloud.size() + 1, 0);
  for (std::size_t p = 0; p < setsOf.size(); ++p) {
    b.setIndex.insert(b.setIndex.end(), setsOf[p].begin(), setsOf[p].end());
    b.setOffsets[p + 1] = static_cast<int>(b.setIndex.size());
  }
  b.globalId = std::move(cloud.globalId);
  b.x = std::move(cloud.x);
  b.volume = std::move(cloud.volume);
  b.horizon = std::move(horizon);
  b.blockId = std::move(cloud.blockId);
  cloud.globalId.clear();
  cloud.x.clear();
  cloud.volume.clear();
  cloud.blockId.clear();
  horizon.clear();
  return b;
}

}  // namespace

Topology buildTopology(const PointCloud& cloud, const std::vector<double>& horizon,
                       const TopologyOptions& options, MPI_Comm comm) {
  return buildTopology(PointCloud(cloud), std::vector<double>(horizon), options, comm);
}

Topology buildTopology(PointCloud&& cloud, std::vector<double>&& horizon,
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
    for (std::size_t i = 0; i < points.size(); ++i) {
      opt.rule.overlapReach =
          std::max(opt.rule.overlapReach,
                   cellOverlapReach(cellEdge(points.volume[i], cloud.dimension, cloud.thickness),
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
  points = migrate(std::move(points), owner, comm);
  std::vector<int> bondCount;  // per owned point (in the order of `points`)
  if (t.numRanks > 1 && opt.weightByBondCount) {
    // Rebalance with each point weighted by its work (1 + its bonds). A point's bond count does
    // not depend on the partition, so the counts travel with the points and the lists are
    // searched once, on the final partition.
    {
      Candidates first = gatherCandidates(std::move(points), facts, opt, codes, cloud.dimension,
                                          cloud.thickness, comm);
      countNeighbors(searchInput(first, facts, opt), first.queries, bondCount);
      points = std::move(first.owned);
    }
    std::vector<double> weight(points.size());
    for (std::size_t p = 0; p < weight.size(); ++p)
      weight[p] = 1.0 + static_cast<double>(bondCount[p]);
    owner = partitionShare(points.x, weight, comm);
    bondCount = migrateValues(bondCount, owner, comm);
    points = migrate(std::move(points), owner, comm);
  }
  Candidates cand = gatherCandidates(std::move(points), facts, opt, codes, cloud.dimension,
                                     cloud.thickness, comm);
  NeighborSearchInput searchIn = searchInput(cand, facts, opt);
  if (bondCount.empty()) countNeighbors(searchIn, cand.queries, bondCount);
  // The lists' storage is taken now, untouched, so that the page-fault helper
  // (core/BackgroundFaults.hpp) faults it in while the curve sort below keeps one processor.
  t.neighbors.reserve(static_cast<std::size_t>(
      std::accumulate(bondCount.begin(), bondCount.end(), std::int64_t{0})));
  const PointBatch& owned = cand.owned;
  const PointBatch& halo = cand.halo.points;
  const std::size_t numOwned = owned.size();
  const std::size_t numCandidates = cand.source.size();
  t.numOwned = static_cast<int>(numOwned);
  t.hasCurveBox = true;
  for (int d = 0; d < 3; ++d) {
    t.curveLo[d] = facts.lo[d];
    t.curveHi[d] = facts.hi[d];
  }

  // Space-filling-curve order of the owned points (ties broken by global id).
  std::vector<std::size_t> order(numOwned);  // owned local index k -> owned point p
  {
    struct Key {
      unsigned long long morton;
      long long id;
      std::size_t p;
    };
    std::vector<Key> keys(numOwned);
    for (std::size_t p = 0; p < numOwned; ++p)
      keys[p] = {mortonKey(&owned.x[3 * p], facts.lo, facts.hi), owned.globalId[p], p};
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
      return a.morton != b.morton ? a.morton < b.morton : a.id < b.id;
    });
    for (std::size_t k = 0; k < numOwned; ++k) order[k] = keys[k].p;
  }

  // Bond lists in SFC order of their owners, each sorted by (global id, shift): a fixed
  // summation order whatever the rank count. The search writes candidate indices, which are
  // in that order; they become local indices below.
  t.bondOffsets.assign(numOwned + 1, 0);
  std::vector<std::int64_t> listBegin(numOwned);
  for (std::size_t k = 0; k < numOwned; ++k) {
    listBegin[order[k]] = t.bondOffsets[k];
    t.bondOffsets[k + 1] = t.bondOffsets[k] + bondCount[order[k]];
  }
  t.neighbors.resize(static_cast<std::size_t>(t.bondOffsets[numOwned]));
  searchIn.bondFilterCuts = opt.bondFilterCuts;
  fillNeighbors(searchIn, cand.queries, listBegin, bondCount, t.neighbors.data());
  listBegin = std::vector<std::int64_t>();
  bondCount = std::vector<int>();

  // Ghosts: the real points behind neighbours owned elsewhere (also of periodic images),
  // sorted by global id; one halo record of each stands for it. Images come last, sorted by
  // (global id, shift). Candidates of one global id are adjacent in identity order.
  // Only halo candidates can become ghosts or images: without a halo (one rank, no periodic
  // axis) the pass over every bond that marks the used candidates is skipped.
  std::vector<char> used(numCandidates, 0);
  if (!halo.globalId.empty())
    for (int c : t.neighbors) used[static_cast<std::size_t>(c)] = 1;
  std::vector<std::size_t> ghosts, images;  // candidate indices
  auto sameImage = [&](std::size_t c, std::size_t e) {
    return cand.globalId(c) == cand.globalId(e) && cand.code(c) == cand.code(e);
  };
  for (std::size_t a = 0, b = 0; a < numCandidates; a = b) {
    const long long id = cand.globalId(a);
    bool ownedHere = false, usedHere = false;
    std::size_t record = numCandidates;
    for (b = a; b < numCandidates && cand.globalId(b) == id; ++b) {
      ownedHere = ownedHere || cand.isOwned(b);
      usedHere = usedHere || used[b];
      if (!cand.isOwned(b) && record == numCandidates) record = b;
      if (used[b] && cand.code(b) != kNoShift && !(!images.empty() && sameImage(images.back(), b)))
        images.push_back(b);
    }
    if (!ownedHere && usedHere) ghosts.push_back(record);
  }
  used = std::vector<char>();
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
    const std::size_t s = cand.source[c];
    const PointBatch& from = s < numOwned ? owned : halo;
    const std::size_t p = s < numOwned ? s : s - numOwned;
    double shift[3] = {0, 0, 0};
    if (applyShift) shiftVector(cand.code(c), facts.boxLength, shift);
    for (int d = 0; d < 3; ++d) t.referencePosition[3 * k + d] = from.x[3 * p + d] + shift[d];
    t.overlapGlobalId[k] = from.globalId[p];
    t.volume[k] = from.volume[p];
    t.horizon[k] = from.horizon[p];
    t.blockId[k] = from.blockId[p];
  };
  // The local index of every candidate a list may hold: its point's (owned or ghost) when
  // unshifted, its image's when shifted.
  std::vector<int> localOf(numCandidates, -1);
  std::vector<int> localOfOwned(numOwned);
  for (std::size_t k = 0; k < numOwned; ++k) {
    setPoint(k, cand.queries[order[k]], false);
    localOfOwned[order[k]] = static_cast<int>(k);
  }
  for (std::size_t k = 0; k < ghosts.size(); ++k) setPoint(numOwned + k, ghosts[k], false);
  for (std::size_t a = 0, b = 0, g = 0, m = 0; a < numCandidates; a = b) {
    const long long id = cand.globalId(a);
    int real = -1;  // the local index of the point itself, if it is owned or a ghost
    for (b = a; b < numCandidates && cand.globalId(b) == id; ++b)
      if (cand.isOwned(b)) real = localOfOwned[cand.source[b]];
    if (real < 0 && g < ghosts.size() && cand.globalId(ghosts[g]) == id)
      real = static_cast<int>(numOwned + g++);
    for (std::size_t c = a; c < b; ++c) {
      if (cand.code(c) == kNoShift) {
        localOf[c] = real;
      } else if (m < images.size() && images[m] == c) {
        const int k = static_cast<int>(numOwned + ghosts.size() + m++);
        setPoint(static_cast<std::size_t>(k), c, true);
        t.imageSource.push_back(real);
        double shift[3];
        shiftVector(cand.code(c), facts.boxLength, shift);
        t.imageShift.insert(t.imageShift.end(), shift, shift + 3);
        localOf[c] = k;
      } else if (m > 0 && sameImage(images[m - 1], c)) {
        localOf[c] = static_cast<int>(numOwned + ghosts.size() + m - 1);  // the same image again
      }
    }
  }
  localOfOwned = std::vector<int>();
  {
    // One gather per bond (a quarter of a second at 128^3 on one thread).
    int* c = t.neighbors.data();
    const std::size_t numBonds = t.neighbors.size();
    runChunksOnThreads(threadsFor(opt.searchThreads, numBonds), numBonds, std::size_t{1} << 20,
                       [&](int, std::size_t first, std::size_t last) {
                         for (std::size_t b = first; b < last; ++b)
                           c[b] = localOf[static_cast<std::size_t>(c[b])];
                       });
  }
  localOf = std::vector<int>();

  // Point sets as owned local indices.
  for (const auto& set : cloud.pointSets) t.pointSetNames.push_back(set.name);
  t.ownedPointSets.assign(cloud.pointSets.size(), {});
  for (std::size_t k = 0; k < numOwned; ++k) {
    const std::size_t p = order[k];
    for (int s = owned.setOffsets[p]; s < owned.setOffsets[p + 1]; ++s)
      t.ownedPointSets[owned.setIndex[s]].push_back(static_cast<int>(k));
  }
  cand = Candidates();

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
  std::vector<GlobalOrdinal> ids(t.overlapGlobalId.begin(), t.overlapGlobalId.begin() + t.numOwned);
  std::vector<GlobalOrdinal> ghostIds(t.overlapGlobalId.begin() + t.numOwned,
                                      t.overlapGlobalId.begin() + t.numOwned + t.numGhosts);
  t.ownedMap = nonContiguousMap(ids, teuchosComm);
  t.ghostMap = nonContiguousMap(ghostIds, teuchosComm);
  t.ghostImport = Teuchos::rcp(new Import(t.ownedMap, t.ghostMap));
  return t;
}

const Teuchos::RCP<const Map>& Topology::ownedMap3() const {
  if (ownedMap3_.is_null()) {
    std::vector<GlobalOrdinal> ids(3 * static_cast<std::size_t>(numOwned));
    for (std::size_t k = 0; k < static_cast<std::size_t>(numOwned); ++k)
      for (int d = 0; d < 3; ++d) ids[3 * k + d] = 3 * overlapGlobalId[k] + d;
    ownedMap3_ = nonContiguousMap(ids, ownedMap->getComm());
  }
  return ownedMap3_;
}

}  // namespace peridot
