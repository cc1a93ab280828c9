#pragma once
// Where each owned point goes in the output file, and how per-point values travel there, with
// no rank holding more than O(N/P) points plus O(P) and O(blocks) tables.
//
// Output order (Peridigm's layout): blocks by id, points by global id within a block. A point's
// output position is found by a distributed count: every point's (block, id) goes to a "home"
// rank chosen by id range, each home sorts what it received, and exclusive scans over the homes
// and over the blocks give each point its position, which goes back to the owner.
//
// For writing, output positions are cut into contiguous ranges: rank r holds the values of
// positions [rangeBegin(r), rangeBegin(r + 1)), about N/P of them; toRange() moves owned values
// there (one all-to-all), and the writing rank then takes one range at a time.
#include <mpi.h>

#include <vector>

#include "parallel/Topology.hpp"

namespace peridot {

class OutputDistribution {
 public:
  explicit OutputDistribution(const Topology& topology);  // collective

  long long numPoints() const { return numPoints_; }
  // Blocks that hold points, by id, and their global point counts: O(blocks).
  const std::vector<int>& blockIds() const { return blockIds_; }
  const std::vector<long long>& blockCounts() const { return blockCounts_; }
  // First output position of rank r's range (r in [0, P]; rangeBegin(P) = N).
  long long rangeBegin(int r) const;
  long long localBegin() const { return rangeBegin(rank_); }
  long long localCount() const { return rangeBegin(rank_ + 1) - rangeBegin(rank_); }

  // Collective: owned values (`components` per point, interleaved, owned order) to this rank's
  // range, in output order.
  void toRange(const double* owned, int components, std::vector<double>& range) const;
  void toRange(const long long* owned, int components, std::vector<long long>& range) const;
  // Collective: for each set, given as the sorted global ids of the owned points in it, the
  // output positions of its points within this rank's range, sorted.
  std::vector<std::vector<long long>> setsInRange(
      const std::vector<const std::vector<long long>*>& ownedSetIds) const;

 private:
  template <class T>
  void move(const T* owned, int components, MPI_Datatype type, std::vector<T>& range) const;

  MPI_Comm comm_;
  int rank_ = 0, numRanks_ = 1;
  long long numPoints_ = 0;
  std::vector<int> blockIds_;
  std::vector<long long> blockCounts_;
  const std::vector<GlobalOrdinal>& overlapGlobalId_;  // the topology's
  // The plan owned order -> ranges: owned indices in send order, per-rank counts (points), and
  // for each received point its slot in the local range.
  std::vector<int> sendOrder_;
  std::vector<int> sendCounts_, sendDispls_, recvCounts_, recvDispls_;
  std::vector<long long> recvSlot_;
};

// Rank 0 receives every rank's range of a field, one range at a time, and hands each to
// `write(firstPosition, count, values)`; the other ranks send theirs. Collective. The next
// range is received while one is written (two buffers: rank 0 holds at most its own range and
// two others).
template <class T, class Write>
void streamRangesToRoot(const OutputDistribution& d, MPI_Comm comm, const std::vector<T>& range,
                        int components, MPI_Datatype type, Write&& write) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if (rank != 0) {
    MPI_Send(range.data(), static_cast<int>(range.size()), type, 0, 0, comm);
    return;
  }
  std::vector<T> buffer[2];
  MPI_Request request = MPI_REQUEST_NULL;
  auto post = [&](int r) {
    const long long count = d.rangeBegin(r + 1) - d.rangeBegin(r);
    std::vector<T>& b = buffer[r % 2];
    b.resize(static_cast<std::size_t>(count * components));
    MPI_Irecv(b.data(), static_cast<int>(b.size()), type, r, 0, comm, &request);
  };
  if (size > 1) post(1);
  write(d.localBegin(), d.localCount(), range.data());
  for (int r = 1; r < size; ++r) {
    MPI_Wait(&request, MPI_STATUS_IGNORE);
    if (r + 1 < size) post(r + 1);
    write(d.rangeBegin(r), d.rangeBegin(r + 1) - d.rangeBegin(r), buffer[r % 2].data());
  }
}

}  // namespace peridot
