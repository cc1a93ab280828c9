#pragma once
// Peridigm's QuasiStatic solver on Tpetra: load steps (prescribed displacements and body forces
// evaluated at each step's time), each solved by Newton's method on the residual
// R = V (f_int + b) with the tangent stiffness (solvers/Tangent.hpp), a Belos Krylov solver
// (BlockCG or BlockGMRES) with an optional preconditioner, a line search, and after 8 iterations
// a damped Newton (diagonal scaled and shifted). Outputs are written after every load step.
#include <memory>

#include "solvers/AdaptiveLoadStepping.hpp"
#include "solvers/QuasiStaticConfig.hpp"
#include "solvers/SolverContext.hpp"
#include "solvers/StaticProblem.hpp"
#include "solvers/Tangent.hpp"

namespace peridot {

class QuasiStatic {
 public:
  QuasiStatic(const QuasiStaticConfig& config, SolverContext context);
  // Runs every load step, writing outputs. Throws RunError when a step does not converge (the
  // outputs of the completed steps stay in the files). With Adaptive Load-Stepping a failed step
  // is halved and retried from the last converged state; when the reductions are exhausted the
  // run stops (RunError) or, with Switch to Verlet, run() returns with switchedToVerlet() set and
  // the state of the last converged step restored for the Verlet solver. Collective.
  void run();
  bool switchedToVerlet() const { return switched_; }
  // Load steps converged (outputs' step numbers continue from here) and the time reached.
  long long acceptedSteps() const { return acceptedSteps_; }
  double endTime() const { return endTime_; }
  // After a switch: the time Verlet starts from (the last converged) and runs to.
  double switchTime() const { return switchTime_; }
  double finalTime() const { return finalTime_; }
  // Set before run(): the run's outputs and its per-step observer (may be empty).
  void setRunHooks(OutputManager* outputs, std::function<void(long long, double)> observer) {
    c_.outputs = outputs;
    c_.observer = std::move(observer);
  }

  // Statistics of the run (all load steps), for tests and benches.
  struct Statistics {
    long long newtonIterations = 0, linearIterations = 0, tangentAssemblies = 0;
    std::vector<int> newtonIterationsPerStep;  // converged steps
    // Every attempt of a load step, in order (a cut step appears once per attempt).
    struct Attempt {
      double start, end;
      bool converged;
    };
    std::vector<Attempt> attempts;
    int reductions = 0;       // halvings by Adaptive Load-Stepping
    double tangentBytes = 0;  // this rank
  };
  const Statistics& statistics() const { return stats_; }
  Tangent& tangent() { return *tangent_; }
  // For tests: evaluates the forces at y = x + u (collective) and returns ||R||; assembles the
  // tangent at the state of the last evaluation. residual(): R = V (f + b), owned.
  double evaluate(double) { return problem_.evaluateResidual(); }
  // For tests: a load step of duration dt from u = 0 for the trial evaluations and the probes.
  void setStepDt(double dt) {
    testStepStart_.assign(3 * static_cast<std::size_t>(c_.topology->numOwned), 0.0);
    problem_.beginStep(dt, &testStepStart_);
    tangent_->setProbeTimeStep(dt);
  }
  void assembleTangent() {
    tangent_->assemble(c_.evaluator->state(), *c_.blocks, problem_.held(), 1.0);
  }
  const std::vector<double>& residual() const { return problem_.residual(); }

 private:
  struct StepResult {
    // nonFinite: an evaluation of the attempt gave a non-finite residual (adaptive only;
    // otherwise StaticProblem throws).
    bool converged = false, linearFailed = false, nonFinite = false;
    double norm = 0, criterion = 0;
    int iterations = 0, linearIterations = 0;
  };
  // One attempt at the load step [previous, time] from the owned displacement `stepStart`
  // (the current c_.u). Throws RunError on a failed linear solve or a non-finite residual unless
  // adaptive; with adaptive load stepping both end the attempt as failed.
  StepResult solveStep(long long step, double previous, double time,
                       const std::vector<double>& stepStart, const std::vector<double>& predictor,
                       bool usePredictor);
  // Back to the start of a failed step: displacement and bond damage.
  void restore(const std::vector<double>& stepStart);
  // Reductions exhausted: throws RunError, or prepares the switch to Verlet.
  void exhausted(long long step, const LoadSchedule& schedule, const StepResult& last,
                 const std::vector<double>& predictor);
  int solveLinear(bool precondition);  // -1: not converged
  double lineSearch(double residualNorm);

  QuasiStaticConfig config_;
  SolverContext c_;
  StaticProblem problem_;  // residual R = V (f + b), held degrees of freedom
  std::unique_ptr<Tangent> tangent_;
  std::vector<double> increment_;               // owned: the Newton direction
  std::vector<double> start_;                   // owned: u at the start of the step / line search
  std::vector<double> testStepStart_;           // setStepDt's step start (zero)
  ModelEvaluator::DamageSnapshot startDamage_;  // damage at the start of the line search
  ModelEvaluator::DamageSnapshot stepDamage_;   // at the start of the load step (adaptive)
  long long acceptedSteps_ = 0;
  double endTime_ = 0, switchTime_ = 0, finalTime_ = 0;
  bool switched_ = false;
  long long rankDeficient_ = 0;  // points held because no intact bond is left
  Statistics stats_;
};

}  // namespace peridot
