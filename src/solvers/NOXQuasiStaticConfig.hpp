#pragma once
// The keys of Peridigm's `Solver -> NOXQuasiStatic` list: Peridigm's own (load steps,
// tolerances, Max Solver Iterations, Max Age Of Prec, Verbose), the lists NOX reads itself
// (Nonlinear Solver, Direction, Line Search, Solver Options, Printing), checked here and handed
// to NOX, and the AztecOO linear-solver keys of the direction's `Linear Solver` list, mapped to
// their Belos/Ifpack2 counterparts (doc/deck-reference.md#noxquasistatic says which and how).
#include <Teuchos_ParameterList.hpp>
#include <string>
#include <vector>

#include "deck/Deck.hpp"
#include "solvers/LinearSolve.hpp"

namespace peridot {

struct NOXQuasiStaticConfig {
  std::string path;
  std::vector<double> times;  // load-step end times, the first being the initial time
  bool absoluteTolerance = false;
  double tolerance = 1e-6;  // Relative Tolerance (x the reactions) or Absolute Tolerance
  int maxIterations = 50;   // Max Solver Iterations
  bool verbose = false;
  std::string direction = "Newton";  // Newton, NonlinearCG, Steepest Descent
  // Direction -> <method> -> Linear Solver -> Jacobian Operator: Matrix-Free (finite-difference
  // Jacobian-vector products of the residual) or the assembled analytic tangent.
  bool matrixFree = false;
  // The Krylov solver and the preconditioner (`linear.preconditioner`: "None", "Full Tangent",
  // "ILU", "ILUT", "Block 3x3", "Jacobi", "Symmetric Gauss-Seidel").
  LinearSolverSettings linear;
  // Requests a preconditioner serves before it is rebuilt from a newly assembled tangent.
  int maxAgeOfPrec = 1;
  // The Peridigm Preconditioner of the Solver list (what "User Defined" selects).
  std::string peridigmPreconditioner = "Full Tangent";
  // The list handed to NOX::Solver::buildSolver (Printing is completed by the solver).
  Teuchos::RCP<Teuchos::ParameterList> nox;
  int outputPrecision = 3, outputProcessor = 0;
};

NOXQuasiStaticConfig readNOXQuasiStatic(ListReader& list, double initialTime, double finalTime,
                                        bool finalTimeGiven, const std::string& preconditioner,
                                        bool verbose);

}  // namespace peridot
