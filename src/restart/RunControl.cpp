#include "restart/RunControl.hpp"

#include <algorithm>

#include "app/Signals.hpp"

namespace peridot {

RunControl::RunControl(const RestartConfig& config, MPI_Comm comm) : config_(config), comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  lastCheckpointAt_ = lastStepAt_ = secondsSinceStart();
}

void RunControl::checkpointed() { lastCheckpointAt_ = secondsSinceStart(); }

RunControl::Decision RunControl::afterStep(long long step, bool lastStep,
                                           double lastCheckpointSeconds) {
  enum { kInterval = 1, kWallClock = 2 };
  // Clocks differ between ranks: rank 0's decides, the reduction tells everyone.
  int local[2] = {pendingStopSignal(), 0};
  if (rank_ == 0) {
    const double now = secondsSinceStart();
    slowestStep_ = std::max(slowestStep_, now - lastStepAt_);
    lastStepAt_ = now;
    if (config_.checkpointInterval > 0 &&
        now - lastCheckpointAt_ >= 60 * config_.checkpointInterval)
      local[1] |= kInterval;
    // Stop while a step and a checkpoint (each counted twice) still fit, with 1% to spare.
    const double limit = 60 * config_.wallClockLimit;
    if (limit > 0 && now + 2 * slowestStep_ + 2 * lastCheckpointSeconds + 0.01 * limit >= limit)
      local[1] |= kWallClock;
  }
  int global[2];
  const double before = secondsSinceStart();
  MPI_Allreduce(local, global, 2, MPI_INT, MPI_MAX, comm_);
  checking_ += secondsSinceStart() - before;
  Decision d;
  d.signal = global[0];
  d.stop = !lastStep && (global[0] != 0 || (global[1] & kWallClock));
  if (config_.enabled) {
    d.checkpoint = lastStep || d.stop || (global[1] & kInterval) ||
                   (config_.checkpointFrequency > 0 && step % config_.checkpointFrequency == 0);
  }
  return d;
}

}  // namespace peridot
