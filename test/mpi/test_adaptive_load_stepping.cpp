// QuasiStatic's Adaptive Load-Stepping at 1-3 ranks, each against an independent run: the
// halvings a large-strain step needs are predicted by plain QuasiStatic runs with 2^k steps,
// and the adaptive run must then be that fixed-step run; a cut step with bonds breaking restarts
// from the committed state (the same displacements and bond damage as a run that took the
// smaller steps from the start); exhausted reductions stop with the documented error; Switch to
// Verlet continues as a chained QuasiStatic + Verlet deck would; an attempt whose residual is
// not finite is a failed attempt (cut and retried), not a stop.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include "../common/StaticBar.hpp"
#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "materials/Elastic.hpp"
#include "output/ExodusCompare.hpp"
#include "solvers/QuasiStatic.hpp"

namespace peridot {
namespace {

// A test double, registered in this test executable only: Peridigm's "Elastic" whose force
// density is NaN at every point when the evaluation's time step (a load step's length) exceeds
// Longest Finite Step, as a model whose update fails for too large an increment. At shorter
// steps it is "Elastic" to the bit.
class ElasticNonFiniteForLongSteps : public Elastic {
 public:
  explicit ElasticNonFiniteForLongSteps(ListReader& p)
      : Elastic(p), longest_(p.positiveNumber("Longest Finite Step")) {}
  void computeForce(const ModelState& s, const std::vector<int>& points) override {
    Elastic::computeForce(s, points);
    if (!(s.dt > longest_)) return;
    for (int i : points)
      if (i < s.topology->numOwned)
        for (int d = 0; d < 3; ++d)
          s.forceDensity[3 * i + d] = std::numeric_limits<double>::quiet_NaN();
  }

 private:
  double longest_;
};

}  // namespace

PERIDOT_REGISTER_MATERIAL("Test Elastic NonFinite For Long Steps", ElasticNonFiniteForLongSteps,
                          "test double: Elastic with a NaN force density for load steps longer "
                          "than Longest Finite Step",
                          (std::vector<ParameterDoc>{
                              {"Longest Finite Step", "positive number: the longest step"}}))

namespace {

std::unique_ptr<Simulation> makeSimulation(const std::string& yaml) {
  static std::ostringstream runLog;
  auto deck = parseDeck(yaml, "yaml");
  return std::make_unique<Simulation>(readRunConfig(*deck), MPI_COMM_WORLD, runLog);
}

// The static bar pulled along x by its end layers, u_x = rate t x (no lateral motion held), LPS
// steel, optionally with a critical stretch.
std::string barProblem(double rate, double criticalStretch) {
  std::ostringstream v;
  v << rate << "*t*x";
  const std::string value[3] = {v.str(), "0.0", "0.0"};
  std::string material =
      "      Material Model: Elastic\n      Density: 7800.0\n      Young's Modulus: 200.0e9\n"
      "      Poisson's Ratio: 0.25\n";
  std::string deck = testing::staticBarProblemWith(material, value);
  if (criticalStretch > 0) {
    std::ostringstream d;
    d << "  Damage Models:\n    D:\n      Damage Model: Critical Stretch\n      Critical Stretch: "
      << criticalStretch << "\n";
    const std::string blocks = "  Blocks:\n";
    deck.insert(deck.find(blocks), d.str());
    const std::string horizon = "      Horizon: 1.51\n";
    deck.insert(deck.find(horizon) + horizon.size(), "      Damage Model: D\n");
  }
  return deck;
}

// A QuasiStatic list: `steps` is "Number of Load Steps: n" or "Time Steps: ...".
std::string quasiStatic(const std::string& steps, int maxIterations, const std::string& adaptive) {
  std::ostringstream d;
  d << "  Solver:\n    Final Time: 1.0\n    QuasiStatic:\n      " << steps
    << "\n      Relative Tolerance: 1.0e-8\n      Belos Relative Tolerance: 1.0e-12\n"
    << "      Maximum Solver Iterations: " << maxIterations << "\n"
    << adaptive;
  return d.str();
}

std::string adaptiveList(int inOne, int total, bool reduceAll, const std::string& more = "") {
  std::ostringstream d;
  d << "      Adaptive Load-Stepping:\n        Maximum load step reductions in one step: " << inOne
    << "\n        Maximum total load step reductions: " << total
    << "\n        Reduce all remaining load steps: " << (reduceAll ? "true" : "false") << "\n"
    << more;
  return d.str();
}

// The message of the RunError `run` throws, or "" if none.
template <class Run>
std::string runError(Run run) {
  try {
    run();
  } catch (const RunError& e) {
    return e.what();
  }
  return "";
}

// Owned values of a node field by global id, gathered to every rank (small problems only).
std::vector<double> gathered(Simulation& sim, const char* field, int components) {
  const Topology& t = sim.topology();
  std::vector<double> all(static_cast<std::size_t>(components * t.globalNumPoints), 0.0);
  const double* values = sim.fields().node(field, components);
  for (int i = 0; i < t.numOwned; ++i)
    for (int c = 0; c < components; ++c)
      all[static_cast<std::size_t>(components * t.overlapGlobalId[i] + c)] =
          values[components * i + c];
  MPI_Allreduce(MPI_IN_PLACE, all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  return all;
}

// Broken bonds per point by global id (every rank).
std::vector<double> brokenBonds(Simulation& sim) {
  const Topology& t = sim.topology();
  std::vector<double> all(static_cast<std::size_t>(t.globalNumPoints), 0.0);
  const auto& damage = sim.fields().bondFloat("Bond_Damage");
  for (int i = 0; i < t.numOwned; ++i)
    for (auto b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b)
      all[static_cast<std::size_t>(t.overlapGlobalId[i])] += damage[b];
  MPI_Allreduce(MPI_IN_PLACE, all.data(), static_cast<int>(all.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  return all;
}

std::string timeSteps(const std::vector<double>& times) {
  std::ostringstream d;
  d.precision(17);
  d << "Time Steps: \"";
  for (std::size_t k = 0; k < times.size(); ++k) d << (k ? " " : "") << times[k];
  d << "\"";
  return d.str();
}

// The ends of the converged load steps, after the initial time 0.
std::vector<double> convergedTimes(Simulation& sim) {
  std::vector<double> times{0.0};
  for (const auto& a : sim.quasiStatic()->statistics().attempts)
    if (a.converged) times.push_back(a.end);
  return times;
}

TEST(AdaptiveLoadStepping, HalvingsArePredictedByFixedStepRunsAndTheStateIsTheirs) {
  // 20% strain in one load step with 3 Newton iterations does not converge. The rule halves the
  // first step until it converges: k halvings where 2^k fixed steps is the first plain run whose
  // first step converges. With Reduce all remaining load steps every later step has that length,
  // so the adaptive run must be the 2^k-step run, to the bit (the same operations).
  const std::string problem = barProblem(0.2, 0.0);
  int k = -1;
  std::unique_ptr<Simulation> fixed;
  for (int j = 0; j <= 5 && k < 0; ++j) {
    auto plain = makeSimulation(
        problem + quasiStatic("Number of Load Steps: " + std::to_string(1 << j), 3, ""));
    const std::string message = runError([&] { plain->run(); });
    if (message.find("load step 1 ") == std::string::npos) {
      k = j;
      ASSERT_EQ(message, "") << "the 2^k-step run must complete";
      fixed = std::move(plain);
    }
  }
  ASSERT_GE(k, 1) << "the plain one-step run must fail for the test to mean anything";
  auto adaptive = makeSimulation(
      problem + quasiStatic("Number of Load Steps: 1", 3, adaptiveList(5, 10, true)));
  ASSERT_EQ(runError([&] { adaptive->run(); }), "");
  const auto& stats = adaptive->quasiStatic()->statistics();
  EXPECT_EQ(stats.reductions, k);
  EXPECT_EQ(adaptive->quasiStatic()->acceptedSteps(), 1LL << k);
  ASSERT_EQ(stats.attempts.size(), static_cast<std::size_t>(k + (1 << k)));
  for (int j = 0; j < k; ++j) EXPECT_FALSE(stats.attempts[j].converged) << j;
  EXPECT_EQ(adaptive->lastStep(), 1LL << k);
  EXPECT_EQ(adaptive->time(), 1.0);
  const auto u = gathered(*adaptive, "Displacement", 3);
  EXPECT_EQ(u, gathered(*fixed, "Displacement", 3));
  // And the end state is the equilibrium at 20% strain reached by many small steps, within the
  // solver tolerance (elastic: path independent). Relative Tolerance 1e-8 of the reaction, a
  // step accepted within 100x: 1e-6 of the largest displacement bounds it.
  auto fine = makeSimulation(problem + quasiStatic("Number of Load Steps: 16", 3, ""));
  ASSERT_EQ(runError([&] { fine->run(); }), "");
  const auto uFine = gathered(*fine, "Displacement", 3);
  double largest = 0, difference = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    largest = std::max(largest, std::fabs(uFine[i]));
    difference = std::max(difference, std::fabs(u[i] - uFine[i]));
  }
  EXPECT_LT(difference, 1e-6 * largest);
}

TEST(AdaptiveLoadStepping, AdaptiveOutputFrequencyDoublesPerHalving) {
  // The 20% strain bar in one step, cut k times (statistics), then 2^k steps of 1/2^k: with
  // Output Frequency 1 doubled per halving (2^k), records are due at the step numbers that are
  // multiples of 2^k: step 0 and the last (without the doubling, all 2^k + 1 records).
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  // One name on every rank (rank 0 writes the file).
  const std::string stem = "adaptive_output_frequency_test";
  const std::string output = "  Output:\n    Output Filename: " + stem +
                             "\n    Output Frequency: 1\n    Output Variables:\n"
                             "      Displacement: true\n";
  auto sim = makeSimulation(
      barProblem(0.2, 0.0) +
      quasiStatic("Number of Load Steps: 1", 3,
                  adaptiveList(5, 10, true, "        Adaptive output frequency: true\n")) +
      output);
  ASSERT_EQ(runError([&] { sim->run(); }), "");
  const int k = sim->quasiStatic()->statistics().reductions;
  ASSERT_GE(k, 2);
  EXPECT_EQ(sim->quasiStatic()->acceptedSteps(), 1LL << k);
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0) {
    const auto results = readExodusResults(stem + ".e");
    ASSERT_EQ(results.times.size(), 2u);
    EXPECT_EQ(results.times[0], 0.0);
    EXPECT_EQ(results.times[1], 1.0);
    std::remove((stem + ".e").c_str());
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

// The bar with a critical stretch of 0.6% pulled to 1% strain: bonds break from t ~ 0.4 on
// and Newton stalls there (observed: steps of 1/16 fail from t = 0.375).
const double kRate = 0.01, kStretch = 0.006;

TEST(AdaptiveLoadStepping, ACutStepWithBreakingBondsRestartsFromTheCommittedState) {
  const std::string problem = barProblem(kRate, kStretch);
  std::vector<double> sixteenths;
  for (int j = 0; j <= 7; ++j) sixteenths.push_back(j / 16.0);
  auto adaptive =
      makeSimulation(problem + quasiStatic(timeSteps(sixteenths), 4, adaptiveList(5, 20, false)));
  ASSERT_EQ(runError([&] { adaptive->run(); }), "");
  const auto& stats = adaptive->quasiStatic()->statistics();
  ASSERT_GT(stats.reductions, 0) << "the test needs a cut step";
  // Reduce all remaining load steps false: a cut step's other half is the next step, and the
  // original step ends stay step ends.
  const auto times = convergedTimes(*adaptive);
  for (double t : sixteenths) EXPECT_NE(std::find(times.begin(), times.end(), t), times.end()) << t;
  EXPECT_EQ(times.size(), sixteenths.size() + static_cast<std::size_t>(stats.reductions));
  // The run that takes the converged steps from the start.
  auto fixed = makeSimulation(problem + quasiStatic(timeSteps(times), 4, ""));
  ASSERT_EQ(runError([&] { fixed->run(); }), "");
  const auto broken = brokenBonds(*adaptive);
  double total = 0;
  for (double b : broken) total += b;
  EXPECT_GT(total, 0.0) << "bonds must have broken by the end";
  EXPECT_EQ(broken, brokenBonds(*fixed));
  EXPECT_EQ(gathered(*adaptive, "Displacement", 3), gathered(*fixed, "Displacement", 3));
}

TEST(AdaptiveLoadStepping, ACutStepOfAPlasticBarLeavesNoPlasticHistory) {
  // Elastic Plastic (yield strain 1e-3) pulled to 0.225% strain in three steps of 4 Newton
  // iterations: the first step fails and is halved. A failed attempt's evaluations are trials
  // (no history written), so Lambda and the displacements must be those of a run that took the
  // converged steps from the start.
  std::ostringstream v;
  v << 0.003 << "*t*x";
  const std::string value[3] = {v.str(), "0.0", "0.0"};
  const std::string problem = testing::staticBarProblemWith(
      "      Material Model: Elastic Plastic\n      Density: 7800.0\n"
      "      Young's Modulus: 200.0e9\n      Poisson's Ratio: 0.25\n"
      "      Yield Stress: 200.0e6\n",
      value);
  const std::vector<double> quarters{0, 0.25, 0.5, 0.75};
  auto adaptive =
      makeSimulation(problem + quasiStatic(timeSteps(quarters), 4, adaptiveList(3, 6, false)));
  ASSERT_EQ(runError([&] { adaptive->run(); }), "");
  ASSERT_GT(adaptive->quasiStatic()->statistics().reductions, 0) << "the test needs a cut step";
  auto fixed = makeSimulation(problem + quasiStatic(timeSteps(convergedTimes(*adaptive)), 4, ""));
  ASSERT_EQ(runError([&] { fixed->run(); }), "");
  const auto lambda = gathered(*adaptive, "Lambda", 1);
  double total = 0;
  for (double l : lambda) total += l;
  EXPECT_GT(total, 0.0) << "the bar must have yielded";
  EXPECT_EQ(lambda, gathered(*fixed, "Lambda", 1));
  EXPECT_EQ(gathered(*adaptive, "Displacement", 3), gathered(*fixed, "Displacement", 3));
}

TEST(AdaptiveLoadStepping, ExhaustedReductionsStopWithTheDocumentedError) {
  std::vector<double> sixteenths;
  for (int j = 0; j <= 8; ++j) sixteenths.push_back(j / 16.0);
  auto sim = makeSimulation(barProblem(kRate, kStretch) +
                            quasiStatic(timeSteps(sixteenths), 4, adaptiveList(1, 1, false)));
  const std::string message = runError([&] { sim->run(); });
  EXPECT_NE(message.find("QuasiStatic: load step "), std::string::npos) << message;
  EXPECT_NE(message.find("did not converge after"), std::string::npos) << message;
  EXPECT_NE(message.find("Maximum"), std::string::npos) << message;
  EXPECT_NE(message.find("residual"), std::string::npos) << message;
  EXPECT_NE(message.find("Switch to Verlet"), std::string::npos) << message;
  EXPECT_NE(message.find("are in the files"), std::string::npos) << message;
  // The converged steps are done and counted; the run stopped before the final time.
  EXPECT_EQ(sim->quasiStatic()->statistics().reductions, 1);
  EXPECT_LT(sim->quasiStatic()->endTime(), 0.5);
}

TEST(AdaptiveLoadStepping, SwitchToVerletContinuesAsAChainedVerletRun) {
  // Time scaled by 1e-3 so that the explicit part is short: the quasi-static steps are the same
  // (rate independent). No reduction allowed: the first failed step switches.
  const double scale = 1e-3, dt = 1e-6;
  const std::string problem = barProblem(kRate / scale, kStretch);
  std::vector<double> times;
  for (int j = 0; j <= 7; ++j) times.push_back(scale * j / 16.0);
  std::ostringstream verlet;
  verlet << "        Switch to Verlet:\n          Fixed dt: " << dt << "\n";
  auto switched = makeSimulation(
      problem + quasiStatic(timeSteps(times), 4, adaptiveList(0, 0, false, verlet.str())));
  std::vector<std::pair<long long, double>> records;
  switched->setStepObserver([&](long long s, double t) { records.push_back({s, t}); });
  ASSERT_EQ(runError([&] { switched->run(); }), "");
  ASSERT_TRUE(switched->switchedToVerlet());
  const double switchTime = switched->quasiStatic()->switchTime();
  const long long converged = switched->quasiStatic()->acceptedSteps();
  ASSERT_LT(switchTime, times.back());
  // The chained deck: QuasiStatic to the switch time, then Verlet to the final time.
  std::vector<double> before(times.begin(), times.begin() + converged + 1);
  ASSERT_EQ(before.back(), switchTime);
  std::string chained = problem;
  std::ostringstream solvers;
  solvers.precision(17);
  solvers << "  Solver1:\n    Initial Time: 0.0\n    Final Time: " << switchTime
          << "\n    QuasiStatic:\n      " << timeSteps(before)
          << "\n      Relative Tolerance: 1.0e-8\n      Belos Relative Tolerance: 1.0e-12\n"
          << "      Maximum Solver Iterations: 4\n"
          << "  Solver2:\n    Initial Time: " << switchTime << "\n    Final Time: " << times.back()
          << "\n    Verlet:\n      Fixed dt: " << dt << "\n";
  auto reference = makeSimulation(chained + solvers.str());
  std::vector<std::pair<long long, double>> referenceRecords;
  reference->setStepObserver([&](long long s, double t) { referenceRecords.push_back({s, t}); });
  ASSERT_EQ(runError([&] { reference->run(); }), "");
  // The record stream continues across the switch: steps and times as the chained run's.
  EXPECT_EQ(records, referenceRecords);
  ASSERT_FALSE(records.empty());
  EXPECT_GT(records.back().first, converged + 1);
  EXPECT_NEAR(records.back().second, times.back(), dt);
  EXPECT_EQ(gathered(*switched, "Displacement", 3), gathered(*reference, "Displacement", 3));
  EXPECT_EQ(gathered(*switched, "Velocity", 3), gathered(*reference, "Velocity", 3));
  EXPECT_EQ(brokenBonds(*switched), brokenBonds(*reference));
}

// The bar at 0.2% strain in the test double above with steps longer than `longest` NaN.
std::string nonFiniteBar(double longest) {
  std::ostringstream m;
  m << "      Material Model: Test Elastic NonFinite For Long Steps\n      Density: 7800.0\n"
       "      Young's Modulus: 200.0e9\n      Poisson's Ratio: 0.25\n"
       "      Longest Finite Step: "
    << longest << "\n";
  const std::string value[3] = {"0.002*t*x", "0.0", "0.0"};
  return testing::staticBarProblemWith(m.str(), value);
}

TEST(AdaptiveLoadStepping, ANonFiniteResidualIsAFailedAttemptThatIsCut) {
  // One load step of length 1: its residual is NaN. Cut once, the halves (length 0.5) are
  // finite and converge; the run must then be the plain Elastic run with the steps 0, 0.5, 1
  // from the start, to the bit.
  auto adaptive = makeSimulation(
      nonFiniteBar(0.6) + quasiStatic("Number of Load Steps: 1", 10, adaptiveList(3, 3, false)));
  ASSERT_EQ(runError([&] { adaptive->run(); }), "");
  const auto& stats = adaptive->quasiStatic()->statistics();
  EXPECT_EQ(stats.reductions, 1);
  ASSERT_EQ(stats.attempts.size(), 3u);
  EXPECT_FALSE(stats.attempts[0].converged);
  EXPECT_EQ(stats.attempts[0].end, 1.0);
  EXPECT_TRUE(stats.attempts[1].converged);
  EXPECT_EQ(stats.attempts[1].end, 0.5);
  EXPECT_TRUE(stats.attempts[2].converged);
  EXPECT_EQ(adaptive->time(), 1.0);
  auto plain =
      makeSimulation(barProblem(0.002, 0.0) + quasiStatic(timeSteps({0.0, 0.5, 1.0}), 10, ""));
  ASSERT_EQ(runError([&] { plain->run(); }), "");
  const auto u = gathered(*adaptive, "Displacement", 3);
  EXPECT_EQ(u, gathered(*plain, "Displacement", 3));
  double largest = 0;
  for (double v : u) largest = std::max(largest, std::fabs(v));
  EXPECT_GT(largest, 0.0) << "the bar must have been pulled";
}

TEST(AdaptiveLoadStepping, NonFiniteResidualsUntilTheCutsAreExhaustedStopWithTheDocumentedError) {
  // Steps longer than 0.2 are NaN; one reduction allowed: [0, 1] and [0, 0.5] fail, and the run
  // stops with the exhausted error saying why the last attempt failed.
  auto sim = makeSimulation(nonFiniteBar(0.2) +
                            quasiStatic("Number of Load Steps: 1", 10, adaptiveList(1, 1, false)));
  const std::string message = runError([&] { sim->run(); });
  EXPECT_NE(message.find("QuasiStatic: load step 1 (time 0 -> 0.5) did not converge after 1"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("the residual is not finite"), std::string::npos) << message;
  EXPECT_EQ(sim->quasiStatic()->statistics().attempts.size(), 2u);
  // Without Adaptive Load-Stepping the same attempt stops the run at once, as before.
  auto plain = makeSimulation(nonFiniteBar(0.2) + quasiStatic("Number of Load Steps: 1", 10, ""));
  EXPECT_EQ(runError([&] { plain->run(); }),
            "QuasiStatic: the residual is not finite (a force or displacement diverged)");
}

}  // namespace
}  // namespace peridot
