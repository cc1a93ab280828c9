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
  // them broken, so every trial starts from the damage before the search.
  std::vector<float>* damage =
      c_.evaluator->state().bondDamage ? &c_.fields->bondFloat("Bond_Damage") : nullptr;
  if (damage) startDamage_ = *damage;
  auto tryStep = [&](double alpha) {
    if (damage) std::copy(startDamage_.begin(), startDamage_.end(), damage->begin());
    for (int k = 0; k < n3; ++k) c_.u[k] = start_[k] + alpha * increment_[k];
    return problem_.evaluateResidual();
  };
  double best = tryStep(1.0), bestAlpha = 1.0;
  if (best < residualNorm) return best;
  for (double alpha : {0.75, 0.5, 0.3, 0.2, 0.1}) {
    const double norm = tryStep(alpha);
    if (norm < best) {
      best = norm;
      bestAlpha = alpha;
    }
  }
  return tryStep(bestAlpha);
}

void QuasiStatic::run() {
  const auto& t = *c_.topology;
  const int n3 = 3 * t.numOwned;
  std::ostream& log = *c_.log;
  const auto& times = config_.times;
  std::vector<double> stepStart(n3, 0.0);
  double time = times[0];
  std::vector<double> predictor = problem_.start(time);
  if (c_.rank == 0) {
    log << "QuasiStatic: " << times.size() - 1 << " load steps, " << config_.linearSolver
        << ", preconditioner " << config_.preconditioner << "\n";
  }
  const auto runStart = std::chrono::steady_clock::now();
  for (std::size_t step = 1; step < times.size(); ++step) {
    const auto stepClock = std::chrono::steady_clock::now();
    const double previous = time;
    time = times[step];
    const double dt = time - previous;
    for (int k = 0; k < n3; ++k) stepStart[k] = c_.u[k];
    problem_.beginStep(dt, &stepStart);
    tangent_->setProbeTimeStep(dt);
    c_.conditions->applyPrescribedDisplacement(time, c_.u);
    if (c_.b) c_.conditions->applyBodyForce(time, c_.b, t.numOwned);
    double norm = problem_.evaluateResidual();
    // Convergence: Absolute Tolerance, or Relative Tolerance x the load of the step: the
    // reactions at the held components (Peridigm) and, with body forces, the applied force.
    const double tolerance = problem_.criterion(config_.absoluteTolerance, config_.tolerance, norm);
    if (c_.rank == 0) {
      log << "Load step " << step << ", time " << previous << " -> " << time
          << ", convergence criterion " << tolerance << "\n";
    }
    int iteration = 1;
    bool damped = false;
    int linearThisStep = 0;
    const long long linearBefore = stats_.linearIterations;
    while (norm > tolerance && iteration <= config_.maxIterations) {
      if (c_.rank == 0) log << "  iteration " << iteration << ": residual = " << norm << "\n";
      if (iteration == 1 && (step > 1 || c_.predictorFromPrevious)) {
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
            if (!damped)
              dampDiagonal(*tangent_->matrix(), config_.dampedScale, config_.dampedShift);
            damped = true;
            linear = solveLinear(false);
          }
        }
        if (linear < 0) {
          std::ostringstream msg;
          msg << "QuasiStatic: the linear solver (" << config_.linearSolver
              << ") did not converge at load step " << step << " (time " << formatNumber(time)
              << "), Newton iteration " << iteration << ", residual " << formatNumber(norm)
              << ". The tangent may be singular (a body or a part of it not held by prescribed "
                 "displacements in every direction)";
          if (config_.linearSolver == "BlockCG")
            msg << " or not positive definite (try \"Belos Linear Solver\": \"BlockGMRES\")";
          msg << "; also try a larger \"Belos Maximum Iterations\"";
          throw RunError(msg.str());
        }
      }
      {
        Timers::Scope timer(*c_.timers, "Line search");
        norm = lineSearch(norm);
      }
      ++iteration;
    }
    linearThisStep = static_cast<int>(stats_.linearIterations - linearBefore);
    stats_.newtonIterations += iteration - 1;
    stats_.newtonIterationsPerStep.push_back(iteration - 1);
    if (norm > tolerance) {
      if (norm < 100.0 * tolerance) {
        if (c_.rank == 0)
          log << "  warning: residual " << norm << " above the criterion after "
              << config_.maxIterations << " iterations; within 100x: accepted (as Peridigm)\n";
      } else {
        std::ostringstream msg;
        msg << "QuasiStatic: load step " << step << " (time " << formatNumber(previous) << " -> "
            << formatNumber(time) << ") did not converge in " << config_.maxIterations
            << " Newton iterations: residual " << formatNumber(norm) << ", criterion "
            << formatNumber(tolerance) << " (L2 norm of V (f + b) over the free components). "
            << "Try more load steps (Number of Load Steps), more iterations (Maximum Solver "
               "Iterations) or a looser Relative Tolerance; if bonds are breaking, the "
               "structure may have failed (Verlet follows it). The outputs of the steps before "
               "are in the files.";
        throw RunError(msg.str());
      }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - stepClock).count();
    if (c_.rank == 0) {
      log << "  iteration " << iteration << ": residual = " << norm << "  (" << iteration - 1
          << " Newton, " << linearThisStep << " linear iterations, " << seconds << " s)\n"
          << std::flush;
    }
    problem_.finishStep(step, time, dt, stepStart, iteration - 1, predictor);
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
