// The implicit solvers' part of a run: set-up checks and the hand-over to the solver, which
// lives in src/solvers (the explicit Verlet loop stays in Simulation.cpp).
#include <chrono>
#include <functional>
#include <memory>
#include <ostream>

#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"
#include "restart/RunControl.hpp"
#include "solvers/DynamicRelaxation.hpp"
#include "solvers/Implicit.hpp"
#include "solvers/NOXQuasiStatic.hpp"
#include "solvers/QuasiStatic.hpp"

namespace peridot {

namespace {

// Thrown by the per-step hook on every rank alike (the decision is collective) to leave an
// implicit solver's step loop after a completed step; caught in runImplicit.
struct StopAfterStep {
  int signal;
};

}  // namespace

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
  // After every completed step (the solvers call this once its outputs are written): the
  // caller's observer, a stop signal on any rank (RunControl, collective: the implicit solvers
  // write no checkpoint, so the run ends there with the records written so far, as a Verlet run
  // without Restart), and for Implicit, whose steps print nothing unless Verbose, a progress
  // line every 5 s.
  // (The solver keeps a copy of the hook: it captures nothing of this frame by reference.)
  const auto start = std::chrono::steady_clock::now();
  auto lastReport = std::make_shared<std::chrono::steady_clock::time_point>(start);
  const long long firstRecord = stepOffset_;
  std::function<void(long long, double)> afterStep = [this, start, lastReport, firstRecord](
                                                         long long record, double t) {
    if (observer_) observer_(record, t);
    lastStep_ = record;
    time_ = t;
    const RunControl::Decision decision = control_->afterStep(record, false, 0.0);
    if (decision.stop) throw StopAfterStep{decision.signal};
    if (!implicit_ || rank_ != 0 || record == firstRecord) return;
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - *lastReport).count() <= 5.0) return;
    *lastReport = now;
    const double elapsed = std::chrono::duration<double>(now - start).count();
    const long long done = record - firstRecord, last = firstRecord + numSteps_;
    log_ << progressLine(record, last, t, elapsed,
                         elapsed / static_cast<double>(done) * static_cast<double>(last - record))
         << std::endl;
  };
  try {
    if (implicit_) {
      implicit_->setRunHooks(outputs_.get(), afterStep);
      implicit_->run();
      lastStep_ = stepOffset_ + numSteps_;
      time_ = config_.solver.initialTime + static_cast<double>(numSteps_) * dt_;
      return;
    }
    if (relaxation_) {
      relaxation_->setRunHooks(outputs_.get(), afterStep);
      relaxation_->run();
    } else if (noxQuasiStatic_) {
      noxQuasiStatic_->setRunHooks(outputs_.get(), afterStep);
      noxQuasiStatic_->run();
    } else {
      quasiStatic_->setRunHooks(outputs_.get(), afterStep);
      quasiStatic_->run();
      lastStep_ = stepOffset_ + quasiStatic_->acceptedSteps();
      time_ = quasiStatic_->endTime();
      if (quasiStatic_->switchedToVerlet()) switchToVerlet();
      return;
    }
  } catch (const StopAfterStep& stop) {
    stopped_ = true;
    stoppedInImplicitSolver_ = true;
    stopSignal_ = stop.signal;
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
