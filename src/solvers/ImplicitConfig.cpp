#include "solvers/ImplicitConfig.hpp"

#include "core/Error.hpp"

namespace peridot {

ImplicitConfig readImplicit(ListReader& s, const std::string& preconditioner, bool verbose) {
  ImplicitConfig c;
  c.path = s.path();
  c.dt = s.positiveNumber("Fixed dt", 1.0);
  c.beta = s.number("Beta", 0.25);
  if (!(c.beta > 0.0 && c.beta <= 0.5)) {
    throw InputError(s.pathOf("Beta"),
                     "must be in (0, 0.5] (Beta = 0 is the explicit central difference: use "
                     "Verlet)");
  }
  c.gamma = s.number("Gamma", 0.5);
  if (!(c.gamma >= 0.5 && c.gamma <= 1.0)) {
    throw InputError(s.pathOf("Gamma"),
                     "must be in [0.5, 1] (below 0.5 Newmark's method amplifies every mode)");
  }
  c.tolerance = s.positiveNumber("Absolute Tolerance", 1e-6);
  const long long maxIterations = s.integer("Maximum Solver Iterations", 10);
  if (maxIterations < 1) throw InputError(s.pathOf("Maximum Solver Iterations"), "must be >= 1");
  c.maxIterations = static_cast<int>(maxIterations);
  // Peridot extensions (Peridigm's Implicit fixes these): the Krylov solver of the Newton steps.
  c.linear.solver = s.choice("Belos Linear Solver", {"BlockCG", "BlockGMRES"}, "BlockCG");
  if (s.has("Belos Maximum Iterations")) {
    const long long m = s.integer("Belos Maximum Iterations");
    if (m < 1) throw InputError(s.pathOf("Belos Maximum Iterations"), "must be >= 1");
    c.linear.maxIterations = static_cast<int>(m);
  }
  c.linear.tolerance = s.positiveNumber("Belos Relative Tolerance", 1e-10);
  c.linear.printStatus = s.boolean("Belos Print Status", false);
  c.linear.preconditioner = preconditioner;
  c.verbose = s.boolean("Verbose", false) || verbose;
  s.finish();
  return c;
}

}  // namespace peridot
