// Simulation's stable time step: Peridigm's estimate from the materials' bond-stiffness sums
// and, on request, the true limit of velocity Verlet for the linearized problem.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "solvers/StableTimeStep.hpp"
#include "solvers/VerletLimit.hpp"

namespace peridot {

void Simulation::estimateStableTimeStep() {
  {
    std::vector<double> stiffness(topology_.numOverlap, 0.0);
    for (const auto& b : blocks_)
      b.material->stiffnessSum(evaluator_->state(), b.points, stiffness.data());
    peridigmDt_ = stableTimeStep(topology_, density_.data(), stiffness.data());
    if (!(peridigmDt_ > 0)) explainZeroTimeStep(stiffness.data());
  }
  stableDt_ = peridigmDt_;
  if (!config_.solver.verletLimitEstimate) return;
  for (const auto& b : blocks_)
    if (b.material->advancesHistory()) {
      throw InputError(config_.solver.path + " -> Verlet -> Stable Time Step Estimate",
                       "\"Verlet Limit\" probes the stiffness with extra force evaluations, "
                       "which would advance the history of block " +
                           b.name + "'s material; use the default estimate (\"Peridigm\")");
    }

  // K v by central differences of the internal force about the reference configuration, no
  // bond breaking: the probe displacement is 1e-6 of the smallest horizon at its largest
  // component, where the models are linear to round-off and no critical stretch is reached.
  const int n3 = 3 * topology_.numOwned;
  double smallestHorizon = topology_.numOwned > 0 ? topology_.horizon[0] : 1e300;
  for (int i = 0; i < topology_.numOwned; ++i)
    smallestHorizon = std::min(smallestHorizon, topology_.horizon[i]);
  MPI_Allreduce(MPI_IN_PLACE, &smallestHorizon, 1, MPI_DOUBLE, MPI_MIN, comm_);
  const std::vector<double> savedY(y_, y_ + 3 * topology_.numOverlap);
  const std::vector<double> savedF(f_, f_ + n3);
  std::vector<double> plus(n3);
  auto applyStiffness = [&](const double* v, double* kv) {
    double largest = 0;
    for (int k = 0; k < n3; ++k) largest = std::max(largest, std::fabs(v[k]));
    MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, comm_);
    const double eps = largest > 0 ? 1e-6 * smallestHorizon / largest : 0.0;
    for (int k = 0; k < n3; ++k) y_[k] = x_[k] + eps * v[k];
    evaluator_->evaluate(0.0, false);
    std::copy(f_, f_ + n3, plus.begin());
    for (int k = 0; k < n3; ++k) y_[k] = x_[k] - eps * v[k];
    evaluator_->evaluate(0.0, false);
    for (int k = 0; k < n3; ++k) kv[k] = eps > 0 ? -(plus[k] - f_[k]) / (2.0 * eps) : 0.0;
  };
  const VerletLimitResult r =
      estimateVerletLimit(topology_, density_.data(), volume_, planar_ ? 2 : 3, applyStiffness);
  std::copy(savedY.begin(), savedY.end(), y_);
  std::copy(savedF.begin(), savedF.end(), f_);
  verletLimitIterations_ = r.iterations;
  if (r.stableStep > 0) stableDt_ = r.stableStep;
}

}  // namespace peridot
