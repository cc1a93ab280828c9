#pragma once
// An input error found on some ranks only (a bad value at a point one rank owns) must stop
// every rank with the same message, not leave the others waiting in the next collective call.
#include <mpi.h>

#include <string>

namespace peridot {

// Collective. If any rank passes a non-empty message, every rank throws InputError (or
// RunError when `duringRun`) with the message of the lowest such rank.
void throwIfAnyRank(const std::string& localMessage, MPI_Comm comm, bool duringRun = false);

}  // namespace peridot
