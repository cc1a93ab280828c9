#include "solvers/StaticProblem.hpp"

#include <cmath>
#include <ostream>
#include <string>

#include "core/Error.hpp"

namespace peridot {

namespace {
const char* kHeldField = "QuasiStatic_Held";
}  // namespace

double globalNorm(const std::vector<double>& values, MPI_Comm comm) {
  double local = 0, total = 0;
  for (double v : values) local += v * v;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, comm);
  return std::sqrt(total);
}

StaticProblem::StaticProblem(SolverContext& context, const char* name) : c_(context), name_(name) {
  const int n3 = 3 * c_.topology->numOwned;
  held_ = c_.fields->node(kHeldField, 3);
  baseHeld_.assign(n3, 0.0);
  c_.conditions->markPrescribed(baseHeld_.data());
  if (c_.planar)
    for (int i = 0; i < c_.topology->numOwned; ++i) baseHeld_[3 * i + 2] = 1.0;
  residual_.assign(n3, 0.0);
}

void StaticProblem::updateHeld() {
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

double StaticProblem::evaluateResidual(bool commit) {
  const auto& t = *c_.topology;
  for (int k = 0; k < 3 * t.numOwned; ++k) c_.y[k] = c_.x[k] + c_.u[k];
  // Rate models integrate over the load step: dt and the velocity of its displacement increment.
  if (stepDt_ > 0 && stepStart_ && c_.evaluator->readsVelocity())
    for (int k = 0; k < 3 * t.numOwned; ++k) c_.v[k] = (c_.u[k] - (*stepStart_)[k]) / stepDt_;
  c_.evaluator->evaluate(stepDt_, true, commit);
  updateHeld();
  for (int i = 0; i < t.numOwned; ++i)
    for (int d = 0; d < 3; ++d) {
      const int k = 3 * i + d;
      residual_[k] = held_[k] != 0.0 ? 0.0 : c_.volume[i] * (c_.f[k] + (c_.b ? c_.b[k] : 0.0));
    }
  const double norm = globalNorm(residual_, c_.comm);
  if (!std::isfinite(norm) && !returnNonFinite_) {
    throw RunError(std::string(name_) +
                   ": the residual is not finite (a force or displacement diverged)");
  }
  return norm;
}

double StaticProblem::heldDiagonal() const {
  // The mean stiffness of a point's own block, V_i * (force per unit displacement), estimated
  // from the stable-time-step stiffness sum.
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

double StaticProblem::criterion(bool absolute, double tolerance, double residualNorm) const {
  if (absolute) return tolerance;
  const auto& t = *c_.topology;
  double local = 0, total = 0;
  for (int i = 0; i < t.numOwned; ++i)
    for (int d = 0; d < 3; ++d) {
      const int k = 3 * i + d;
      const double reaction = baseHeld_[k] != 0.0 ? c_.volume[i] * c_.f[k] : 0.0;
      const double applied = c_.b ? c_.volume[i] * c_.b[k] : 0.0;
      local += reaction * reaction + applied * applied;
    }
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, c_.comm);
  const double load = std::sqrt(total) > 0 ? std::sqrt(total) : residualNorm;
  return tolerance * load;
}

std::vector<double> StaticProblem::start(double time) {
  const int n3 = 3 * c_.topology->numOwned;
  if (c_.b) c_.conditions->applyBodyForce(time, c_.b, c_.topology->numOwned);
  evaluateResidual();
  std::vector<double> rate(n3, 0.0);
  for (int k = 0; k < n3; ++k) c_.a[k] = 0.0;
  if (c_.stepOffset == 0) {
    c_.outputs->write(0, time);
    if (c_.observer) c_.observer(0, time);
  }
  // Initialize Predictor From Previous Solver: the first load step starts from the velocity
  // the previous solver left.
  if (c_.predictorFromPrevious)
    for (int k = 0; k < n3; ++k) rate[k] = c_.v[k];
  return rate;
}

void StaticProblem::finishStep(std::size_t step, double time, double dt,
                               const std::vector<double>& stepStart, int iterations,
                               std::vector<double>& rate) {
  const int n3 = 3 * c_.topology->numOwned;
  // The converged state is the step's end: history models advance to it (the same force).
  if (c_.evaluator->hasHistory()) evaluateResidual(true);
  rate.resize(n3);
  for (int k = 0; k < n3; ++k) {
    rate[k] = (c_.u[k] - stepStart[k]) / dt;
    c_.v[k] = rate[k];
    c_.a[k] = 0.0;
  }
  if (c_.nonlinearIterations) *c_.nonlinearIterations = iterations;
  const long long record = c_.stepOffset + static_cast<long long>(step);
  if (c_.outputs->due(record)) c_.outputs->write(record, time);
  if (c_.observer) c_.observer(record, time);
}

}  // namespace peridot
