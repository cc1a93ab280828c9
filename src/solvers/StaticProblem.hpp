#pragma once
// What the load-stepped static solvers (QuasiStatic's own Newton, NOXQuasiStatic) share: the
// residual R = V (f + b) of the owned degrees of freedom with the held ones (prescribed
// displacements, planar z, points left without an intact bond) zeroed, the convergence criterion
// of a load step (Peridigm's: absolute, or relative to the reactions and applied forces), and
// the bookkeeping after a converged step (velocity = the step's displacement rate, outputs).
#include <vector>

#include "solvers/SolverContext.hpp"

namespace peridot {

class StaticProblem {
 public:
  // `name` prefixes the messages (the solver's deck name).
  StaticProblem(SolverContext& context, const char* name);
  // Evaluates the forces at y = x + u and returns ||R|| (L2, all ranks). A trial of the load
  // step (history models keep its start, ModelState::commitHistory) unless `commit`; finishStep
  // commits. Collective.
  double evaluateResidual(bool commit = false);
  // A non-finite ||R|| throws RunError (the default), or with `returned` is returned for the
  // caller to treat as a failed attempt (QuasiStatic's adaptive load stepping cuts the step).
  void setReturnNonFiniteResidual(bool returned) { returnNonFinite_ = returned; }
  // A load step of duration dt from the owned displacement `stepStart` (kept by the caller):
  // rate models see dt and the velocity (u - stepStart) / dt of the step's increment.
  void beginStep(double dt, const std::vector<double>* stepStart) {
    stepDt_ = dt;
    stepStart_ = stepStart;
  }
  const std::vector<double>& residual() const { return residual_; }
  // Overlap, 3 per point: 1 where a degree of freedom is held (ghosts refreshed).
  const double* held() const { return held_; }
  // Owned, 3 per point: 1 where prescribed (or planar z); what the reactions are taken at.
  const std::vector<double>& baseHeld() const { return baseHeld_; }
  // A representative diagonal for the held rows of a tangent (any positive value decouples
  // them; a typical one keeps the Krylov solver's scaling). Collective.
  double heldDiagonal() const;
  // The load step's criterion on ||R||: `tolerance` when absolute, else `tolerance` x the norm
  // of the reactions at the held components and the applied body forces at the current state
  // (call after evaluateResidual at the step's prescribed displacements); ||R|| when there is
  // no load. Collective.
  double criterion(bool absolute, double tolerance, double residualNorm) const;
  // After a converged step from `stepStart` (owned u) over `dt`: commits the history models
  // (one evaluation at the converged state, when some model keeps one), v = (u - stepStart) / dt,
  // a = 0; records the iterations and writes the step's outputs. Returns the velocity in
  // `rate` (owned, the next step's predictor). Collective.
  void finishStep(std::size_t step, double time, double dt, const std::vector<double>& stepStart,
                  int iterations, std::vector<double>& rate);
  // Applies the body force at `time`, evaluates the initial state, writes the initial record (a
  // solver that starts a chain) and returns the initial predictor rate: the previous solver's
  // velocity when the deck asks for it, else zero. Collective.
  std::vector<double> start(double time);

 private:
  void updateHeld();
  SolverContext& c_;
  const char* name_;
  double* held_ = nullptr;        // overlap, 3 per point
  std::vector<double> baseHeld_;  // owned: prescribed and planar z
  std::vector<double> residual_;  // owned, 3 per point
  long long rankDeficient_ = 0;   // points held because no intact bond is left
  double stepDt_ = 0.0;           // the load step's duration (0 before the first)
  const std::vector<double>* stepStart_ = nullptr;
  bool returnNonFinite_ = false;
};

// sqrt(sum v^2) over all ranks.
double globalNorm(const std::vector<double>& values, MPI_Comm comm);

}  // namespace peridot
