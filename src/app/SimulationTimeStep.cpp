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

  // About the reference configuration (solvers/VerletLimit.hpp).
  const VerletLimitResult r = estimateVerletLimitAbout(topology_, *evaluator_, x_, y_, f_,
                                                       density_.data(), volume_, planar_ ? 2 : 3);
  verletLimitIterations_ = r.iterations;
  if (r.stableStep > 0) stableDt_ = r.stableStep;
}

}  // namespace peridot
