// Adaptive dynamic relaxation at 1-3 ranks: its equilibria against QuasiStatic's (a second code
// path: Newton on the analytic tangent) for a 3D LPS bar and a 2D bond-based plate, bonds
// breaking with re-relaxation, the message of a step that does not relax, and deck errors.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "solvers/DynamicRelaxation.hpp"

namespace peridot {
namespace {

std::unique_ptr<Simulation> makeSimulation(const std::string& yaml) {
  static std::ostringstream runLog;
  return std::make_unique<Simulation>(readRunConfig(*parseDeck(yaml, "yaml")), MPI_COMM_WORLD,
                                      runLog);
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

// Points within `width` of x = 0 (left) and x = length (right) of a grid of unit spacing
// starting at 0.5, as id lists; `perLayer` points per x layer.
std::string idsWhere(int nx, int perLayer, bool left, double width) {
  std::ostringstream s;
  for (int i = 0; i < nx; ++i) {
    const double x = i + 0.5;
    if (left ? x < width : x > nx - width)
      for (int k = 0; k < perLayer; ++k) s << k * nx + i + 1 << " ";
  }
  return s.str();
}

// A bar (3D LPS, 16 x 3 x 3) or a plate (2D plane-stress bond-based, 16 x 6) pulled by its
// end layers, with a quadratic lateral load so that the solution is not a homogeneous strain.
std::string deck(bool planar, const std::string& solver, double criticalStretch = 0.0) {
  const int nx = 16, perLayer = planar ? 6 : 9;
  std::ostringstream d;
  d << "Peridigm:\n  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n";
  if (planar) {
    d << "    Thickness: 0.5\n    TensorProduct2DMeshGenerator:\n"
         "      X Origin: 0.0\n      Y Origin: 0.0\n      X Length: 16.0\n      Y Length: 6.0\n"
         "      Number Points X: 16\n      Number Points Y: 6\n";
  } else {
    d << "    TensorProduct3DMeshGenerator:\n"
         "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
         "      X Length: 16.0\n      Y Length: 3.0\n      Z Length: 3.0\n"
         "      Number Points X: 16\n      Number Points Y: 3\n      Number Points Z: 3\n";
  }
  d << "  Materials:\n    M:\n      Material Model: "
    << (planar ? "Elastic Bond Based\n      Plane Stress: true\n" : "Elastic\n")
    << "      Density: 2.0\n      Bulk Modulus: 5.0\n"
    << (planar ? "" : "      Shear Modulus: 3.0\n");
  if (criticalStretch > 0) {
    d << "  Damage Models:\n    D:\n      Damage Model: Critical Stretch\n"
      << "      Critical Stretch: " << criticalStretch << "\n";
  }
  d << "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 2.01\n"
    << (criticalStretch > 0 ? "      Damage Model: D\n" : "")
    << "  Boundary Conditions:\n    Left Node Set: \"" << idsWhere(nx, perLayer, true, 2.0)
    << "\"\n    Right Node Set: \"" << idsWhere(nx, perLayer, false, 2.0) << "\"\n"
    << "    Lx:\n      Type: Prescribed Displacement\n      Node Set: Left Node Set\n"
       "      Coordinate: x\n      Value: \"0.0\"\n"
       "    Ly:\n      Type: Prescribed Displacement\n      Node Set: Left Node Set\n"
       "      Coordinate: y\n      Value: \"0.0\"\n"
    << (planar ? ""
               : "    Lz:\n      Type: Prescribed Displacement\n      Node Set: Left Node Set\n"
                 "      Coordinate: z\n      Value: \"0.0\"\n")
    << "    Rx:\n      Type: Prescribed Displacement\n      Node Set: Right Node Set\n"
       "      Coordinate: x\n      Value: \"0.02*t\"\n"
       "    Sag:\n      Type: Body Force\n      Node Set: All Node Set\n      Coordinate: y\n"
       "      Value: \"-0.001*t*x*x\"\n"
    << "    All Node Set: \"";
  for (int i = 1; i <= nx * perLayer; ++i) d << i << " ";
  d << "\"\n  Solver:\n    Final Time: 1.0\n" << solver;
  return d.str();
}

const std::string kQuasiStatic =
    "    QuasiStatic:\n      Number of Load Steps: 2\n      Relative Tolerance: 1.0e-11\n"
    "      Maximum Solver Iterations: 20\n      Belos Relative Tolerance: 1.0e-13\n";
const std::string kRelaxation =
    "    Adaptive Dynamic Relaxation:\n      Number of Load Steps: 2\n"
    "      Relative Tolerance: 1.0e-11\n";

// Largest |u_a - u_b| over all points and components, relative to the largest |u_b|.
double relativeDifference(Simulation& a, Simulation& b) {
  std::vector<double> ua, ub;
  a.variables().nodeVariable("Displacement", ua);
  b.variables().nodeVariable("Displacement", ub);
  double local[2] = {0, 0};
  for (std::size_t k = 0; k < ua.size(); ++k) {
    local[0] = std::max(local[0], std::fabs(ua[k] - ub[k]));
    local[1] = std::max(local[1], std::fabs(ub[k]));
  }
  MPI_Allreduce(MPI_IN_PLACE, local, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return local[0] / local[1];
}

TEST(DynamicRelaxation, MatchesQuasiStaticIn3DAnd2D) {
  for (bool planar : {false, true}) {
    auto newton = makeSimulation(deck(planar, kQuasiStatic));
    newton->run();
    auto relaxed = makeSimulation(deck(planar, kRelaxation));
    relaxed->run();
    // Both stop at a residual of 1e-11 of the load; the equilibria agree to about that times
    // the condition of the stiffness (measured: ~1e-10).
    const double difference = relativeDifference(*relaxed, *newton);
    EXPECT_LT(difference, 1e-8) << (planar ? "2D" : "3D");
    const auto& stats = relaxed->dynamicRelaxation()->statistics();
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) {
      std::cout << (planar ? "2D" : "3D") << ": |u_ADR - u_QuasiStatic| / |u| = " << difference
                << ", iterations " << stats.iterationsPerStep[0] << " + "
                << stats.iterationsPerStep[1] << "\n";
    }
    ASSERT_EQ(stats.iterationsPerStep.size(), 2u);
    EXPECT_GT(stats.iterationsPerStep[0], 10);
    EXPECT_EQ(stats.relaxationsPerStep[0], 1);
    EXPECT_GT(stats.lambdaMax, 0.0);
    std::vector<double> g;
    relaxed->variables().globalVariable("Nonlinear_Solver_Iterations", g);
    ASSERT_EQ(g.size(), 1u);
    EXPECT_EQ(g[0], static_cast<double>(stats.iterationsPerStep[1]));
  }
}

TEST(DynamicRelaxation, BondsBreakAndTheStepRelaxesAgain) {
  // Pulled 0.02 over the 12 free units: a stretch ~1.7e-3 in the middle at t = 1, above the
  // critical 1.2e-3: bonds break in the second step and the bar is relaxed again.
  std::string text = deck(false, kRelaxation, 1.2e-3);
  // Without the lateral load: a piece that breaks free must stay in equilibrium.
  text.replace(text.find("-0.001*t*x*x"), 12, "0.0");
  text.replace(text.find("      Relative Tolerance: 1.0e-11"), 33,
               "      Relative Tolerance: 1.0e-8");
  auto sim = makeSimulation(text);
  sim->run();
  const auto& stats = sim->dynamicRelaxation()->statistics();
  ASSERT_EQ(stats.relaxationsPerStep.size(), 2u);
  EXPECT_EQ(stats.relaxationsPerStep[0], 1);  // t = 0.5: stretch below critical
  EXPECT_GT(stats.relaxationsPerStep[1], 1);
  std::vector<double> damageField;
  sim->variables().nodeVariable("Damage", damageField);
  double largest = 0;
  for (double d : damageField) largest = std::max(largest, d);
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_GT(largest, 0.0);
}

TEST(DynamicRelaxation, AReleasedBodyRelaxesWithoutAnyLoad) {
  // No prescribed displacement, no body force: the load is zero, and the criterion is relative
  // to the starting residual. A bar released from a stretch relaxes to (nearly) no strain.
  std::ostringstream d;
  d << "Peridigm:\n  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
       "    TensorProduct3DMeshGenerator:\n"
       "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
       "      X Length: 8.0\n      Y Length: 3.0\n      Z Length: 3.0\n"
       "      Number Points X: 8\n      Number Points Y: 3\n      Number Points Z: 3\n"
       "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 2.0\n"
       "      Bulk Modulus: 5.0\n      Shear Modulus: 3.0\n"
       "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 2.01\n"
       "  Boundary Conditions:\n    All Node Set: \"";
  for (int i = 1; i <= 72; ++i) d << i << " ";
  d << "\"\n    Stretch:\n      Type: Initial Displacement\n      Node Set: All Node Set\n"
       "      Coordinate: x\n      Value: \"0.01*x*x\"\n"
       "  Solver:\n    Final Time: 1.0\n    Adaptive Dynamic Relaxation:\n"
       "      Number of Load Steps: 1\n      Relative Tolerance: 1.0e-8\n";
  auto sim = makeSimulation(d.str());
  std::vector<double> before;
  sim->variables().globalVariable("Global_Stored_Elastic_Energy", before);
  sim->run();
  std::vector<double> after;
  sim->variables().globalVariable("Global_Stored_Elastic_Energy", after);
  ASSERT_GT(before[0], 0.0);
  EXPECT_LT(after[0], 1e-8 * before[0]);
}

TEST(DynamicRelaxation, AStepThatDoesNotRelaxIsReported) {
  std::string text = deck(false, kRelaxation + "      Maximum Iterations: 10\n");
  auto sim = makeSimulation(text);
  const std::string message = errorOf<RunError>([&] { sim->run(); });
  EXPECT_NE(message.find("load step 1"), std::string::npos) << message;
  EXPECT_NE(message.find("did not relax in 10 iterations"), std::string::npos) << message;
  EXPECT_NE(message.find("residual"), std::string::npos) << message;
  EXPECT_NE(message.find("Number of Load Steps"), std::string::npos) << message;
}

TEST(DynamicRelaxation, DeckErrorsNameTheKey) {
  std::string message = errorOf<InputError>(
      [&] { makeSimulation(deck(false, kRelaxation + "      Mass Safety Factor: 1.0\n")); });
  EXPECT_NE(message.find("Mass Safety Factor"), std::string::npos) << message;
  message = errorOf<InputError>(
      [&] { makeSimulation(deck(false, kRelaxation + "    Verlet:\n      Fixed dt: 0.1\n")); });
  EXPECT_NE(message.find("one solver list per Solver"), std::string::npos) << message;
  message = errorOf<InputError>(
      [&] { makeSimulation(deck(false, kRelaxation + "      Line Search: true\n")); });
  EXPECT_NE(message.find("Line Search"), std::string::npos) << message;
  // A damage law integrated over time would never grow under dt = 0: refused, for QuasiStatic too.
  for (const std::string& solver : {kRelaxation, kQuasiStatic}) {
    std::string text = deck(false, solver, 1e-3);
    text.replace(text.find("Damage Model: Critical Stretch"), 30, "Damage Model: LSJ-T");
    message = errorOf<InputError>([&] { makeSimulation(text); });
    EXPECT_NE(message.find("integrates over time"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace peridot
