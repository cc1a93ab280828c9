#pragma once
// The keys of Peridigm's `Solver -> Implicit` list (Newmark-beta implicit dynamics), read and
// checked with the rest of the deck.
#include <string>

#include "deck/Deck.hpp"
#include "solvers/LinearSolve.hpp"

namespace peridot {

struct ImplicitConfig {
  std::string path;
  double dt = 1.0;                  // Fixed dt (Peridigm's default 1.0)
  double beta = 0.25, gamma = 0.5;  // Newmark's parameters (trapezoidal rule by default)
  double tolerance = 1e-6;          // Absolute Tolerance on beta dt^2 |rho a - f - b|
  int maxIterations = 10;           // Maximum Solver Iterations
  // Peridigm solves each Newton system with BlockCG to a relative 1e-10, unpreconditioned;
  // Peridot keeps that default and honours the Solver's Peridigm Preconditioner.
  LinearSolverSettings linear;
  bool verbose = false;
};

// `implicit` is the Implicit sub-list; `preconditioner` the Solver's Peridigm Preconditioner.
ImplicitConfig readImplicit(ListReader& implicit, const std::string& preconditioner, bool verbose);

}  // namespace peridot
