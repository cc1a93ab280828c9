#pragma once
// Peridigm's NOXQuasiStatic on Trilinos NOX over Tpetra: load steps as QuasiStatic's (shared in
// StaticProblem), each solved by NOX's line-search solver with the deck's own direction (Newton,
// NonlinearCG, Steepest Descent), line search and status tests (finite values, ||F||_2 below the
// step's criterion, Max Solver Iterations), as Peridigm drives NOX. The Jacobian is the
// assembled analytic tangent (solvers/Tangent.hpp) or matrix-free: J v by a forward difference
// of the residual, which serves every material without history, with or without a tangent.
// Linear solves are Belos (GMRES or CG) with Ifpack2 or Peridot preconditioners
// (solvers/LinearSolve.hpp).
#include <memory>
#include <vector>

#include "solvers/NOXGroup.hpp"
#include "solvers/NOXQuasiStaticConfig.hpp"
#include "solvers/SolverContext.hpp"
#include "solvers/StaticProblem.hpp"
#include "solvers/Tangent.hpp"

namespace peridot {

class NOXQuasiStatic : public NOXProblem {
 public:
  // Throws InputError when a block's material advances a history in its force evaluation, or
  // when the options need a tangent the material does not have.
  NOXQuasiStatic(const NOXQuasiStaticConfig& config, SolverContext context);
  ~NOXQuasiStatic() override;
  // Runs every load step, writing outputs. Throws RunError when a step does not converge (the
  // outputs of the completed steps stay in the files). Collective.
  void run();
  void setRunHooks(OutputManager* outputs, std::function<void(long long, double)> observer) {
    c_.outputs = outputs;
    c_.observer = std::move(observer);
  }

  struct Statistics {
    long long nonlinearIterations = 0, linearIterations = 0, residualEvaluations = 0,
              tangentAssemblies = 0, preconditionerBuilds = 0;
    std::vector<int> nonlinearIterationsPerStep, linearIterationsPerStep;
    std::vector<double> secondsPerStep;
  };
  const Statistics& statistics() const { return stats_; }

  // NOXProblem
  void computeResidual(const TpetraVector& x, TpetraVector& f) override;
  long long linearize(const TpetraVector& x, const TpetraVector& f) override;
  long long linearization() const override { return linearization_; }
  void applyJacobian(const TpetraVector& in, TpetraVector& out, bool transpose) override;
  bool solveJacobian(const TpetraVector& in, TpetraVector& out, double tolerance) override;
  void applyPreconditioner(const TpetraVector& x, const TpetraVector& in,
                           TpetraVector& out) override;

 private:
  class MatrixFreeStiffness;
  void setDisplacement(const TpetraVector& x);
  double evaluateAt(const TpetraVector& x);  // sets u = x, restores damage, evaluates
  void assembleTangentAt(const TpetraVector& x);
  // K in by a forward difference around the linearization point (K = -J).
  void matrixFreeStiffness(const TpetraVector& in, TpetraVector& out);

  NOXQuasiStaticConfig config_;
  SolverContext c_;
  StaticProblem problem_;
  std::unique_ptr<Tangent> tangent_;  // null when nothing needs it (matrix-free, unpreconditioned)
  Teuchos::RCP<TpetraOperator> matrixFree_;
  Teuchos::RCP<TpetraOperator> preconditioner_;
  int preconditionerAge_ = 0;
  double heldDiagonal_ = 1.0;
  double coordinateNorm_ = 1.0;  // ||X + u|| at the matrix-free linearization point
  long long linearization_ = 0;
  TpetraVector* baseX_ = nullptr;  // matrix-free linearization point and its residual
  TpetraVector* baseF_ = nullptr;
  std::unique_ptr<TpetraVector> baseXStore_, baseFStore_, scratch_;
  std::unique_ptr<TpetraVector> tangentX_;     // where the tangent was last assembled (this step)
  ModelEvaluator::DamageSnapshot stepDamage_;  // damage at the start of the load step
  std::vector<double> heldScratch_;
  Statistics stats_;
};

}  // namespace peridot
