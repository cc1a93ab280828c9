#include "solvers/LinearSolve.hpp"

#include <BelosBlockCGSolMgr.hpp>
#include <BelosBlockGmresSolMgr.hpp>
#include <BelosLinearProblem.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Ifpack2_Factory.hpp>
#include <Tpetra_Vector.hpp>
#include <cmath>

namespace peridot {

namespace {

using MV = Tpetra::MultiVector<double, LocalOrdinal, GlobalOrdinal>;
using OP = Tpetra::Operator<double, LocalOrdinal, GlobalOrdinal>;
using RowMatrix = Tpetra::RowMatrix<double, LocalOrdinal, GlobalOrdinal>;

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

}  // namespace

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

Teuchos::RCP<TpetraOperator> makePreconditioner(const Teuchos::RCP<CrsMatrix>& A,
                                                const LinearSolverSettings& settings) {
  const std::string& kind = settings.preconditioner;
  if (kind == "Block 3x3") return Teuchos::rcp(new BlockJacobi(*A));
  if (kind == "None") return Teuchos::null;
  Teuchos::ParameterList params;
  std::string type;
  if (kind == "Full Tangent" || kind == "ILU") {
    type = "RILUK";
    params.set("fact: iluk level-of-fill", kind == "ILU" ? settings.levelOfFill : 0);
  } else if (kind == "ILUT") {
    type = "ILUT";
    params.set("fact: ilut level-of-fill", 1.0 + settings.levelOfFill);
  } else {
    type = "RELAXATION";
    params.set("relaxation: type", kind == "Jacobi" ? "Jacobi" : "Symmetric Gauss-Seidel");
    params.set("relaxation: sweeps", settings.sweeps);
  }
  auto prec = Ifpack2::Factory::create<RowMatrix>(type, A);
  prec->setParameters(params);
  prec->initialize();
  prec->compute();
  return prec;
}

int solveTangentSystem(const Teuchos::RCP<CrsMatrix>& A, const std::vector<double>& rhs,
                       const double* held, const LinearSolverSettings& settings, bool precondition,
                       std::vector<double>& x, long long& iterations) {
  Teuchos::RCP<TpetraOperator> preconditioner;
  if (precondition) preconditioner = makePreconditioner(A, settings);
  return solveLinearSystem(A, preconditioner, rhs, held, settings, x, iterations);
}

int solveLinearSystem(const Teuchos::RCP<const TpetraOperator>& A,
                      const Teuchos::RCP<TpetraOperator>& preconditioner,
                      const std::vector<double>& rhs, const double* held,
                      const LinearSolverSettings& settings, std::vector<double>& x,
                      long long& iterations) {
  const auto map = A->getRangeMap();
  auto B = Teuchos::rcp(new MV(map, 1));
  auto X = Teuchos::rcp(new MV(map, 1));
  {
    auto b = B->getDataNonConst(0);
    for (std::size_t k = 0; k < rhs.size(); ++k) b[k] = rhs[k];
  }
  auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(A, X, B));
  if (!preconditioner.is_null()) {
    if (settings.rightPreconditioning)
      problem->setRightPrec(preconditioner);
    else
      problem->setLeftPrec(preconditioner);
  }
  if (settings.solver == "BlockCG") problem->setHermitian();
  problem->setProblem();
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Block Size", 1);
  params->set("Maximum Iterations", settings.maxIterations > 0
                                        ? settings.maxIterations
                                        : static_cast<int>(map->getGlobalNumElements()));
  params->set("Convergence Tolerance", settings.tolerance);
  int verbosity = Belos::Errors + Belos::Warnings;
  if (settings.printStatus) {
    verbosity += Belos::StatusTestDetails;
    params->set("Output Frequency", 1);
  } else {
    params->set("Output Frequency", -1);
  }
  params->set("Verbosity", verbosity);
  params->set("Output Style", static_cast<int>(Belos::Brief));
  if (!settings.orthogonalization.empty())
    params->set("Orthogonalization", settings.orthogonalization);
  Teuchos::RCP<Belos::SolverManager<double, MV, OP>> solver;
  if (settings.solver == "BlockGMRES") {
    params->set("Num Blocks", settings.krylovSize);
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
  const int count = solver->getNumIters();
  iterations += count;
  const auto solution = X->getData(0);
  x.resize(rhs.size());
  for (std::size_t k = 0; k < rhs.size(); ++k) x[k] = held[k] != 0.0 ? 0.0 : solution[k];
  return result == Belos::Converged ? count : -1;
}

}  // namespace peridot
