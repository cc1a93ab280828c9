#pragma once
// Contiguous shares of 0..n-1 over the ranks of a communicator, and the all-to-all exchange the
// distributed readers use to route items to the rank whose share holds them.
#include <mpi.h>

#include <algorithm>
#include <climits>
#include <vector>

#include "core/Error.hpp"

namespace peridot {

// Items 0..n-1 in contiguous, balanced ranges, rank r holding [begin(r), begin(r + 1)).
struct Slicing {
  long long n = 0;
  int size = 1;
  long long begin(int r) const {
    const long long q = n / size, extra = n % size;
    return r * q + std::min<long long>(r, extra);
  }
  int home(long long item) const {
    const long long q = n / size, extra = n % size, big = extra * (q + 1);
    if (item < big) return static_cast<int>(item / (q + 1));
    return static_cast<int>(extra + (item - big) / q);
  }
};

// Alltoallv of trivially copyable items grouped by destination rank (sendCounts[r] items for r).
template <class T>
inline std::vector<T> exchange(const std::vector<T>& send, const std::vector<int>& sendCounts,
                               std::vector<int>& recvCounts, MPI_Comm comm) {
  const int size = static_cast<int>(sendCounts.size());
  recvCounts.assign(static_cast<std::size_t>(size), 0);
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, comm);
  std::vector<int> sendDispl(size, 0), recvDispl(size, 0);
  long long sendTotal = 0, recvTotal = 0;
  for (int r = 0; r < size; ++r) {
    sendDispl[r] = static_cast<int>(std::min<long long>(sendTotal, INT_MAX));
    recvDispl[r] = static_cast<int>(std::min<long long>(recvTotal, INT_MAX));
    sendTotal += sendCounts[r];
    recvTotal += recvCounts[r];
  }
  // MPI displacements are ints. Every rank learns whether any rank overflows, so that all
  // throw together instead of leaving the others in MPI_Alltoallv.
  int tooMany = sendTotal > INT_MAX || recvTotal > INT_MAX ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &tooMany, 1, MPI_INT, MPI_MAX, comm);
  if (tooMany != 0) {
    throw RunError(
        "a rank's share of the mesh needs more than INT_MAX items in one exchange; "
        "use more ranks");
  }
  std::vector<T> recv(static_cast<std::size_t>(recvTotal));
  MPI_Datatype type;
  MPI_Type_contiguous(static_cast<int>(sizeof(T)), MPI_BYTE, &type);
  MPI_Type_commit(&type);
  MPI_Alltoallv(send.data(), sendCounts.data(), sendDispl.data(), type, recv.data(),
                recvCounts.data(), recvDispl.data(), type, comm);
  MPI_Type_free(&type);
  return recv;
}

}  // namespace peridot
