#include "solvers/QuasiStaticConfig.hpp"

#include <sstream>
#include <string>

#include "core/Error.hpp"
#include "core/Format.hpp"

namespace peridot {

std::vector<double> readLoadSteps(ListReader& list, double initialTime, double finalTime,
                                  bool finalTimeGiven) {
  std::vector<double> times;
  if (list.has("Number of Load Steps") && list.has("Time Steps")) {
    throw InputError(list.pathOf("Time Steps"),
                     "give Number of Load Steps or Time Steps, not both");
  }
  if (list.has("Number of Load Steps")) {
    if (!finalTimeGiven) {
      throw InputError(list.pathOf("Number of Load Steps"),
                       "needs the solver's Final Time (the load steps divide [Initial Time, Final "
                       "Time])");
    }
    const long long n = list.integer("Number of Load Steps");
    if (n < 1) throw InputError(list.pathOf("Number of Load Steps"), "must be at least 1");
    // Each load step is a nonlinear solve and its time is kept (8 bytes a step, on every rank):
    // a count past 1e8 is a typing error, not a run (2^31 would allocate 17 GB first).
    if (n > 100000000) {
      throw InputError(list.pathOf("Number of Load Steps"),
                       "must be at most 1e8 (got " + std::to_string(n) +
                           "; each load step is a nonlinear solve)");
    }
    times.push_back(initialTime);
    for (long long k = 1; k <= n; ++k)
      times.push_back(initialTime + k * (finalTime - initialTime) / static_cast<double>(n));
  } else if (list.has("Time Steps")) {
    std::istringstream in(list.string("Time Steps"));
    double t;
    while (in >> t) times.push_back(t);
    if (!in.eof() || times.size() < 2) {
      throw InputError(list.pathOf("Time Steps"),
                       "expected a list of at least two increasing times separated by spaces");
    }
    for (std::size_t k = 1; k < times.size(); ++k) {
      if (!(times[k] > times[k - 1])) {
        throw InputError(list.pathOf("Time Steps"), "the times must increase (" +
                                                        formatNumber(times[k - 1]) + " then " +
                                                        formatNumber(times[k]) + ")");
      }
    }
  } else {
    throw InputError(list.path(),
                     "give Number of Load Steps (with the solver's Final Time) or "
                     "Time Steps");
  }
  return times;
}

QuasiStaticConfig readQuasiStatic(ListReader& qs, double initialTime, double finalTime,
                                  bool finalTimeGiven, const std::string& preconditioner,
                                  bool verbose) {
  QuasiStaticConfig c;
  c.path = qs.path();
  c.verbose = verbose;
  c.preconditioner = preconditioner;
  c.times = readLoadSteps(qs, initialTime, finalTime, finalTimeGiven);
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
    if (!qs.isSublist("Adaptive Load-Stepping")) {
      throw InputError(qs.pathOf("Adaptive Load-Stepping"),
                       "must be a list (Maximum load step reductions in one step, Maximum total "
                       "load step reductions, ...)");
    }
    ListReader adaptive = qs.sublist("Adaptive Load-Stepping");
    c.adaptive = readAdaptiveLoadStepping(adaptive);
  }
  qs.finish();
  return c;
}

}  // namespace peridot
