#include "parallel/PointExchange.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace peridot {

void PointBatch::reserve(std::size_t n) {
  globalId.reserve(n);
  x.reserve(3 * n);
  volume.reserve(n);
  horizon.reserve(n);
  blockId.reserve(n);
  setOffsets.reserve(n + 1);
}

void PointBatch::append(const PointBatch& from, std::size_t p) {
  globalId.push_back(from.globalId[p]);
  x.insert(x.end(), &from.x[3 * p], &from.x[3 * p] + 3);
  volume.push_back(from.volume[p]);
  horizon.push_back(from.horizon[p]);
  blockId.push_back(from.blockId[p]);
  setIndex.insert(setIndex.end(), from.setIndex.begin() + from.setOffsets[p],
                  from.setIndex.begin() + from.setOffsets[p + 1]);
  setOffsets.push_back(static_cast<int>(setIndex.size()));
}

namespace {

// One point on the wire: id, position, volume, horizon, block, a tag (the shift code of a halo
// point, or the number of sets that follow).
constexpr std::size_t kRecordBytes = 8 + 24 + 8 + 8 + 4 + 4;

struct Outgoing {
  int rank;
  std::size_t point;
  int tag;  // shift code (halo) or -1 (migration: the point's sets follow)
};

template <class T>
void put(char*& out, const T& value) {
  std::memcpy(out, &value, sizeof(T));
  out += sizeof(T);
}

template <class T>
T take(const char*& in) {
  T value;
  std::memcpy(&value, in, sizeof(T));
  in += sizeof(T);
  return value;
}

// Packs the records by destination rank, exchanges them, and unpacks into `received` (and the
// tags into `tags`, or the sets into received's set lists when a record carries them).
void exchange(const PointBatch& points, std::vector<Outgoing>& outgoing, MPI_Comm comm,
              PointBatch& received, std::vector<int>* tags) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::stable_sort(outgoing.begin(), outgoing.end(),
                   [](const Outgoing& a, const Outgoing& b) { return a.rank < b.rank; });
  auto bytesOf = [&](const Outgoing& o) {
    const std::size_t sets =
        o.tag < 0
            ? static_cast<std::size_t>(points.setOffsets[o.point + 1] - points.setOffsets[o.point])
            : 0;
    return kRecordBytes + 4 * sets;
  };
  std::vector<long long> sendBytes(size, 0);
  for (const auto& o : outgoing) sendBytes[o.rank] += static_cast<long long>(bytesOf(o));
  std::vector<long long> recvBytes(size, 0);
  MPI_Alltoall(sendBytes.data(), 1, MPI_LONG_LONG, recvBytes.data(), 1, MPI_LONG_LONG, comm);
  std::vector<int> sendCounts(size), sendDispls(size), recvCounts(size), recvDispls(size);
  long long sendTotal = 0, recvTotal = 0;
  for (int r = 0; r < size; ++r) {
    if (sendTotal > INT_MAX || recvTotal > INT_MAX || sendBytes[r] > INT_MAX ||
        recvBytes[r] > INT_MAX) {
      throw std::runtime_error("point exchange of more than 2 GiB on one rank: use more ranks");
    }
    sendCounts[r] = static_cast<int>(sendBytes[r]);
    recvCounts[r] = static_cast<int>(recvBytes[r]);
    sendDispls[r] = static_cast<int>(sendTotal);
    recvDispls[r] = static_cast<int>(recvTotal);
    sendTotal += sendBytes[r];
    recvTotal += recvBytes[r];
  }
  if (sendTotal > INT_MAX || recvTotal > INT_MAX) {
    throw std::runtime_error("point exchange of more than 2 GiB on one rank: use more ranks");
  }
  std::vector<char> sendBuffer(static_cast<std::size_t>(sendTotal));
  char* out = sendBuffer.data();
  for (const auto& o : outgoing) {
    const std::size_t p = o.point;
    put(out, points.globalId[p]);
    for (int d = 0; d < 3; ++d) put(out, points.x[3 * p + d]);
    put(out, points.volume[p]);
    put(out, points.horizon[p]);
    put(out, points.blockId[p]);
    if (o.tag >= 0) {
      put(out, o.tag);
    } else {
      const int first = points.setOffsets[p], count = points.setOffsets[p + 1] - first;
      put(out, count);
      for (int k = 0; k < count; ++k) put(out, points.setIndex[first + k]);
    }
  }
  outgoing = std::vector<Outgoing>();
  std::vector<char> recvBuffer(static_cast<std::size_t>(recvTotal));
  MPI_Alltoallv(sendBuffer.data(), sendCounts.data(), sendDispls.data(), MPI_BYTE,
                recvBuffer.data(), recvCounts.data(), recvDispls.data(), MPI_BYTE, comm);
  sendBuffer = std::vector<char>();
  // At most this many records (a migrated record may carry sets): reserved so that the arrays
  // do not grow by doubling (copies and fresh pages).
  const std::size_t records = recvBuffer.size() / kRecordBytes;
  received.reserve(received.size() + records);
  if (tags) tags->reserve(tags->size() + records);
  const char* in = recvBuffer.data();
  const char* end = in + recvBuffer.size();
  while (in < end) {
    received.globalId.push_back(take<long long>(in));
    for (int d = 0; d < 3; ++d) received.x.push_back(take<double>(in));
    received.volume.push_back(take<double>(in));
    received.horizon.push_back(take<double>(in));
    received.blockId.push_back(take<int>(in));
    const int tag = take<int>(in);
    if (tags) {
      tags->push_back(tag);
    } else {
      for (int k = 0; k < tag; ++k) received.setIndex.push_back(take<int>(in));
    }
    received.setOffsets.push_back(static_cast<int>(received.setIndex.size()));
  }
}

}  // namespace

PointBatch migrate(PointBatch points, const std::vector<int>& destination, MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  // One rank: every point stays, in its order (what the exchange would return, without a copy).
  if (size == 1) return points;
  std::vector<Outgoing> outgoing(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) outgoing[p] = {destination[p], p, -1};
  PointBatch received;
  exchange(points, outgoing, comm, received, nullptr);
  return received;
}

std::vector<int> migrateValues(const std::vector<int>& values, const std::vector<int>& destination,
                               MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<int> sendCounts(size, 0), recvCounts(size), sendDispls(size, 0), recvDispls(size, 0);
  for (int r : destination) ++sendCounts[r];
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < size; ++r) {
    sendDispls[r] = sendDispls[r - 1] + sendCounts[r - 1];
    recvDispls[r] = recvDispls[r - 1] + recvCounts[r - 1];
  }
  // By destination, in the order of the points (migrate's stable sort by rank).
  std::vector<int> send(values.size()), next(sendDispls);
  for (std::size_t p = 0; p < values.size(); ++p) send[next[destination[p]]++] = values[p];
  std::vector<int> received(static_cast<std::size_t>(recvDispls[size - 1] + recvCounts[size - 1]));
  MPI_Alltoallv(send.data(), sendCounts.data(), sendDispls.data(), MPI_INT, received.data(),
                recvCounts.data(), recvDispls.data(), MPI_INT, comm);
  return received;
}

HaloBatch exchangeHalo(const PointBatch& owned, double reach, const std::vector<int>& codes,
                       const double* boxLength, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  // Every rank's box of owned points (an empty box on a rank that owns none).
  double box[6];
  for (int d = 0; d < 3; ++d) {
    box[d] = std::numeric_limits<double>::max();
    box[3 + d] = std::numeric_limits<double>::lowest();
  }
  for (std::size_t p = 0; p < owned.size(); ++p)
    for (int d = 0; d < 3; ++d) {
      box[d] = std::min(box[d], owned.x[3 * p + d]);
      box[3 + d] = std::max(box[3 + d], owned.x[3 * p + d]);
    }
  std::vector<double> boxes(6 * static_cast<std::size_t>(size));
  MPI_Allgather(box, 6, MPI_DOUBLE, boxes.data(), 6, MPI_DOUBLE, comm);

  // The box tests below run on rounded sums (b + reach), while the search measures distances as
  // rounded differences: a neighbour at almost exactly the reach can pass the one and fail the
  // other. Widening by far more than the rounding (1e-14 of the coordinates' scale, at most 1e-3 of
  // the reach, so that a degenerate mesh does not send everything) sends a few
  // more candidates, which the search rejects, and never drops one, so the bonds cannot depend
  // on where the rank boundaries fall.
  double scale = reach;
  for (double v : boxes)
    if (std::fabs(v) < std::numeric_limits<double>::max()) scale = std::max(scale, std::fabs(v));
  for (int d = 0; d < 3; ++d) scale = std::max(scale, std::fabs(boxLength ? boxLength[d] : 0.0));
  reach += std::min(1e-14 * scale, 1e-3 * reach);

  std::vector<Outgoing> outgoing;
  std::vector<int> nearRanks;
  for (int code : codes) {
    double shift[3];
    shiftVector(code, boxLength, shift);
    // Only ranks whose widened box meets this rank's shifted box can receive a point of it.
    nearRanks.clear();
    for (int r = 0; r < size; ++r) {
      if (r == rank && code == kNoShift) continue;
      const double* b = &boxes[6 * static_cast<std::size_t>(r)];
      bool meets = owned.size() > 0;
      for (int d = 0; d < 3 && meets; ++d)
        meets = box[d] + shift[d] <= b[3 + d] + reach && box[3 + d] + shift[d] >= b[d] - reach;
      if (meets) nearRanks.push_back(r);
    }
    for (std::size_t p = 0; p < owned.size() && !nearRanks.empty(); ++p) {
      double y[3];
      for (int d = 0; d < 3; ++d) y[d] = owned.x[3 * p + d] + shift[d];
      for (int r : nearRanks) {
        const double* b = &boxes[6 * static_cast<std::size_t>(r)];
        bool inside = true;
        for (int d = 0; d < 3 && inside; ++d)
          inside = y[d] >= b[d] - reach && y[d] <= b[3 + d] + reach;
        if (inside) outgoing.push_back({r, p, code});
      }
    }
  }
  HaloBatch halo;
  exchange(owned, outgoing, comm, halo.points, &halo.shift);
  return halo;
}

}  // namespace peridot
