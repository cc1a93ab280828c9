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
  // The probes are trial evaluations (no history moves), at dt = 0: a rate model's stress
  // does not respond to them.
  for (const auto& b : blocks_)
    if (b.material->needsVelocity()) {
      throw InputError(config_.solver.path + " -> Verlet -> Stable Time Step Estimate",
                       "\"Verlet Limit\" probes the stiffness with extra force evaluations at "
                       "fixed velocities, to which the rate form of block " +
                           b.name +
                           "'s material does not respond; use the default estimate "
                           "(\"Peridigm\") or \"Stress Integration\": \"Total Lagrangian "
                           "Green Strain\"");
    }

  // About the reference configuration (solvers/VerletLimit.hpp).
  const VerletLimitResult r = estimateVerletLimitAbout(topology_, *evaluator_, x_, y_, f_,
                                                       density_.data(), volume_, planar_ ? 2 : 3);
  verletLimitIterations_ = r.iterations;
  if (r.stableStep > 0) stableDt_ = r.stableStep;
}

}  // namespace peridot
