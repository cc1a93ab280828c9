// Simulation's restart pieces: continuing from a checkpoint and writing one. Kept apart from
// Simulation.cpp, which holds the set-up and the time loop.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"

namespace peridot {

namespace {

// Positions of the last contact search: the contact lists are a function of them, so a
// continued run rebuilds the same lists from them.
const char* const kContactSearchPositions = "Contact_Search_Coordinates";

}  // namespace

void Simulation::searchContact() {
  contact_->search(y_);
  double* saved = fields_->node(kContactSearchPositions, 3);
  for (int k = 0; k < 3 * topology_.numOwned; ++k) saved[k] = y_[k];
}

void Simulation::resume() {
  const auto& s = config_.solver;
  const auto started = std::chrono::steady_clock::now();
  const CheckpointClock clock = checkpoint_->read();
  evaluator_->bondDamageRewritten();  // the checkpoint's bond damage, also into the half list
  const double readSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const std::string where = "checkpoint " + checkpoint_->path();
  if (clock.dt != dt_) {
    throw InputError(where + " was written with time step " + formatNumber(clock.dt) +
                     ", this run's is " + formatNumber(dt_));
  }
  // A continuation deck starts where the previous run ended (its Initial Time is that run's
  // Final Time, which the last step may fall short of by less than a step); a rerun of the
  // same deck (after a signal or a batch time limit) has its checkpoint inside its time span.
  if (clock.time < s.initialTime - dt_ * (1 + 1e-9)) {
    throw InputError(where + " is at time " + formatNumber(clock.time) +
                     ", more than one step before this deck's Initial Time (" +
                     formatNumber(s.initialTime) + "): it belongs to an earlier part of the run");
  }
  origin_ = clock.origin;
  numSteps_ = static_cast<long long>(std::floor((s.finalTime - origin_) / dt_));
  firstStep_ = clock.step + 1;
  lastStep_ = clock.step;
  time_ = clock.time;
  resumed_ = true;
  conditions_->resume(time_);
  // Temperatures are functions of the time alone (no conduction): set, not saved.
  if (conditions_->hasTemperature())
    conditions_->applyPrescribedTemperature(time_, temperature_, temperatureChange_);
  for (auto& b : blocks_)
    if (b.damage) b.damage->resume();
  if (contact_) {
    // y of the last search, then the lists as they were; y itself is recomputed each step.
    const double* saved = fields_->node(kContactSearchPositions, 3);
    contact_->search(saved);
  }
  if (rank_ == 0) {
    log_ << "Restart: continuing from " << where << " at step " << clock.step << ", time "
         << formatNumber(clock.time) << " (read in " << readSeconds << " s)\n";
    if (firstStep_ > numSteps_)
      log_ << "Restart: the checkpoint is at or past the Final Time; nothing to do\n";
  }
}

void Simulation::writeCheckpoint(long long step) {
  Timers::Scope t(timers_, "Checkpoint");
  // Coordinates too: y = (x + u) + dt v is not x + u to the bit, and the contact search at the
  // first continued step (when it is a search step) reads y of the checkpoint's step.
  std::vector<std::string> nodeFields = {"Displacement", "Velocity", "Acceleration", "Coordinates"};
  if (contact_) nodeFields.push_back(kContactSearchPositions);
  for (const auto& b : blocks_) {  // the models' per-point history (plastic multiplier, ...)
    std::vector<std::string> history = b.material->historyNodeFields();
    if (b.damage)  // and the damage models' (the Johnson-Cook damage parameter)
      for (const auto& f : b.damage->historyNodeFields()) history.push_back(f);
    for (const auto& f : history)
      if (std::find(nodeFields.begin(), nodeFields.end(), f) == nodeFields.end())
        nodeFields.push_back(f);
  }
  CheckpointClock clock;
  clock.step = step;
  clock.time = time_;
  clock.origin = origin_;
  clock.dt = dt_;
  checkpoint_->write(clock, nodeFields);
  control_->checkpointed();
  if (rank_ == 0) {
    char text[160];
    std::snprintf(text, sizeof text, "  checkpoint at step %lld (%.1f MB, %.3f s)", step,
                  checkpoint_->lastBytes() / 1e6, checkpoint_->lastWriteSeconds());
    log_ << text << std::endl;
  }
}

void Simulation::reportCheckpoints(std::ostream& out) {
  double checking = control_->secondsChecking(), maxChecking = 0;
  MPI_Allreduce(&checking, &maxChecking, 1, MPI_DOUBLE, MPI_MAX, comm_);
  if (rank_ != 0 || !checkpoint_) return;
  char text[400];
  const double bytes = checkpoint_->lastBytes();
  std::snprintf(text, sizeof text,
                "Checkpoints: %d written, %.1f MB in all, %.3f s writing; last %.0f bytes "
                "(%lld bytes per point + %lld per bond); per-step stop checks (MPI_Allreduce, "
                "including waits for the slowest rank) %.4f s\n",
                checkpoint_->count(), checkpoint_->bytesWritten() / 1e6,
                checkpoint_->secondsWriting(), bytes, checkpoint_->pointRecordBytes(),
                checkpoint_->bondRecordBytes(), maxChecking);
  out << text;
}

}  // namespace peridot
