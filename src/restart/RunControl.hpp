#pragma once
// Per-step decisions of the time loop that must be taken by all ranks together: stop (a signal
// on any rank, or the wall-clock limit near) and checkpoint (cadence in steps or minutes). One
// small MPI_Allreduce per step carries both.
#include <mpi.h>

#include "deck/RunConfig.hpp"

namespace peridot {

class RunControl {
 public:
  RunControl(const RestartConfig& config, MPI_Comm comm);

  struct Decision {
    bool checkpoint = false;  // write a checkpoint now (only with Restart)
    bool stop = false;        // leave the time loop after this step
    int signal = 0;           // the stop signal, 0 when the wall-clock limit stops the run
  };
  // Collective, after every completed step. `lastCheckpointSeconds`: time the last checkpoint
  // took (0 before the first), kept as margin before the wall-clock limit.
  Decision afterStep(long long step, bool lastStep, double lastCheckpointSeconds);
  // A checkpoint was just written (restarts the interval clock).
  void checkpointed();
  // Seconds spent in afterStep's reduction (the cost of checking for signals).
  double secondsChecking() const { return checking_; }

 private:
  RestartConfig config_;
  MPI_Comm comm_;
  int rank_ = 0;
  double lastCheckpointAt_ = 0;  // seconds since start
  double lastStepAt_ = 0, slowestStep_ = 0;
  double checking_ = 0;
};

}  // namespace peridot
