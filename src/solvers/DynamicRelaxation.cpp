#include "solvers/DynamicRelaxation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ostream>
#include <sstream>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"
#include "parallel/ExactSum.hpp"
#include "solvers/VerletLimit.hpp"

namespace peridot {

DynamicRelaxation::DynamicRelaxation(const DynamicRelaxationConfig& config, SolverContext context)
    : config_(config), c_(std::move(context)) {
  // History models relax with trial evaluations and commit once per load step; a rate model
  // (velocities) would see the relaxation's fictitious velocities in the stiffness probe below.
  for (const auto& b : *c_.blocks)
    if (b.material->needsVelocity()) {
      throw InputError(config_.path,
                       "the material of block " + b.name +
                           " integrates a rate (the hypoelastic rate form), which adaptive "
                           "dynamic relaxation does not support; use \"Stress Integration\": "
                           "\"Total Lagrangian Green Strain\", QuasiStatic or Verlet");
    }
  const auto& t = *c_.topology;
  const int n = t.numOwned, n3 = 3 * n;
  held_.assign(n3, 0.0);
  c_.conditions->markPrescribed(held_.data());
  if (c_.planar)
    for (int i = 0; i < n; ++i) held_[3 * i + 2] = 1.0;
  force_.assign(n3, 0.0);
  terms3_.assign(n3, 0.0);  // swapped with force_ every iteration: the same size
  velocity_.assign(n3, 0.0);
  terms_.assign(n, 0.0);
  terms2_.assign(n, 0.0);

  // lambda_max of the stiffness about the configuration the solver starts from, bonds frozen.
  std::vector<double> current(n3);
  for (int k = 0; k < n3; ++k) current[k] = c_.x[k] + c_.u[k];
  const VerletLimitResult r =
      estimateVerletLimitAbout(*c_.topology, *c_.evaluator, current.data(), c_.y, c_.f, c_.density,
                               c_.volume, c_.planar ? 2 : 3);
  // The unit step is stable for the undamped iteration when every eigenvalue of Lambda^-1 K is
  // at most 4: Lambda = s lambda_max rho / 4 with s > 1 (Kilic & Madenci bound the eigenvalue
  // by a row sum instead, which is up to twice larger: slower convergence for nothing). The
  // residual of the Ritz value is added, as for the Verlet limit, to stay on the safe side.
  const double lambdaMax = r.lambdaMax + std::min(r.residual, r.lambdaMax);
  if (!(lambdaMax > 0)) {
    throw InputError(config_.path,
                     "the stiffness has no positive eigenvalue (no bonds?): nothing to relax");
  }
  stats_.lambdaMax = lambdaMax;
  stats_.fictitiousDensityScale = config_.massSafetyFactor * lambdaMax / 4.0;
  lambda_.resize(n);
  for (int i = 0; i < n; ++i) lambda_[i] = stats_.fictitiousDensityScale * c_.density[i];
}

double DynamicRelaxation::sum(const std::vector<double>& perPoint) {
  return exactSum(perPoint, c_.topology->globalNumPoints, c_.comm);
}

double DynamicRelaxation::evaluate(double time, bool updateDamage, bool commit) {
  const auto& t = *c_.topology;
  for (int k = 0; k < 3 * t.numOwned; ++k) c_.y[k] = c_.x[k] + c_.u[k];
  c_.evaluator->setTime(time);
  c_.evaluator->evaluate(stepDt_, updateDamage, commit);
  for (int i = 0; i < t.numOwned; ++i) {
    double load = 0;
    for (int d = 0; d < 3; ++d) {
      const int k = 3 * i + d;
      const double b = c_.b ? c_.b[k] : 0.0;
      force_[k] = held_[k] != 0.0 ? 0.0 : c_.f[k] + b;
      const double reaction = held_[k] != 0.0 ? c_.volume[i] * c_.f[k] : 0.0;
      load += reaction * reaction + c_.volume[i] * b * c_.volume[i] * b;
    }
    terms_[i] = load;
  }
  return std::sqrt(sum(terms_));
}

double DynamicRelaxation::residualNorm() {
  for (int i = 0; i < c_.topology->numOwned; ++i) {
    double r = 0;
    for (int d = 0; d < 3; ++d) r += force_[3 * i + d] * force_[3 * i + d];
    terms_[i] = c_.volume[i] * c_.volume[i] * r;
  }
  const double norm = std::sqrt(sum(terms_));
  if (!std::isfinite(norm)) {
    throw RunError(
        "Adaptive Dynamic Relaxation: the residual is not finite (a force or "
        "displacement diverged)");
  }
  return norm;
}

double DynamicRelaxation::damageSum() {
  const auto& t = *c_.topology;
  const ModelState& s = c_.evaluator->state();
  for (int i = 0; i < t.numOwned; ++i) {
    double d = 0;
    for (auto b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) d += 1.0 - intactFraction(s, b);
    terms_[i] = d;
  }
  return sum(terms_);
}

long long DynamicRelaxation::relax(double time, long long budget) {
  const auto& t = *c_.topology;
  const int n = t.numOwned;
  std::ostream& log = *c_.log;
  std::fill(velocity_.begin(), velocity_.end(), 0.0);
  double load = evaluate(time, false);
  double damping = 0.0;
  double initialNorm = 0.0;
  for (long long iteration = 0;; ++iteration) {
    // The criterion follows the load, but never falls below a fraction of the largest load
    // already carried: once the body has failed its reactions vanish, and a criterion relative
    // to them could not be met. Without any load (a body released from an initial deformation)
    // it is relative to the residual the relaxation started from.
    const double norm = residualNorm();
    if (iteration == 0) initialNorm = norm;
    double criterion = config_.tolerance;
    if (!config_.absoluteTolerance) {
      const double reference = std::max(largestLoad_, load);
      criterion *= reference > 0 ? reference : initialNorm;
    }
    lastNorm_ = norm;
    lastCriterion_ = criterion;
    if (norm <= criterion) {
      largestLoad_ = std::max(largestLoad_, load);
      return iteration;
    }
    if (iteration >= budget) return -1;
    if (config_.verbose && c_.rank == 0 && iteration % 1000 == 0) {
      log << "    iteration " << iteration << ": residual " << norm << ", criterion " << criterion
          << ", damping " << damping << "\n";
    }
    // Kilic & Madenci's central-difference update with unit steps; from rest, half a step.
    const double keep = iteration == 0 ? 0.0 : (2.0 - damping) / (2.0 + damping);
    const double push = iteration == 0 ? 0.5 : 2.0 / (2.0 + damping);
    std::vector<double>& previousForce = terms3_;
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) {
        const int k = 3 * i + d;
        velocity_[k] = keep * velocity_[k] + push * force_[k] / lambda_[i];
        c_.u[k] += velocity_[k];
      }
    previousForce.swap(force_);  // evaluate() refills every entry of force_
    load = evaluate(time, false);
    // Damping: twice the square root of the Rayleigh quotient of the local diagonal stiffness
    // k_kk = -(a_k^new - a_k^old) / v_k (the lowest frequency the iteration now excites).
    for (int i = 0; i < n; ++i) {
      double numerator = 0, denominator = 0;
      for (int d = 0; d < 3; ++d) {
        const int k = 3 * i + d;
        if (held_[k] != 0.0) continue;
        const double u = c_.u[k];
        if (velocity_[k] != 0.0) {
          const double stiffness = -(force_[k] - previousForce[k]) / (lambda_[i] * velocity_[k]);
          numerator += u * stiffness * u;
        }
        denominator += u * u;
      }
      terms_[i] = numerator;
      terms2_[i] = denominator;
    }
    const double numerator = sum(terms_), denominator = sum(terms2_);
    damping = numerator > 0 && denominator > 0 ? 2.0 * std::sqrt(numerator / denominator) : 0.0;
    damping = std::min(damping, 2.0);  // critical damping of the unit step's highest mode
  }
}

void DynamicRelaxation::run() {
  const auto& t = *c_.topology;
  const int n3 = 3 * t.numOwned;
  std::ostream& log = *c_.log;
  const auto& times = config_.times;
  std::vector<double> stepStart(n3, 0.0);
  double time = times[0];
  if (c_.b) c_.conditions->applyBodyForce(time, c_.b, t.numOwned);
  if (c_.temperature) {
    throwIfAnyRank(
        c_.conditions->applyPrescribedTemperature(time, c_.temperature, c_.temperatureChange),
        c_.comm, true);
  }
  evaluate(time, false, true);
  for (int k = 0; k < n3; ++k) c_.a[k] = 0.0;
  if (c_.stepOffset == 0) {
    c_.outputs->write(0, time);
    if (c_.observer) c_.observer(0, time);
  }
  if (c_.rank == 0) {
    log << "Adaptive Dynamic Relaxation: " << times.size() - 1 << " load steps; fictitious density "
        << stats_.fictitiousDensityScale << " x rho (lambda_max of rho^-1 K = " << stats_.lambdaMax
        << ")\n";
  }
  const auto runStart = std::chrono::steady_clock::now();
  for (std::size_t step = 1; step < times.size(); ++step) {
    const auto stepClock = std::chrono::steady_clock::now();
    const double previous = time;
    time = times[step];
    stepDt_ = time - previous;
    for (int k = 0; k < n3; ++k) stepStart[k] = c_.u[k];
    c_.conditions->applyPrescribedDisplacement(time, c_.u);
    if (c_.b) c_.conditions->applyBodyForce(time, c_.b, t.numOwned);
    if (c_.temperature) {
      throwIfAnyRank(
          c_.conditions->applyPrescribedTemperature(time, c_.temperature, c_.temperatureChange),
          c_.comm, true);
    }
    long long iterations = 0;
    int relaxations = 0;
    const double damageBefore = damageSum();
    double damage = damageBefore;
    for (;;) {
      ++relaxations;
      const long long taken = relax(time, config_.maxIterations - iterations);
      if (taken < 0) {
        std::ostringstream msg;
        msg << "Adaptive Dynamic Relaxation: load step " << step << " (time "
            << formatNumber(previous) << " -> " << formatNumber(time) << ") did not relax in "
            << config_.maxIterations << " iterations (Maximum Iterations): residual "
            << formatNumber(lastNorm_) << ", criterion " << formatNumber(lastCriterion_)
            << " (L2 norm of V (f + b) over the free components), after " << relaxations - 1
            << " re-relaxation(s) for breaking bonds. Try more load steps (Number of Load "
               "Steps), more iterations or a looser Relative Tolerance";
        if (relaxations > 1) {
          msg << "; bonds broke in this step: if a part came loose under a load nothing holds, "
                 "there is no equilibrium to relax to (Verlet follows such a failure)";
        }
        msg << ". The outputs of the steps before are in the files.";
        throw RunError(msg.str());
      }
      iterations += taken;
      // Bonds break at the relaxed state; if any did, the state is no longer in equilibrium.
      evaluate(time, true);
      const double now = damageSum();
      if (!(now > damage)) break;
      damage = now;
    }
    // The relaxed state is the step's end: history models advance to it (same force).
    if (c_.evaluator->hasHistory()) evaluate(time, false, true);
    const double damageGrowth = damage - damageBefore;
    stats_.iterations += iterations;
    stats_.iterationsPerStep.push_back(iterations);
    stats_.relaxationsPerStep.push_back(relaxations);
    const double dt = time - previous;
    for (int k = 0; k < n3; ++k) {
      c_.v[k] = (c_.u[k] - stepStart[k]) / dt;
      c_.a[k] = 0.0;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - stepClock).count();
    if (c_.rank == 0) {
      log << "Load step " << step << ", time " << previous << " -> " << time << ": relaxed in "
          << iterations << " iterations";
      if (relaxations > 1) {
        log << " (" << relaxations << " relaxations; bond damage grew by " << damageGrowth << ")";
      }
      log << ", residual " << lastNorm_ << " <= " << lastCriterion_ << ", " << seconds << " s\n"
          << std::flush;
    }
    if (c_.nonlinearIterations) *c_.nonlinearIterations = iterations;
    const long long record = c_.stepOffset + static_cast<long long>(step);
    if (c_.outputs->due(record)) c_.outputs->write(record, time);
    if (c_.observer) c_.observer(record, time);
  }
  if (c_.rank == 0) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
    log << "Adaptive Dynamic Relaxation: " << stats_.iterations << " iterations, " << seconds
        << " s\n";
  }
}

}  // namespace peridot
