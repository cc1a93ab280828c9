// The implicit solvers' part of a run: set-up checks and the hand-over to the solver, which
// lives in src/solvers (the explicit Verlet loop stays in Simulation.cpp).
#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "solvers/DynamicRelaxation.hpp"
#include "solvers/Implicit.hpp"
#include "solvers/NOXQuasiStatic.hpp"
#include "solvers/QuasiStatic.hpp"

namespace peridot {

void Simulation::checkImplicit() {
  if (config_.restart.enabled) {
    throw InputError(
        config_.restart.path,
        "Restart with the QuasiStatic, NOXQuasiStatic, Implicit and Adaptive Dynamic Relaxation "
        "solvers is not supported yet");
  }
  if (contact_) {
    throw InputError(
        config_.contact.path,
        "contact with the QuasiStatic, NOXQuasiStatic, Implicit and Adaptive Dynamic Relaxation "
        "solvers is not supported (nor by Peridigm)");
  }
  if (config_.solver.loadStepped()) {
    for (const auto& b : blocks_)
      if (b.damage && b.damage->integratesInTime()) {
        throw InputError(
            config_.solver.path,
            "the damage model \"" + b.damageName + "\" of block " + b.name +
                " integrates over time (LSJ-T), which a load-stepped solver "
                "(QuasiStatic, NOXQuasiStatic, Adaptive Dynamic Relaxation) does not have: its "
                "damage would never grow; use Verlet or Implicit");
      }
  }
  // The solver and its tangent are built here, so that a material without a tangent stops the
  // run before any output is written.
  SolverContext context;
  context.comm = comm_;
  context.rank = rank_;
  context.log = &log_;
  context.timers = &timers_;
  context.topology = &topology_;
  context.fields = fields_.get();
  context.blocks = &blocks_;
  context.blockIndexOfPoint = &blockIndexOfPoint_;
  context.evaluator = evaluator_.get();
  context.conditions = conditions_.get();
  context.planar = planar_;
  context.x = x_;
  context.y = y_;
  context.u = u_;
  context.v = v_;
  context.a = a_;
  context.f = f_;
  context.b = b_;
  context.volume = volume_;
  context.density = density_.data();
  context.temperature = temperature_;
  context.temperatureChange = temperatureChange_;
  context.stepOffset = stepOffset_;
  context.probeLength = config_.solver.probeLength;
  context.nonlinearIterations = &nonlinearIterations_;
  context.predictorFromPrevious = stepOffset_ > 0 && config_.solver.predictorFromPrevious;
  if (config_.solver.implicit) {
    implicit_ = std::make_unique<Implicit>(config_.solver.implicitConfig,
                                           config_.solver.initialTime, numSteps_, context);
  } else if (config_.solver.dynamicRelaxation) {
    relaxation_ =
        std::make_unique<DynamicRelaxation>(config_.solver.dynamicRelaxationConfig, context);
  } else if (config_.solver.noxQuasiStatic) {
    noxQuasiStatic_ =
        std::make_unique<NOXQuasiStatic>(config_.solver.noxQuasiStaticConfig, context);
  } else {
    quasiStatic_ = std::make_unique<QuasiStatic>(config_.solver.quasiStaticConfig, context);
  }
}

void Simulation::runImplicit() {
  if (!outputs_) openOutputs();
  if (rank_ == 0 && stepOffset_ == 0) {
    log_ << "Points: " << topology_.globalNumPoints
         << ", bonds (one-sided): " << topology_.globalNumBonds << ", ranks: " << topology_.numRanks
         << "\n";
    if (planar_) log_ << "Planar (2D) run, thickness " << thickness_ << "\n";
    for (const auto& f : outputs_->fileNames()) log_ << "Output: " << f << "\n";
    log_ << std::flush;
  }
  if (implicit_) {
    implicit_->setRunHooks(outputs_.get(), observer_);
    implicit_->run();
    lastStep_ = stepOffset_ + numSteps_;
    time_ = config_.solver.initialTime + static_cast<double>(numSteps_) * dt_;
    return;
  }
  if (relaxation_) {
    relaxation_->setRunHooks(outputs_.get(), observer_);
    relaxation_->run();
  } else if (noxQuasiStatic_) {
    noxQuasiStatic_->setRunHooks(outputs_.get(), observer_);
    noxQuasiStatic_->run();
  } else {
    quasiStatic_->setRunHooks(outputs_.get(), observer_);
    quasiStatic_->run();
    lastStep_ = stepOffset_ + quasiStatic_->acceptedSteps();
    time_ = quasiStatic_->endTime();
    if (quasiStatic_->switchedToVerlet()) switchToVerlet();
    return;
  }
  const auto& times = relaxation_       ? config_.solver.dynamicRelaxationConfig.times
                      : noxQuasiStatic_ ? config_.solver.noxQuasiStaticConfig.times
                                        : config_.solver.quasiStaticConfig.times;
  lastStep_ = stepOffset_ + static_cast<long long>(times.size()) - 1;
  time_ = times.back();
}

void Simulation::switchToVerlet() {
  // Adaptive Load-Stepping -> Switch to Verlet: the rest of the run, from the last converged
  // load step to the final load time, by the explicit solver, as a chained solver would (the
  // step numbers and the output files continue).
  const AdaptiveLoadSteppingConfig a = config_.solver.quasiStaticConfig.adaptive;
  SolverConfig verlet;
  verlet.path = a.verletPath;
  verlet.initialTime = quasiStatic_->switchTime();
  verlet.finalTime = quasiStatic_->finalTime();
  verlet.fixedDtGiven = a.verletFixedDtGiven;
  verlet.fixedDt = a.verletFixedDt;
  verlet.safetyFactor = a.verletSafetyFactor;
  verlet.probeLength = config_.solver.probeLength;
  stepOffset_ = lastStep_;
  config_.solver = verlet;
  time_ = verlet.initialTime;
  switchedToVerlet_ = true;
  switching_ = true;
  prepareSolver();
  switching_ = false;
  conditions_->resume(time_);
  if (a.verletOutputFrequency > 0) outputs_->setFrequency(a.verletOutputFrequency);
  if (rank_ == 0) {
    log_ << a.verletPath << ": from time " << time_ << ", step " << stepOffset_ << ", " << numSteps_
         << " steps of " << dt_ << "\n"
         << std::flush;
  }
  runSolver();
}

}  // namespace peridot
