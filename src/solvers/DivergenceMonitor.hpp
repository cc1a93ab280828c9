#pragma once
// Stops a run whose explicit time integration has become unstable, long before its values
// overflow. An unstable Verlet step amplifies the highest-frequency mode by a fixed factor
// |lambda| > 1 per step with a change of sign (lambda < -1), so the accelerations it carries
// reverse their direction every step and grow geometrically. The measure is the displacement
// the current force would give a point within one step, against the point's horizon delta_i:
//
//   q_i = dt^2 |a_i| / delta_i,   q = max_i q_i over all ranks.
//
// Two tests, on global quantities that every rank holds after the reductions:
//  * growth: for kRunSteps or more consecutive steps q has increased while the acceleration
//    field reversed (correlation of a^n with a^(n-1) below kReversal), q has grown by kGrowth
//    or more since the run of such steps began, and by sqrt(kGrowth) or more over the last
//    half of the run. Physical loading does not reverse the field each step; a stable mode
//    near the limit only beats, and the rise of a beat from its node (like a power law from
//    rest) slows down, so its last half grows far less than its first, where geometric growth
//    keeps its rate. This catches a diverging run while its displacements are still of the
//    size of the physical ones.
//  * bound: q > 1, the force would carry a point across its whole neighbourhood in one step.
//    No meaningful run comes near it (it takes strains of order one), whatever its cause.
//
// Only free degrees of freedom count: a component whose motion a boundary condition prescribes
// is left out (its acceleration is the reaction to the user's motion, not the integration's;
// a fully prescribed run is never stopped, however large the prescribed deformation).
//
// It only reads the accelerations: no result changes. Each step costs one pass over the owned
// accelerations (check: also a copy of them; a caller whose own pass over the points still holds
// the previous check's accelerations gives them to accumulate() instead, without the copy), and
// two small MPI_Allreduce calls.
#include <mpi.h>

#include <deque>
#include <functional>
#include <string>
#include <vector>

namespace peridot {

class DivergenceMonitor {
 public:
  // Owned points only. `horizon` per owned point; `describe(i)` names owned point i in messages
  // (e.g. "point 17 (block block_1)"). `dt` and `stableDt`: the run's time step and estimate.
  // `prescribed`: 3 per owned point, non-zero where the component's motion is prescribed (left
  // out of the check); null when none is.
  DivergenceMonitor(int numOwned, const double* horizon, std::function<std::string(int)> describe,
                    double dt, double stableDt, MPI_Comm comm, const double* prescribed = nullptr);

  // Collective, after the accelerations of `step` are computed (steps in increasing order).
  // Throws RunError on every rank (marked collective) when the run diverges.
  void check(long long step, double time, const double* acceleration);

  // A check in two parts, for a caller that passes over the points anyway (solvers/VerletStep):
  // accumulate() over the owned points in increasing blocks, then conclude() (collective).
  // The sums' order of additions is the vector lanes' (they only decide threshold tests, and are
  // summed over the ranks anyway); the largest q_i and its point are found exactly.
  struct LocalSums {
    double worst = 0;  // the largest q_i^2 so far, at point `where` (-1: none > 0)
    int where = -1;
    double dot = 0, norm2 = 0, previousNorm2 = 0;  // a.a_prev, |a|^2, |a_prev|^2
  };
  // Points [begin, begin + count), at most kBlock: `a` and `previous` (this check's and the
  // last check's accelerations, all components, prescribed ones included) start at the block's
  // first point.
  static constexpr int kBlock = 256;
  void accumulate(int begin, int count, const double* a, const double* previous,
                  LocalSums& sums) const;
  void conclude(long long step, double time, const LocalSums& sums);

  // The q of the last check, over all ranks (for tests and measurements).
  double lastMaximum() const { return history_.empty() ? 0.0 : history_.back().q; }
  // Consecutive steps of growth with reversal up to the last check, and the growth of q over
  // them (1 when there are none).
  int runLength() const { return run_; }
  double runGrowth() const {
    return history_.empty() || !(history_.front().q > 0) ? 1.0
                                                         : history_.back().q / history_.front().q;
  }

  static constexpr double kBound = 1.0;
  static constexpr double kGrowth = 100.0;
  static constexpr int kRunSteps = 10;
  static constexpr double kReversal = -0.5;

 private:
  struct Record {
    long long step = 0;
    double q = 0;
    int owner = 0;        // rank holding the largest q_i at this step
    int localPoint = -1;  // its local index, valid on the owner only
  };
  std::string shareDescription(const Record& r) const;
  [[noreturn]] void fail(double time) const;

  int numOwned_;
  const double* horizon_;
  std::function<std::string(int)> describe_;
  double dt_, stableDt_;
  MPI_Comm comm_;
  int rank_ = 0;
  // 3 per owned point: 1 for a free component, 0 if prescribed; empty when none is prescribed.
  std::vector<double> free_;
  std::vector<double> previous_;  // check(): a of the previous check, owned points
  bool havePrevious_ = false;
  int run_ = 0;                 // consecutive steps of growth with reversal
  std::deque<Record> history_;  // oldest first, back to the start of the current run
};

}  // namespace peridot
