#include "solvers/Implicit.hpp"

#include <chrono>
#include <cmath>
#include <ostream>
#include <sstream>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"
#include "solvers/LinearSolve.hpp"

namespace peridot {

namespace {
const char* kHeldField = "Implicit_Held";
}

Implicit::Implicit(const ImplicitConfig& config, double initialTime, long long numSteps,
                   SolverContext context)
    : config_(config), c_(std::move(context)), initialTime_(initialTime), numSteps_(numSteps) {
  tangent_ = std::make_unique<Tangent>(*c_.topology, *c_.blocks, config_.path, c_.probe());
  // Newmark: v = v~ + gamma dt a with a = (u - u~) / (beta dt^2), so dv/du = gamma / (beta dt).
  tangent_->setProbeTimeStep(config_.dt, config_.gamma / (config_.beta * config_.dt));
  if (tangent_->finiteDifference() && c_.rank == 0) {
    *c_.log << "Implicit: finite-difference tangent, " << tangent_->colours()
            << " colours, probe length " << tangent_->probeLength() << "\n";
  }
  const int numOwned = c_.topology->numOwned;
  const int n3 = 3 * numOwned;
  held_ = c_.fields->node(kHeldField, 3);
  for (int k = 0; k < n3; ++k) held_[k] = 0.0;
  c_.conditions->markPrescribed(held_);
  if (c_.planar)
    for (int i = 0; i < numOwned; ++i) held_[3 * i + 2] = 1.0;
  c_.fields->refreshGhosts(kHeldField);
  // No point needs holding for lack of bonds: the mass term keeps the Jacobian regular.
  const double scale = 1.0 / (config_.beta * config_.dt * config_.dt);
  mass_.assign(n3, 0.0);
  for (int i = 0; i < numOwned; ++i)
    for (int d = 0; d < 3; ++d) mass_[3 * i + d] = c_.density[i] * c_.volume[i] * scale;
  // The diagonal of a held row: any positive value gives the same solution (held rows are
  // decoupled); the mean mass term keeps the Krylov solver's scaling.
  double local[2] = {0, 0}, total[2] = {0, 0};
  for (int k = 0; k < n3; ++k) local[0] += mass_[k];
  local[1] = n3;
  MPI_Allreduce(local, total, 2, MPI_DOUBLE, MPI_SUM, c_.comm);
  if (total[1] > 0 && total[0] > 0) heldDiagonal_ = total[0] / total[1];
  uTilde_.assign(n3, 0.0);
  vTilde_.assign(n3, 0.0);
  residual_.assign(n3, 0.0);
  increment_.assign(n3, 0.0);
}

double Implicit::evaluateResidual(double time, bool commit) {
  const auto& t = *c_.topology;
  for (int k = 0; k < 3 * t.numOwned; ++k) c_.y[k] = c_.x[k] + c_.u[k];
  c_.evaluator->setTime(time);
  c_.evaluator->evaluate(config_.dt, true, commit);
  double local = 0;
  for (int i = 0; i < t.numOwned; ++i)
    for (int d = 0; d < 3; ++d) {
      const int k = 3 * i + d;
      const double r =
          held_[k] != 0.0 ? 0.0 : c_.f[k] + (c_.b ? c_.b[k] : 0.0) - c_.density[i] * c_.a[k];
      residual_[k] = c_.volume[i] * r;
      local += r * r;
    }
  double total = 0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, c_.comm);
  const double norm = config_.beta * config_.dt * config_.dt * std::sqrt(total);
  if (!std::isfinite(norm)) {
    throw RunError("Implicit: the residual at time " + formatNumber(time) +
                   " is not finite (a force or displacement diverged)");
  }
  return norm;
}

void Implicit::updateRates() {
  const double dt = config_.dt, beta = config_.beta, gamma = config_.gamma;
  for (std::size_t k = 0; k < uTilde_.size(); ++k) {
    c_.a[k] = (c_.u[k] - uTilde_[k]) / (beta * dt * dt);
    c_.v[k] = vTilde_[k] + gamma * dt * c_.a[k];
  }
}

void Implicit::run() {
  const auto& t = *c_.topology;
  const int numOwned = t.numOwned;
  const int n3 = 3 * numOwned;
  std::ostream& log = *c_.log;
  const double dt = config_.dt, beta = config_.beta, gamma = config_.gamma;
  double time = initialTime_;
  if (c_.b) c_.conditions->applyBodyForce(time, c_.b, numOwned);
  if (c_.temperature) {
    throwIfAnyRank(
        c_.conditions->applyPrescribedTemperature(time, c_.temperature, c_.temperatureChange),
        c_.comm, true);
  }
  for (int k = 0; k < 3 * numOwned; ++k) c_.y[k] = c_.x[k] + c_.u[k];
  c_.evaluator->setTime(time);
  c_.evaluator->evaluate(dt);
  for (int i = 0; i < numOwned; ++i)
    for (int d = 0; d < 3; ++d) {
      const int k = 3 * i + d;
      c_.a[k] = held_[k] != 0.0 ? 0.0 : (c_.f[k] + (c_.b ? c_.b[k] : 0.0)) / c_.density[i];
    }
  if (c_.stepOffset == 0) {
    c_.outputs->write(0, time);
    if (c_.observer) c_.observer(0, time);
  }
  if (c_.rank == 0) {
    log << "Implicit (Newmark beta = " << beta << ", gamma = " << gamma << "): " << numSteps_
        << " steps of " << dt << ", " << config_.linear.solver << ", preconditioner "
        << config_.linear.preconditioner << "\n";
  }
  const auto runStart = std::chrono::steady_clock::now();
  for (long long step = 1; step <= numSteps_; ++step) {
    time = initialTime_ + static_cast<double>(step) * dt;
    for (int k = 0; k < n3; ++k) {
      uTilde_[k] = c_.u[k] + dt * c_.v[k] + 0.5 * dt * dt * (1.0 - 2.0 * beta) * c_.a[k];
      vTilde_[k] = c_.v[k] + dt * (1.0 - gamma) * c_.a[k];
      c_.u[k] = uTilde_[k];
    }
    c_.conditions->applyPrescribedDisplacement(time, c_.u);
    if (c_.planar)
      for (int i = 0; i < numOwned; ++i) c_.u[3 * i + 2] = uTilde_[3 * i + 2];
    updateRates();
    if (c_.b) c_.conditions->applyBodyForce(time, c_.b, numOwned);
    if (c_.temperature) {
      throwIfAnyRank(
          c_.conditions->applyPrescribedTemperature(time, c_.temperature, c_.temperatureChange),
          c_.comm, true);
    }
    double norm = evaluateResidual(time);
    int iteration = 0;
    while (norm > config_.tolerance && iteration < config_.maxIterations) {
      if (c_.rank == 0 && config_.verbose)
        log << "  step " << step << ", iteration " << iteration << ": residual = " << norm << "\n";
      {
        Timers::Scope timer(*c_.timers, "Tangent");
        tangent_->assemble(c_.evaluator->state(), *c_.blocks, held_, heldDiagonal_, mass_.data());
      }
      int linear;
      {
        Timers::Scope timer(*c_.timers, "Linear solve");
        linear = solveTangentSystem(tangent_->matrix(), residual_, held_, config_.linear,
                                    config_.linear.preconditioner != "None", increment_,
                                    stats_.linearIterations);
      }
      if (linear < 0 && c_.rank == 0) {
        // As Peridigm: the unconverged Krylov solution is still a descent direction.
        log << "  warning: the linear solver did not converge at step " << step
            << ", Newton iteration " << iteration << "; proceeding\n";
      }
      for (int k = 0; k < n3; ++k) c_.u[k] += increment_[k];
      updateRates();
      norm = evaluateResidual(time);
      ++iteration;
    }
    // The converged state is the step's end: history models advance to it (the same force).
    if (c_.evaluator->hasHistory()) evaluateResidual(time, true);
    stats_.newtonIterations += iteration;
    stats_.newtonIterationsPerStep.push_back(iteration);
    if (norm > config_.tolerance) {
      if (norm < 100.0 * config_.tolerance) {
        if (c_.rank == 0)
          log << "  warning: step " << step << ": residual " << norm << " above the Absolute "
              << "Tolerance after " << iteration << " Newton iterations; within 100x: accepted\n";
      } else {
        std::ostringstream msg;
        msg << "Implicit: step " << step << " (time " << formatNumber(time - dt) << " -> "
            << formatNumber(time) << ") did not converge in " << config_.maxIterations
            << " Newton iterations: residual " << formatNumber(norm) << " (beta dt^2 |f + b - "
            << "rho a| over the free components), Absolute Tolerance "
            << formatNumber(config_.tolerance)
            << ". Try a smaller Fixed dt, more Maximum Solver Iterations or a looser Absolute "
               "Tolerance. The outputs of the steps before are in the files.";
        throw RunError(msg.str());
      }
    }
    if (c_.rank == 0 && config_.verbose)
      log << "  step " << step << ", time " << time << ": residual = " << norm << " (" << iteration
          << " Newton iterations)\n";
    if (c_.nonlinearIterations) *c_.nonlinearIterations = iteration;
    const long long record = c_.stepOffset + step;
    if (c_.outputs->due(record)) c_.outputs->write(record, time);
    if (c_.observer) c_.observer(record, time);
  }
  if (c_.rank == 0) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
    log << "Implicit: " << stats_.newtonIterations << " Newton iterations, "
        << stats_.linearIterations << " linear iterations, " << seconds << " s\n";
  }
}

}  // namespace peridot
