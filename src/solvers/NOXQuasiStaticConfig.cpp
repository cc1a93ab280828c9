#include "solvers/NOXQuasiStaticConfig.hpp"

#include <set>

#include "core/Error.hpp"
#include "solvers/QuasiStaticConfig.hpp"

namespace peridot {

namespace {

// Keys NOX reads in a list and that Peridot hands over unchanged: accepted here, read by NOX.
void acceptKeys(ListReader& list, const std::set<std::string>& keys) {
  for (const auto& key : list.keys())
    if (keys.count(key)) list.accept(key);
  list.finish();
}

// The line-search method sublists NOX reads (NOX_LineSearch_*.C in Trilinos 13.2).
void checkLineSearch(ListReader ls) {
  const std::string method =
      ls.choice("Method", {"Full Step", "Backtrack", "Polynomial", "More'-Thuente", "NonlinearCG"},
                "Full Step");
  (void)method;
  if (ls.isSublist("Full Step")) {
    ListReader s = ls.sublist("Full Step");
    acceptKeys(s, {"Full Step"});
  }
  if (ls.isSublist("Backtrack")) {
    ListReader s = ls.sublist("Backtrack");
    acceptKeys(s,
               {"Default Step", "Minimum Step", "Recovery Step", "Max Iters", "Reduction Factor"});
  }
  if (ls.isSublist("Polynomial")) {
    ListReader s = ls.sublist("Polynomial");
    acceptKeys(s, {"Default Step", "Max Iters", "Minimum Step", "Recovery Step Type",
                   "Recovery Step", "Interpolation Type", "Min Bounds Factor", "Max Bounds Factor",
                   "Sufficient Decrease Condition", "Alpha Factor", "Force Interpolation",
                   "Use Counters", "Maximum Iteration for Increase", "Allowed Relative Increase"});
  }
  if (ls.isSublist("More'-Thuente")) {
    ListReader s = ls.sublist("More'-Thuente");
    acceptKeys(s, {"Sufficient Decrease", "Curvature Condition", "Interval Width", "Maximum Step",
                   "Minimum Step", "Max Iters", "Default Step", "Recovery Step Type",
                   "Recovery Step", "Sufficient Decrease Condition", "Optimize Slope Calculation"});
  }
  if (ls.isSublist("NonlinearCG")) {
    ListReader s = ls.sublist("NonlinearCG");
    s.finish();
  }
  ls.finish();
}

// AztecOO's keys of a direction's `Linear Solver` list (NOX::Epetra::LinearSystemAztecOO),
// mapped to Belos and Ifpack2. Keys that only shape AztecOO's printing or bookkeeping are
// accepted without effect; keys with no Tpetra counterpart are refused.
void readLinearSolver(ListReader ls, const std::string& peridigmPreconditioner, int peridigmMaxAge,
                      NOXQuasiStaticConfig& c) {
  if (ls.has("Jacobian Operator")) {
    c.matrixFree = ls.choice("Jacobian Operator", {"Matrix-Free", "Use Jacobian"}) == "Matrix-Free";
  }
  const std::string solver =
      ls.choice("Aztec Solver", {"GMRES", "CG", "CGS", "TFQMR", "BiCGStab", "LU"}, "GMRES");
  if (solver != "GMRES" && solver != "CG") {
    throw InputError(ls.pathOf("Aztec Solver"),
                     "\"" + solver +
                         "\" is not mapped to a Belos solver by Peridot; use \"GMRES\" "
                         "(Belos BlockGMRES) or \"CG\" (Belos BlockCG)");
  }
  c.linear.solver = solver == "CG" ? "BlockCG" : "BlockGMRES";
  const long long maxIterations = ls.integer("Max Iterations", 400);
  if (maxIterations < 1) throw InputError(ls.pathOf("Max Iterations"), "must be >= 1");
  c.linear.maxIterations = static_cast<int>(maxIterations);
  c.linear.tolerance = ls.positiveNumber("Tolerance", 1e-4);
  const long long krylov = ls.integer("Size of Krylov Subspace", 300);
  if (krylov < 1) throw InputError(ls.pathOf("Size of Krylov Subspace"), "must be >= 1");
  c.linear.krylovSize = static_cast<int>(krylov);
  const std::string orthogonalization =
      ls.choice("Orthogonalization", {"Classical", "Modified"}, "Classical");
  c.linear.orthogonalization = orthogonalization == "Classical" ? "ICGS" : "IMGS";
  ls.choice("Convergence Test", {"r0", "rhs"}, "r0");  // the same with a zero initial guess
  const std::string prec = ls.choice(
      "Preconditioner", {"None", "AztecOO", "Ifpack", "New Ifpack", "ML", "User Defined"}, "None");
  if (prec == "ML") {
    throw InputError(ls.pathOf("Preconditioner"),
                     "ML (Epetra's multigrid) has no counterpart in Peridot's Tpetra stack; use "
                     "\"Ifpack\" (ILU), \"AztecOO\" or \"User Defined\" (Peridigm Preconditioner)");
  }
  const long long sweeps = ls.integer("AztecOO Preconditioner Iterations", 3);
  if (sweeps < 1) {
    throw InputError(ls.pathOf("AztecOO Preconditioner Iterations"), "must be >= 1");
  }
  c.linear.sweeps = static_cast<int>(sweeps);
  if (ls.has("Graph Fill")) {
    // AztecOO's ILU level of fill (some decks give it as a bool: false = 0).
    const auto& list = ls.list();
    const auto& e = list.getEntry("Graph Fill");
    long long fill = 0;
    if (e.isType<bool>()) {
      fill = Teuchos::getValue<bool>(e) ? 1 : 0;
      ls.accept("Graph Fill");
    } else {
      fill = ls.integer("Graph Fill");
    }
    if (fill < 0) throw InputError(ls.pathOf("Graph Fill"), "must be >= 0");
    c.linear.levelOfFill = static_cast<int>(fill);
  }
  if (ls.has("Overlap")) {
    // Additive Schwarz overlap: Peridot's incomplete factorizations are per rank (overlap 0).
    const auto& e = ls.list().getEntry("Overlap");
    const bool zero = e.isType<bool>()  ? !Teuchos::getValue<bool>(e)
                      : e.isType<int>() ? Teuchos::getValue<int>(e) == 0
                                        : false;
    if (!zero) {
      throw InputError(ls.pathOf("Overlap"),
                       "only 0 (no overlap between the ranks' subdomains) is supported");
    }
    ls.accept("Overlap");
  }
  std::string aztecPrec = "ilu";
  if (prec == "AztecOO") {
    aztecPrec = ls.choice(
        "Aztec Preconditioner",
        {"ilu", "ilut", "Jacobi", "Symmetric Gauss-Seidel", "Polynomial", "Dom_Decomp"}, "ilu");
    if (aztecPrec == "Polynomial") {
      throw InputError(ls.pathOf("Aztec Preconditioner"),
                       "AztecOO's Neumann polynomial has no Ifpack2 counterpart; use \"Jacobi\", "
                       "\"Symmetric Gauss-Seidel\", \"ilu\" or \"ilut\"");
    }
  } else if (ls.has("Aztec Preconditioner")) {
    ls.choice("Aztec Preconditioner",
              {"ilu", "ilut", "Jacobi", "Symmetric Gauss-Seidel", "Polynomial", "Dom_Decomp"});
  }
  if (prec == "Ifpack" || prec == "New Ifpack") ls.choice("Ifpack Preconditioner", {"ILU"}, "ILU");
  const std::string reuse =
      ls.choice("Preconditioner Reuse Policy", {"Rebuild", "Recompute", "Reuse"}, "Rebuild");
  const long long age = ls.integer("Max Age Of Prec", 1);
  if (age < 1) throw InputError(ls.pathOf("Max Age Of Prec"), "must be >= 1");
  ls.choice("Preconditioner Operator", {"Use Jacobian"}, "Use Jacobian");
  // AztecOO's bookkeeping and printing: no effect on the solution.
  for (const char* key : {"Zero Initial Guess", "Compute Scaling Manually", "Output Solver Details",
                          "Throw Error on Prec Failure"})
    ls.boolean(key, false);
  ls.integer("Output Frequency", 0);
  ls.choice("RCM Reordering", {"Enabled", "Disabled"}, "Disabled");
  ls.finish();

  if (prec == "None") {
    c.linear.preconditioner = "None";
  } else if (prec == "User Defined") {
    // Peridigm's own preconditioner (Peridigm::computePreconditioner): the inverted 3x3 blocks
    // of its tangent, rebuilt after Max Age Of Prec uses; with a full tangent, ILU(0) as
    // QuasiStatic.
    c.linear.preconditioner =
        peridigmPreconditioner == "Full Tangent" ? "Full Tangent" : "Block 3x3";
    c.maxAgeOfPrec = peridigmMaxAge;
    return;
  } else if (prec == "Ifpack" || prec == "New Ifpack") {
    c.linear.preconditioner = "ILU";
  } else if (aztecPrec == "Jacobi") {
    c.linear.preconditioner = "Jacobi";
  } else if (aztecPrec == "Symmetric Gauss-Seidel") {
    c.linear.preconditioner = "Symmetric Gauss-Seidel";
  } else if (aztecPrec == "ilut") {
    c.linear.preconditioner = "ILUT";
  } else {
    c.linear.preconditioner = "ILU";  // ilu and Dom_Decomp (ILU on each rank's subdomain)
  }
  c.maxAgeOfPrec = reuse == "Reuse" ? static_cast<int>(age) : 1;
}

}  // namespace

NOXQuasiStaticConfig readNOXQuasiStatic(ListReader& nox, double initialTime, double finalTime,
                                        bool finalTimeGiven, const std::string& preconditioner,
                                        bool solverVerbose) {
  NOXQuasiStaticConfig c;
  c.path = nox.path();
  c.peridigmPreconditioner = preconditioner;
  // NOX's AztecOO defaults, for a direction without a Linear Solver list.
  c.linear.solver = "BlockGMRES";
  c.linear.preconditioner = "None";
  c.linear.maxIterations = 400;
  c.linear.tolerance = 1e-4;
  c.linear.krylovSize = 300;
  c.times = readLoadSteps(nox, initialTime, finalTime, finalTimeGiven);
  c.verbose = nox.boolean("Verbose", false) || solverVerbose;
  if (nox.has("Absolute Tolerance")) {
    c.absoluteTolerance = true;
    c.tolerance = nox.positiveNumber("Absolute Tolerance");
    if (nox.has("Relative Tolerance"))
      nox.positiveNumber("Relative Tolerance");  // Peridigm: unused
  } else {
    c.tolerance = nox.positiveNumber("Relative Tolerance", 1e-6);
  }
  const long long maxIterations = nox.integer("Max Solver Iterations", 50);
  if (maxIterations < 1) throw InputError(nox.pathOf("Max Solver Iterations"), "must be >= 1");
  c.maxIterations = static_cast<int>(maxIterations);
  const long long peridigmMaxAge = nox.integer("Max Age Of Prec", 200);
  if (peridigmMaxAge < 1) throw InputError(nox.pathOf("Max Age Of Prec"), "must be >= 1");

  c.nox = Teuchos::rcp(new Teuchos::ParameterList("NOXQuasiStatic"));
  const std::string solver =
      nox.choice("Nonlinear Solver",
                 {"Line Search Based", "Trust Region Based", "Inexact Trust Region Based",
                  "Tensor Based", "Anderson Accelerated Fixed-Point", "Single Step"},
                 "Line Search Based");
  if (solver != "Line Search Based") {
    throw InputError(nox.pathOf("Nonlinear Solver"),
                     "\"" + solver +
                         "\" is not supported by Peridot's NOXQuasiStatic; use \"Line Search "
                         "Based\" (the solver of Peridigm's NOX decks)");
  }
  c.nox->set("Nonlinear Solver", solver);

  // Direction: NOX reads the method and its sublist; the Linear Solver sublist is Peridot's.
  Teuchos::ParameterList& direction = c.nox->sublist("Direction");
  std::string linearListPath;
  if (nox.isSublist("Direction")) {
    ListReader d = nox.sublist("Direction");
    c.direction = d.choice("Method",
                           {"Newton", "NonlinearCG", "Steepest Descent", "Broyden", "Tensor",
                            "Modified-Newton", "Quasi-Newton"},
                           "Newton");
    if (c.direction != "Newton" && c.direction != "NonlinearCG" &&
        c.direction != "Steepest Descent") {
      throw InputError(d.pathOf("Method"),
                       "\"" + c.direction +
                           "\" is not supported by Peridot's NOXQuasiStatic; use \"Newton\", "
                           "\"NonlinearCG\" or \"Steepest Descent\"");
    }
    direction = d.list();
    // Peridigm's own key (the tangent refresh interval of NonlinearCG) is not NOX's.
    if (d.isSublist("Nonlinear CG"))
      direction.sublist("Nonlinear CG").remove("Update Jacobian", false);
    if (d.isSublist("Newton")) {
      ListReader n = d.sublist("Newton");
      if (n.isSublist("Linear Solver"))
        readLinearSolver(n.sublist("Linear Solver"), preconditioner,
                         static_cast<int>(peridigmMaxAge), c);
      acceptKeys(n, {"Forcing Term Method", "Forcing Term Initial Tolerance",
                     "Forcing Term Minimum Tolerance", "Forcing Term Maximum Tolerance",
                     "Forcing Term Alpha", "Forcing Term Gamma", "Rescue Bad Newton Solve"});
    }
    if (d.isSublist("Nonlinear CG")) {
      ListReader n = d.sublist("Nonlinear CG");
      n.choice("Precondition", {"On", "Off"}, "Off");
      n.choice("Orthogonalize", {"Fletcher-Reeves", "Polak-Ribiere"}, "Fletcher-Reeves");
      if (n.has("Restart Frequency") && n.integer("Restart Frequency") < 1)
        throw InputError(n.pathOf("Restart Frequency"), "must be >= 1");
      if (n.has("Update Jacobian")) {
        const long long every = n.integer("Update Jacobian");
        if (every < 1) throw InputError(n.pathOf("Update Jacobian"), "must be >= 1");
        c.maxAgeOfPrec = static_cast<int>(every);
      }
      if (n.isSublist("Linear Solver")) {
        const int age = c.maxAgeOfPrec;
        readLinearSolver(n.sublist("Linear Solver"), preconditioner,
                         static_cast<int>(peridigmMaxAge), c);
        if (n.has("Update Jacobian")) c.maxAgeOfPrec = age;
      }
      n.finish();
    }
    if (d.isSublist("Steepest Descent")) {
      ListReader n = d.sublist("Steepest Descent");
      n.choice("Scaling Type", {"2-Norm", "Quadratic Model Min Reduction", "F 2-Norm", "None"},
               "2-Norm");
      n.finish();
    }
    d.finish();
  } else {
    direction.set("Method", "Newton");
  }
  if (nox.isSublist("Line Search")) {
    checkLineSearch(nox.sublist("Line Search"));
    c.nox->sublist("Line Search") = nox.list().sublist("Line Search");
  }
  if (nox.isSublist("Solver Options")) {
    ListReader o = nox.sublist("Solver Options");
    o.choice("Status Test Check Type", {"Complete", "Minimal", "None"}, "Minimal");
    o.finish();
    c.nox->sublist("Solver Options") = nox.list().sublist("Solver Options");
  }
  if (nox.isSublist("Printing")) {
    ListReader p = nox.sublist("Printing");
    c.outputPrecision = static_cast<int>(p.integer("Output Precision", 3));
    c.outputProcessor = static_cast<int>(p.integer("Output Processor", 0));
    // Peridigm sets Output Information itself (from Verbose), whatever the deck says.
    p.accept("Output Information");
    p.accept("MyPID");
    p.finish();
  }
  nox.finish();
  return c;
}

}  // namespace peridot
