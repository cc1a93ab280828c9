// Finite-difference tangents and history models in the implicit solvers, at 1-3 ranks:
//  - the probed tangent (coloured central differences of whole trial evaluations) against the
//    analytic tangent of every material that has one, 3D and 2D;
//  - the probed tangent of materials without one against single-column central differences of
//    the residual (a second code path: one column at a time, no colouring);
//  - QuasiStatic on a bar: Elastic Correspondence against the uniform strain, and Elastic
//    Plastic loaded past yield and unloaded against the elastic-perfectly-plastic response
//    built from the run's own elastic slope; trial evaluations leave the history alone.
#include <gtest/gtest.h>
#include <mpi.h>

#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

#include "../common/RoughBlock.hpp"
#include "../common/StaticBar.hpp"
#include "../common/TangentColumns.hpp"
#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "solvers/QuasiStatic.hpp"

namespace peridot {
namespace {

// The rough 5^3 (or 5^2) block with a one-step QuasiStatic solver (not run).
std::string blockDeck(const std::string& material, bool planar) {
  return testing::roughBlockProblem(material, planar) +
         "  Solver:\n    Final Time: 1.0\n    QuasiStatic:\n      Number of Load Steps: 1\n";
}

std::string keys(const std::string& model, const std::string& more = "") {
  return "      Material Model: \"" + model + "\"\n      Density: 2.0\n" + more;
}

std::unique_ptr<Simulation> makeSimulation(const std::string& yaml) {
  static std::ostringstream runLog;
  auto deck = parseDeck(yaml, "yaml");
  return std::make_unique<Simulation>(readRunConfig(*deck), MPI_COMM_WORLD, runLog);
}

// Every entry of the owned matrix by (global row, global column).
std::map<std::pair<GlobalOrdinal, GlobalOrdinal>, double> entries(const CrsMatrix& A) {
  std::map<std::pair<GlobalOrdinal, GlobalOrdinal>, double> out;
  const auto rows = A.getRowMap();
  const auto cols = A.getColMap();
  for (std::size_t r = 0; r < A.getNodeNumRows(); ++r) {
    CrsMatrix::local_inds_host_view_type c;
    CrsMatrix::values_host_view_type v;
    A.getLocalRowView(static_cast<LocalOrdinal>(r), c, v);
    for (std::size_t k = 0; k < c.extent(0); ++k)
      out[{rows->getGlobalElement(static_cast<LocalOrdinal>(r)), cols->getGlobalElement(c(k))}] =
          v(k);
  }
  return out;
}

ProbeSettings probeOf(Simulation& sim) {
  ProbeSettings p;
  p.evaluator = &sim.evaluator();
  p.y = sim.fields().node("Coordinates", 3);
  p.v = sim.fields().node("Velocity", 3);
  p.f = sim.fields().node("Force_Density", 3);
  p.volume = sim.fields().node("Volume", 1);
  return p;
}

// max |K_analytic - K_probed| / max |K_analytic| over every entry (collective).
double probedAgainstAnalytic(Simulation& sim, int* colours, double* seconds) {
  QuasiStatic& qs = *sim.quasiStatic();
  qs.evaluate(0.0);
  const auto t0 = std::chrono::steady_clock::now();
  qs.assembleTangent();
  const auto t1 = std::chrono::steady_clock::now();
  const auto analytic = entries(*qs.tangent().matrix());
  ProbeSettings p = probeOf(sim);
  p.always = true;
  Tangent probed(sim.topology(), sim.blocks(), "test", p);
  const double* held = sim.fields().node("QuasiStatic_Held", 3);
  const auto t2 = std::chrono::steady_clock::now();
  probed.assemble(sim.evaluator().state(), sim.blocks(), held, 1.0);
  const auto t3 = std::chrono::steady_clock::now();
  *colours = probed.colours();
  seconds[0] = std::chrono::duration<double>(t1 - t0).count();
  seconds[1] = std::chrono::duration<double>(t3 - t2).count();
  const auto fd = entries(*probed.matrix());
  double worst = 0, largest = 0;
  for (const auto& [key, value] : analytic) {
    const auto it = fd.find(key);
    const double other = it == fd.end() ? 0.0 : it->second;
    worst = std::max(worst, std::fabs(value - other));
    largest = std::max(largest, std::fabs(value));
  }
  for (const auto& [key, value] : fd)
    if (!analytic.count(key)) worst = std::max(worst, std::fabs(value));
  double g[2] = {worst, largest};
  MPI_Allreduce(MPI_IN_PLACE, g, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_GT(g[1], 0.0);
  return g[0] / g[1];
}

// The probe is Peridigm's default, 1e-6 x the element radius (0.62 spacings here): central
// differences leave a truncation error ~ eps^2 |f'''| / 6 ~ 1e-13 relative and a rounding
// error ~ 1e-16 |y| / eps ~ 1e-9 relative; 1e-6 bounds both with room, while a wrong colouring
// or reach (a column lost or mixed with another) is an O(1) error.
TEST(FiniteDifferenceTangent, AgreesWithEveryAnalyticTangent) {
  struct Case {
    std::string material;
    bool planar;
  };
  const std::string lps = "      Bulk Modulus: 5.0\n      Shear Modulus: 3.0\n";
  const std::string bond = "      Bulk Modulus: 5.0\n";
  const Case cases[] = {
      {keys("Elastic", lps), false},
      {keys("Elastic Bond Based", bond), false},
      {keys("Normalized PMB", bond), false},
      {keys("Pals", lps), false},
      {keys("Elastic", lps + "      Plane Strain: true\n"), true},
      {keys("Elastic", lps + "      Plane Stress: true\n"), true},
      {keys("Elastic Bond Based", bond + "      Plane Stress: true\n"), true},
      {keys("Normalized PMB", bond + "      Plane Strain: true\n"), true},
  };
  for (const auto& c : cases) {
    auto sim = makeSimulation(blockDeck(c.material, c.planar));
    int colours = 0;
    double seconds[2] = {0, 0};
    const double error = probedAgainstAnalytic(*sim, &colours, seconds);
    EXPECT_LT(error, 1e-6) << c.material;
    EXPECT_GT(colours, 0);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) {
      std::printf("  %s%s: relative error %.2e, %d colours, analytic %.4f s, probed %.4f s\n",
                  c.material.substr(23, c.material.find('"', 23) - 23).c_str(),
                  c.planar ? " (2D)" : "", error, colours, seconds[0], seconds[1]);
    }
  }
}

// Largest |K_probed - K_column| over the columns of every third point, relative to the largest
// entry (test/common/TangentColumns.hpp); the tangent must be the probed one.
double probedAgainstColumns(Simulation& sim, bool planar) {
  const double error = testing::tangentAgainstColumns(sim, planar);
  EXPECT_TRUE(sim.quasiStatic()->tangent().finiteDifference());
  return error;
}

TEST(FiniteDifferenceTangent, MaterialsWithoutAnalyticTangentMatchColumnDifferences) {
  struct Case {
    std::string material;
    bool planar;
    double stepDt;  // > 0: the rate form integrates the displacement over a step this long
  };
  const std::string moduli = "      Bulk Modulus: 5.0\n      Shear Modulus: 3.0\n";
  const std::string green = moduli +
                            "      Hourglass Coefficient: 0.02\n"
                            "      Stress Integration: \"Total Lagrangian Green Strain\"\n";
  const Case cases[] = {
      {keys("Linearized LPS", moduli), false, 0.0},
      {keys("Elastic Correspondence", green), false, 0.0},
      {keys("Elastic Correspondence", moduli + "      Hourglass Coefficient: 0.02\n"), false, 1.0},
      {keys("Continuum Kinematics", "      Young's Modulus: 5.0\n      Poisson's Ratio: 0.3\n"),
       false, 0.0},
      {keys("Elastic Plastic", moduli + "      Yield Stress: 100.0\n"), false, 0.0},
      // Yielding (the return mapping differentiated): every point is plastic at this load.
      {keys("Elastic Plastic", moduli + "      Yield Stress: 0.002\n"), false, 0.0},
      {keys("Viscoplastic Needleman Correspondence",
            moduli + "      Hourglass Coefficient: 0.02\n      Yield Stress: 0.002\n"
                     "      Strain Hardening Exponent: 0.1\n      Rate Hardening Exponent: 0.05\n"
                     "      Reference Strain Rate: 1.0\n      Reference Strain 0: 0.01\n"
                     "      Reference Strain 1: 10.0\n"),
       false, 1.0},
      {keys("Viscoelastic", moduli + "      lambda_i: 0.5\n      tau b: 0.3\n"), false, 1.0},
      {keys("Linearized LPS", moduli + "      Plane Stress: true\n"), true, 0.0},
  };
  for (const auto& c : cases) {
    auto sim = makeSimulation(blockDeck(c.material, c.planar));
    if (c.stepDt > 0) sim->quasiStatic()->setStepDt(c.stepDt);
    EXPECT_LT(probedAgainstColumns(*sim, c.planar), 1e-6) << c.material;
  }
}

// The bar of test/common/StaticBar.hpp with its ends following u = eps(t) (x, -nu y, -nu z).
std::string barDeck(const std::string& material, const std::string& strain,
                    const std::string& steps) {
  const std::string value[3] = {"(" + strain + ")*x", "-0.25*(" + strain + ")*y",
                                "-0.25*(" + strain + ")*z"};
  std::ostringstream d;
  d << testing::staticBarProblemWith(material, value);
  d << "  Solver:\n    Final Time: 1.0\n    QuasiStatic:\n      Time Steps: \"" << steps
    << "\"\n      Relative Tolerance: 1.0e-8\n      Belos Relative Tolerance: 1.0e-12\n"
       "      Belos Linear Solver: BlockGMRES\n      Maximum Solver Iterations: 20\n";
  return d.str();
}

// Least-squares slope of u_x over x for the points of the middle 40% (x in (3, 7)).
double interiorStrain(Simulation& sim) {
  const Topology& t = sim.topology();
  const double* x = sim.fields().node("Model_Coordinates", 3);
  const double* u = sim.fields().node("Displacement", 3);
  double s[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < t.numOwned; ++i) {
    if (x[3 * i] < 3 || x[3 * i] > 7) continue;
    s[0] += 1;
    s[1] += x[3 * i];
    s[2] += u[3 * i];
    s[3] += x[3 * i] * x[3 * i];
    s[4] += x[3 * i] * u[3 * i];
  }
  MPI_Allreduce(MPI_IN_PLACE, s, 5, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return (s[0] * s[4] - s[1] * s[2]) / (s[0] * s[3] - s[1] * s[1]);
}

// Elastic Correspondence in both stress integrations under the bar's end strain: the interior
// carries the applied strain (correspondence F is exact for affine motion; the lateral surfaces
// leave a few percent, bounded as in the LPS bar test).
TEST(FiniteDifferenceTangent, CorrespondenceBarCarriesTheAppliedStrain) {
  const double strain = 1e-3;
  for (const char* integration : {"Total Lagrangian Green Strain", "Hypoelastic Rate"}) {
    const std::string material =
        keys("Elastic Correspondence",
             "      Young's Modulus: 200.0e9\n      Poisson's Ratio: 0.25\n"
             "      Hourglass Coefficient: 0.02\n      Stress Integration: \"" +
                 std::string(integration) + "\"\n");
    auto sim = makeSimulation(barDeck(material, "1.0e-3*t", "0 0.5 1.0"));
    sim->run();
    EXPECT_NEAR(interiorStrain(*sim) / strain, 1.0, 0.05) << integration;
    const auto& stats = sim->quasiStatic()->statistics();
    for (int n : stats.newtonIterationsPerStep) EXPECT_LE(n, 6) << integration;
  }
}

// Elastic Plastic (perfectly plastic): loaded to 3x the yield strain, unloaded to 2x. The axial
// force of the right end (sum of V f_x over its layer) follows the elastic-perfectly-plastic
// response built from the run's own elastic slope k (first step): on unloading it falls by
// exactly k x the strain decrement, the plastic multiplier of every point never decreases and
// does not move while unloading, and once the bar has yielded through further loading gains
// little force (the stress stays on the yield surface).
TEST(FiniteDifferenceTangent, ElasticPlasticBarLoadedPastYieldAndUnloaded) {
  const double E = 200.0e9, yieldStress = 200.0e6, yieldStrain = yieldStress / E;
  std::ostringstream material;
  material << keys("Elastic Plastic",
                   "      Young's Modulus: 200.0e9\n      Poisson's Ratio: "
                   "0.25\n      Yield Stress: 200.0e6\n");
  // eps(t) = 3 eps_y min(t, 2 - t): t = 0.05 is elastic (the truncated families at the surface
  // yield the bar near 0.8 sigma_Y), t = 1 the peak, t = 1.2 unloaded to 2.4 eps_y
  // (further, reverse yielding begins at the held ends).
  std::ostringstream strain;
  strain << 3 * yieldStrain << "*min(t,2-t)";
  auto sim = makeSimulation(
      barDeck(material.str(), strain.str(), "0 0.05 0.5 0.625 0.75 0.875 1.0 1.1 1.2"));
  const Topology& t = sim->topology();
  const double* x = sim->fields().node("Model_Coordinates", 3);
  const double* f = sim->fields().node("Force_Density", 3);
  const double* volume = sim->fields().node("Volume", 1);
  const double* lambda = sim->fields().node("Lambda", 1);
  std::vector<double> force, times, previousLambda(t.numOwned, 0.0);
  std::vector<double> largestLambda;
  std::vector<int> lambdaDecreased, lambdaMovedUnloading;
  sim->setStepObserver([&](long long, double time) {
    double local = 0;
    for (int i = 0; i < t.numOwned; ++i)
      if (x[3 * i] > 10 - 1.51) local -= volume[i] * f[3 * i];  // reaction of the held layer
    double total = 0;
    MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    double lmax = 0;
    for (int i = 0; i < t.numOwned; ++i) lmax = std::max(lmax, lambda[i]);
    MPI_Allreduce(MPI_IN_PLACE, &lmax, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    largestLambda.push_back(lmax);
    int decreased = 0, moved = 0;
    for (int i = 0; i < t.numOwned; ++i) {
      if (lambda[i] < previousLambda[i]) ++decreased;
      if (time > 1.0 + 1e-9 && lambda[i] != previousLambda[i]) ++moved;
      previousLambda[i] = lambda[i];
    }
    MPI_Allreduce(MPI_IN_PLACE, &decreased, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &moved, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    force.push_back(total);
    times.push_back(time);
    lambdaDecreased.push_back(decreased);
    lambdaMovedUnloading.push_back(moved);
  });
  sim->run();
  ASSERT_EQ(force.size(), 9u);
  auto eps = [&](double time) { return 3 * yieldStrain * std::min(time, 2 - time); };
  const double k = force[1] / eps(times[1]);  // elastic: the first step stays below yield
  EXPECT_GT(k, 0.0);
  EXPECT_EQ(largestLambda[1], 0.0);
  for (std::size_t s = 0; s < force.size(); ++s) {
    EXPECT_EQ(lambdaDecreased[s], 0) << "step " << s;
    EXPECT_EQ(lambdaMovedUnloading[s], 0) << "step " << s;
  }
  double peakLambda = 0;
  for (int i = 0; i < t.numOwned; ++i) peakLambda = std::max(peakLambda, lambda[i]);
  MPI_Allreduce(MPI_IN_PLACE, &peakLambda, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_GT(peakLambda, 0.0);  // it did yield
  // Elastic unloading from the peak (step 6, t = 1): F = F_peak - k (eps_peak - eps). The
  // geometric nonlinearity changes the slope by O(eps) ~ 3e-3 of k (eps_peak - eps) <= 1.3
  // sigma_Y A; a history advanced by trials or never committed is off by O(sigma_Y A).
  for (std::size_t s = 7; s < force.size(); ++s) {
    const double expected = force[6] - k * (eps(1.0) - eps(times[s]));
    EXPECT_NEAR(force[s] / (yieldStress * 4.0), expected / (yieldStress * 4.0), 1e-2)
        << "step " << s;
  }
  // On the yield surface: the last loading step (t 0.875 -> 1) gains far less than k would.
  const double gained = force[6] - force[5], elastic = k * (eps(1.0) - eps(0.875));
  EXPECT_LT(gained, 0.1 * elastic);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) {
    std::printf(
        "  elastic slope k = %.6g N (k / (E A) = %.4f); peak force / (sigma_Y A) = %.4f; "
        "last loading step gains %.3g of k\n",
        k, k / (E * 4.0), force[6] / (yieldStress * 4.0), gained / elastic);
  }
}

// Trials leave the history alone; one committing evaluation advances it.
TEST(FiniteDifferenceTangent, TrialEvaluationsKeepTheHistory) {
  std::ostringstream strain;
  strain << 3e-3 << "*t";
  auto sim = makeSimulation(barDeck(keys("Elastic Plastic",
                                         "      Young's Modulus: 200.0e9\n"
                                         "      Poisson's Ratio: 0.25\n"
                                         "      Yield Stress: 200.0e6\n"),
                                    strain.str(), "0 1"));
  const Topology& t = sim->topology();
  double* u = sim->fields().node("Displacement", 3);
  const double* x = sim->fields().node("Model_Coordinates", 3);
  const double* lambda = sim->fields().node("Lambda", 1);
  const double* f = sim->fields().node("Force_Density", 3);
  double* y = sim->fields().node("Coordinates", 3);
  for (int i = 0; i < t.numOwned; ++i) u[3 * i] = 3e-3 * x[3 * i];  // past yield everywhere
  for (int k = 0; k < 3 * t.numOwned; ++k) y[k] = x[k] + u[k];
  sim->evaluator().evaluate(1.0, false, false);
  const std::vector<double> first(f, f + 3 * t.numOwned);
  sim->evaluator().evaluate(1.0, false, false);
  double lambdaSum = 0;
  for (int i = 0; i < t.numOwned; ++i) lambdaSum += lambda[i];
  for (int k = 0; k < 3 * t.numOwned; ++k) ASSERT_EQ(f[k], first[k]);
  EXPECT_EQ(lambdaSum, 0.0);
  sim->evaluator().evaluate(1.0, false, true);  // commit: the same force, the history moves
  double largest = 0, difference = 0;
  for (int k = 0; k < 3 * t.numOwned; ++k) {
    largest = std::max(largest, std::fabs(first[k]));
    difference = std::max(difference, std::fabs(f[k] - first[k]));
  }
  // Bit-identical in exact arithmetic; the committing loop also stores the history, so the
  // compiler may vectorise its force sum differently: rounding (measured 3e-16) only.
  EXPECT_LT(difference, 1e-14 * largest);
  lambdaSum = 0;
  for (int i = 0; i < t.numOwned; ++i) lambdaSum += lambda[i];
  MPI_Allreduce(MPI_IN_PLACE, &lambdaSum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(lambdaSum, 0.0);
}

}  // namespace
}  // namespace peridot

namespace peridot {
namespace {

// Adaptive dynamic relaxation with the same history material and load steps reaches the same
// equilibria as QuasiStatic (a different solver: no tangent, trials relaxed to rest): the
// plastic multiplier at the end agrees within the solvers' tolerances.
TEST(FiniteDifferenceTangent, RelaxationAndQuasiStaticAgreeOnThePlasticBar) {
  const std::string material = keys("Elastic Plastic",
                                    "      Young's Modulus: 200.0e9\n      Poisson's Ratio: 0.25\n"
                                    "      Yield Stress: 200.0e6\n");
  const std::string strain = "3.0e-3*min(t,2-t)", steps = "0 0.5 1.0 1.2";
  std::string relaxation = barDeck(material, strain, steps);
  relaxation = relaxation.substr(0, relaxation.find("    QuasiStatic:")) +
               "    Adaptive Dynamic Relaxation:\n      Time Steps: \"" + steps +
               "\"\n      Relative Tolerance: 1.0e-7\n";
  std::vector<std::vector<double>> lambdas;
  for (const std::string& deck : {barDeck(material, strain, steps), relaxation}) {
    auto sim = makeSimulation(deck);
    sim->run();
    const double* lambda = sim->fields().node("Lambda", 1);
    lambdas.emplace_back(lambda, lambda + sim->topology().numOwned);
  }
  double largest = 0, difference = 0;
  for (std::size_t i = 0; i < lambdas[0].size(); ++i) {
    largest = std::max(largest, lambdas[0][i]);
    difference = std::max(difference, std::fabs(lambdas[0][i] - lambdas[1][i]));
  }
  double g[2] = {largest, difference};
  MPI_Allreduce(MPI_IN_PLACE, g, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_GT(g[0], 0.0);
  // Both stop at a residual ~1e-7 of the load: the equilibria differ at that order, the
  // plastic multiplier (a difference of strains near yield) at some ten times it.
  EXPECT_LT(g[1], 1e-4 * g[0]);  // 3e-6 measured
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) std::printf("  Lambda: ADR vs QuasiStatic %.3g of the largest\n", g[1] / g[0]);
}

}  // namespace
}  // namespace peridot
