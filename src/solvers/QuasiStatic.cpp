#include "solvers/QuasiStatic.hpp"

#include <BelosBlockCGSolMgr.hpp>
#include <BelosBlockGmresSolMgr.hpp>
#include <BelosLinearProblem.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Ifpack2_Factory.hpp>
#include <Tpetra_Vector.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"

namespace peridot {

namespace {

using MV = Tpetra::MultiVector<double, LocalOrdinal, GlobalOrdinal>;
using OP = Tpetra::Operator<double, LocalOrdinal, GlobalOrdinal>;
using RowMatrix = Tpetra::RowMatrix<double, LocalOrdinal, GlobalOrdinal>;

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

// Block-diagonal (3x3 per point) Jacobi preconditioner: Peridigm's "Block 3x3".
class BlockJacobi : public OP {
 public:
  explicit BlockJacobi(const CrsMatrix& A) : map_(A.getRowMap()) {
    const int points = static_cast<int>(A.getNodeNumRows() / 3);
    inverse_.assign(9 * static_cast<std::size_t>(points), 0.0);
    const auto colMap = A.getColMap();
    for (int i = 0; i < points; ++i) {
      double block[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
      const GlobalOrdinal base = map_->getGlobalElement(3 * i);
      for (int r = 0; r < 3; ++r) {
        CrsMatrix::local_inds_host_view_type columns;
        CrsMatrix::values_host_view_type values;
        A.getLocalRowView(3 * i + r, columns, values);
        for (std::size_t k = 0; k < columns.extent(0); ++k) {
          const GlobalOrdinal g = colMap->getGlobalElement(columns(k));
          if (g >= base && g < base + 3) block[3 * r + (g - base)] = values(k);
        }
      }
      invert(block, &inverse_[9 * static_cast<std::size_t>(i)]);
    }
  }
  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  void apply(const MV& X, MV& Y, Teuchos::ETransp = Teuchos::NO_TRANS, double alpha = 1.0,
             double beta = 0.0) const override {
    const int points = static_cast<int>(inverse_.size() / 9);
    for (std::size_t col = 0; col < X.getNumVectors(); ++col) {
      const auto x = X.getData(col);
      auto y = Y.getDataNonConst(col);
      for (int i = 0; i < points; ++i) {
        const double* m = &inverse_[9 * static_cast<std::size_t>(i)];
        for (int r = 0; r < 3; ++r) {
          const double z =
              m[3 * r] * x[3 * i] + m[3 * r + 1] * x[3 * i + 1] + m[3 * r + 2] * x[3 * i + 2];
          y[3 * i + r] = alpha * z + (beta == 0.0 ? 0.0 : beta * y[3 * i + r]);
        }
      }
    }
  }

 private:
  // Inverse of a symmetric positive 3x3 block; a singular block (no stiffness) acts as the
  // identity on its degrees of freedom.
  static void invert(const double* a, double* out) {
    const double c00 = a[4] * a[8] - a[5] * a[7], c01 = a[5] * a[6] - a[3] * a[8],
                 c02 = a[3] * a[7] - a[4] * a[6];
    const double det = a[0] * c00 + a[1] * c01 + a[2] * c02;
    const double scale = std::fabs(a[0]) + std::fabs(a[4]) + std::fabs(a[8]);
    if (!(std::fabs(det) > 1e-14 * scale * scale * scale)) {
      for (int r = 0; r < 9; ++r) out[r] = (r % 4 == 0) ? (a[r] != 0 ? 1.0 / a[r] : 1.0) : 0.0;
      return;
    }
    out[0] = c00 / det;
    out[1] = (a[2] * a[7] - a[1] * a[8]) / det;
    out[2] = (a[1] * a[5] - a[2] * a[4]) / det;
    out[3] = c01 / det;
    out[4] = (a[0] * a[8] - a[2] * a[6]) / det;
    out[5] = (a[2] * a[3] - a[0] * a[5]) / det;
    out[6] = c02 / det;
    out[7] = (a[1] * a[6] - a[0] * a[7]) / det;
    out[8] = (a[0] * a[4] - a[1] * a[3]) / det;
  }
  Teuchos::RCP<const Map> map_;
  std::vector<double> inverse_;
};

// Damped Newton (Peridigm): diagonal d -> scale d + shift max|d|.
void dampDiagonal(CrsMatrix& A, double scale, double shift) {
  Tpetra::Vector<double, LocalOrdinal, GlobalOrdinal> diagonal(A.getRowMap());
  A.getLocalDiagCopy(diagonal);
  const double largest = diagonal.normInf();
  const auto colMap = A.getColMap();
  const auto rowMap = A.getRowMap();
  const auto d = diagonal.getData(0);
  A.resumeFill();
  for (LocalOrdinal r = 0; r < static_cast<LocalOrdinal>(A.getNodeNumRows()); ++r) {
    const LocalOrdinal column = colMap->getLocalElement(rowMap->getGlobalElement(r));
    const double value = scale * d[r] + shift * largest;
    A.replaceLocalValues(r, 1, &value, &column);
  }
  A.fillComplete(A.getDomainMap(), A.getRangeMap());
}

}  // namespace

QuasiStatic::QuasiStatic(const QuasiStaticConfig& config, SolverContext context)
    : config_(config), c_(std::move(context)) {
  tangent_ = std::make_unique<Tangent>(*c_.topology, *c_.blocks, config_.path);
  const int n3 = 3 * c_.topology->numOwned;
  held_ = c_.fields->node(kHeldField, 3);
  baseHeld_.assign(n3, 0.0);
  c_.conditions->markPrescribed(baseHeld_.data());
  if (c_.planar)
    for (int i = 0; i < c_.topology->numOwned; ++i) baseHeld_[3 * i + 2] = 1.0;
  residual_.assign(n3, 0.0);
  increment_.assign(n3, 0.0);
  start_.assign(n3, 0.0);
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

double QuasiStatic::evaluateResidual(double time) {
  const auto& t = *c_.topology;
  for (int k = 0; k < 3 * t.numOwned; ++k) c_.y[k] = c_.x[k] + c_.u[k];
  c_.evaluator->evaluate(0.0);
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

int QuasiStatic::solveLinear(bool damped, bool precondition, int step, int iteration) {
  (void)step;
  (void)iteration;
  auto A = tangent_->matrix();
  const auto map = A->getRowMap();
  auto B = Teuchos::rcp(new MV(map, 1));
  auto X = Teuchos::rcp(new MV(map, 1));
  {
    auto b = B->getDataNonConst(0);
    for (std::size_t k = 0; k < residual_.size(); ++k) b[k] = residual_[k];
  }
  (void)damped;
  auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(A, X, B));
  Teuchos::RCP<OP> preconditioner;
  if (precondition && config_.preconditioner == "Full Tangent") {
    auto ilu = Ifpack2::Factory::create<RowMatrix>("RILUK", A);
    Teuchos::ParameterList params;
    params.set("fact: iluk level-of-fill", 0);
    ilu->setParameters(params);
    ilu->initialize();
    ilu->compute();
    preconditioner = ilu;
  } else if (precondition && config_.preconditioner == "Block 3x3") {
    preconditioner = Teuchos::rcp(new BlockJacobi(*A));
  }
  if (!preconditioner.is_null()) problem->setLeftPrec(preconditioner);
  if (config_.linearSolver == "BlockCG") problem->setHermitian();
  problem->setProblem();
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Block Size", 1);
  params->set("Maximum Iterations", config_.linearMaxIterations > 0
                                        ? config_.linearMaxIterations
                                        : static_cast<int>(A->getGlobalNumRows()));
  params->set("Convergence Tolerance", config_.linearTolerance);
  int verbosity = Belos::Errors + Belos::Warnings;
  if (config_.printLinearStatus) {
    verbosity += Belos::StatusTestDetails;
    params->set("Output Frequency", 1);
  } else {
    params->set("Output Frequency", -1);
  }
  params->set("Verbosity", verbosity);
  params->set("Output Style", static_cast<int>(Belos::Brief));
  Teuchos::RCP<Belos::SolverManager<double, MV, OP>> solver;
  if (config_.linearSolver == "BlockGMRES") {
    params->set("Num Blocks", 500);
    params->set("Maximum Restarts", 10);
    solver = Teuchos::rcp(new Belos::BlockGmresSolMgr<double, MV, OP>(problem, params));
  } else {
    solver = Teuchos::rcp(new Belos::BlockCGSolMgr<double, MV, OP>(problem, params));
  }
  Belos::ReturnType result = Belos::Unconverged;
  try {
    result = solver->solve();
  } catch (const std::exception&) {
    result = Belos::Unconverged;  // a breakdown (e.g. an indefinite tangent under CG)
  }
  const int iterations = solver->getNumIters();
  stats_.linearIterations += iterations;
  const auto x = X->getData(0);
  for (std::size_t k = 0; k < increment_.size(); ++k) increment_[k] = held_[k] != 0.0 ? 0.0 : x[k];
  return result == Belos::Converged ? iterations : -1;
}

double QuasiStatic::lineSearch(double residualNorm, double time) {
  // The full Newton step when it lowers the residual (always, near the solution); otherwise the
  // best of a few shorter steps (Peridigm's candidates), even if none lowers it.
  const int n3 = static_cast<int>(start_.size());
  for (int k = 0; k < n3; ++k) start_[k] = c_.u[k];
  auto tryStep = [&](double alpha) {
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
  std::vector<double> predictor(n3, 0.0), stepStart(n3, 0.0);
  double time = times[0];
  if (c_.b) c_.conditions->applyBodyForce(time, c_.b, t.numOwned);
  evaluateResidual(time);
  for (int k = 0; k < n3; ++k) c_.a[k] = 0.0;
  c_.outputs->write(0, time);
  if (c_.observer) c_.observer(0, time);
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
      if (iteration == 1 && step > 1) {
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
          linear = solveLinear(damped, config_.preconditioner != "None", static_cast<int>(step),
                               iteration);
          if (linear < 0) {
            if (c_.rank == 0)
              log << "  --linear solver did not converge: damped tangent, no preconditioner--\n";
            if (!damped)
              dampDiagonal(*tangent_->matrix(), config_.dampedScale, config_.dampedShift);
            damped = true;
            linear = solveLinear(true, false, static_cast<int>(step), iteration);
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
    if (c_.outputs->due(static_cast<long long>(step)))
      c_.outputs->write(static_cast<long long>(step), time);
    if (c_.observer) c_.observer(static_cast<long long>(step), time);
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
