#include "contact/ShortRangeContact.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Vector.hpp>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "neighbor/NeighborSearch.hpp"
#include "parallel/PointExchange.hpp"

namespace peridot {

namespace {

using Vector = Tpetra::Vector<double, LocalOrdinal, GlobalOrdinal>;

// Some Peridigm versions write pi as 3.1415 in this model; its Contact_Cubes gold was made with
// the exact value (with 3.1415 the run departs from the gold once the cubes touch).
const double kPi = 3.14159265358979323846;

struct PairForce {
  double onNode[3], onNeighbor[3];
};

// The force of the pair (node, neighbour) in Peridigm's form: `node` is the end whose list
// holds the pair, and its horizon scales the spring constant.
inline bool pairForce(const double* yi, const double* yj, const double* vi, const double* vj,
                      double volumeI, double volumeJ, double horizonI, double contactRadius,
                      double springConstant, double friction, PairForce& out) {
  const double d = std::sqrt((yj[0] - yi[0]) * (yj[0] - yi[0]) + (yj[1] - yi[1]) * (yj[1] - yi[1]) +
                             (yj[2] - yi[2]) * (yj[2] - yi[2]));
  if (!(d < contactRadius)) return false;
  const double c = 9.0 * springConstant / (kPi * horizonI * horizonI * horizonI * horizonI);
  const double temp = c * (contactRadius - d) / horizonI;
  for (int k = 0; k < 3; ++k) {
    out.onNode[k] = -(temp * volumeJ * (yj[k] - yi[k]) / d);
    out.onNeighbor[k] = temp * volumeI * (yj[k] - yi[k]) / d;
  }
  if (friction == 0.0) return true;
  double n[3], vperpI[3], vperpJ[3], relI[3], relJ[3];
  for (int k = 0; k < 3; ++k) n[k] = (yj[k] - yi[k]) / d;
  const double vin = vi[0] * n[0] + vi[1] * n[1] + vi[2] * n[2];
  const double vjn = vj[0] * n[0] + vj[1] * n[1] + vj[2] * n[2];
  for (int k = 0; k < 3; ++k) {
    vperpI[k] = vi[k] - vin * n[k];
    vperpJ[k] = vj[k] - vjn * n[k];
  }
  for (int k = 0; k < 3; ++k) {
    const double centre = 0.5 * (vperpI[k] + vperpJ[k]);
    relI[k] = vperpI[k] - centre;
    relJ[k] = vperpJ[k] - centre;
  }
  const double normRelI = std::sqrt(relI[0] * relI[0] + relI[1] * relI[1] + relI[2] * relI[2]);
  const double normRelJ = std::sqrt(relJ[0] * relJ[0] + relJ[1] * relJ[1] + relJ[2] * relJ[2]);
  const double fI = std::sqrt(out.onNode[0] * out.onNode[0] + out.onNode[1] * out.onNode[1] +
                              out.onNode[2] * out.onNode[2]);
  const double fJ =
      std::sqrt(out.onNeighbor[0] * out.onNeighbor[0] + out.onNeighbor[1] * out.onNeighbor[1] +
                out.onNeighbor[2] * out.onNeighbor[2]);
  for (int k = 0; k < 3; ++k) {
    out.onNode[k] += normRelI != 0.0 ? -friction * fI * relI[k] / normRelI : 0.0;
    out.onNeighbor[k] += normRelJ != 0.0 ? -friction * fJ * relJ[k] / normRelJ : 0.0;
  }
  return true;
}

}  // namespace

ShortRangeContact::ShortRangeContact(const ContactConfig& config, const Topology& topology,
                                     const std::vector<std::string>& blockNameOfPoint,
                                     const double* horizon, const double* volume, Timers& timers)
    : config_(config), topology_(topology), horizon_(horizon), volume_(volume), timers_(timers) {
  // Halo points carry their block as an index, so every rank needs the same name list: the
  // sorted union of the ranks' names (O(ranks x blocks) to gather, done once).
  std::vector<std::string> mine(blockNameOfPoint);
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
  std::string joined;
  for (const auto& b : mine) joined += b + '\n';
  const int size = topology_.numRanks;
  int len = static_cast<int>(joined.size());
  std::vector<int> lens(size), offs(size, 0);
  MPI_Allgather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, topology_.comm);
  for (int r = 1; r < size; ++r) offs[r] = offs[r - 1] + lens[r - 1];
  std::string all(static_cast<std::size_t>(offs[size - 1] + lens[size - 1]), '\0');
  MPI_Allgatherv(joined.data(), len, MPI_CHAR, all.data(), lens.data(), offs.data(), MPI_CHAR,
                 topology_.comm);
  for (std::size_t start = 0; start < all.size();) {
    const std::size_t end = all.find('\n', start);
    blockNames_.push_back(all.substr(start, end - start));
    start = end + 1;
  }
  std::sort(blockNames_.begin(), blockNames_.end());
  blockNames_.erase(std::unique(blockNames_.begin(), blockNames_.end()), blockNames_.end());
  blockIndex_.reserve(blockNameOfPoint.size());
  for (const auto& b : blockNameOfPoint) {
    blockIndex_.push_back(static_cast<int>(
        std::lower_bound(blockNames_.begin(), blockNames_.end(), b) - blockNames_.begin()));
  }
  offsets_.assign(topology_.numOwned + 1, 0);
}

void ShortRangeContact::search(const double* y) {
  Timers::Scope timer(timers_, "Contact search");
  const int n = topology_.numOwned;
  // Candidates: the owned points (first n) and a halo of the other ranks' points that lie near
  // this rank's box of current owned positions. A contact pair is decided by the two positions
  // alone, so every point within the search radius of an owned point is among the candidates
  // and the lists match a search over the whole cloud. The reach gets a margin of 1e-6 of the
  // radius so that rounding in the box test (of order an ulp of the coordinates) cannot drop a
  // point the distance test would keep; extra halo points are harmless, the distance decides.
  PointBatch owned;
  owned.globalId.assign(topology_.overlapGlobalId.begin(), topology_.overlapGlobalId.begin() + n);
  owned.x.assign(y, y + 3 * static_cast<std::size_t>(n));
  owned.volume.assign(volume_, volume_ + n);
  owned.horizon.assign(horizon_, horizon_ + n);
  owned.blockId = blockIndex_;
  const double reach = config_.searchRadius * (1.0 + 1e-6);
  const double noBox[3] = {0, 0, 0};
  HaloBatch halo = exchangeHalo(owned, reach, {kNoShift}, noBox, topology_.comm);
  PointBatch& all = owned;  // owned, then the halo (sets are not used here)
  const PointBatch& h = halo.points;
  all.globalId.insert(all.globalId.end(), h.globalId.begin(), h.globalId.end());
  all.x.insert(all.x.end(), h.x.begin(), h.x.end());
  all.volume.insert(all.volume.end(), h.volume.begin(), h.volume.end());
  all.horizon.insert(all.horizon.end(), h.horizon.begin(), h.horizon.end());
  all.blockId.insert(all.blockId.end(), h.blockId.begin(), h.blockId.end());
  halo = HaloBatch();
  numHaloPoints_ = static_cast<long long>(all.size()) - n;
  const std::size_t total = all.size();
  const std::vector<long long>& ids = all.globalId;

  std::vector<double> radius(total, config_.searchRadius);
  NeighborSearchInput in;
  in.x = all.x.data();
  in.numPoints = total;
  in.horizon = radius.data();
  std::vector<std::size_t> queries(n);
  for (int i = 0; i < n; ++i) queries[i] = static_cast<std::size_t>(i);
  std::vector<long long> found;
  std::vector<std::size_t> candidates;
  findNeighbors(in, queries, found, candidates);

  std::vector<long long> ghostIds;
  std::vector<std::vector<long long>> lists(n);
  for (int i = 0; i < n; ++i) {
    std::vector<long long> bonded;
    for (auto b = topology_.bondOffsets[i]; b < topology_.bondOffsets[i + 1]; ++b)
      bonded.push_back(topology_.overlapGlobalId[topology_.neighbors[b]]);
    std::sort(bonded.begin(), bonded.end());
    for (long long k = found[i]; k < found[i + 1]; ++k) {
      const std::size_t j = candidates[k];
      if (std::binary_search(bonded.begin(), bonded.end(), ids[j])) continue;  // bonded: no contact
      if (!config_.interacts(blockNames_[blockIndex_[i]], blockNames_[all.blockId[j]])) continue;
      lists[i].push_back(static_cast<long long>(j));
    }
    std::sort(lists[i].begin(), lists[i].end(),
              [&](long long a, long long b) { return ids[a] < ids[b]; });
  }
  // Local numbering: owned points first, then the contact ghosts sorted by global id.
  std::unordered_map<long long, int> localOfId;
  for (int i = 0; i < n; ++i) localOfId[ids[i]] = i;
  std::vector<std::size_t> ghosts;
  for (const auto& l : lists)
    for (long long j : l)
      if (!localOfId.count(ids[j])) ghosts.push_back(static_cast<std::size_t>(j));
  std::sort(ghosts.begin(), ghosts.end(),
            [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  ghostVolume_.resize(ghosts.size());
  ghostHorizon_.resize(ghosts.size());
  for (std::size_t g = 0; g < ghosts.size(); ++g) {
    localOfId[ids[ghosts[g]]] = n + static_cast<int>(g);
    ghostVolume_[g] = all.volume[ghosts[g]];
    ghostHorizon_[g] = all.horizon[ghosts[g]];
    ghostIds.push_back(ids[ghosts[g]]);
  }
  offsets_.assign(n + 1, 0);
  neighbors_.clear();
  for (int i = 0; i < n; ++i) {
    for (long long j : lists[i]) neighbors_.push_back(localOfId.at(ids[j]));
    offsets_[i + 1] = static_cast<std::int64_t>(neighbors_.size());
  }
  std::vector<GlobalOrdinal> ghost3(3 * ghostIds.size());
  for (std::size_t g = 0; g < ghostIds.size(); ++g)
    for (int d = 0; d < 3; ++d) ghost3[3 * g + d] = 3 * ghostIds[g] + d;
  ghostMap3_ =
      Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                           Teuchos::ArrayView<const GlobalOrdinal>(ghost3.data(), ghost3.size()), 0,
                           topology_.ownedMap3()->getComm()));
  ghostImport3_ = Teuchos::rcp(new Import(topology_.ownedMap3(), ghostMap3_));
}

void ShortRangeContact::refresh(const double* owned, std::vector<double>& ghost) {
  Vector source(topology_.ownedMap3(), false), target(ghostMap3_, false);
  {
    auto data = source.getDataNonConst();
    std::copy(owned, owned + 3 * topology_.numOwned, data.getRawPtr());
  }
  target.doImport(source, *ghostImport3_, Tpetra::INSERT);
  auto data = target.getData();
  ghost.assign(data.getRawPtr(), data.getRawPtr() + data.size());
}

void ShortRangeContact::computeForce(const double* y, const double* v, double* contactForce) {
  Timers::Scope timer(timers_, "Contact");
  const int n = topology_.numOwned;
  refresh(y, ghostY_);
  const bool friction = config_.frictionCoefficient != 0.0;
  if (friction) refresh(v, ghostV_);
  const double zero[3] = {0, 0, 0};
  auto position = [&](int k) { return k < n ? y + 3 * k : ghostY_.data() + 3 * (k - n); };
  auto velocity = [&](int k) {
    if (!friction) return zero + 0;
    return k < n ? v + 3 * k : ghostV_.data() + 3 * (k - n);
  };
  auto volumeOf = [&](int k) { return k < n ? volume_[k] : ghostVolume_[k - n]; };
  auto horizonOf = [&](int k) { return k < n ? horizon_[k] : ghostHorizon_[k - n]; };
  for (int i = 0; i < n; ++i) {
    double f[3] = {0, 0, 0};
    for (auto b = offsets_[i]; b < offsets_[i + 1]; ++b) {
      const int j = neighbors_[b];
      PairForce p;
      // i's own entry, then j's entry for the same pair (the contact lists are symmetric).
      if (pairForce(position(i), position(j), velocity(i), velocity(j), volumeOf(i), volumeOf(j),
                    horizonOf(i), config_.contactRadius, config_.springConstant,
                    config_.frictionCoefficient, p)) {
        for (int d = 0; d < 3; ++d) f[d] += p.onNode[d];
      }
      if (pairForce(position(j), position(i), velocity(j), velocity(i), volumeOf(j), volumeOf(i),
                    horizonOf(j), config_.contactRadius, config_.springConstant,
                    config_.frictionCoefficient, p)) {
        for (int d = 0; d < 3; ++d) f[d] += p.onNeighbor[d];
      }
    }
    for (int d = 0; d < 3; ++d) contactForce[3 * i + d] = f[d];
  }
}

std::vector<std::vector<long long>> ShortRangeContact::contactListIds() const {
  const int n = topology_.numOwned;
  std::vector<std::vector<long long>> lists(n);
  for (int i = 0; i < n; ++i)
    for (auto b = offsets_[i]; b < offsets_[i + 1]; ++b) {
      const int k = neighbors_[b];
      lists[i].push_back(k < n ? topology_.overlapGlobalId[k]
                               : ghostMap3_->getGlobalElement(3 * (k - n)) / 3);
    }
  return lists;
}

}  // namespace peridot
