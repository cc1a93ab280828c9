#pragma once
// The linear solve of a Newton iteration of the implicit solvers: Belos BlockCG or BlockGMRES on
// the tangent (solvers/Tangent.hpp), with Peridigm's preconditioner choices (ILU(0) of the
// full tangent through Ifpack2, 3x3 block Jacobi, none), and Peridigm's damped Newton
// modification of the diagonal.
#include <string>
#include <vector>

#include "solvers/Tangent.hpp"

namespace peridot {

struct LinearSolverSettings {
  std::string solver = "BlockCG";  // or BlockGMRES
  int maxIterations = 0;           // 0: the number of unknowns (Peridigm's default)
  double tolerance = 1e-4;         // relative residual
  bool printStatus = false;
  std::string preconditioner = "Full Tangent";  // Block 3x3, None (and the kinds below)
  // NOXQuasiStatic's mapping of AztecOO's options: GMRES's Krylov space (Num Blocks) and its
  // orthogonalization (Belos's names, "" for Belos's default); the sweeps of a relaxation
  // preconditioner and the level of fill of an incomplete factorization.
  int krylovSize = 500;
  std::string orthogonalization;
  int sweeps = 1;
  int levelOfFill = 0;
  // Right preconditioning (GMRES then measures the true residual): for matrix-free operators,
  // whose products carry a noise floor that a left-preconditioned residual hides.
  bool rightPreconditioning = false;
};

using TpetraOperator = Tpetra::Operator<double, LocalOrdinal, GlobalOrdinal>;

// A preconditioner of the tangent A (an approximation of A^-1): `kind` is "Full Tangent"
// (ILU(0) of A, as QuasiStatic), "ILU" (ILU(levelOfFill)), "ILUT", "Block 3x3" (3x3 block
// Jacobi), "Jacobi" or "Symmetric Gauss-Seidel" (`sweeps` relaxation sweeps); null for "None".
// Collective.
Teuchos::RCP<TpetraOperator> makePreconditioner(const Teuchos::RCP<CrsMatrix>& A,
                                                const LinearSolverSettings& settings);

// Solves A x = rhs with the Krylov solver of `settings`, preconditioned by M when not null (on
// the left unless settings.rightPreconditioning);
// A is any operator on the owned map (an assembled tangent or a matrix-free one). Held
// components (held[k] != 0) of x are zeroed. Returns the iterations, or -1 when not converged.
int solveLinearSystem(const Teuchos::RCP<const TpetraOperator>& A,
                      const Teuchos::RCP<TpetraOperator>& M, const std::vector<double>& rhs,
                      const double* held, const LinearSolverSettings& settings,
                      std::vector<double>& x, long long& iterations);

// Solves A x = rhs (owned, 3 per point) with x = 0 where held[k] != 0 (overlap layout, owned
// part read). Adds the Krylov iterations to `iterations`. Returns the iterations of this solve,
// or -1 when the solver did not converge (or broke down). Collective.
int solveTangentSystem(const Teuchos::RCP<CrsMatrix>& A, const std::vector<double>& rhs,
                       const double* held, const LinearSolverSettings& settings, bool precondition,
                       std::vector<double>& x, long long& iterations);

// Damped Newton (Peridigm): each diagonal entry d becomes scale d + shift max|d|.
void dampDiagonal(CrsMatrix& A, double scale, double shift);

}  // namespace peridot
