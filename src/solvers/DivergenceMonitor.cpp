#include "solvers/DivergenceMonitor.hpp"

#include <cmath>
#include <cstdio>

#include "core/Error.hpp"
#include "core/Format.hpp"

namespace peridot {

DivergenceMonitor::DivergenceMonitor(int numOwned, const double* horizon,
                                     std::function<std::string(int)> describe, double dt,
                                     double stableDt, MPI_Comm comm, const double* prescribed)
    : numOwned_(numOwned),
      horizon_(horizon),
      describe_(std::move(describe)),
      dt_(dt),
      stableDt_(stableDt),
      comm_(comm),
      free_(3 * static_cast<std::size_t>(numOwned), 1.0),
      previous_(3 * static_cast<std::size_t>(numOwned), 0.0) {
  MPI_Comm_rank(comm_, &rank_);
  if (prescribed)
    for (std::size_t k = 0; k < free_.size(); ++k) free_[k] = prescribed[k] != 0.0 ? 0.0 : 1.0;
}

void DivergenceMonitor::check(long long step, double time, const double* a) {
  // Squared q_i (no square root per point); sums for the correlation of a with the previous a.
  double worst = 0, sums[3] = {0, 0, 0};  // a.a_prev, |a|^2, |a_prev|^2
  int where = -1;
  const double dt4 = dt_ * dt_ * dt_ * dt_;
  for (int i = 0; i < numOwned_; ++i) {
    double a2 = 0;
    for (int d = 0; d < 3; ++d) {
      // A prescribed component counts as at rest (a multiplication, no branch).
      const double ak = free_[3 * i + d] * a[3 * i + d], pk = previous_[3 * i + d];
      a2 += ak * ak;
      sums[0] += ak * pk;
      sums[2] += pk * pk;
      previous_[3 * i + d] = ak;
    }
    sums[1] += a2;
    const double q2 = dt4 * a2 / (horizon_[i] * horizon_[i]);
    if (q2 > worst) {
      worst = q2;
      where = i;
    }
  }
  struct {
    double q;
    int rank;
  } local{std::sqrt(worst), rank_}, global{0, 0};
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm_);
  MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_DOUBLE, MPI_SUM, comm_);

  Record r;
  r.step = step;
  r.q = global.q;
  r.owner = global.rank;
  r.localPoint = global.rank == rank_ ? where : -1;
  const bool reversed = havePrevious_ && sums[1] > 0 && sums[2] > 0 &&
                        sums[0] < kReversal * std::sqrt(sums[1] * sums[2]);
  const bool growing = !history_.empty() && r.q > history_.back().q;
  havePrevious_ = true;
  if (reversed && growing) {
    ++run_;
  } else {
    run_ = 0;
    history_.clear();  // only the current run (and the step it starts from) is kept
  }
  history_.push_back(r);
  // Growth from a node of a beat, or a power law from rest, slows down (its last half grows
  // far less than its first); a geometric one does not: require both halves' growth.
  const double lastHalf = r.q / history_[history_.size() - 1 - run_ / 2].q;
  const bool geometric =
      run_ >= kRunSteps && runGrowth() >= kGrowth && lastHalf >= std::sqrt(kGrowth);
  if (r.q > kBound || geometric) fail(time);
}

std::string DivergenceMonitor::shareDescription(const Record& r) const {
  std::string text = r.owner == rank_ && r.localPoint >= 0 ? describe_(r.localPoint) : "";
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, r.owner, comm_);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, r.owner, comm_);
  return text;
}

void DivergenceMonitor::fail(double time) const {
  const Record& last = history_.back();
  const Record& first = history_.front();
  const std::string here = shareDescription(last);
  const std::string origin = shareDescription(first);
  char text[200];
  std::snprintf(text, sizeof text, "%.6g", time);
  std::string msg = "the run diverged at step " + std::to_string(last.step) + ", time " + text +
                    ": the force on " + here;
  std::snprintf(text, sizeof text, " would move it %.3g horizons in one step", last.q);
  msg += text;
  if (last.step > first.step && first.q > 0) {
    const double rate =
        std::pow(last.q / first.q, 1.0 / static_cast<double>(last.step - first.step));
    std::snprintf(text, sizeof text,
                  ", x%.3g since step %lld (x%.3g per step, reversing its direction each step), "
                  "when the largest was on ",
                  last.q / first.q, first.step, rate);
    msg += text + origin;
  }
  std::snprintf(text, sizeof text, ". The time step %.6g is %.3g x the stable estimate %.6g", dt_,
                dt_ / stableDt_, stableDt_);
  msg += text;
  if (dt_ > stableDt_) {
    msg += ": use a smaller Fixed dt (or Safety Factor instead)";
  } else {
    // Below the estimate, either the scene is wrong or the estimate does not bound it: Peridigm's
    // takes the spring constant of a full neighbourhood, which a state-based model exceeds
    // where neighbourhoods are cut short (a horizon comparable to the body).
    msg +=
        ": look for a model parameter, condition or contact stiffness out of range, or a "
        "horizon comparable to the body (Peridigm's estimate assumes full neighbourhoods; "
        "Stable Time Step Estimate \"Verlet Limit\" measures the limit)";
  }
  msg += ". The output files hold the records written before this step";
  throw RunError(msg).markCollective();
}

}  // namespace peridot
