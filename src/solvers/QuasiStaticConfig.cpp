#include "solvers/QuasiStaticConfig.hpp"

#include <sstream>

#include "core/Error.hpp"
#include "core/Format.hpp"

namespace peridot {

QuasiStaticConfig readQuasiStatic(ListReader& qs, double initialTime, double finalTime,
                                  bool finalTimeGiven, const std::string& preconditioner,
                                  bool verbose) {
  QuasiStaticConfig c;
  c.path = qs.path();
  c.verbose = verbose;
  c.preconditioner = preconditioner;
  if (qs.has("Number of Load Steps") && qs.has("Time Steps")) {
    throw InputError(qs.pathOf("Time Steps"), "give Number of Load Steps or Time Steps, not both");
  }
  if (qs.has("Number of Load Steps")) {
    if (!finalTimeGiven) {
      throw InputError(qs.pathOf("Number of Load Steps"),
                       "needs the solver's Final Time (the load steps divide [Initial Time, Final "
                       "Time])");
    }
    const long long n = qs.integer("Number of Load Steps");
    if (n < 1) throw InputError(qs.pathOf("Number of Load Steps"), "must be at least 1");
    c.times.push_back(initialTime);
    for (long long k = 1; k <= n; ++k)
      c.times.push_back(initialTime + k * (finalTime - initialTime) / static_cast<double>(n));
  } else if (qs.has("Time Steps")) {
    std::istringstream in(qs.string("Time Steps"));
    double t;
    while (in >> t) c.times.push_back(t);
    if (!in.eof() || c.times.size() < 2) {
      throw InputError(qs.pathOf("Time Steps"),
                       "expected a list of at least two increasing times separated by spaces");
    }
    for (std::size_t k = 1; k < c.times.size(); ++k) {
      if (!(c.times[k] > c.times[k - 1])) {
        throw InputError(qs.pathOf("Time Steps"), "the times must increase (" +
                                                      formatNumber(c.times[k - 1]) + " then " +
                                                      formatNumber(c.times[k]) + ")");
      }
    }
  } else {
    throw InputError(qs.path(),
                     "give Number of Load Steps (with the solver's Final Time) or "
                     "Time Steps");
  }
  if (qs.has("Absolute Tolerance")) {
    c.absoluteTolerance = true;
    c.tolerance = qs.positiveNumber("Absolute Tolerance");
    if (qs.has("Relative Tolerance")) qs.positiveNumber("Relative Tolerance");  // Peridigm: unused
  } else {
    c.tolerance = qs.positiveNumber("Relative Tolerance", 1e-6);
  }
  const long long maxIterations = qs.integer("Maximum Solver Iterations", 10);
  if (maxIterations < 1) throw InputError(qs.pathOf("Maximum Solver Iterations"), "must be >= 1");
  c.maxIterations = static_cast<int>(maxIterations);
  c.dampedScale = qs.positiveNumber("Damped Newton Diagonal Scale Factor", 1.0001);
  c.dampedShift = qs.nonNegativeNumber("Damped Newton Diagonal Shift Factor", 1e-5);
  c.linearSolver = qs.choice("Belos Linear Solver", {"BlockCG", "BlockGMRES"}, "BlockCG");
  if (qs.has("Belos Maximum Iterations")) {
    const long long m = qs.integer("Belos Maximum Iterations");
    if (m < 1) throw InputError(qs.pathOf("Belos Maximum Iterations"), "must be >= 1");
    c.linearMaxIterations = static_cast<int>(m);
  }
  c.linearTolerance = qs.positiveNumber("Belos Relative Tolerance", 1e-4);
  c.printLinearStatus = qs.boolean("Belos Print Status", false);
  if (qs.has("Adaptive Load-Stepping")) {
    throw InputError(qs.pathOf("Adaptive Load-Stepping"),
                     "adaptive load stepping (and its Switch to Verlet) is not supported by "
                     "Peridot yet; give more load steps instead");
  }
  qs.finish();
  return c;
}

}  // namespace peridot
