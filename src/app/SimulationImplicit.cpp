// The implicit solvers' part of a run: set-up checks and the hand-over to the solver, which
// lives in src/solvers (the explicit Verlet loop stays in Simulation.cpp).
#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "solvers/QuasiStatic.hpp"

namespace peridot {

void Simulation::checkImplicit() {
  if (config_.restart.enabled) {
    throw InputError(config_.restart.path,
                     "Restart with the QuasiStatic solver is not supported "
                     "yet");
  }
  if (contact_) {
    throw InputError(config_.contact.path,
                     "contact with the QuasiStatic solver is not supported (nor by Peridigm)");
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
  quasiStatic_ = std::make_unique<QuasiStatic>(config_.solver.quasiStaticConfig, context);
}

void Simulation::runQuasiStatic() {
  if (!outputs_) openOutputs();
  if (rank_ == 0) {
    log_ << "Points: " << topology_.globalNumPoints
         << ", bonds (one-sided): " << topology_.globalNumBonds << ", ranks: " << topology_.numRanks
         << "\n";
    if (planar_) log_ << "Planar (2D) run, thickness " << thickness_ << "\n";
    for (const auto& f : outputs_->fileNames()) log_ << "Output: " << f << "\n";
    log_ << std::flush;
  }
  quasiStatic_->setRunHooks(outputs_.get(), observer_);
  quasiStatic_->run();
  const auto& times = config_.solver.quasiStaticConfig.times;
  lastStep_ = static_cast<long long>(times.size()) - 1;
  time_ = times.back();
}

}  // namespace peridot
