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
  std::string preconditioner = "Full Tangent";  // Block 3x3, None
};

// Solves A x = rhs (owned, 3 per point) with x = 0 where held[k] != 0 (overlap layout, owned
// part read). Adds the Krylov iterations to `iterations`. Returns the iterations of this solve,
// or -1 when the solver did not converge (or broke down). Collective.
int solveTangentSystem(const Teuchos::RCP<CrsMatrix>& A, const std::vector<double>& rhs,
                       const double* held, const LinearSolverSettings& settings, bool precondition,
                       std::vector<double>& x, long long& iterations);

// Damped Newton (Peridigm): each diagonal entry d becomes scale d + shift max|d|.
void dampDiagonal(CrsMatrix& A, double scale, double shift);

}  // namespace peridot
