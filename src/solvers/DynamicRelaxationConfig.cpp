#include "solvers/DynamicRelaxationConfig.hpp"

#include "core/Error.hpp"
#include "solvers/QuasiStaticConfig.hpp"

namespace peridot {

DynamicRelaxationConfig readDynamicRelaxation(ListReader& list, double initialTime,
                                              double finalTime, bool finalTimeGiven, bool verbose) {
  DynamicRelaxationConfig c;
  c.path = list.path();
  c.verbose = verbose || list.boolean("Verbose", false);
  c.times = readLoadSteps(list, initialTime, finalTime, finalTimeGiven);
  if (list.has("Absolute Tolerance")) {
    if (list.has("Relative Tolerance")) {
      throw InputError(list.pathOf("Relative Tolerance"),
                       "give Absolute Tolerance or Relative Tolerance, not both");
    }
    c.absoluteTolerance = true;
    c.tolerance = list.positiveNumber("Absolute Tolerance");
  } else {
    c.tolerance = list.positiveNumber("Relative Tolerance", 1e-6);
  }
  const long long maxIterations = list.integer("Maximum Iterations", 100000);
  if (maxIterations < 1) throw InputError(list.pathOf("Maximum Iterations"), "must be >= 1");
  c.maxIterations = maxIterations;
  c.massSafetyFactor = list.positiveNumber("Mass Safety Factor", 1.25);
  if (!(c.massSafetyFactor > 1.0)) {
    throw InputError(list.pathOf("Mass Safety Factor"),
                     "must be larger than 1 (at 1 the iteration is at its stability limit)");
  }
  list.finish();
  return c;
}

}  // namespace peridot
