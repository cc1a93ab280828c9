#pragma once
// The keys of Peridigm's `Solver -> QuasiStatic` list, read and checked with the rest of the deck.
#include <string>
#include <vector>

#include "deck/Deck.hpp"
#include "solvers/AdaptiveLoadStepping.hpp"

namespace peridot {

struct QuasiStaticConfig {
  std::string path;
  // Times at which the load steps end, the first being the initial time (Number of Load Steps
  // spreads them evenly over [Initial Time, Final Time]; Time Steps lists them).
  std::vector<double> times;
  bool absoluteTolerance = false;  // Absolute Tolerance given: ||R|| <= tolerance
  double tolerance = 1e-6;         // else Relative Tolerance x the reaction norm
  int maxIterations = 10;          // Maximum Solver Iterations
  double dampedScale = 1.0001, dampedShift = 1e-5;
  std::string linearSolver = "BlockCG";  // or BlockGMRES
  int linearMaxIterations = 0;           // 0: the number of unknowns (Peridigm's default)
  double linearTolerance = 1e-4;
  bool printLinearStatus = false;
  std::string preconditioner = "Full Tangent";  // Peridigm Preconditioner: Block 3x3, None
  bool verbose = false;
  AdaptiveLoadSteppingConfig adaptive;  // Adaptive Load-Stepping (enabled when the list is given)
};

// The times at which load steps end, the first being the initial time, from `Number of Load
// Steps` (spread evenly over [Initial Time, Final Time]) or `Time Steps` (listed) of `list`.
std::vector<double> readLoadSteps(ListReader& list, double initialTime, double finalTime,
                                  bool finalTimeGiven);

// `solver` is the Solver list (Initial/Final Time and Peridigm Preconditioner live there),
// `qs` its QuasiStatic sub-list.
QuasiStaticConfig readQuasiStatic(ListReader& qs, double initialTime, double finalTime,
                                  bool finalTimeGiven, const std::string& preconditioner,
                                  bool verbose);

}  // namespace peridot
