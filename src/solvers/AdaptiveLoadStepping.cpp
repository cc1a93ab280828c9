#include "solvers/AdaptiveLoadStepping.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace peridot {

AdaptiveLoadSteppingConfig readAdaptiveLoadStepping(ListReader& list) {
  AdaptiveLoadSteppingConfig c;
  c.enabled = true;
  c.path = list.path();
  // Both limits are required, as in Peridigm (which reads them without a default).
  const long long inOne = list.integer("Maximum load step reductions in one step");
  const long long total = list.integer("Maximum total load step reductions");
  if (inOne < 0 || inOne > 60) {
    throw InputError(list.pathOf("Maximum load step reductions in one step"),
                     "must be between 0 and 60 (each reduction halves the step)");
  }
  if (total < inOne || total > 1000000000LL) {
    throw InputError(list.pathOf("Maximum total load step reductions"),
                     "cannot be smaller than Maximum load step reductions in one step (" +
                         std::to_string(inOne) + ") and must be at most 1e9");
  }
  c.maxReductionsInOneStep = static_cast<int>(inOne);
  c.maxTotalReductions = static_cast<int>(total);
  c.reduceAllRemaining = list.boolean("Reduce all remaining load steps", false);
  c.adaptiveOutputFrequency = list.boolean("Adaptive output frequency", false);
  if (list.has("Switch to Verlet")) {
    if (!list.isSublist("Switch to Verlet")) {
      throw InputError(list.pathOf("Switch to Verlet"),
                       "must be a list (Fixed dt or Safety Factor, Output Frequency)");
    }
    ListReader verlet = list.sublist("Switch to Verlet");
    c.switchToVerlet = true;
    c.verletPath = verlet.path();
    if (verlet.has("Fixed dt")) {
      c.verletFixedDtGiven = true;
      c.verletFixedDt = verlet.positiveNumber("Fixed dt");
      // Peridigm ignores the safety factor when a fixed dt is given.
      if (verlet.has("Safety Factor")) verlet.positiveNumber("Safety Factor");
    } else {
      c.verletSafetyFactor = verlet.positiveNumber("Safety Factor", 1.0);
    }
    if (verlet.has("Output Frequency")) {
      c.verletOutputFrequency = verlet.integer("Output Frequency");
      if (c.verletOutputFrequency < 1)
        throw InputError(verlet.pathOf("Output Frequency"), "must be at least 1");
    }
    verlet.finish();
  }
  list.finish();
  return c;
}

LoadSchedule::LoadSchedule(std::vector<double> times, const AdaptiveLoadSteppingConfig& config)
    : times_(std::move(times)), config_(config) {}

bool LoadSchedule::cut() {
  if (reductionsThisStep_ + 1 > config_.maxReductionsInOneStep ||
      totalReductions_ + 1 > config_.maxTotalReductions)
    return false;
  ++reductionsThisStep_;
  ++totalReductions_;
  const double middle = start() + 0.5 * (end() - start());
  times_.insert(times_.begin() + static_cast<std::ptrdiff_t>(next_), middle);
  return true;
}

void LoadSchedule::accept() {
  const bool wasCut = reductionsThisStep_ > 0;
  reductionsThisStep_ = 0;
  ++next_;
  if (!wasCut || !config_.reduceAllRemaining || done()) return;
  // The remaining steps all take the length of the step just converged; the last ends at the
  // final time (Peridigm would step past it when the length does not divide the rest).
  const double now = times_[next_ - 1], length = now - times_[next_ - 2];
  const double finalTime = times_.back();
  const double ratio = (finalTime - now) / length;
  long long count = std::llround(ratio);
  if (std::fabs(ratio - static_cast<double>(count)) > 1e-9 * std::max(1.0, ratio))
    count = static_cast<long long>(std::ceil(ratio));
  if (count < 1) count = 1;
  times_.resize(next_);
  for (long long k = 1; k < count; ++k) times_.push_back(now + static_cast<double>(k) * length);
  times_.push_back(finalTime);
}

}  // namespace peridot
