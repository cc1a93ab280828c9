// Simulation's time step: Peridigm's stable estimate from the materials' bond-stiffness sums
// and, on request, the true limit of velocity Verlet for the linearized problem; the step and
// its count, and the explicit integrator with its divergence check (prepareSolver).
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"
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

void Simulation::prepareSolver() {
  {
    Timers::Scope t(timers_, "Setup: time step estimate");
    estimateStableTimeStep();
  }
  const auto& s = config_.solver;
  if (!s.fixedDtGiven && !(stableDt_ < std::numeric_limits<double>::max())) {
    // The estimate sums bond stiffnesses; contact springs depend on where bodies meet and are
    // not in it (nor in Peridigm's), so a run without bonds has no estimate.
    throw InputError(s.path + " -> Verlet -> Fixed dt",
                     "required: no point has a bond (the horizon is smaller than the spacing, all "
                     "interaction is through contact), so there is no stable time step estimate");
  }
  dt_ = s.fixedDtGiven ? s.fixedDt : s.safetyFactor * stableDt_;
  const double ratio = (s.finalTime - s.initialTime) / dt_;
  if (!(ratio < 1e15)) {  // also NaN; a long long would not hold the count
    throw InputError(s.path + " -> Final Time",
                     "the run would take " + formatNumber(ratio) + " steps of dt = " +
                         formatNumber(dt_) + " (the stable time step estimate is " +
                         formatNumber(stableDt_) + "); check the moduli, density and Fixed dt");
  }
  numSteps_ = static_cast<long long>(std::floor(ratio));  // as Peridigm counts them
  if (!s.explicitVerlet()) checkImplicit();
  // (A switch from QuasiStatic close to the final time may leave less than one step: none.)
  if (numSteps_ < 1 && !s.loadStepped() && !switching_) {
    throw InputError(s.path + " -> Final Time",
                     "the run is shorter than one time step (dt = " + formatNumber(dt_) + ")");
  }
  origin_ = s.initialTime;
  // The motion of prescribed components is the user's, not the integration's: not checked.
  std::vector<double> prescribed(3 * static_cast<std::size_t>(topology_.numOwned), 0.0);
  conditions_->markPrescribed(prescribed.data());
  freeComponents_ = countFreeComponents(prescribed);
  divergence_ = std::make_unique<DivergenceMonitor>(
      topology_.numOwned, fields_->node("Horizon", 1),
      [this](int i) {
        return "point " + std::to_string(topology_.overlapGlobalId[i] + 1) + " (block " +
               blocks_[blockIndexOfPoint_[i]].name + ")";
      },
      dt_, stableDt_, comm_, prescribed.data());
  VerletArrays arrays;
  arrays.numOwned = topology_.numOwned;
  arrays.x = x_, arrays.u = u_, arrays.v = v_, arrays.y = y_, arrays.a = a_;
  arrays.force = f_, arrays.contactForce = fc_, arrays.bodyForce = b_;
  arrays.density = density_.data();
  arrays.planar = planar_;
  verlet_ = std::make_unique<VerletStep>(arrays, dt_, prescribed.data());
}

long long Simulation::countFreeComponents(const std::vector<double>& prescribed) const {
  const int dims = planar_ ? 2 : 3;
  long long free = 0;
  for (int i = 0; i < topology_.numOwned; ++i)
    for (int d = 0; d < dims; ++d) free += prescribed[3 * i + d] == 0.0 ? 1 : 0;
  long long total = 0;
  MPI_Allreduce(&free, &total, 1, MPI_LONG_LONG, MPI_SUM, comm_);
  return total;
}

}  // namespace peridot
