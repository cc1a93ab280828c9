#include "solvers/QuasiStatic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"
#include "solvers/AdaptiveLoadStepping.hpp"
#include "solvers/LinearSolve.hpp"

namespace peridot {

namespace {

// Peridigm's schedule: plain Newton for 8 iterations, then damped Newton with the tangent
// re-assembled every 8 iterations.
const int kPureNewtonIterations = 8;
const int kDampedTangentInterval = 8;

}  // namespace

QuasiStatic::QuasiStatic(const QuasiStaticConfig& config, SolverContext context)
    : config_(config), c_(std::move(context)), problem_(c_, "QuasiStatic") {
  tangent_ = std::make_unique<Tangent>(*c_.topology, *c_.blocks, config_.path, c_.probe());
  if (tangent_->finiteDifference() && c_.rank == 0) {
    *c_.log << "QuasiStatic: finite-difference tangent, " << tangent_->colours()
            << " colours, probe length " << tangent_->probeLength() << "\n";
  }
  const int n3 = 3 * c_.topology->numOwned;
  endTime_ = config_.times.front();
  increment_.assign(n3, 0.0);
  start_.assign(n3, 0.0);
}

int QuasiStatic::solveLinear(bool precondition) {
  LinearSolverSettings settings;
  settings.solver = config_.linearSolver;
  settings.maxIterations = config_.linearMaxIterations;
  settings.tolerance = config_.linearTolerance;
  settings.printStatus = config_.printLinearStatus;
  settings.preconditioner = config_.preconditioner;
  return solveTangentSystem(tangent_->matrix(), problem_.residual(), problem_.held(), settings,
                            precondition, increment_, stats_.linearIterations);
}

double QuasiStatic::lineSearch(double residualNorm) {
  // The full Newton step when it lowers the residual (always, near the solution); otherwise the
  // best of a few shorter steps (Peridigm's candidates), even if none lowers it.
  const int n3 = static_cast<int>(start_.size());
  for (int k = 0; k < n3; ++k) start_[k] = c_.u[k];
  // Bond damage is irreversible: a trial that breaks bonds and is then rejected must not leave
  // them broken, so every trial starts from the damage before the search (the bond damage and
  // what materials keep themselves).
  c_.evaluator->saveDamage(startDamage_);
  auto tryStep = [&](double alpha) {
    c_.evaluator->restoreDamage(startDamage_);
    for (int k = 0; k < n3; ++k) c_.u[k] = start_[k] + alpha * increment_[k];
    return problem_.evaluateResidual();
  };
  double best = tryStep(1.0), bestAlpha = 1.0;
  // Non-finite (adaptive load stepping only; otherwise StaticProblem threw): the attempt fails.
  if (!std::isfinite(best)) return best;
  if (best < residualNorm) return best;
  for (double alpha : {0.75, 0.5, 0.3, 0.2, 0.1}) {
    const double norm = tryStep(alpha);
    if (!std::isfinite(norm)) return norm;
    if (norm < best) {
      best = norm;
      bestAlpha = alpha;
    }
  }
  return tryStep(bestAlpha);
}

QuasiStatic::StepResult QuasiStatic::solveStep(long long step, double previous, double time,
                                               const std::vector<double>& stepStart,
                                               const std::vector<double>& predictor,
                                               bool usePredictor) {
  const auto& t = *c_.topology;
  const int n3 = 3 * t.numOwned;
  std::ostream& log = *c_.log;
  const double dt = time - previous;
  problem_.beginStep(dt, &stepStart);
  tangent_->setProbeTimeStep(dt);
  c_.conditions->applyPrescribedDisplacement(time, c_.u);
  if (c_.b) c_.conditions->applyBodyForce(time, c_.b, t.numOwned);
  StepResult r;
  r.norm = problem_.evaluateResidual();
  if (!std::isfinite(r.norm)) {
    // Adaptive load stepping (otherwise evaluateResidual threw): a failed attempt.
    if (c_.rank == 0) {
      log << "Load step " << step << ", time " << previous << " -> " << time
          << ": the residual at the step's prescribed displacements is not finite\n";
    }
    r.nonFinite = true;
    return r;
  }
  // Convergence: Absolute Tolerance, or Relative Tolerance x the load of the step: the
  // reactions at the held components (Peridigm) and, with body forces, the applied force.
  r.criterion = problem_.criterion(config_.absoluteTolerance, config_.tolerance, r.norm);
  if (c_.rank == 0) {
    log << "Load step " << step << ", time " << previous << " -> " << time
        << ", convergence criterion " << r.criterion << "\n";
  }
  int iteration = 1;
  bool damped = false;
  const long long linearBefore = stats_.linearIterations;
  while (r.norm > r.criterion && iteration <= config_.maxIterations) {
    if (c_.rank == 0) log << "  iteration " << iteration << ": residual = " << r.norm << "\n";
    if (iteration == 1 && usePredictor) {
      // Predictor: the previous step's rate of displacement over this step.
      for (int k = 0; k < n3; ++k)
        increment_[k] = problem_.held()[k] != 0.0 ? 0.0 : predictor[k] * dt;
    } else {
      if (iteration > kPureNewtonIterations && !damped) {
        damped = true;
        if (c_.rank == 0) log << "  --switching to damped Newton--\n";
      }
      if (!damped || (iteration - kPureNewtonIterations - 1) % kDampedTangentInterval == 0) {
        Timers::Scope timer(*c_.timers, "Tangent");
        tangent_->assemble(c_.evaluator->state(), *c_.blocks, problem_.held(),
                           problem_.heldDiagonal());
        ++stats_.tangentAssemblies;
        if (damped) dampDiagonal(*tangent_->matrix(), config_.dampedScale, config_.dampedShift);
      }
      int linear;
      {
        Timers::Scope timer(*c_.timers, "Linear solve");
        linear = solveLinear(config_.preconditioner != "None");
        if (linear < 0) {
          if (c_.rank == 0)
            log << "  --linear solver did not converge: damped tangent, no preconditioner--\n";
          if (!damped) dampDiagonal(*tangent_->matrix(), config_.dampedScale, config_.dampedShift);
          damped = true;
          linear = solveLinear(false);
        }
      }
      if (linear < 0) {
        std::ostringstream msg;
        msg << "QuasiStatic: the linear solver (" << config_.linearSolver
            << ") did not converge at load step " << step << " (time " << formatNumber(time)
            << "), Newton iteration " << iteration << ", residual " << formatNumber(r.norm)
            << ". The tangent may be singular (a body or a part of it not held by prescribed "
               "displacements in every direction)";
        if (config_.linearSolver == "BlockCG")
          msg << " or not positive definite (try \"Belos Linear Solver\": \"BlockGMRES\")";
        msg << "; also try a larger \"Belos Maximum Iterations\"";
        // Adaptive load stepping treats a failed linear solve as a failed step (Peridigm).
        if (!config_.adaptive.enabled) throw RunError(msg.str());
        if (c_.rank == 0) log << "  --linear solver failed twice: the step failed--\n";
        r.linearFailed = true;
        break;
      }
    }
    {
      Timers::Scope timer(*c_.timers, "Line search");
      r.norm = lineSearch(r.norm);
    }
    ++iteration;
    if (!std::isfinite(r.norm)) {
      if (c_.rank == 0) log << "  --the residual is not finite: the step failed--\n";
      r.nonFinite = true;
      break;
    }
  }
  r.iterations = iteration - 1;
  r.linearIterations = static_cast<int>(stats_.linearIterations - linearBefore);
  stats_.newtonIterations += r.iterations;
  // Converged, or within 100x of the criterion: accepted with a warning (as Peridigm).
  r.converged = !r.linearFailed && !r.nonFinite && r.norm < 100.0 * r.criterion;
  if (r.converged && r.norm > r.criterion && c_.rank == 0) {
    log << "  warning: residual " << r.norm << " above the criterion after "
        << config_.maxIterations << " iterations; within 100x: accepted (as Peridigm)\n";
  }
  return r;
}

void QuasiStatic::restore(const std::vector<double>& stepStart) {
  const int n3 = static_cast<int>(stepStart.size());
  for (int k = 0; k < n3; ++k) c_.u[k] = stepStart[k];
  c_.evaluator->restoreDamage(stepDamage_);
}

void QuasiStatic::exhausted(long long step, const LoadSchedule& schedule, const StepResult& last,
                            const std::vector<double>& predictor) {
  const auto& adaptive = config_.adaptive;
  const bool inStep = schedule.reductionsThisStep() + 1 > adaptive.maxReductionsInOneStep;
  std::ostringstream why;
  why << "load step " << step << " (time " << formatNumber(schedule.start()) << " -> "
      << formatNumber(schedule.end()) << ") did not converge after "
      << schedule.reductionsThisStep() << " reduction(s) of this step and "
      << schedule.totalReductions() << " in all, the limit of "
      << (inStep ? "Maximum load step reductions in one step (" +
                       std::to_string(adaptive.maxReductionsInOneStep) + ")"
                 : "Maximum total load step reductions (" +
                       std::to_string(adaptive.maxTotalReductions) + ")")
      << "; last attempt: " << last.iterations << " Newton iteration(s)"
      << (last.linearFailed ? " (the linear solver failed)" : "")
      << (last.nonFinite ? " (the residual is not finite: a force or displacement diverged)" : "")
      << ", residual " << formatNumber(last.norm) << ", criterion " << formatNumber(last.criterion);
  if (!adaptive.switchToVerlet) {
    std::ostringstream msg;
    msg << "QuasiStatic: " << why.str()
        << ". Try larger Maximum load step reductions in one step / Maximum total load step "
           "reductions, more Maximum Solver Iterations, a looser tolerance, Adaptive "
           "Load-Stepping -> Switch to Verlet (continues explicitly from the last converged "
           "state), or the Adaptive Dynamic Relaxation solver; if bonds are breaking, the "
           "structure may have failed. The outputs of the "
        << schedule.accepted() << " converged load step(s), to time "
        << formatNumber(schedule.start()) << ", are in the files.";
    // Every rank decides alike (global norms): an orderly collective stop.
    RunError error(msg.str());
    error.markCollective();
    throw error;
  }
  // Switch to Verlet: the state of the last converged step, moving at that step's rate (the
  // velocity Peridigm hands to its explicit solver).
  const int n3 = 3 * c_.topology->numOwned;
  for (int k = 0; k < n3; ++k) {
    c_.v[k] = predictor[k];
    c_.a[k] = 0.0;
  }
  switchTime_ = schedule.start();
  finalTime_ = schedule.finalTime();
  switched_ = true;
  if (c_.rank == 0) {
    *c_.log << "QuasiStatic: " << why.str() << ".\nSwitching to Verlet from time " << switchTime_
            << " (the last converged load step) to " << finalTime_ << "\n"
            << std::flush;
  }
}

void QuasiStatic::run() {
  const auto& t = *c_.topology;
  const int n3 = 3 * t.numOwned;
  std::ostream& log = *c_.log;
  const auto& adaptive = config_.adaptive;
  LoadSchedule schedule(config_.times, adaptive);
  std::vector<double> stepStart(n3, 0.0);
  std::vector<double> predictor = problem_.start(config_.times[0]);
  if (c_.rank == 0) {
    log << "QuasiStatic: " << config_.times.size() - 1 << " load steps, " << config_.linearSolver
        << ", preconditioner " << config_.preconditioner
        << (adaptive.enabled ? ", adaptive load stepping" : "") << "\n";
  }
  const auto runStart = std::chrono::steady_clock::now();
  while (!schedule.done()) {
    const auto stepClock = std::chrono::steady_clock::now();
    const long long step = schedule.accepted() + 1;
    const double previous = schedule.start(), time = schedule.end();
    for (int k = 0; k < n3; ++k) stepStart[k] = c_.u[k];
    // A cut step restarts from this state: bond damage is irreversible, so keep it. (History
    // models are not touched: a trial evaluation commits none, ModelState::commitHistory.)
    if (adaptive.enabled) c_.evaluator->saveDamage(stepDamage_);
    // With adaptive load stepping a non-finite residual is a failed attempt, not a stop.
    problem_.setReturnNonFiniteResidual(adaptive.enabled);
    const StepResult r =
        solveStep(step, previous, time, stepStart, predictor, step > 1 || c_.predictorFromPrevious);
    problem_.setReturnNonFiniteResidual(false);
    stats_.attempts.push_back({previous, time, r.converged});
    if (!r.converged) {
      if (!adaptive.enabled) {
        std::ostringstream msg;
        msg << "QuasiStatic: load step " << step << " (time " << formatNumber(previous) << " -> "
            << formatNumber(time) << ") did not converge in " << config_.maxIterations
            << " Newton iterations: residual " << formatNumber(r.norm) << ", criterion "
            << formatNumber(r.criterion) << " (L2 norm of V (f + b) over the free components). "
            << "Try more load steps (Number of Load Steps), more iterations (Maximum Solver "
               "Iterations), a looser Relative Tolerance or Adaptive Load-Stepping; if bonds "
               "are breaking, the structure may have failed (Verlet follows it). The outputs of "
               "the steps before are in the files.";
        // Every rank decides alike (global norms): an orderly collective stop.
        RunError error(msg.str());
        error.markCollective();
        throw error;
      }
      restore(stepStart);
      const bool cut = schedule.cut();
      stats_.reductions = schedule.totalReductions();
      if (cut) {
        if (c_.outputs && adaptive.adaptiveOutputFrequency) c_.outputs->multiplyFrequency(2);
        if (c_.rank == 0) {
          log << "  load step " << step << " failed (";
          if (r.nonFinite)
            log << "non-finite residual";
          else
            log << "residual " << r.norm << ", criterion " << r.criterion;
          log << "): cut in half, retried over " << schedule.start() << " -> " << schedule.end()
              << " (reduction " << schedule.reductionsThisStep() << " of "
              << adaptive.maxReductionsInOneStep << " in this step, " << schedule.totalReductions()
              << " of " << adaptive.maxTotalReductions << " in all)\n";
        }
        continue;
      }
      exhausted(step, schedule, r, predictor);
      break;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - stepClock).count();
    if (c_.rank == 0) {
      log << "  iteration " << r.iterations + 1 << ": residual = " << r.norm << "  ("
          << r.iterations << " Newton, " << r.linearIterations << " linear iterations, " << seconds
          << " s)\n"
          << std::flush;
    }
    stats_.newtonIterationsPerStep.push_back(r.iterations);
    problem_.finishStep(static_cast<std::size_t>(step), time, time - previous, stepStart,
                        r.iterations, predictor);
    schedule.accept();
    acceptedSteps_ = schedule.accepted();
    endTime_ = time;
  }
  stats_.tangentBytes = tangent_->bytes();
  double tangentBytes = 0;
  MPI_Allreduce(&stats_.tangentBytes, &tangentBytes, 1, MPI_DOUBLE, MPI_SUM, c_.comm);
  if (c_.rank == 0) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "Tangent memory (all ranks): %.1f MB = %.0f bytes per bond (one-sided)\n",
                  tangentBytes / 1e6,
                  tangentBytes / static_cast<double>(std::max(1LL, t.globalNumBonds)));
    log << text;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
    log << "QuasiStatic: " << stats_.newtonIterations << " Newton iterations, "
        << stats_.linearIterations << " linear iterations, " << stats_.tangentAssemblies
        << " tangent assemblies, " << seconds << " s\n";
  }
}

}  // namespace peridot
