// The Implicit (Newmark) solver at 1-3 ranks: a one-degree-of-freedom spring against the
// closed-form Newmark recurrence, a vibrating LPS bar against a fine Verlet run (a second
// integrator) with second-order convergence in dt, energy conservation of the trapezoidal rule
// (and dissipation with gamma > 1/2), and the same nodal results as a one-rank run.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "output/ExodusCompare.hpp"
#include "solvers/Implicit.hpp"

namespace peridot {
namespace {

std::unique_ptr<Simulation> makeSimulation(const std::string& yaml,
                                           MPI_Comm comm = MPI_COMM_WORLD) {
  static std::ostringstream runLog;
  auto deck = parseDeck(yaml, "yaml");
  return std::make_unique<Simulation>(readRunConfig(*deck), comm, runLog);
}

std::string implicitSolver(double finalTime, double dt, double beta, double gamma) {
  std::ostringstream d;
  d.precision(17);
  d << "  Solver:\n    Final Time: " << finalTime << "\n    Implicit:\n      Fixed dt: " << dt
    << "\n      Beta: " << beta << "\n      Gamma: " << gamma
    << "\n      Absolute Tolerance: 1.0e-14\n      Maximum Solver Iterations: 10\n";
  return d.str();
}

// Two points one bond apart (x = 0.5 and 1.5, unit volumes), point 1 held, point 2 moving
// along the bond: a bond-based (PMB) spring is exactly linear along its axis, f_2 = -c u / l0
// V_1 with c = 18 K / (pi delta^4), so point 2 is an oscillator rho u'' = -c V_1 / l0 u.
std::string springDeck() {
  return "Peridigm:\n  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
         "    TensorProduct3DMeshGenerator:\n"
         "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
         "      X Length: 2.0\n      Y Length: 1.0\n      Z Length: 1.0\n"
         "      Number Points X: 2\n      Number Points Y: 1\n      Number Points Z: 1\n"
         "  Materials:\n    M:\n      Material Model: Elastic Bond Based\n      Density: 1.5\n"
         "      Bulk Modulus: 2.0\n"
         "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 1.5\n"
         "  Boundary Conditions:\n    Fixed Node Set: \"1\"\n    Moving Node Set: \"2\"\n"
         "    Fx:\n      Type: Prescribed Displacement\n      Node Set: Fixed Node Set\n"
         "      Coordinate: x\n      Value: \"0.0\"\n"
         "    Fy:\n      Type: Prescribed Displacement\n      Node Set: Fixed Node Set\n"
         "      Coordinate: y\n      Value: \"0.0\"\n"
         "    Fz:\n      Type: Prescribed Displacement\n      Node Set: Fixed Node Set\n"
         "      Coordinate: z\n      Value: \"0.0\"\n"
         "    V:\n      Type: Initial Velocity\n      Node Set: Moving Node Set\n"
         "      Coordinate: x\n      Value: \"0.01\"\n";
}

// u and v (x) of the point with global id `gid` (0-based), on every rank.
void pointState(Simulation& sim, long long gid, double* uv) {
  const Topology& t = sim.topology();
  const double* u = sim.fields().node("Displacement", 3);
  const double* v = sim.fields().node("Velocity", 3);
  double local[2] = {0, 0};
  for (int i = 0; i < t.numOwned; ++i)
    if (t.overlapGlobalId[i] == gid) {
      local[0] = u[3 * i];
      local[1] = v[3 * i];
    }
  MPI_Allreduce(local, uv, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

TEST(Implicit, SpringFollowsTheNewmarkRecurrence) {
  const double pi = std::acos(-1.0);
  const double rho = 1.5, K = 2.0, delta = 1.5;
  const double c = 18.0 * K / (pi * std::pow(delta, 4));
  const double omega2 = c * 1.0 / 1.0 / rho;  // V_1 = 1, l0 = 1
  struct Case {
    double beta, gamma;
  };
  for (const Case& k : {Case{0.25, 0.5}, Case{0.3025, 0.6}, Case{1.0 / 6.0, 0.5}}) {
    const double dt = 0.4;
    const int steps = 25;
    auto sim =
        makeSimulation(springDeck() + implicitSolver(steps * dt + 1e-9, dt, k.beta, k.gamma));
    std::vector<double> us, vs;
    sim->setStepObserver([&](long long, double) {
      double uv[2];
      pointState(*sim, 1, uv);
      us.push_back(uv[0]);
      vs.push_back(uv[1]);
    });
    sim->run();
    ASSERT_EQ(us.size(), static_cast<std::size_t>(steps + 1));
    // The closed-form recurrence of Newmark's method for u'' = -omega^2 u.
    double u = 0, v = 0.01, a = -omega2 * u;
    double largest = 0, worst = 0;
    for (int n = 1; n <= steps; ++n) {
      const double uTilde = u + dt * v + 0.5 * dt * dt * (1 - 2 * k.beta) * a;
      const double vTilde = v + dt * (1 - k.gamma) * a;
      u = uTilde / (1 + k.beta * dt * dt * omega2);
      a = -omega2 * u;
      v = vTilde + k.gamma * dt * a;
      worst = std::max({worst, std::fabs(us[n] - u) / 0.01, std::fabs(vs[n] - v) / 0.01});
      largest = std::max(largest, std::fabs(u));
    }
    EXPECT_GT(largest, 0.005);  // it oscillates
    EXPECT_LT(worst, 1e-9) << "beta " << k.beta << " gamma " << k.gamma;
    EXPECT_EQ(sim->implicit()->statistics().newtonIterationsPerStep.size(),
              static_cast<std::size_t>(steps));
  }
}

const char* const kElasticBar =
    "      Material Model: Elastic\n      Density: 1.0\n"
    "      Bulk Modulus: 1.0\n      Shear Modulus: 0.6\n";

// A free LPS bar, 10 x 3 x 3 points 0.5 apart, vibrating from an initial velocity; `material` is
// the body of its material list.
std::string barDeck(const std::string& material = kElasticBar) {
  std::ostringstream all;
  for (int i = 1; i <= 90; ++i) all << i << (i < 90 ? " " : "");
  return "Peridigm:\n  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
         "    TensorProduct3DMeshGenerator:\n"
         "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
         "      X Length: 5.0\n      Y Length: 1.5\n      Z Length: 1.5\n"
         "      Number Points X: 10\n      Number Points Y: 3\n      Number Points Z: 3\n"
         "  Materials:\n    M:\n" +
         material +
         "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 1.01\n"
         "  Boundary Conditions:\n    All Node Set: \"" +
         all.str() +
         "\"\n    V:\n      Type: Initial Velocity\n      Node Set: All Node Set\n"
         "      Coordinate: x\n      Value: \"1.0e-4*cos(0.6283185307*x) + 3.0e-5*y\"\n";
}

// Owned displacements by global id, gathered on every rank.
std::vector<double> displacements(Simulation& sim) {
  const Topology& t = sim.topology();
  const double* u = sim.fields().node("Displacement", 3);
  std::vector<double> all(3 * static_cast<std::size_t>(t.globalNumPoints), 0.0);
  for (int i = 0; i < t.numOwned; ++i)
    for (int d = 0; d < 3; ++d) all[3 * t.overlapGlobalId[i] + d] = u[3 * i + d];
  MPI_Allreduce(MPI_IN_PLACE, all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  return all;
}

double maxDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::fabs(a[k] - b[k]));
  return worst;
}

TEST(Implicit, BarConvergesToVerletAtSecondOrder) {
  const double finalTime = 4.0;
  auto verlet = makeSimulation(barDeck() +
                               "  Solver:\n    Final Time: 4.0\n    Verlet:\n"
                               "      Fixed dt: 0.0025\n");
  verlet->run();
  const auto reference = displacements(*verlet);
  double scale = 0;
  for (double u : reference) scale = std::max(scale, std::fabs(u));
  ASSERT_GT(scale, 1e-5);
  std::vector<double> errors;
  for (double dt : {0.2, 0.1}) {
    auto sim = makeSimulation(barDeck() + implicitSolver(finalTime, dt, 0.25, 0.5));
    sim->run();
    errors.push_back(maxDifference(displacements(*sim), reference) / scale);
  }
  // Newmark's trapezoidal rule is second order: halving dt divides the error by ~4 (the Verlet
  // reference's own error is ~(0.0025/0.1)^2 smaller).
  EXPECT_LT(errors[1], 0.02) << errors[0] << " " << errors[1];
  EXPECT_GT(errors[0] / errors[1], 3.5) << errors[0] << " " << errors[1];
  EXPECT_LT(errors[0] / errors[1], 4.5) << errors[0] << " " << errors[1];
}

double totalEnergy(Simulation& sim) {
  std::vector<double> kinetic, stored;
  sim.variables().globalVariable("Global_Kinetic_Energy", kinetic);
  sim.variables().globalVariable("Global_Stored_Elastic_Energy", stored);
  return kinetic.at(0) + stored.at(0);
}

TEST(Implicit, TrapezoidalRuleConservesEnergyAndGammaDissipates) {
  // The small amplitude (strain ~1e-5) keeps the problem linear to ~1e-5, where the trapezoidal
  // rule conserves energy exactly; gamma = 0.6 (beta = (gamma + 1/2)^2 / 4) damps the high modes.
  for (double gamma : {0.5, 0.6}) {
    const double beta = 0.25 * (gamma + 0.5) * (gamma + 0.5);
    auto sim = makeSimulation(barDeck() + implicitSolver(8.0, 0.4, beta, gamma));
    double first = -1, low = 1e300, high = 0;
    sim->setStepObserver([&](long long step, double) {
      const double e = totalEnergy(*sim);
      if (step == 0) first = e;
      low = std::min(low, e);
      high = std::max(high, e);
    });
    sim->run();
    ASSERT_GT(first, 0);
    if (gamma == 0.5) {
      EXPECT_LT((high - low) / first, 1e-4) << "gamma 0.5";
    } else {
      EXPECT_LT(low / first, 0.999) << "gamma 0.6 keeps its energy";
    }
  }
}

// Owned values of a point field by global id, gathered on every rank.
std::vector<double> pointValues(Simulation& sim, const char* name) {
  const Topology& t = sim.topology();
  const double* f = sim.fields().node(name, 1);
  std::vector<double> all(static_cast<std::size_t>(t.globalNumPoints), 0.0);
  for (int i = 0; i < t.numOwned; ++i) all[t.overlapGlobalId[i]] = f[i];
  MPI_Allreduce(MPI_IN_PLACE, all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  return all;
}

// The vibrating bar made of Elastic Plastic with a yield stress below its peak stress: the
// displacements and plastic multipliers of Newmark (history committed once per converged step)
// converge to a fine Verlet run's (a second integrator) as dt falls, and no point's Lambda ever
// decreases. (Committing every Newton trial instead is not caught here: the iterates move
// monotonically, so that path gives nearly the same plastic strain; the NOX and probed-tangent
// tests catch it.)
TEST(Implicit, PlasticBarConvergesToVerletAndLambdaNeverDecreases) {
  const std::string material =
      "      Material Model: Elastic Plastic\n      Density: 1.0\n"
      "      Bulk Modulus: 1.0\n      Shear Modulus: 0.6\n      Yield Stress: 4.0e-5\n";
  auto verlet = makeSimulation(barDeck(material) +
                               "  Solver:\n    Final Time: 4.0\n    Verlet:\n"
                               "      Fixed dt: 0.0025\n");
  verlet->run();
  const auto reference = displacements(*verlet);
  const auto referenceLambda = pointValues(*verlet, "Lambda");
  double scale = 0, lambdaScale = 0;
  for (double u : reference) scale = std::max(scale, std::fabs(u));
  for (double l : referenceLambda) lambdaScale = std::max(lambdaScale, l);
  ASSERT_GT(lambdaScale, 0.0) << "the bar does not yield";
  std::vector<double> errors, lambdaErrors;
  for (double dt : {0.2, 0.1}) {
    auto sim = makeSimulation(barDeck(material) + implicitSolver(4.0, dt, 0.25, 0.5));
    std::vector<double> previous;
    int decreased = 0;
    sim->setStepObserver([&](long long, double) {
      const auto lambda = pointValues(*sim, "Lambda");
      for (std::size_t k = 0; k < previous.size(); ++k)
        if (lambda[k] < previous[k]) ++decreased;
      previous = lambda;
    });
    sim->run();
    EXPECT_EQ(decreased, 0) << "dt " << dt;
    errors.push_back(maxDifference(displacements(*sim), reference) / scale);
    lambdaErrors.push_back(maxDifference(pointValues(*sim, "Lambda"), referenceLambda) /
                           lambdaScale);
  }
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("  plastic bar vs Verlet: u %.3g -> %.3g, Lambda %.3g -> %.3g (peak %.3g)\n",
                errors[0], errors[1], lambdaErrors[0], lambdaErrors[1], lambdaScale);
  EXPECT_LT(errors[1], 0.05) << errors[0] << " " << errors[1];
  EXPECT_LT(errors[1], 0.6 * errors[0]) << errors[0] << " " << errors[1];
  EXPECT_LT(lambdaErrors[1], 0.1) << lambdaErrors[0] << " " << lambdaErrors[1];
}

TEST(Implicit, SameResultOnAnyRankCount) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::string deck = barDeck() + implicitSolver(2.0, 0.2, 0.25, 0.5);
  auto parallel = makeSimulation(deck);
  parallel->run();
  const auto mine = displacements(*parallel);
  // The whole problem on each rank alone: the one-rank result.
  auto serial = makeSimulation(deck, MPI_COMM_SELF);
  serial->run();
  const Topology& t = serial->topology();
  const double* u = serial->fields().node("Displacement", 3);
  double worst = 0, scale = 0;
  for (int i = 0; i < t.numOwned; ++i)
    for (int d = 0; d < 3; ++d) {
      worst = std::max(worst, std::fabs(u[3 * i + d] - mine[3 * t.overlapGlobalId[i] + d]));
      scale = std::max(scale, std::fabs(u[3 * i + d]));
    }
  ASSERT_EQ(t.numOwned, 90);
  // Not bitwise: the Krylov solver's dot products sum in another order on other rank counts;
  // Belos' relative tolerance 1e-10 bounds the difference.
  EXPECT_LT(worst, 1e-8 * scale) << worst << " of " << scale;
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

TEST(Implicit, BadParametersAreNamed) {
  std::string message =
      errorOf<InputError>([&] { makeSimulation(barDeck() + implicitSolver(1.0, 0.1, 0.0, 0.5)); });
  EXPECT_NE(message.find("Implicit -> Beta"), std::string::npos) << message;
  message =
      errorOf<InputError>([&] { makeSimulation(barDeck() + implicitSolver(1.0, 0.1, 0.25, 0.4)); });
  EXPECT_NE(message.find("Implicit -> Gamma"), std::string::npos) << message;
  message = errorOf<InputError>([&] {
    makeSimulation(barDeck() + implicitSolver(1.0, 0.1, 0.25, 0.5) + "      Line Search: true\n");
  });
  EXPECT_NE(message.find("Line Search"), std::string::npos) << message;
}

// Chained solvers. Two Verlet lists over [0, 1] and [1, 2] are one Verlet run over [0, 2]:
// the same state at the end and step numbers continuing. Not to the bit: the second list
// evaluates the forces at y = x + u, where the loop had y = x + u_old + dt v (one rounding
// apart): the bond stretches are differences of coordinates ~1 holding displacements ~1e-4, so
// that rounding is ~1e-12 of u (1.5e-12 measured); 1e-9 bounds it while a state not carried
// over (u, v or a) is off by its own order.
TEST(ImplicitChain, TwoVerletListsAreOneVerletRun) {
  auto one = makeSimulation(barDeck() +
                            "  Solver:\n    Final Time: 2.0\n    Verlet:\n"
                            "      Fixed dt: 0.05\n");
  one->run();
  auto chained = makeSimulation(barDeck() +
                                "  Solver1:\n    Final Time: 1.0\n    Verlet:\n"
                                "      Fixed dt: 0.05\n"
                                "  Solver2:\n    Initial Time: 1.0\n    Final Time: 2.0\n"
                                "    Verlet:\n      Fixed dt: 0.05\n");
  std::vector<long long> steps;
  chained->setStepObserver([&](long long step, double) { steps.push_back(step); });
  chained->run();
  const auto reference = displacements(*one);
  double scale = 0;
  for (double u : reference) scale = std::max(scale, std::fabs(u));
  EXPECT_LT(maxDifference(reference, displacements(*chained)), 1e-9 * scale);
  ASSERT_EQ(steps.size(), 41u);
  for (std::size_t k = 0; k < steps.size(); ++k) EXPECT_EQ(steps[k], static_cast<long long>(k));
  EXPECT_EQ(chained->lastStep(), 40);
}

// A bar pulled quasi-statically to a strain held from t = 1 on, then followed by Verlet and by
// Implicit: the preloaded bar is in equilibrium and the last load step holds the load (its
// displacement rate, the velocity handed on, is 0), so both dynamic solvers must keep it where
// it is. Every record goes to one Exodus file, times increasing.
TEST(ImplicitChain, PreloadThenVerletThenImplicitStaysInEquilibrium) {
  std::ostringstream left, right;
  for (int k = 0; k < 9; ++k) {
    left << 10 * k + 1 << " ";
    right << 10 * k + 10 << " ";
  }
  std::string deck = barDeck();
  deck = deck.substr(0, deck.find("    V:\n"));  // no initial velocity
  deck +=
      "    Left Node Set: \"" + left.str() + "\"\n    Right Node Set: \"" + right.str() + "\"\n";
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a)
    deck += std::string("    L") + axes[a] +
            ":\n      Type: Prescribed Displacement\n      Node Set: Left Node Set\n"
            "      Coordinate: " +
            axes[a] + "\n      Value: \"0.0\"\n";
  deck +=
      "    Rx:\n      Type: Prescribed Displacement\n      Node Set: Right Node Set\n"
      "      Coordinate: x\n      Value: \"if (t <= 1.0) { value = 0.001*t; } else { value = "
      "0.001; }\"\n"
      "  Solver1:\n    Initial Time: 0.0\n    QuasiStatic:\n      Time Steps: \"0 0.5 1 1.5\"\n"
      "      Relative Tolerance: 1.0e-11\n      Belos Relative Tolerance: 1.0e-12\n"
      "  Solver2:\n    Initial Time: 1.5\n    Final Time: 2.5\n    Verlet:\n"
      "      Fixed dt: 0.1\n"
      "  Solver3:\n    Initial Time: 2.5\n    Final Time: 3.5\n    Implicit:\n"
      "      Fixed dt: 0.25\n      Absolute Tolerance: 1.0e-16\n"
      "  Output:\n    Output Filename: implicit_chain_test\n    Output Frequency: 1\n"
      "    Output Variables:\n      Displacement: true\n";
  auto sim = makeSimulation(deck);
  std::vector<double> preload;
  double drift = 0, scale = 0;
  sim->setStepObserver([&](long long step, double) {
    const auto u = displacements(*sim);
    if (step == 3) preload = u;
    if (step > 3) drift = std::max(drift, maxDifference(u, preload));
  });
  sim->run();
  for (double u : preload) scale = std::max(scale, std::fabs(u));
  EXPECT_NEAR(scale, 0.001, 1e-12);
  EXPECT_LT(drift, 1e-7 * scale) << drift;
  EXPECT_EQ(sim->lastStep(), 3 + 10 + 4);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) {
    const auto file = readExodusResults("implicit_chain_test.e");
    ASSERT_EQ(file.times.size(), 18u);
    const double expected[] = {0.0, 0.5, 1.0, 1.5, 1.6, 2.5, 2.75, 3.5};
    const std::size_t at[] = {0, 1, 2, 3, 4, 13, 14, 17};
    for (int k = 0; k < 8; ++k) EXPECT_NEAR(file.times[at[k]], expected[k], 1e-12) << at[k];
  }
}

TEST(ImplicitChain, GapBetweenSolversIsNamed) {
  const std::string message = errorOf<InputError>([&] {
    makeSimulation(barDeck() +
                   "  Solver1:\n    Final Time: 1.0\n    Verlet:\n      Fixed dt: 0.05\n"
                   "  Solver2:\n    Initial Time: 1.5\n    Final Time: 2.0\n"
                   "    Verlet:\n      Fixed dt: 0.05\n");
  });
  EXPECT_NE(message.find("Solver2 -> Initial Time"), std::string::npos) << message;
  EXPECT_NE(message.find("Solver1"), std::string::npos) << message;
}

}  // namespace
}  // namespace peridot
