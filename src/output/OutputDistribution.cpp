#include "output/OutputDistribution.hpp"

#include <algorithm>
#include <climits>
#include <numeric>
#include <string>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/IdIndex.hpp"

namespace peridot {

namespace {

// Displacements of an all-to-all from its counts.
std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> d(counts.size(), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) d[r] = d[r - 1] + counts[r - 1];
  return d;
}

// Indices 0 .. n-1 ordered by bucket(i) in [0, buckets), in index order within a bucket (a
// counting sort: these orders are by rank, of which there are few).
template <class Bucket>
std::vector<int> bucketOrder(int n, int buckets, Bucket bucket) {
  std::vector<int> start(static_cast<std::size_t>(buckets) + 1, 0);
  for (int i = 0; i < n; ++i) ++start[bucket(i) + 1];
  for (int b = 0; b < buckets; ++b) start[b + 1] += start[b];
  std::vector<int> order(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) order[start[bucket(i)]++] = i;
  return order;
}

std::vector<int> scaled(const std::vector<int>& v, int factor) {
  std::vector<int> out(v);
  for (auto& x : out) x *= factor;
  return out;
}

}  // namespace

OutputDistribution::OutputDistribution(const Topology& t)
    : comm_(t.comm),
      rank_(t.rank),
      numRanks_(t.numRanks),
      numPoints_(t.globalNumPoints),
      overlapGlobalId_(t.overlapGlobalId) {
  const int n = t.numOwned;
  const int P = numRanks_;

  // Blocks holding points: the union of every rank's blocks (O(P * blocks) on each rank).
  std::vector<int> mine(t.blockId.begin(), t.blockId.begin() + n);
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
  int numMine = static_cast<int>(mine.size());
  std::vector<int> numEach(P);
  MPI_Allgather(&numMine, 1, MPI_INT, numEach.data(), 1, MPI_INT, comm_);
  std::vector<int> each(std::accumulate(numEach.begin(), numEach.end(), 0));
  MPI_Allgatherv(mine.data(), numMine, MPI_INT, each.data(), numEach.data(),
                 displacements(numEach).data(), MPI_INT, comm_);
  std::sort(each.begin(), each.end());
  each.erase(std::unique(each.begin(), each.end()), each.end());
  blockIds_ = each;
  const int numBlocks = static_cast<int>(blockIds_.size());
  auto blockIndex = [&](int id) {
    return static_cast<int>(std::lower_bound(blockIds_.begin(), blockIds_.end(), id) -
                            blockIds_.begin());
  };
  std::vector<long long> localCounts(numBlocks, 0);
  std::vector<int> ownedBlock(n);
  for (int i = 0; i < n; ++i) ++localCounts[ownedBlock[i] = blockIndex(t.blockId[i])];
  blockCounts_.assign(numBlocks, 0);
  MPI_Allreduce(localCounts.data(), blockCounts_.data(), numBlocks, MPI_LONG_LONG, MPI_SUM, comm_);
  if (std::accumulate(blockCounts_.begin(), blockCounts_.end(), 0LL) != numPoints_)
    throw RunError("output: the ranks own " +
                   std::to_string(std::accumulate(blockCounts_.begin(), blockCounts_.end(), 0LL)) +
                   " points, the topology says " + std::to_string(numPoints_));
  // MPI counts are ints: the largest message is 4 values (id and position) per point of a rank.
  throwIfAnyRank(4LL * std::max<long long>(n, localCount()) > INT_MAX
                     ? "output: too many points on rank " + std::to_string(rank_) +
                           " for one MPI message; run on more ranks"
                     : "",
                 comm_, true);
  std::vector<long long> blockOffset(numBlocks, 0);
  for (int b = 1; b < numBlocks; ++b) blockOffset[b] = blockOffset[b - 1] + blockCounts_[b - 1];

  // Home of an id: ids cut into P equal ranges up to the largest id.
  long long maxId = -1, localMax = -1;
  for (int i = 0; i < n; ++i) localMax = std::max(localMax, t.overlapGlobalId[i]);
  MPI_Allreduce(&localMax, &maxId, 1, MPI_LONG_LONG, MPI_MAX, comm_);
  const long long idsPerHome = std::max(1LL, (maxId + 1 + P - 1) / P);
  auto homeOf = [&](long long id) { return static_cast<int>(id / idsPerHome); };

  // Send (block, id) to the homes.
  const std::vector<int> toHome =
      bucketOrder(n, P, [&](int i) { return homeOf(t.overlapGlobalId[i]); });
  std::vector<int> homeCounts(P, 0), fromCounts(P);
  std::vector<long long> pairs(2 * static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const int i = toHome[k];
    ++homeCounts[homeOf(t.overlapGlobalId[i])];
    pairs[2 * k] = ownedBlock[i];
    pairs[2 * k + 1] = t.overlapGlobalId[i];
  }
  MPI_Alltoall(homeCounts.data(), 1, MPI_INT, fromCounts.data(), 1, MPI_INT, comm_);
  const int numHomed = std::accumulate(fromCounts.begin(), fromCounts.end(), 0);
  std::vector<long long> homed(2 * static_cast<std::size_t>(numHomed));
  MPI_Alltoallv(pairs.data(), scaled(homeCounts, 2).data(),
                displacements(scaled(homeCounts, 2)).data(), MPI_LONG_LONG, homed.data(),
                scaled(fromCounts, 2).data(), displacements(scaled(fromCounts, 2)).data(),
                MPI_LONG_LONG, comm_);
  pairs.clear();
  pairs.shrink_to_fit();

  // At the home: rank among the ids of the block, offset by the same block's points on the
  // homes before (which hold smaller ids) and by the blocks before.
  // The ids in ascending order (IdIndex: a table over the home's range of ids, which the homes'
  // cut makes dense for a mesh numbered without large gaps, else a sort), each block counting
  // its own. An index sort whose comparisons read the pairs at random took 0.2 s here at 2 * 10^6
  // points.
  std::vector<long long> homeBlockCounts(numBlocks, 0), before(numBlocks, 0);
  for (int k = 0; k < numHomed; ++k) ++homeBlockCounts[homed[2 * k]];
  MPI_Exscan(homeBlockCounts.data(), before.data(), numBlocks, MPI_LONG_LONG, MPI_SUM, comm_);
  if (rank_ == 0) std::fill(before.begin(), before.end(), 0);  // Exscan leaves rank 0 undefined
  std::vector<long long> homedPosition(numHomed);
  std::string problem;
  {
    std::vector<long long> ids(static_cast<std::size_t>(numHomed));
    for (int j = 0; j < numHomed; ++j) ids[j] = homed[2 * j + 1];
    const IdIndex byId(ids.data(), ids.size());
    ids = std::vector<long long>();
    long long visited = 0;
    byId.forEachInOrder([&](long long, int j) {
      ++visited;
      const auto b = static_cast<std::size_t>(homed[2 * j]);
      homedPosition[j] = blockOffset[b] + before[b]++;
    });
    for (int j = 0; j < numHomed && visited != numHomed && problem.empty(); ++j)
      if (byId.find(homed[2 * j + 1]) != j)
        problem = "output: global id " + std::to_string(homed[2 * j + 1]) + " is owned twice";
  }
  throwIfAnyRank(problem, comm_, true);
  homed.clear();
  homed.shrink_to_fit();
  std::vector<long long> sentPosition(n);
  MPI_Alltoallv(homedPosition.data(), fromCounts.data(), displacements(fromCounts).data(),
                MPI_LONG_LONG, sentPosition.data(), homeCounts.data(),
                displacements(homeCounts).data(), MPI_LONG_LONG, comm_);
  std::vector<long long> ownedPosition(n);
  for (int k = 0; k < n; ++k) ownedPosition[toHome[k]] = sentPosition[k];

  // The plan owned -> output ranges.
  auto ownerOf = [&](long long p) {
    // rangeBegin is monotone: the last r with rangeBegin(r) <= p.
    int lo = 0, hi = P - 1;
    while (lo < hi) {
      const int mid = (lo + hi + 1) / 2;
      if (rangeBegin(mid) <= p)
        lo = mid;
      else
        hi = mid - 1;
    }
    return lo;
  };
  std::vector<int> dest(n);
  sendCounts_.assign(P, 0);
  for (int i = 0; i < n; ++i) ++sendCounts_[dest[i] = ownerOf(ownedPosition[i])];
  sendOrder_ = bucketOrder(n, P, [&](int i) { return dest[i]; });
  sendDispls_ = displacements(sendCounts_);
  recvCounts_.assign(P, 0);
  MPI_Alltoall(sendCounts_.data(), 1, MPI_INT, recvCounts_.data(), 1, MPI_INT, comm_);
  recvDispls_ = displacements(recvCounts_);
  std::vector<long long> positions;
  move(ownedPosition.data(), 1, MPI_LONG_LONG, positions);  // recvSlot_ empty: arrival order
  throwIfAnyRank(static_cast<long long>(positions.size()) != localCount()
                     ? "output: the points do not cover the output positions once each"
                     : "",
                 comm_, true);
  recvSlot_.resize(positions.size());
  for (std::size_t k = 0; k < positions.size(); ++k) recvSlot_[k] = positions[k] - localBegin();
}

long long OutputDistribution::rangeBegin(int r) const {
  // N r / P without overflow for any N < 2^63 / P.
  return numPoints_ / numRanks_ * r + numPoints_ % numRanks_ * r / numRanks_;
}

namespace {

// Copies `count` groups of C values, group k from src + from(k) * C to dst + to(k) * C; C known
// at compile time for the usual 1, 3, 4 so that the copy is a few moves, not a memmove call.
template <int C, class T, class From, class To>
void copyGroups(std::size_t count, const T* src, From from, T* dst, To to) {
  for (std::size_t k = 0; k < count; ++k)
    for (int j = 0; j < C; ++j) dst[to(k) * C + j] = src[from(k) * C + j];
}

template <class T, class From, class To>
void copyGroups(int c, std::size_t count, const T* src, From from, T* dst, To to) {
  switch (c) {
    case 1:
      return copyGroups<1>(count, src, from, dst, to);
    case 3:
      return copyGroups<3>(count, src, from, dst, to);
    case 4:
      return copyGroups<4>(count, src, from, dst, to);
    default:
      for (std::size_t k = 0; k < count; ++k)
        for (int j = 0; j < c; ++j) dst[to(k) * c + j] = src[from(k) * c + j];
  }
}

}  // namespace

template <class T>
void OutputDistribution::move(const T* owned, int components, MPI_Datatype type,
                              std::vector<T>& range) const {
  const std::size_t c = static_cast<std::size_t>(components);
  auto same = [](std::size_t k) { return k; };
  const auto sent = [&](std::size_t k) { return static_cast<std::size_t>(sendOrder_[k]); };
  if (numRanks_ == 1) {
    // Everything stays here: the plan is a permutation, done without the copies to send and
    // receive (two copies of the field: 134 MB for the mesh write's 4 values a point at 128^3).
    range.resize(sendOrder_.size() * c);
    if (recvSlot_.empty())
      copyGroups(components, sendOrder_.size(), owned, sent, range.data(), same);
    else
      copyGroups(components, sendOrder_.size(), owned, sent, range.data(),
                 [&](std::size_t k) { return static_cast<std::size_t>(recvSlot_[k]); });
    return;
  }
  std::vector<T> send(sendOrder_.size() * c);
  copyGroups(components, sendOrder_.size(), owned, sent, send.data(), same);
  // What arrives (the local range once the plan is checked).
  const std::size_t numReceived =
      static_cast<std::size_t>(std::accumulate(recvCounts_.begin(), recvCounts_.end(), 0LL));
  std::vector<T> received(numReceived * c);
  MPI_Alltoallv(send.data(), scaled(sendCounts_, components).data(),
                scaled(sendDispls_, components).data(), type, received.data(),
                scaled(recvCounts_, components).data(), scaled(recvDispls_, components).data(),
                type, comm_);
  send = std::vector<T>();
  if (recvSlot_.empty()) {  // building the plan: keep the arrival order
    range = std::move(received);
    return;
  }
  range.resize(numReceived * c);
  copyGroups(components, numReceived, received.data(), same, range.data(),
             [&](std::size_t k) { return static_cast<std::size_t>(recvSlot_[k]); });
}

void OutputDistribution::toRange(const double* owned, int components,
                                 std::vector<double>& range) const {
  move(owned, components, MPI_DOUBLE, range);
}

void OutputDistribution::toRange(const long long* owned, int components,
                                 std::vector<long long>& range) const {
  move(owned, components, MPI_LONG_LONG, range);
}

std::vector<std::vector<long long>> OutputDistribution::setsInRange(
    const std::vector<const std::vector<long long>*>& ownedSetIds) const {
  // The owned points by id, to find a member's owned index: built for the call (at output
  // opening), not kept through the run.
  const std::size_t n = sendOrder_.size();
  const IdIndex byId(overlapGlobalId_.data(), n);
  // Flag each set's members (owned order), move the flags to the ranges, read the positions.
  std::vector<std::vector<long long>> positions(ownedSetIds.size());
  std::vector<long long> member(n), flags;
  for (std::size_t s = 0; s < ownedSetIds.size(); ++s) {
    std::fill(member.begin(), member.end(), 0);
    std::string problem;
    for (long long id : *ownedSetIds[s]) {
      const int local = byId.find(id);
      if (local < 0) {
        problem = "output: node set member " + std::to_string(id) + " is not an owned point";
        break;
      }
      member[local] = 1;
    }
    throwIfAnyRank(problem, comm_, true);
    move(member.data(), 1, MPI_LONG_LONG, flags);
    for (std::size_t k = 0; k < flags.size(); ++k)
      if (flags[k]) positions[s].push_back(localBegin() + static_cast<long long>(k));
  }
  return positions;
}

}  // namespace peridot
