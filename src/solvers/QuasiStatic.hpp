#pragma once
// Peridigm's QuasiStatic solver on Tpetra: load steps (prescribed displacements and body forces
// evaluated at each step's time), each solved by Newton's method on the residual
// R = V (f_int + b) with the tangent stiffness (solvers/Tangent.hpp), a Belos Krylov solver
// (BlockCG or BlockGMRES) with an optional preconditioner, a line search, and after 8 iterations
// a damped Newton (diagonal scaled and shifted). Outputs are written after every load step.
#include <memory>

#include "solvers/QuasiStaticConfig.hpp"
#include "solvers/SolverContext.hpp"
#include "solvers/Tangent.hpp"

namespace peridot {

class QuasiStatic {
 public:
  QuasiStatic(const QuasiStaticConfig& config, SolverContext context);
  // Runs every load step, writing outputs. Throws RunError when a step does not converge (the
  // outputs of the completed steps stay in the files). Collective.
  void run();
  // Set before run(): the run's outputs and its per-step observer (may be empty).
  void setRunHooks(OutputManager* outputs, std::function<void(long long, double)> observer) {
    c_.outputs = outputs;
    c_.observer = std::move(observer);
  }

  // Statistics of the run (all load steps), for tests and benches.
  struct Statistics {
    long long newtonIterations = 0, linearIterations = 0, tangentAssemblies = 0;
    std::vector<int> newtonIterationsPerStep;
    double tangentBytes = 0;  // this rank
  };
  const Statistics& statistics() const { return stats_; }
  Tangent& tangent() { return *tangent_; }
  // For tests: evaluates the forces at y = x + u (collective) and returns ||R||; assembles the
  // tangent at the state of the last evaluation. residual(): R = V (f + b), owned.
  double evaluate(double time) { return evaluateResidual(time); }
  // For tests: the step size of the trial evaluations and of the tangent's probes.
  void setStepDt(double dt) {
    stepDt_ = dt;
    tangent_->setProbeTimeStep(dt);
  }
  void assembleTangent() { tangent_->assemble(c_.evaluator->state(), *c_.blocks, held_, 1.0); }
  const std::vector<double>& residual() const { return residual_; }

 private:
  // Evaluates the forces at y = x + u (a trial of the load step unless `commit`); returns ||R||.
  double evaluateResidual(double time, bool commit = false);
  void updateHeld();
  double heldDiagonal() const;
  int solveLinear(bool precondition);  // -1: not converged
  double lineSearch(double residualNorm, double time);

  QuasiStaticConfig config_;
  SolverContext c_;
  std::unique_ptr<Tangent> tangent_;
  double* held_ = nullptr;          // overlap, 3 per point
  std::vector<double> baseHeld_;    // owned: prescribed and planar z
  std::vector<double> residual_;    // owned, 3 per point: R = V (f + b), 0 where held
  std::vector<double> increment_;   // owned: the Newton direction
  std::vector<double> start_;       // owned: u at the start of the step / line search
  std::vector<double> stepStart_;   // owned: u at the start of the load step
  double stepDt_ = 0.0;             // the load step's duration (0 before the first)
  std::vector<float> startDamage_;  // bond damage at the start of the line search
  long long rankDeficient_ = 0;     // points held because no intact bond is left
  Statistics stats_;
};

}  // namespace peridot
