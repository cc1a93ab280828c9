#include "solvers/NOXQuasiStatic.hpp"

#include <NOX_Solver_Factory.H>
#include <NOX_Solver_Generic.H>
#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_FiniteValue.H>
#include <NOX_StatusTest_MaxIters.H>
#include <NOX_StatusTest_NormF.H>
#include <NOX_Utils.H>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ostream>
#include <sstream>

#include "core/Error.hpp"
#include "core/Format.hpp"

namespace peridot {

namespace {
using MV = Tpetra::MultiVector<double, LocalOrdinal, GlobalOrdinal>;
// The matrix-free difference step: eta = sqrt(machine epsilon) ||y|| / ||v||, y the current
// coordinates, so that every component moves by ~1e-8 of the coordinates. NOX's own choice,
// lambda (lambda + ||x|| / ||v||), scales with the unknowns, here displacements, which can be
// 1e-9 of the coordinates: the difference of two forces would then be mostly rounding (the
// forces are computed from y = X + u).
const double kSqrtEpsilon = 1.4901161193847656e-08;
}  // namespace

// K v by a forward difference of the residual (K = -dF/du): the Krylov solver's operator when
// the Jacobian is matrix-free.
class NOXQuasiStatic::MatrixFreeStiffness : public TpetraOperator {
 public:
  MatrixFreeStiffness(NOXQuasiStatic& owner, Teuchos::RCP<const Map> map)
      : owner_(owner), map_(std::move(map)) {}
  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  void apply(const MV& X, MV& Y, Teuchos::ETransp = Teuchos::NO_TRANS, double alpha = 1.0,
             double beta = 0.0) const override {
    for (std::size_t col = 0; col < X.getNumVectors(); ++col) {
      TpetraVector in(map_), out(map_);
      in.assign(*X.getVector(col));
      owner_.matrixFreeStiffness(in, out);
      Y.getVectorNonConst(col)->update(alpha, out, beta);
    }
  }

 private:
  NOXQuasiStatic& owner_;
  Teuchos::RCP<const Map> map_;
};

NOXQuasiStatic::NOXQuasiStatic(const NOXQuasiStaticConfig& config, SolverContext context)
    : config_(config), c_(std::move(context)), problem_(c_, "NOXQuasiStatic") {
  // Materials with a history (plasticity, viscoelasticity) run: every residual NOX asks for is a
  // trial evaluation from the history at the start of the load step, and StaticProblem commits
  // the history once, at the converged state (finishStep).
  // The tangent is assembled when the Jacobian is the assembled one, or when a preconditioner
  // is built from it; matrix-free without a preconditioner needs none (any material).
  const bool needsTangent = !config_.matrixFree || config_.linear.preconditioner != "None";
  if (needsTangent)
    tangent_ = std::make_unique<Tangent>(*c_.topology, *c_.blocks, config_.path, c_.probe());
  const auto& map = c_.topology->ownedMap3();
  matrixFree_ = Teuchos::rcp(new MatrixFreeStiffness(*this, map));
  baseXStore_ = std::make_unique<TpetraVector>(map);
  baseFStore_ = std::make_unique<TpetraVector>(map);
  scratch_ = std::make_unique<TpetraVector>(map);
}

NOXQuasiStatic::~NOXQuasiStatic() = default;

void NOXQuasiStatic::setDisplacement(const TpetraVector& x) {
  const auto data = x.getData(0);
  const int n3 = 3 * c_.topology->numOwned;
  for (int k = 0; k < n3; ++k) c_.u[k] = data[k];
}

double NOXQuasiStatic::evaluateAt(const TpetraVector& x) {
  setDisplacement(x);
  // Every evaluation of a load step starts from the damage the step started with: NOX's trial
  // points (line searches, difference quotients) must not break bonds for the next ones.
  c_.evaluator->restoreDamage(stepDamage_);
  ++stats_.residualEvaluations;
  Timers::Scope timer(*c_.timers, "Residual");
  return problem_.evaluateResidual();
}

void NOXQuasiStatic::computeResidual(const TpetraVector& x, TpetraVector& f) {
  evaluateAt(x);
  auto out = f.getDataNonConst(0);
  const auto& r = problem_.residual();
  for (std::size_t k = 0; k < r.size(); ++k) out[k] = r[k];
}

void NOXQuasiStatic::assembleTangentAt(const TpetraVector& x) {
  // NOX often asks for the Jacobian where the preconditioner was just built (NonlinearCG's line
  // search after its preconditioned direction): the tangent of the same state is kept.
  if (tangentX_) {
    const auto a = x.getData(0);
    const auto b = tangentX_->getData(0);
    int same = 1;
    for (decltype(a.size()) k = 0; k < a.size() && same; ++k) same = a[k] == b[k];
    int all = 0;
    MPI_Allreduce(&same, &all, 1, MPI_INT, MPI_MIN, c_.comm);
    if (all) return;
  } else {
    tangentX_ = std::make_unique<TpetraVector>(x.getMap());
  }
  tangentX_->assign(x);
  evaluateAt(x);
  Timers::Scope timer(*c_.timers, "Tangent");
  heldDiagonal_ = problem_.heldDiagonal();
  tangent_->assemble(c_.evaluator->state(), *c_.blocks, problem_.held(), heldDiagonal_);
  ++stats_.tangentAssemblies;
}

long long NOXQuasiStatic::linearize(const TpetraVector& x, const TpetraVector& f) {
  if (config_.matrixFree) {
    baseXStore_->assign(x);
    baseFStore_->assign(f);
    baseX_ = baseXStore_.get();
    baseF_ = baseFStore_.get();
    heldScratch_.assign(problem_.held(), problem_.held() + 3 * c_.topology->numOwned);
    // ||X + u|| at the linearization point (the difference step's scale).
    const auto u = x.getData(0);
    double local = 0;
    for (int k = 0; k < 3 * c_.topology->numOwned; ++k) {
      const double y = c_.x[k] + u[k];
      local += y * y;
    }
    MPI_Allreduce(&local, &coordinateNorm_, 1, MPI_DOUBLE, MPI_SUM, c_.comm);
    coordinateNorm_ = std::sqrt(coordinateNorm_);
    if (!(coordinateNorm_ > 0)) coordinateNorm_ = 1.0;
    if (linearization_ == 0) heldDiagonal_ = problem_.heldDiagonal();
  } else {
    assembleTangentAt(x);
    // A Jacobian of its own: the preconditioner ages by one.
  }
  return ++linearization_;
}

void NOXQuasiStatic::matrixFreeStiffness(const TpetraVector& in, TpetraVector& out) {
  const int n3 = 3 * c_.topology->numOwned;
  // The direction with the held components zeroed: they stay at their prescribed values.
  scratch_->assign(in);
  {
    auto v = scratch_->getDataNonConst(0);
    for (int k = 0; k < n3; ++k)
      if (heldScratch_[k] != 0.0) v[k] = 0.0;
  }
  const double normV = scratch_->norm2();
  if (normV == 0.0) {
    out.putScalar(0.0);
  } else {
    const double eta = kSqrtEpsilon * coordinateNorm_ / normV;
    TpetraVector perturbed(scratch_->getMap());
    perturbed.update(1.0, *baseX_, eta, *scratch_, 0.0);
    evaluateAt(perturbed);
    auto o = out.getDataNonConst(0);
    const auto f0 = baseF_->getData(0);
    const auto& f1 = problem_.residual();
    for (int k = 0; k < n3; ++k) o[k] = -(f1[k] - f0[k]) / eta;
  }
  // Held rows: the identity scaled as the assembled tangent's (decoupled, nonsingular).
  auto o = out.getDataNonConst(0);
  const auto v = in.getData(0);
  for (int k = 0; k < n3; ++k)
    if (heldScratch_[k] != 0.0) o[k] = heldDiagonal_ * v[k];
}

void NOXQuasiStatic::applyJacobian(const TpetraVector& in, TpetraVector& out, bool transpose) {
  // J = -K. Matrix-free products give J v only; J^T v is taken as J v, exact for the
  // hyperelastic materials NOXQuasiStatic admits (their stiffness is the Hessian of an energy).
  if (config_.matrixFree) {
    matrixFreeStiffness(in, out);
  } else {
    tangent_->matrix()->apply(in, out, transpose ? Teuchos::TRANS : Teuchos::NO_TRANS);
  }
  out.scale(-1.0);
}

bool NOXQuasiStatic::solveJacobian(const TpetraVector& in, TpetraVector& out, double tolerance) {
  // J out = in  <=>  K out = -in.
  Teuchos::RCP<TpetraOperator> M;
  if (config_.linear.preconditioner != "None") {
    if (preconditioner_.is_null() || preconditionerAge_ >= config_.maxAgeOfPrec) {
      if (config_.matrixFree) assembleTangentAt(*baseX_);
      Timers::Scope timer(*c_.timers, "Preconditioner");
      preconditioner_ = makePreconditioner(tangent_->matrix(), config_.linear);
      preconditionerAge_ = 0;
      ++stats_.preconditionerBuilds;
    }
    ++preconditionerAge_;
    M = preconditioner_;
  }
  const int n3 = 3 * c_.topology->numOwned;
  std::vector<double> rhs(n3), x;
  const auto b = in.getData(0);
  for (int k = 0; k < n3; ++k) rhs[k] = -b[k];
  LinearSolverSettings settings = config_.linear;
  settings.tolerance = tolerance;
  settings.printStatus = config_.verbose;
  settings.rightPreconditioning = config_.matrixFree;
  const double* held = config_.matrixFree ? heldScratch_.data() : problem_.held();
  Teuchos::RCP<const TpetraOperator> A;
  if (config_.matrixFree)
    A = matrixFree_;
  else
    A = tangent_->matrix();
  int iterations;
  {
    Timers::Scope timer(*c_.timers, "Linear solve");
    iterations = solveLinearSystem(A, M, rhs, held, settings, x, stats_.linearIterations);
  }
  auto o = out.getDataNonConst(0);
  for (int k = 0; k < n3; ++k) o[k] = x[k];
  return iterations >= 0;
}

void NOXQuasiStatic::applyPreconditioner(const TpetraVector& x, const TpetraVector& in,
                                         TpetraVector& out) {
  if (config_.linear.preconditioner == "None") {
    out.assign(in);
    return;
  }
  if (preconditioner_.is_null() || preconditionerAge_ >= config_.maxAgeOfPrec) {
    assembleTangentAt(x);
    Timers::Scope timer(*c_.timers, "Preconditioner");
    preconditioner_ = makePreconditioner(tangent_->matrix(), config_.linear);
    preconditionerAge_ = 0;
    ++stats_.preconditionerBuilds;
  }
  ++preconditionerAge_;
  // M^-1 of J = -K: minus the stiffness preconditioner.
  preconditioner_->apply(in, out);
  out.scale(-1.0);
}

void NOXQuasiStatic::run() {
  const auto& t = *c_.topology;
  const int n3 = 3 * t.numOwned;
  std::ostream& log = *c_.log;
  const auto& times = config_.times;
  const auto& map = t.ownedMap3();
  std::vector<double> stepStart(n3, 0.0);
  double time = times[0];
  std::vector<double> rate = problem_.start(time);
  if (c_.rank == 0) {
    log << "NOXQuasiStatic: " << times.size() - 1 << " load steps, direction " << config_.direction
        << ", Jacobian " << (config_.matrixFree ? "matrix-free" : "assembled tangent") << ", "
        << config_.linear.solver << ", preconditioner " << config_.linear.preconditioner << "\n";
  }
  // NOX's printing on this run's log, on the Output Processor.
  Teuchos::ParameterList& printing = config_.nox->sublist("Printing");
  printing.set("MyPID", c_.rank);
  printing.set("Output Processor", config_.outputProcessor);
  printing.set("Output Precision", config_.outputPrecision);
  // Peridigm's choice: everything with Verbose, else errors and the status tests' results.
  int information = NOX::Utils::Error + NOX::Utils::TestDetails;
  if (config_.verbose) {
    information += NOX::Utils::OuterIteration + NOX::Utils::OuterIterationStatusTest +
                   NOX::Utils::InnerIteration + NOX::Utils::LinearSolverDetails +
                   NOX::Utils::Parameters + NOX::Utils::Details + NOX::Utils::Warning;
  }
  printing.set("Output Information", information);
  printing.set("Output Stream", Teuchos::rcpFromRef(log));
  printing.set("Error Stream", Teuchos::rcpFromRef(log));
  const auto runStart = std::chrono::steady_clock::now();
  for (std::size_t step = 1; step < times.size(); ++step) {
    const auto stepClock = std::chrono::steady_clock::now();
    const double previous = time;
    time = times[step];
    const double dt = time - previous;
    for (int k = 0; k < n3; ++k) stepStart[k] = c_.u[k];
    problem_.beginStep(dt, &stepStart);
    if (tangent_) tangent_->setProbeTimeStep(dt);
    c_.evaluator->saveDamage(stepDamage_);
    tangentX_.reset();  // another load step: other prescribed values, other damage
    c_.conditions->applyPrescribedDisplacement(time, c_.u);
    if (c_.b) c_.conditions->applyBodyForce(time, c_.b, t.numOwned);
    const double initialNorm = problem_.evaluateResidual();
    const double tolerance =
        problem_.criterion(config_.absoluteTolerance, config_.tolerance, initialNorm);
    if (c_.rank == 0) {
      log << "Load step " << step << ", time " << previous << " -> " << time
          << ", convergence criterion " << tolerance << "\n";
    }
    // The initial guess: the previous step's displacement rate over this step (Peridigm's
    // predictor), the held components at their prescribed values.
    NOXVector guess(map);
    {
      auto g = guess.tpetra().getDataNonConst(0);
      const bool predict = step > 1 || c_.predictorFromPrevious;
      for (int k = 0; k < n3; ++k)
        g[k] = c_.u[k] + (predict && problem_.held()[k] == 0.0 ? rate[k] * dt : 0.0);
    }
    auto group = Teuchos::rcp(new NOXGroup(*this, guess));
    auto finite = Teuchos::rcp(new NOX::StatusTest::FiniteValue);
    auto normF =
        Teuchos::rcp(new NOX::StatusTest::NormF(tolerance, NOX::StatusTest::NormF::Unscaled));
    auto maxIters = Teuchos::rcp(new NOX::StatusTest::MaxIters(config_.maxIterations));
    auto combo = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
    combo->addStatusTest(finite);
    combo->addStatusTest(normF);
    combo->addStatusTest(maxIters);
    const long long linearBefore = stats_.linearIterations;
    Teuchos::RCP<NOX::Solver::Generic> solver;
    try {
      solver = NOX::Solver::buildSolver(group, combo, config_.nox);
    } catch (const std::exception& e) {
      throw InputError(config_.path, std::string("NOX refused the list: ") + e.what());
    }
    NOX::StatusTest::StatusType status = NOX::StatusTest::Unconverged;
    int iteration = 0;
    double norm = initialNorm;
    while (status == NOX::StatusTest::Unconverged) {
      try {
        status = solver->step();
      } catch (const std::exception& e) {
        if (dynamic_cast<const RunError*>(&e)) throw;
        std::ostringstream msg;
        msg << "NOXQuasiStatic: NOX failed at load step " << step << ", iteration " << iteration + 1
            << ": " << e.what();
        throw RunError(msg.str());
      }
      ++iteration;
      norm = solver->getSolutionGroup().getNormF();
      if (c_.rank == 0)
        log << "  iteration " << iteration << ": residual L2 norm = " << norm << "\n";
    }
    if (status != NOX::StatusTest::Converged) {
      std::ostringstream msg;
      msg << "NOXQuasiStatic: load step " << step << " (time " << formatNumber(previous) << " -> "
          << formatNumber(time) << ") did not converge: "
          << (finite->getStatus() == NOX::StatusTest::Failed ? "the residual is not finite"
              : maxIters->getStatus() == NOX::StatusTest::Failed
                  ? "Max Solver Iterations (" + std::to_string(config_.maxIterations) + ") reached"
                  : "the line search or direction failed")
          << " at iteration " << iteration << ", residual " << formatNumber(norm) << " (initial "
          << formatNumber(initialNorm) << "), criterion " << formatNumber(tolerance)
          << " (L2 norm of V (f + b) over the free components). Try more load steps (Number of "
             "Load Steps), a larger Max Solver Iterations, a looser tolerance, Direction "
             "\"Newton\" with a \"Polynomial\" or \"Backtrack\" line search, or a preconditioner; "
             "the outputs of the steps before are in the files.";
      throw RunError(msg.str());
    }
    // The converged state, evaluated (forces and damage as outputs see them).
    evaluateAt(dynamic_cast<const NOXVector&>(solver->getSolutionGroup().getX()).tpetra());
    const int linear = static_cast<int>(stats_.linearIterations - linearBefore);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - stepClock).count();
    stats_.nonlinearIterations += iteration;
    stats_.nonlinearIterationsPerStep.push_back(iteration);
    stats_.linearIterationsPerStep.push_back(linear);
    stats_.secondsPerStep.push_back(seconds);
    if (c_.rank == 0) {
      log << "  converged: " << iteration << " nonlinear, " << linear << " linear iterations, "
          << seconds << " s\n"
          << std::flush;
    }
    problem_.finishStep(step, time, dt, stepStart, iteration, rate);
  }
  if (c_.rank == 0) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
    log << "NOXQuasiStatic: " << stats_.nonlinearIterations << " nonlinear iterations, "
        << stats_.linearIterations << " linear iterations, " << stats_.residualEvaluations
        << " residual evaluations, " << stats_.tangentAssemblies << " tangent assemblies, "
        << seconds << " s\n";
  }
}

}  // namespace peridot
