#include "solvers/DivergenceMonitor.hpp"

#include <algorithm>
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
      comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  const std::size_t n3 = 3 * static_cast<std::size_t>(numOwned);
  bool any = false;
  for (std::size_t k = 0; prescribed && k < n3 && !any; ++k) any = prescribed[k] != 0.0;
  if (any) {
    free_.resize(n3);
    for (std::size_t k = 0; k < n3; ++k) free_[k] = prescribed[k] != 0.0 ? 0.0 : 1.0;
  }
}

namespace {

// Per point of a block: the sums' terms, and q_i^2 (squared: no square root per point) into
// `q2`. A prescribed component counts as at rest: free = 0 multiplies it (no branch); without
// prescribed components (kMasked false) there is no multiplication by 1.
template <bool kMasked>
void blockTerms(int count, const double* a, const double* previous, const double* free,
                const double* horizon, double dt4, double* q2, DivergenceMonitor::LocalSums& s) {
  double dot = 0, norm2 = 0, previousNorm2 = 0;
#pragma omp simd reduction(+ : dot, norm2, previousNorm2)
  for (int i = 0; i < count; ++i) {
    double a2 = 0;
    for (int d = 0; d < 3; ++d) {
      const double ak = kMasked ? free[3 * i + d] * a[3 * i + d] : a[3 * i + d];
      const double pk = kMasked ? free[3 * i + d] * previous[3 * i + d] : previous[3 * i + d];
      a2 += ak * ak;
      dot += ak * pk;
      previousNorm2 += pk * pk;
    }
    norm2 += a2;
    q2[i] = dt4 * a2 / (horizon[i] * horizon[i]);
  }
  s.dot += dot;
  s.norm2 += norm2;
  s.previousNorm2 += previousNorm2;
}

}  // namespace

void DivergenceMonitor::accumulate(int begin, int count, const double* a, const double* previous,
                                   LocalSums& sums) const {
  double q2[kBlock];
  const double dt4 = dt_ * dt_ * dt_ * dt_;
  if (free_.empty())
    blockTerms<false>(count, a, previous, nullptr, horizon_ + begin, dt4, q2, sums);
  else
    blockTerms<true>(count, a, previous, free_.data() + 3 * static_cast<std::size_t>(begin),
                     horizon_ + begin, dt4, q2, sums);
  // The first largest in point order, as one serial pass would find it (NaN never wins).
  for (int i = 0; i < count; ++i)
    if (q2[i] > sums.worst) {
      sums.worst = q2[i];
      sums.where = begin + i;
    }
}

void DivergenceMonitor::check(long long step, double time, const double* a) {
  const std::size_t n3 = 3 * static_cast<std::size_t>(numOwned_);
  if (previous_.size() != n3) previous_.assign(n3, 0.0);
  LocalSums sums;
  for (int begin = 0; begin < numOwned_; begin += kBlock) {
    const std::size_t at = 3 * static_cast<std::size_t>(begin);
    accumulate(begin, std::min(kBlock, numOwned_ - begin), a + at, previous_.data() + at, sums);
  }
  std::copy(a, a + n3, previous_.begin());
  conclude(step, time, sums);
}

void DivergenceMonitor::conclude(long long step, double time, const LocalSums& local) {
  struct {
    double q;
    int rank;
  } mine{std::sqrt(local.worst), rank_}, global{0, 0};
  MPI_Allreduce(&mine, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm_);
  double sums[3] = {local.dot, local.norm2, local.previousNorm2};
  MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_DOUBLE, MPI_SUM, comm_);

  Record r;
  r.step = step;
  r.q = global.q;
  r.owner = global.rank;
  r.localPoint = global.rank == rank_ ? local.where : -1;
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
