#pragma once
// Peridigm's `QuasiStatic -> Adaptive Load-Stepping`: a load step whose Newton iterations end
// above 100x the convergence criterion (or whose linear solve fails) is cut in half and tried
// again from the last converged state; after `Maximum load step reductions in one step` cuts of
// one step, or `Maximum total load step reductions` cuts in the run, the run stops, or with
// `Switch to Verlet` continues explicitly from the last converged state. This file holds the
// keys and the schedule of load steps (pure bookkeeping, the same on every rank); QuasiStatic
// solves the steps and restores the state of a cut one.
#include <string>
#include <vector>

#include "deck/Deck.hpp"

namespace peridot {

struct AdaptiveLoadSteppingConfig {
  bool enabled = false;  // the Adaptive Load-Stepping list is present
  std::string path;
  int maxReductionsInOneStep = 0;   // Maximum load step reductions in one step
  int maxTotalReductions = 0;       // Maximum total load step reductions
  bool reduceAllRemaining = false;  // Reduce all remaining load steps
  bool adaptiveOutputFrequency = false;
  // Switch to Verlet: when the reductions are exhausted, Verlet runs from the last converged
  // time to the final load time with Fixed dt, or Safety Factor x the stable estimate (1.0 as
  // Peridigm's code), and the outputs' frequency becomes Output Frequency (0: unchanged).
  bool switchToVerlet = false;
  std::string verletPath;
  bool verletFixedDtGiven = false;
  double verletFixedDt = 0.0, verletSafetyFactor = 1.0;
  long long verletOutputFrequency = 0;
};

// Reads `Adaptive Load-Stepping` (with its optional `Switch to Verlet`) from `list`.
AdaptiveLoadSteppingConfig readAdaptiveLoadStepping(ListReader& list);

// The load steps still to take. Step k runs from start() to end(); a converged step is
// accept()ed, a failed one cut(). Peridigm's rule: a cut inserts the midpoint of the step, so
// the step is retried over half its length and the rest of it becomes the next step; with
// Reduce all remaining load steps, once a cut step has converged every later step takes the
// length of that last converged step (the final one ending at the final time).
class LoadSchedule {
 public:
  LoadSchedule(std::vector<double> times, const AdaptiveLoadSteppingConfig& config);
  bool done() const { return next_ >= times_.size(); }
  double start() const { return times_[next_ - 1]; }
  double end() const { return times_[next_]; }
  double finalTime() const { return times_.back(); }
  // A failed attempt of the current step. Returns false when the cut would exceed a limit
  // (the schedule is then unchanged); else the step is halved.
  bool cut();
  void accept();
  int reductionsThisStep() const { return reductionsThisStep_; }
  int totalReductions() const { return totalReductions_; }
  // Steps accepted so far.
  long long accepted() const { return static_cast<long long>(next_) - 1; }

 private:
  std::vector<double> times_;  // times_[0] the initial time; steps end at times_[1..]
  std::size_t next_ = 1;       // the current step ends at times_[next_]
  AdaptiveLoadSteppingConfig config_;
  int reductionsThisStep_ = 0, totalReductions_ = 0;
};

}  // namespace peridot
