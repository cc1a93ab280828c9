#pragma once
// The keys of Peridot's `Solver -> Adaptive Dynamic Relaxation` list (an extension: Peridigm has
// no such solver), read and checked with the rest of the deck.
#include <string>
#include <vector>

#include "deck/Deck.hpp"

namespace peridot {

struct DynamicRelaxationConfig {
  std::string path;
  // Times at which the load steps end, the first being the initial time (as QuasiStatic).
  std::vector<double> times;
  bool absoluteTolerance = false;    // Absolute Tolerance given: ||R|| <= tolerance
  double tolerance = 1e-6;           // else Relative Tolerance x the largest load so far
  long long maxIterations = 100000;  // relaxation iterations per load step
  // The fictitious density is this factor times the smallest that keeps the unit-step
  // iteration stable (from the largest eigenvalue of the stiffness); > 1.
  double massSafetyFactor = 1.25;
  bool verbose = false;
};

DynamicRelaxationConfig readDynamicRelaxation(ListReader& list, double initialTime,
                                              double finalTime, bool finalTimeGiven, bool verbose);

}  // namespace peridot
