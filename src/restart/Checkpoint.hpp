#pragma once
// Checkpoint files for restart: the state a continued run needs, keyed by global id so that it
// can be read at any rank count, written and read with MPI-IO so that no rank holds more than its
// share, and validated (header, deck and mesh hashes, trailer, checksum) before any value is used.
//
// Layout (native little-endian, doc/restart.md):
//   header     4096 bytes: magic "PDTCKPT1", version, hashes, sizes, step, time, dt, field list
//   points     numPoints fixed-size records {gid, bond count, first bond, node field values},
//              in the writers' rank order
//   bonds      numBonds records {double bond fields, float bond fields}, each point's bonds
//              contiguous and in its list order (a point's list does not depend on the partition)
//   trailer    32 bytes: magic "PDTCKEND", file length, data checksum, header checksum
#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

#include "deck/RunConfig.hpp"
#include "fields/FieldManager.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

// The scalars of a run's clock: time = origin + step * dt, as in the uninterrupted run.
struct CheckpointClock {
  long long step = 0;
  double time = 0, origin = 0, dt = 0;
};

class Checkpoint {
 public:
  // Collective: computes the mesh checksum (reference positions, volumes, blocks, bond lists).
  Checkpoint(const RestartConfig& config, const Topology& topology, FieldManager& fields);

  const std::string& path() const { return path_; }
  // Collective: whether the checkpoint file exists (rank 0 looks).
  bool exists() const;
  // Collective. Reads the checkpoint into the owned part of its node fields and into its bond
  // fields (allocating them). Throws InputError naming the file and what does not match when the
  // file is truncated, corrupt, or was written by another deck or mesh; nothing is used then.
  CheckpointClock read();
  // Collective. Writes `nodeFields` (owned values) and every bond field that carries history,
  // to a temporary file that replaces the checkpoint once complete (the previous one is kept as
  // <name>.prev). Throws RunError on an I/O failure.
  void write(const CheckpointClock& clock, const std::vector<std::string>& nodeFields);

  int count() const { return count_; }
  double bytesWritten() const { return bytes_; }
  double secondsWriting() const { return seconds_; }
  double lastWriteSeconds() const { return lastSeconds_; }
  double lastBytes() const { return lastBytes_; }
  long long pointRecordBytes() const { return pointRecordBytes_; }
  long long bondRecordBytes() const { return bondRecordBytes_; }

 private:
  std::vector<std::string> historyBondFields(bool floats) const;

  RestartConfig config_;
  const Topology& topology_;
  FieldManager& fields_;
  std::string path_;
  std::uint64_t meshHash_ = 0;
  long long pointRecordBytes_ = 0, bondRecordBytes_ = 0;
  int count_ = 0;
  double bytes_ = 0, seconds_ = 0, lastSeconds_ = 0, lastBytes_ = 0;
};

}  // namespace peridot
