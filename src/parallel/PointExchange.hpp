#pragma once
// Moving points between ranks: to their owners after a partition (migrate, set-up), and copies
// of the points within reach of other ranks' boxes (halo: the set-up's neighbour search, and the
// contact search on current positions), so that no rank ever needs the whole cloud. Both are
// one MPI_Alltoallv of packed records.
#include <mpi.h>

#include <cstddef>
#include <vector>

namespace peridot {

// Points with what the set-up needs of them. Point sets are CSR: the sets of point p are
// setIndex[setOffsets[p] .. setOffsets[p + 1]) (indices into the cloud's list of sets).
struct PointBatch {
  std::vector<long long> globalId;
  std::vector<double> x;  // 3 per point
  std::vector<double> volume;
  std::vector<double> horizon;
  std::vector<int> blockId;
  std::vector<int> setOffsets{0};
  std::vector<int> setIndex;

  std::size_t size() const { return globalId.size(); }
  void reserve(std::size_t n);
  // Appends point p of `from`.
  void append(const PointBatch& from, std::size_t p);
};

// Collective: sends point p to rank destination[p]. Returns the points this rank receives,
// in order of source rank, then of their order on the source. (Taken by value: a caller that
// moves its batch in lends its arrays to a one-rank run.)
PointBatch migrate(PointBatch points, const std::vector<int>& destination, MPI_Comm comm);

// Collective: sends values[p] to rank destination[p], in migrate's order, so that the values
// received line up with the points migrate(points, destination) returns.
std::vector<int> migrateValues(const std::vector<int>& values, const std::vector<int>& destination,
                               MPI_Comm comm);

// Periodic shift codes: c in 0..26 stands for the shift (c % 3 - 1, c / 3 % 3 - 1, c / 9 - 1)
// box lengths; 13 is no shift.
constexpr int kNoShift = 13;
inline void shiftVector(int code, const double* boxLength, double* shift) {
  const int s[3] = {code % 3 - 1, code / 3 % 3 - 1, code / 9 - 1};
  for (int d = 0; d < 3; ++d) shift[d] = s[d] * boxLength[d];
}

// A halo point: a copy of a point owned elsewhere (or a periodic image of an owned one), with
// its position unshifted and the code of its periodic shift.
struct HaloBatch {
  PointBatch points;       // sets are not sent
  std::vector<int> shift;  // per point, the shift code
};

// Collective: each rank receives every point of the other ranks, and every periodic image
// (shift codes in `codes`; 13 = none) of any rank's points, whose position (with the shift
// added, as x + shift) lies within `reach` of the receiving rank's bounding box of `owned`.
// `boxLength` is the periodic box's length per axis (shiftVector).
HaloBatch exchangeHalo(const PointBatch& owned, double reach, const std::vector<int>& codes,
                       const double* boxLength, MPI_Comm comm);

}  // namespace peridot
