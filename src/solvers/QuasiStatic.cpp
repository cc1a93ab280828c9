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

const char* kHeldField = "QuasiStatic_Held";
// Peridigm's schedule: plain Newton for 8 iterations, then damped Newton with the tangent
// re-assembled every 8 iterations.
const int kPureNewtonIterations = 8;
const int kDampedTangentInterval = 8;

double globalNorm(const std::vector<double>& values, MPI_Comm comm) {
  double local = 0, total = 0;
  for (double v : values) local += v * v;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, comm);
  return std::sqrt(total);
}

}  // namespace

QuasiStatic::QuasiStatic(const QuasiStaticConfig& config, SolverContext context)
    : config_(config), c_(std::move(context)) {
  tangent_ = std::make_unique<Tangent>(*c_.topology, *c_.blocks, config_.path, c_.probe());
  const int n3 = 3 * c_.topology->numOwned;
  held_ = c_.fields->node(kHeldField, 3);
  baseHeld_.assign(n3, 0.0);
  c_.conditions->markPrescribed(baseHeld_.data());
  if (c_.planar)
    for (int i = 0; i < c_.topology->numOwned; ++i) baseHeld_[3 * i + 2] = 1.0;
  residual_.assign(n3, 0.0);
  increment_.assign(n3, 0.0);
  start_.assign(n3, 0.0);
  stepStart_.assign(n3, 0.0);
  if (tangent_->finiteDifference() && c_.rank == 0) {
    *c_.log << "QuasiStatic: finite-difference tangent, " << tangent_->colours()
            << " colours, probe length " << tangent_->probeLength() << "\n";
  }
}

void QuasiStatic::updateHeld() {
  // Points left without an intact bond (Peridigm's RANK_DEFICIENT_NODES): their rows of the
  // tangent are zero, so they are held where they are, as Peridigm holds that node set.
  const auto& t = *c_.topology;
  const float* damage = c_.evaluator->state().bondDamage;
  long long deficient = 0;
  for (int i = 0; i < t.numOwned; ++i) {
    bool intact = false;
    for (auto b = t.bondOffsets[i]; b < t.bondOffsets[i + 1] && !intact; ++b)
      intact = !damage || damage[b] < 1.0f;
    for (int d = 0; d < 3; ++d) held_[3 * i + d] = intact ? baseHeld_[3 * i + d] : 1.0;
    if (!intact) ++deficient;
  }
  c_.fields->refreshGhosts(kHeldField);
  long long total = 0;
  MPI_Allreduce(&deficient, &total, 1, MPI_LONG_LONG, MPI_SUM, c_.comm);
  if (total != rankDeficient_ && c_.rank == 0) {
    *c_.log << "  " << total
            << " point(s) without an intact bond are held fixed (RANK_DEFICIENT_NODES)\n";
  }
  rankDeficient_ = total;
}

double QuasiStatic::evaluateResidual(double time, bool commit) {
  const auto& t = *c_.topology;
  for (int k = 0; k < 3 * t.numOwned; ++k) c_.y[k] = c_.x[k] + c_.u[k];
  // Rate models integrate over the load step: dt and the velocity of its displacement increment.
  if (stepDt_ > 0 && c_.evaluator->readsVelocity())
    for (int k = 0; k < 3 * t.numOwned; ++k) c_.v[k] = (c_.u[k] - stepStart_[k]) / stepDt_;
  c_.evaluator->evaluate(stepDt_, true, commit);
  (void)time;
  updateHeld();
  for (int i = 0; i < t.numOwned; ++i)
    for (int d = 0; d < 3; ++d) {
      const int k = 3 * i + d;
      residual_[k] = held_[k] != 0.0 ? 0.0 : c_.volume[i] * (c_.f[k] + (c_.b ? c_.b[k] : 0.0));
    }
  const double norm = globalNorm(residual_, c_.comm);
  if (!std::isfinite(norm)) {
    throw RunError("QuasiStatic: the residual is not finite (a force or displacement diverged)");
  }
  return norm;
}

double QuasiStatic::heldDiagonal() const {
  // The mean stiffness of a point's own block, V_i * (force per unit displacement), estimated
  // from the stable-time-step stiffness sum: any positive value gives the same solution (held
  // rows are decoupled); a typical one keeps the Krylov solver's scaling.
  std::vector<double> stiffness(c_.topology->numOverlap, 0.0);
  for (const auto& b : *c_.blocks)
    b.material->stiffnessSum(c_.evaluator->state(), b.points, stiffness.data());
  double local[2] = {0, 0}, total[2] = {0, 0};
  for (int i = 0; i < c_.topology->numOwned; ++i) {
    local[0] += c_.volume[i] * stiffness[i];
    local[1] += 1;
  }
  MPI_Allreduce(local, total, 2, MPI_DOUBLE, MPI_SUM, c_.comm);
  return total[1] > 0 && total[0] > 0 ? total[0] / total[1] : 1.0;
}

int QuasiStatic::solveLinear(bool precondition) {
  LinearSolverSettings settings;
  settings.solver = config_.linearSolver;
  settings.maxIterations = config_.linearMaxIterations;
  settings.tolerance = config_.linearTolerance;
  settings.printStatus = config_.printLinearStatus;
  settings.preconditioner = config_.preconditioner;
  return solveTangentSystem(tangent_->matrix(), residual_, held_, settings, precondition,
                            increment_, stats_.linearIterations);
}

double QuasiStatic::lineSearch(double residualNorm, double time) {
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
    return evaluateResidual(time);
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
  std::vector<double> predictor(n3, 0.0);
  std::vector<double>& stepStart = stepStart_;
  double time = times[0];
  if (c_.b) c_.conditions->applyBodyForce(time, c_.b, t.numOwned);
  evaluateResidual(time, true);
  for (int k = 0; k < n3; ++k) c_.a[k] = 0.0;
  if (c_.stepOffset == 0) {
    c_.outputs->write(0, time);
    if (c_.observer) c_.observer(0, time);
  }
  // Initialize Predictor From Previous Solver: the first load step starts from the velocity
  // the previous solver left.
  if (c_.predictorFromPrevious)
    for (int k = 0; k < n3; ++k) predictor[k] = c_.v[k];
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
    stepDt_ = dt;
    tangent_->setProbeTimeStep(dt);
    for (int k = 0; k < n3; ++k) stepStart[k] = c_.u[k];
    c_.conditions->applyPrescribedDisplacement(time, c_.u);
    if (c_.b) c_.conditions->applyBodyForce(time, c_.b, t.numOwned);
    double norm = evaluateResidual(time);
    // Convergence: Absolute Tolerance, or Relative Tolerance x the load of the step: the
    // reactions at the held components (Peridigm) and, with body forces, the applied force.
    double tolerance = config_.tolerance;
    if (!config_.absoluteTolerance) {
      double local = 0, total = 0;
      for (int i = 0; i < t.numOwned; ++i)
        for (int d = 0; d < 3; ++d) {
          const int k = 3 * i + d;
          const double reaction = baseHeld_[k] != 0.0 ? c_.volume[i] * c_.f[k] : 0.0;
          const double applied = c_.b ? c_.volume[i] * c_.b[k] : 0.0;
          local += reaction * reaction + applied * applied;
        }
      MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, c_.comm);
      const double load = std::sqrt(total) > 0 ? std::sqrt(total) : norm;
      tolerance *= load;
    }
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
        for (int k = 0; k < n3; ++k) increment_[k] = held_[k] != 0.0 ? 0.0 : predictor[k] * dt;
      } else {
        if (iteration > kPureNewtonIterations && !damped) {
          damped = true;
          if (c_.rank == 0) log << "  --switching to damped Newton--\n";
        }
        if (!damped || (iteration - kPureNewtonIterations - 1) % kDampedTangentInterval == 0) {
          Timers::Scope timer(*c_.timers, "Tangent");
          tangent_->assemble(c_.evaluator->state(), *c_.blocks, held_, heldDiagonal());
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
        norm = lineSearch(norm, time);
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
    // The converged state is the step's end: history models advance to it (the same force).
    if (c_.evaluator->hasHistory()) evaluateResidual(time, true);
    for (int k = 0; k < n3; ++k) {
      predictor[k] = (c_.u[k] - stepStart[k]) / dt;
      c_.v[k] = predictor[k];
      c_.a[k] = 0.0;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - stepClock).count();
    if (c_.rank == 0) {
      log << "  iteration " << iteration << ": residual = " << norm << "  (" << iteration - 1
          << " Newton, " << linearThisStep << " linear iterations, " << seconds << " s)\n"
          << std::flush;
    }
    if (c_.nonlinearIterations) *c_.nonlinearIterations = iteration - 1;
    const long long record = c_.stepOffset + static_cast<long long>(step);
    if (c_.outputs->due(record)) c_.outputs->write(record, time);
    if (c_.observer) c_.observer(record, time);
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
