// NOXQuasiStatic (NOX over Tpetra) at 1-3 ranks, against Peridot's own QuasiStatic Newton on the
// same bar, against adaptive dynamic relaxation for a material without a tangent, a linear
// problem in one Newton step, and its errors.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "../common/StaticBar.hpp"
#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "solvers/NOXQuasiStatic.hpp"
#include "solvers/QuasiStatic.hpp"

namespace peridot {
namespace {

std::unique_ptr<Simulation> makeSimulation(const std::string& yaml) {
  static std::ostringstream runLog;
  auto deck = parseDeck(yaml, "yaml");
  return std::make_unique<Simulation>(readRunConfig(*deck), MPI_COMM_WORLD, runLog);
}

template <class Exception, class Make>
std::string errorOf(Make make) {
  try {
    make();
  } catch (const Exception& e) {
    return e.what();
  }
  return "";
}

// A NOXQuasiStatic list: `direction` is the Direction list's body (8-space indented).
std::string noxSolver(int loadSteps, double relativeTolerance, const std::string& direction,
                      const std::string& lineSearch = "Full Step",
                      const std::string& peridigmPreconditioner = "None", int maxIterations = 50) {
  std::ostringstream d;
  d << "  Solver:\n    Final Time: 1.0\n    Peridigm Preconditioner: " << peridigmPreconditioner
    << "\n    NOXQuasiStatic:\n      Nonlinear Solver: Line Search Based\n"
    << "      Number of Load Steps: " << loadSteps
    << "\n      Max Solver Iterations: " << maxIterations
    << "\n      Relative Tolerance: " << relativeTolerance << "\n      Direction:\n"
    << direction << "      Line Search:\n        Method: \"" << lineSearch << "\"\n";
  return d.str();
}

std::string newton(const std::string& jacobian, const std::string& preconditioner,
                   double linearTolerance = 1e-12) {
  std::ostringstream d;
  d << "        Method: Newton\n        Newton:\n          Forcing Term Method: Constant\n"
       "          Linear Solver:\n            Jacobian Operator: \""
    << jacobian << "\"\n            Preconditioner: \"" << preconditioner
    << "\"\n            Aztec Solver: GMRES\n            Max Iterations: 2000\n"
       "            Tolerance: "
    << linearTolerance << "\n";
  return d.str();
}

const std::string kNonlinearCG =
    "        Method: NonlinearCG\n        Nonlinear CG:\n          Restart Frequency: 50\n"
    "          Precondition: \"On\"\n          Orthogonalize: Polak-Ribiere\n"
    "          Linear Solver:\n            Preconditioner: \"User Defined\"\n";

std::string quasiStaticSolver(int loadSteps, double relativeTolerance) {
  std::ostringstream d;
  d << "  Solver:\n    Final Time: 1.0\n    Peridigm Preconditioner: Full Tangent\n"
       "    QuasiStatic:\n      Number of Load Steps: "
    << loadSteps << "\n      Relative Tolerance: " << relativeTolerance
    << "\n      Maximum Solver Iterations: 20\n      Belos Relative Tolerance: 1.0e-12\n";
  return d.str();
}

// Owned displacements after a run, by global id (gathered: the same at any rank count).
std::vector<double> displacements(Simulation& sim) {
  const Topology& t = sim.topology();
  const double* u = sim.fields().node("Displacement", 3);
  std::vector<double> local(3 * t.globalNumPoints, 0.0), all(3 * t.globalNumPoints, 0.0);
  for (int i = 0; i < t.numOwned; ++i) {
    const long long g = t.ownedMap->getGlobalElement(i);
    for (int d = 0; d < 3; ++d) local[3 * g + d] = u[3 * i + d];
  }
  MPI_Allreduce(local.data(), all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  return all;
}

// max |a - b| / max |b|.
double relativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0, largest = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    worst = std::max(worst, std::fabs(a[k] - b[k]));
    largest = std::max(largest, std::fabs(b[k]));
  }
  EXPECT_GT(largest, 0.0);
  return worst / largest;
}

// Both solvers stop when ||V f|| over the free components is below 1e-10 x the reactions; the
// displacement error that leaves is at most cond(K) x 1e-10 of the displacements, and this
// bar's stiffness has a condition number below 1e4 (its Lanczos estimate: 1.3e3), so two
// converged solutions agree within 1e-6 of the largest displacement. A wrong Jacobian, load or
// boundary condition moves them by the strain's own order.
const double kRelativeTolerance = 1e-10;
const double kAgreement = 1e-6;

TEST(QuasiStaticNOX, NewtonAndNonlinearCGMatchQuasiStatic) {
  const double strain = 1e-3;
  auto reference =
      makeSimulation(testing::staticBarProblem(strain) + quasiStaticSolver(2, kRelativeTolerance));
  reference->run();
  const auto expected = displacements(*reference);
  struct Case {
    const char* name;
    std::string direction, lineSearch, preconditioner;
  };
  const Case cases[] = {
      {"Newton, assembled, ILU", newton("Use Jacobian", "Ifpack"), "Full Step", "Full Tangent"},
      {"Newton, matrix-free", newton("Matrix-Free", "None", 1e-6), "Polynomial", "None"},
      {"Newton, matrix-free, Block 3x3", newton("Matrix-Free", "User Defined", 1e-6), "Backtrack",
       "Block 3x3"},
      {"NonlinearCG, Block 3x3", kNonlinearCG, "NonlinearCG", "Block 3x3"}};
  for (const auto& c : cases) {
    auto sim = makeSimulation(
        testing::staticBarProblem(strain) +
        noxSolver(2, kRelativeTolerance, c.direction, c.lineSearch, c.preconditioner, 2000));
    sim->run();
    const double difference = relativeDifference(displacements(*sim), expected);
    EXPECT_LT(difference, kAgreement) << c.name;
    const auto& stats = sim->noxQuasiStatic()->statistics();
    ASSERT_EQ(stats.nonlinearIterationsPerStep.size(), 2u) << c.name;
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0)
      std::printf("%s: %d + %d nonlinear, %lld linear iterations, %.2e from QuasiStatic\n", c.name,
                  stats.nonlinearIterationsPerStep[0], stats.nonlinearIterationsPerStep[1],
                  stats.linearIterations, difference);
  }
}

TEST(QuasiStaticNOX, LinearProblemConvergesInOneNewtonStep) {
  // At strain 1e-9 the residual is linear in u to ~1e-9 of the load: one Newton step with a
  // tight linear solve meets the relative tolerance 1e-6, assembled or matrix-free (whose
  // difference quotient is exact for a linear residual up to rounding, ~1e-10 relative).
  for (const char* jacobian : {"Use Jacobian", "Matrix-Free"}) {
    auto sim = makeSimulation(testing::staticBarProblem(1e-9) +
                              noxSolver(1, 1e-6, newton(jacobian, "None", 1e-8)));
    sim->run();
    const auto& stats = sim->noxQuasiStatic()->statistics();
    ASSERT_EQ(stats.nonlinearIterationsPerStep.size(), 1u);
    EXPECT_EQ(stats.nonlinearIterationsPerStep[0], 1) << jacobian;
    std::vector<double> g;
    sim->variables().globalVariable("Nonlinear_Solver_Iterations", g);
    ASSERT_EQ(g.size(), 1u);
    EXPECT_EQ(g[0], 1.0);
  }
}

TEST(QuasiStaticNOX, MatrixFreeSolvesMaterialsWithoutTangent) {
  // These materials have no analytic tangent (the assembled path probes one). Matrix-free Newton
  // must reach the equilibrium adaptive dynamic relaxation (no tangent either; an independent
  // iteration) finds on the same bar. ADR stops at ||V f|| <= 1e-9 x the reactions, NOX at
  // 1e-10: with cond(K) < 1e4 both are within 1e-5 of the displacements.
  const char* materials[] = {
      "      Material Model: Linearized LPS\n      Density: 7800.0\n"
      "      Bulk Modulus: 133.3e9\n      Shear Modulus: 80.0e9\n",
      "      Material Model: Continuum Kinematics\n      Density: 7800.0\n"
      "      Young's Modulus: 200.0e9\n      Poisson's Ratio: 0.25\n",
      "      Material Model: Elastic Correspondence\n      Density: 7800.0\n"
      "      Bulk Modulus: 133.3e9\n      Shear Modulus: 80.0e9\n"
      "      Hourglass Coefficient: 0.02\n"
      "      Stress Integration: Total Lagrangian Green Strain\n"};
  for (const char* material : materials) {
    const std::string problem = testing::staticBarProblem(1e-3, material);
    auto relaxation =
        makeSimulation(problem +
                       "  Solver:\n    Final Time: 1.0\n    Adaptive Dynamic Relaxation:\n"
                       "      Number of Load Steps: 1\n      Relative Tolerance: 1.0e-9\n");
    relaxation->run();
    auto nox = makeSimulation(
        problem + noxSolver(1, 1e-10, newton("Matrix-Free", "None", 1e-6), "Polynomial"));
    nox->run();
    const double difference = relativeDifference(displacements(*nox), displacements(*relaxation));
    EXPECT_LT(difference, 1e-5) << material;
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0)
      std::printf("matrix-free vs ADR: %.2e (%d Newton iterations)\n", difference,
                  nox->noxQuasiStatic()->statistics().nonlinearIterationsPerStep[0]);
    // And the assembled path, on the finite-difference tangent (solvers/FiniteDifferenceTangent).
    auto assembled = makeSimulation(problem + noxSolver(1, 1e-10, newton("Use Jacobian", "None")));
    assembled->run();
    EXPECT_LT(relativeDifference(displacements(*assembled), displacements(*relaxation)), 1e-5)
        << material;
  }
}

TEST(QuasiStaticNOX, NonConvergenceNamesStepIterationAndResidual) {
  auto sim = makeSimulation(testing::staticBarProblem(1e-3) +
                            noxSolver(2, 1e-10, kNonlinearCG, "NonlinearCG", "Block 3x3", 2));
  const std::string message = errorOf<RunError>([&] { sim->run(); });
  EXPECT_NE(message.find("load step 1"), std::string::npos) << message;
  EXPECT_NE(message.find("Max Solver Iterations (2) reached at iteration 2"), std::string::npos)
      << message;
  EXPECT_NE(message.find("residual"), std::string::npos) << message;
  EXPECT_NE(message.find("Number of Load Steps"), std::string::npos) << message;
}

// The plastic multiplier of every point, gathered by global id.
std::vector<double> lambdas(Simulation& sim) {
  const Topology& t = sim.topology();
  const double* lambda = sim.fields().node("Lambda", 1);
  std::vector<double> local(t.globalNumPoints, 0.0), all(t.globalNumPoints, 0.0);
  for (int i = 0; i < t.numOwned; ++i) local[t.ownedMap->getGlobalElement(i)] = lambda[i];
  MPI_Allreduce(local.data(), all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  return all;
}

// Elastic Plastic pulled to 5 times its yield strain in 4 load steps: NOX's trial evaluations
// must leave the history of the step's start alone and commit it once per converged step, as
// QuasiStatic does (on the probed tangent). Were the trials to commit, the plastic multiplier
// would grow with every residual NOX asks for and the two would part by far more than the
// solver tolerance.
TEST(QuasiStaticNOX, HistoryMaterialsMatchQuasiStatic) {
  const std::string plastic =
      "      Material Model: Elastic Plastic\n      Density: 7800.0\n"
      "      Bulk Modulus: 133.3e9\n      Shear Modulus: 80.0e9\n      Yield Stress: 1.0e8\n";
  const double strain = 2.5e-3;  // 5 x sigma_Y / E (E = 200 GPa)
  auto reference = makeSimulation(testing::staticBarProblem(strain, plastic) +
                                  quasiStaticSolver(4, kRelativeTolerance));
  reference->run();
  const auto expected = displacements(*reference);
  const auto expectedLambda = lambdas(*reference);
  double largestLambda = 0;
  for (double l : expectedLambda) largestLambda = std::max(largestLambda, l);
  ASSERT_GT(largestLambda, 0.0) << "the bar did not yield: the test would not test the history";
  for (const auto& jacobian : {"Matrix-Free", "Use Jacobian"}) {
    SCOPED_TRACE(jacobian);
    // Matrix-free products difference the residual across the yield surface, so the linear
    // tolerance stays at the products' accuracy and a line search guards the steps.
    auto sim = makeSimulation(
        testing::staticBarProblem(strain, plastic) +
        noxSolver(4, kRelativeTolerance, newton(jacobian, "None", 1e-8), "Polynomial"));
    sim->run();
    const double du = relativeDifference(displacements(*sim), expected);
    const double dl = relativeDifference(lambdas(*sim), expectedLambda);
    EXPECT_LT(du, kAgreement);
    EXPECT_LT(dl, kAgreement);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0)
      std::printf("[ NOX plastic %s ] displacement %.2e, Lambda %.2e (largest Lambda %.3e)\n",
                  jacobian, du, dl, largestLambda);
  }
}

TEST(QuasiStaticNOX, UnmappedOptionsAreRefused) {
  std::string ml = newton("Use Jacobian", "ML");
  const std::string message = errorOf<InputError>(
      [&] { makeSimulation(testing::staticBarProblem(1e-3) + noxSolver(1, 1e-6, ml)); });
  EXPECT_NE(message.find("Linear Solver -> Preconditioner"), std::string::npos) << message;
  EXPECT_NE(message.find("no counterpart"), std::string::npos) << message;
}

}  // namespace
}  // namespace peridot
