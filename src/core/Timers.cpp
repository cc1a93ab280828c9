#include "core/Timers.hpp"

#include <iomanip>
#include <vector>

namespace peridot {

void Timers::report(std::ostream& out, MPI_Comm comm) const {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if (rank == 0) {
    out << "\nWall-clock time (seconds)      Min        Max        Ave\n";
  }
  for (const auto& kv : seconds_) {
    double mn = 0, mx = 0, sum = 0;
    MPI_Allreduce(&kv.second, &mn, 1, MPI_DOUBLE, MPI_MIN, comm);
    MPI_Allreduce(&kv.second, &mx, 1, MPI_DOUBLE, MPI_MAX, comm);
    MPI_Allreduce(&kv.second, &sum, 1, MPI_DOUBLE, MPI_SUM, comm);
    if (rank == 0) {
      out << "  " << std::left << std::setw(26) << kv.first << std::right << std::fixed
          << std::setprecision(3) << std::setw(9) << mn << "  " << std::setw(9) << mx << "  "
          << std::setw(9) << sum / size << "\n";
    }
  }
  // The same phases in CPU seconds (rows named "CPU <phase>", so that a reader of the table
  // above by row name is not confused).
  if (rank == 0 && !cpuSeconds_.empty()) {
    out << "CPU time (seconds)             Min        Max        Ave\n";
  }
  for (const auto& kv : cpuSeconds_) {
    double mn = 0, mx = 0, sum = 0;
    MPI_Allreduce(&kv.second, &mn, 1, MPI_DOUBLE, MPI_MIN, comm);
    MPI_Allreduce(&kv.second, &mx, 1, MPI_DOUBLE, MPI_MAX, comm);
    MPI_Allreduce(&kv.second, &sum, 1, MPI_DOUBLE, MPI_SUM, comm);
    if (rank == 0) {
      out << "  " << std::left << std::setw(26) << ("CPU " + kv.first) << std::right << std::fixed
          << std::setprecision(3) << std::setw(9) << mn << "  " << std::setw(9) << mx << "  "
          << std::setw(9) << sum / size << "\n";
    }
  }
  if (rank == 0) out.unsetf(std::ios::fixed);
}

}  // namespace peridot
