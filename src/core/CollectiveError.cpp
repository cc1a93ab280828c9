#include "core/CollectiveError.hpp"

#include <climits>

#include "core/Error.hpp"

namespace peridot {

void throwIfAnyRank(const std::string& localMessage, MPI_Comm comm, bool duringRun) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int mine = localMessage.empty() ? INT_MAX : rank, first = INT_MAX;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == INT_MAX) return;
  int length = rank == first ? static_cast<int>(localMessage.size()) : 0;
  MPI_Bcast(&length, 1, MPI_INT, first, comm);
  std::string message =
      rank == first ? localMessage : std::string(static_cast<std::size_t>(length), ' ');
  MPI_Bcast(message.data(), length, MPI_CHAR, first, comm);
  if (duringRun) throw RunError(message).markCollective();
  throw InputError(message);
}

}  // namespace peridot
