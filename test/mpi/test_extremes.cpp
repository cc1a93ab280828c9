// Numerical stability at the extremes (issue 14, item 6): whole runs through the Simulation
// class at 1, 2 and 3 ranks. Each scene either runs correctly — checked against a closed form
// or a conservation law, so the test can fail — or must stop with a clear message:
//   one- and two-point bodies, a nearly incompressible LPS body (K/mu up to 1e6), a modulus
//   contrast of 1e6 between two blocks, horizons of 1.01 and 10 spacings, strains of 50%,
//   reflected (inverted) and collapsed bonds, a body spinning at high angular velocity, and
//   (ctest -L long) 10^7 steps of a two-point body.
#include <gtest/gtest.h>
#include <mpi.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

constexpr double kPi = 3.14159265358979323846;

int rankCount() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}
int myRank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

std::ostringstream runLog;  // outlives every Simulation that writes to it

std::unique_ptr<Simulation> makeSimulation(const std::string& yaml) {
  auto deck = parseDeck(yaml, "yaml");
  return std::make_unique<Simulation>(readRunConfig(*deck), MPI_COMM_WORLD, runLog);
}

// A text mesh (x y z block volume per line) written by rank 0. ctest runs this executable at 1,
// 2 and 3 ranks at once in one folder: the file name carries the rank count.
struct MeshFile {
  std::string name;
  MeshFile(const std::string& stem, const std::vector<std::array<double, 5>>& rows)
      : name("extremes_" + stem + "_np" + std::to_string(rankCount()) + ".txt") {
    if (myRank() == 0) {
      FILE* f = std::fopen(name.c_str(), "w");
      for (const auto& r : rows)
        std::fprintf(f, "%.17g %.17g %.17g %d %.17g\n", r[0], r[1], r[2], int(r[3]), r[4]);
      std::fclose(f);
    }
    MPI_Barrier(MPI_COMM_WORLD);
  }
  ~MeshFile() {
    MPI_Barrier(MPI_COMM_WORLD);
    if (myRank() == 0) std::remove(name.c_str());
  }
};

// An nx x ny x nz lattice of unit spacing and unit volume; points with x < split are block 1,
// the others block 2.
std::vector<std::array<double, 5>> lattice(int nx, int ny, int nz, double split = 1e300) {
  std::vector<std::array<double, 5>> rows;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        rows.push_back({double(i), double(j), double(k), i < split ? 1.0 : 2.0, 1.0});
  return rows;
}

std::string idList(std::size_t n) {
  std::ostringstream s;
  for (std::size_t i = 1; i <= n; ++i) s << i << (i < n ? " " : "");
  return s.str();
}

// The moduli lines of a material: bond-based models take Bulk Modulus alone.
std::string moduli(const std::string& model, double K, double mu) {
  std::ostringstream s;
  s.precision(17);
  s << "      Bulk Modulus: " << K << "\n";
  if (model == "Elastic" || model == "Linearized LPS") s << "      Shear Modulus: " << mu << "\n";
  return s.str();
}

struct Scene {
  std::string mesh;
  std::size_t numPoints = 0;
  // Material of block 1 and, when blockTwo is set, of block 2.
  std::string material = "Elastic Bond Based";
  double K1 = 1.0, mu1 = 1.0, K2 = 1.0, mu2 = 1.0;
  bool blockTwo = false;
  double horizon = 1.5;
  // Expressions of x, y, z per axis ("" = none).
  std::string u[3], v[3];
  // Fixed dt when > 0, else Peridigm's estimate with this safety factor.
  double dt = 0.0, safety = 0.5;
  std::string estimate;  // Stable Time Step Estimate ("" = Peridigm's)
  double finalTime = 1.0;
};

std::string deck(const Scene& s) {
  std::ostringstream d;
  d.precision(17);
  d << "Peridigm:\n  Discretization:\n    Type: Text File\n    Input Mesh File: " << s.mesh
    << "\n  Materials:\n    M1:\n      Material Model: \"" << s.material
    << "\"\n      Density: 1.0\n"
    << moduli(s.material, s.K1, s.mu1);
  if (s.blockTwo)
    d << "    M2:\n      Material Model: \"" << s.material << "\"\n      Density: 1.0\n"
      << moduli(s.material, s.K2, s.mu2);
  d << "  Blocks:\n    B1:\n      Block Names: block_1\n      Material: M1\n      Horizon: "
    << s.horizon << "\n";
  if (s.blockTwo)
    d << "    B2:\n      Block Names: block_2\n      Material: M2\n      Horizon: " << s.horizon
      << "\n";
  d << "  Boundary Conditions:\n    All Node Set: \"" << idList(s.numPoints) << "\"\n";
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    if (!s.u[a].empty())
      d << "    U" << axes[a] << ":\n      Type: Initial Displacement\n      Node Set: All Node "
        << "Set\n      Coordinate: " << axes[a] << "\n      Value: \"" << s.u[a] << "\"\n";
    if (!s.v[a].empty())
      d << "    V" << axes[a] << ":\n      Type: Initial Velocity\n      Node Set: All Node Set\n"
        << "      Coordinate: " << axes[a] << "\n      Value: \"" << s.v[a] << "\"\n";
  }
  d << "  Solver:\n    Final Time: " << s.finalTime << "\n    Verlet:\n";
  if (s.dt > 0)
    d << "      Fixed dt: " << s.dt << "\n";
  else
    d << "      Safety Factor: " << s.safety << "\n";
  if (!s.estimate.empty()) d << "      Stable Time Step Estimate: \"" << s.estimate << "\"\n";
  return d.str();
}

struct Energies {
  double kinetic = 0, stored = 0, accelerationTerm = 0, angular[3] = {0, 0, 0},
         momentum[3] = {0, 0, 0};
  bool finite = true;
};

// Sums over all ranks. accelerationTerm = 1/2 sum m |a|^2 (see test_dynamics.cpp: with it the
// leapfrog energy kinetic - (dt/2)^2 accelerationTerm + stored is velocity Verlet's invariant
// for a linear system, free of the O(dt^2) oscillation of kinetic + stored).
Energies energies(Simulation& sim) {
  const Topology& t = sim.topology();
  FieldManager& f = sim.fields();
  const double* y = f.node("Coordinates", 3);
  const double* v = f.node("Velocity", 3);
  const double* a = f.node("Acceleration", 3);
  const double* vol = f.node("Volume", 1);
  double local[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  int bad = 0;
  for (int i = 0; i < t.numOwned; ++i) {
    const double m = vol[i];  // density 1
    for (int d = 0; d < 3; ++d) {
      if (!std::isfinite(y[3 * i + d]) || !std::isfinite(v[3 * i + d])) bad = 1;
      local[0] += 0.5 * m * a[3 * i + d] * a[3 * i + d];
      local[4 + d] += m * v[3 * i + d];
    }
    local[1] += m * (y[3 * i + 1] * v[3 * i + 2] - y[3 * i + 2] * v[3 * i + 1]);
    local[2] += m * (y[3 * i + 2] * v[3 * i] - y[3 * i] * v[3 * i + 2]);
    local[3] += m * (y[3 * i] * v[3 * i + 1] - y[3 * i + 1] * v[3 * i]);
  }
  double global[9];
  MPI_Allreduce(local, global, 9, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  int anyBad = 0;
  MPI_Allreduce(&bad, &anyBad, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  Energies e;
  e.accelerationTerm = global[0];
  for (int d = 0; d < 3; ++d) {
    e.angular[d] = global[1 + d];
    e.momentum[d] = global[4 + d];
  }
  std::vector<double> g;
  sim.variables().globalVariable("Global_Kinetic_Energy", g);
  e.kinetic = g[0];
  sim.variables().globalVariable("Global_Stored_Elastic_Energy", g);
  e.stored = g[0];
  e.finite = anyBad == 0 && std::isfinite(e.kinetic) && std::isfinite(e.stored);
  return e;
}

// Runs a scene to its end, recording the energies after every step.
struct RunRecord {
  std::vector<Energies> history;
  double dt = 0, stableDt = 0;
  long long steps = 0;
};

RunRecord run(const Scene& s,
              std::function<void(Simulation&, long long, double)> observe = nullptr) {
  auto sim = makeSimulation(deck(s));
  RunRecord r;
  r.dt = sim->timeStep();
  r.stableDt = sim->stableTimeStepEstimate();
  r.steps = sim->numSteps();
  sim->setStepObserver([&](long long step, double time) {
    r.history.push_back(energies(*sim));
    if (observe) observe(*sim, step, time);
  });
  sim->run();
  return r;
}

// Largest |leapfrog energy - its initial value| over the run, relative to the initial energy.
double leapfrogDrift(const RunRecord& r) {
  const double h2 = 0.25 * r.dt * r.dt;
  const Energies& e0 = r.history.front();
  const double l0 = e0.kinetic + e0.stored - h2 * e0.accelerationTerm;
  double worst = 0;
  for (const Energies& e : r.history)
    worst = std::max(worst, std::fabs(e.kinetic + e.stored - h2 * e.accelerationTerm - l0));
  return worst / (e0.kinetic + e0.stored);
}

// Largest |kinetic + stored - initial| relative to the initial energy.
double energyDeviation(const RunRecord& r) {
  const Energies& e0 = r.history.front();
  double worst = 0;
  for (const Energies& e : r.history)
    worst = std::max(worst, std::fabs(e.kinetic + e.stored - e0.kinetic - e0.stored));
  return worst / (e0.kinetic + e0.stored);
}

bool allFinite(const RunRecord& r) {
  for (const Energies& e : r.history)
    if (!e.finite) return false;
  return true;
}

// --- one and two points ------------------------------------------------------------------------

TEST(Extremes, OnePointBodyIsRefusedWithAClearMessage) {
  MeshFile mesh("one_point", {{0, 0, 0, 1, 1}});
  Scene s;
  s.mesh = mesh.name;
  s.numPoints = 1;
  try {
    run(s);
    FAIL() << "a one-point body ran";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("single point"), std::string::npos) << e.what();
  }
}

// Two points of unit volume and density, a unit bond along x, pulled apart by +-a: the bond
// length oscillates as r(t) = (2a/w) sin(w t) with w^2 = 2k/m, k the bond's axial stiffness.
// Along the bond both models are exactly linear. PMB: the pair force c s V_i V_j with
// c = 18K/(pi delta^4) gives k = c. LPS: m = |xi|^2 V = 1, theta = 3e, e^d = e - theta|xi|/3 = 0,
// t = (3K theta / m)|xi| = 9Ke per end, k = 18K. The comparison is with velocity Verlet's exact
// discrete solution of the same oscillator, r_n = (2a/(w' cos(w dt/2))) sin(w' n dt) with
// sin(w' dt/2) = w dt/2, so any error of the stiffness shows, not the integrator's.
class TwoPoints : public ::testing::TestWithParam<const char*> {};

TEST_P(TwoPoints, OscillateAtTheDimerFrequency) {
  const std::string model = GetParam();
  MeshFile mesh("two_points_" + std::string(model == "Elastic" ? "lps" : "pmb"),
                {{0, 0, 0, 1, 1}, {1, 0, 0, 1, 1}});
  Scene s;
  s.mesh = mesh.name;
  s.numPoints = 2;
  s.material = model;
  s.horizon = 1.5;
  const double a = 1e-3;
  s.v[0] = "(2*x - 1)*" + std::to_string(a);
  const double k = model == "Elastic" ? 18.0 : 18.0 / (kPi * std::pow(1.5, 4));
  const double w = std::sqrt(2.0 * k);
  const double period = 2 * kPi / w;
  s.dt = period / 200;
  s.finalTime = 3.3 * period;
  const double wd = 2.0 / s.dt * std::asin(0.5 * w * s.dt);
  double worst = 0, amplitude = 2 * a / (w * std::cos(0.5 * wd * s.dt));
  run(s, [&](Simulation& sim, long long step, double) {
    std::vector<double> u;
    sim.variables().nodeVariable("Displacement", u);
    double local[2] = {0, 0};  // u_x of the points at x = 0 and x = 1
    const double* x = sim.fields().node("Model_Coordinates", 3);
    for (int i = 0; i < sim.topology().numOwned; ++i) local[x[3 * i] > 0.5 ? 1 : 0] = u[3 * i];
    double both[2];
    MPI_Allreduce(local, both, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    const double r = both[1] - both[0];
    worst = std::max(worst, std::fabs(r - amplitude * std::sin(wd * step * s.dt)));
  });
  // Rounding only: 1e-8 of the amplitude. A stiffness 1e-6 off would move the phase by
  // ~1e-5 over three periods.
  EXPECT_LT(worst, 1e-8 * amplitude) << model;
}

INSTANTIATE_TEST_SUITE_P(Models, TwoPoints, ::testing::Values("Elastic Bond Based", "Elastic"),
                         [](const auto& info) {
                           return std::string(info.param) == "Elastic" ? "LPS" : "PMB";
                         });

// --- material and discretization extremes ----------------------------------------------------

// A smooth breathing-and-shear motion of a free lattice, no rigid motion.
void smoothVelocity(Scene& s, double centre, double scale) {
  const char* axes[3] = {"x", "y", "z"};
  const char* other[3] = {"y", "z", "x"};
  for (int a = 0; a < 3; ++a) {
    std::ostringstream e;
    e << scale << "*((" << axes[a] << " - " << centre << ") + 0.5*(" << other[a] << " - " << centre
      << "))";
    s.v[a] = e.str();
  }
}

// LPS with K/mu up to 1e6 (nu = 0.4999998): Peridigm's estimate, which grows with K, keeps
// the run stable, and the leapfrog energy is conserved.
TEST(Extremes, NearlyIncompressibleLPSRunsAtTheEstimatedStep) {
  MeshFile mesh("incompressible", lattice(5, 5, 5));
  double previousDt = 0;
  for (double ratio : {1.0, 1e4, 1e6}) {
    Scene s;
    s.mesh = mesh.name;
    s.numPoints = 125;
    s.material = "Elastic";
    s.K1 = ratio;
    s.mu1 = 1.0;
    s.horizon = 2.015;
    smoothVelocity(s, 2.0, 1e-6);
    s.safety = 0.9;
    // 1500 steps whatever the stiffness.
    const double stable = makeSimulation(deck(s))->stableTimeStepEstimate();
    s.finalTime = 1500.5 * 0.9 * stable;
    RunRecord r = run(s);
    ASSERT_TRUE(allFinite(r)) << "K/mu " << ratio;
    EXPECT_EQ(r.steps, 1500);
    EXPECT_LT(leapfrogDrift(r), 1e-6) << "K/mu " << ratio;
    // The estimate scales as 1/sqrt(K) once K dominates.
    if (ratio == 1e6) {
      EXPECT_NEAR(r.stableDt / previousDt, 0.1, 0.001);
    }
    previousDt = r.stableDt;
  }
}

TEST(Extremes, PoissonsRatioOfOneHalfIsAClearError) {
  MeshFile mesh("nu_half", lattice(3, 3, 3));
  std::string d = deck([&] {
    Scene s;
    s.mesh = mesh.name;
    s.numPoints = 27;
    s.material = "Elastic";
    return s;
  }());
  const std::string from = "      Bulk Modulus: 1\n      Shear Modulus: 1\n";
  const auto at = d.find(from);
  ASSERT_NE(at, std::string::npos) << d;
  d.replace(at, from.size(), "      Young's Modulus: 1.0\n      Poisson's Ratio: 0.5\n");
  try {
    makeSimulation(d);
    FAIL() << "Poisson's ratio 0.5 was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("Poisson's Ratio"), std::string::npos) << e.what();
  }
}

// Two blocks of different kinds of material (LPS and PMB) bonded across their interface: their
// models cannot read each other's per-point state, so the set-up stops with a message that says
// how to separate them. (Blocks of one kind skip this check's pass over the bonds.)
TEST(Extremes, BondsBetweenDifferentKindsOfMaterialAreAClearError) {
  MeshFile mesh("two_kinds", lattice(4, 2, 2, 2.0));
  Scene s;
  s.mesh = mesh.name;
  s.numPoints = 16;
  s.material = "Elastic";
  s.blockTwo = true;
  std::string d = deck(s);
  const std::string lps = "    M2:\n      Material Model: \"Elastic\"\n";
  const auto at = d.find(lps);
  ASSERT_NE(at, std::string::npos) << d;
  d.replace(at, lps.size(), "    M2:\n      Material Model: \"Elastic Bond Based\"\n");
  const std::string shear = "      Shear Modulus: 1\n";
  const auto second = d.find(shear, at);
  ASSERT_NE(second, std::string::npos) << d;
  d.erase(second, shear.size());
  try {
    makeSimulation(d);
    FAIL() << "bonds between LPS and PMB blocks were accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("Omit Bonds Between Blocks"), std::string::npos)
        << e.what();
  }
  // Separated, the same blocks set up.
  const std::string mesh0 = "    Input Mesh File: " + mesh.name + "\n";
  const auto m = d.find(mesh0);
  ASSERT_NE(m, std::string::npos) << d;
  d.insert(m + mesh0.size(), "    Omit Bonds Between Blocks: All\n");
  EXPECT_NO_THROW(makeSimulation(d));
}

// Two blocks whose moduli differ by 1e6, bonded across their interface: the estimate follows the
// stiff block, the run is stable and the leapfrog energy is conserved.
class Contrast : public ::testing::TestWithParam<const char*> {};

TEST_P(Contrast, OfAMillionBetweenBlocksIsStable) {
  const std::string model = GetParam();
  MeshFile mesh(std::string("contrast_") + (model == "Elastic" ? "lps" : "pmb"),
                lattice(8, 4, 4, 4.0));
  Scene s;
  s.mesh = mesh.name;
  s.numPoints = 128;
  s.material = model;
  s.blockTwo = true;
  s.K1 = 1e6;
  s.mu1 = 6e5;
  s.K2 = 1.0;
  s.mu2 = 0.6;
  s.horizon = 2.015;
  smoothVelocity(s, 2.0, 1e-6);
  s.safety = 0.9;
  Scene stiffOnly = s;
  stiffOnly.K2 = s.K1;
  stiffOnly.mu2 = s.mu1;
  const double stiffDt = makeSimulation(deck(stiffOnly))->stableTimeStepEstimate();
  const double stable = makeSimulation(deck(s))->stableTimeStepEstimate();
  EXPECT_LE(stable, stiffDt * (1 + 1e-12));
  s.finalTime = 3000.5 * 0.9 * stable;
  RunRecord r = run(s);
  ASSERT_TRUE(allFinite(r));
  EXPECT_EQ(r.steps, 3000);
  EXPECT_LT(leapfrogDrift(r), 1e-6) << model;
  // The soft block moved and deformed: energy went between kinetic and stored.
  double moved = 0;
  for (const Energies& e : r.history)
    moved = std::max(moved, std::fabs(e.kinetic - r.history.front().kinetic));
  EXPECT_GT(moved, 1e-3 * (r.history.front().kinetic + r.history.front().stored));
}

INSTANTIATE_TEST_SUITE_P(Models, Contrast, ::testing::Values("Elastic Bond Based", "Elastic"),
                         [](const auto& info) {
                           return std::string(info.param) == "Elastic" ? "LPS" : "PMB";
                         });

// Horizons from 1.01 spacings (6 neighbours: only the axis bonds) to 10 (every point of the
// 6^3 lattice bonded to every other). With Peridigm's estimate the run is either stable or
// stopped by the divergence check with its message: the estimate takes the bond-based spring
// constant 18K/(pi delta^4) of a full neighbourhood, while LPS's stiffness grows as the
// weighted volume m shrinks, and at delta = 10 on a body of 6 every neighbourhood is truncated
// (LPS there diverges at 0.9 of the estimate, step 4). With "Verlet Limit", which measures the
// assembled stiffness, every case is stable and conserves the leapfrog energy.
class Horizons : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

TEST_P(Horizons, RunStablyOrStopWithAMessage) {
  const std::string model = std::get<0>(GetParam());
  const double horizon = std::get<1>(GetParam());
  MeshFile mesh(std::string("horizon_") + (model == "Elastic" ? "lps_" : "pmb_") +
                    std::to_string(int(horizon * 100)),
                lattice(6, 6, 6));
  for (const std::string estimate : {"Peridigm", "Verlet Limit"}) {
    Scene s;
    s.mesh = mesh.name;
    s.numPoints = 216;
    s.material = model;
    s.horizon = horizon;
    s.estimate = estimate;
    // Small amplitude: the leapfrog energy is velocity Verlet's invariant for the linear
    // problem, and at 0.9 of the true limit the geometric nonlinearity's share of it is
    // amplified (drift 4e-5 at an amplitude of 1e-6, 4e-7 at 1e-8: it scales as amplitude^2).
    smoothVelocity(s, 2.5, 1e-8);
    s.safety = 0.9;
    s.finalTime = 1e4;  // for the estimate alone
    const double stable = makeSimulation(deck(s))->stableTimeStepEstimate();
    s.finalTime = 1000.5 * 0.9 * stable;
    try {
      RunRecord r = run(s);
      ASSERT_TRUE(allFinite(r));
      EXPECT_EQ(r.steps, 1000);
      EXPECT_LT(leapfrogDrift(r), 1e-6) << model << " horizon " << horizon << " " << estimate;
      if (myRank() == 0)
        std::printf("%s, horizon %g, %s estimate %.6g: stable, leapfrog drift %.3g\n",
                    model.c_str(), horizon, estimate.c_str(), stable, leapfrogDrift(r));
    } catch (const std::exception& e) {
      const std::string what = e.what();
      EXPECT_EQ(estimate, "Peridigm") << what;
      EXPECT_NE(what.find("the run diverged at step"), std::string::npos) << what;
      if (myRank() == 0)
        std::printf("%s, horizon %g, %s estimate %.6g: %s\n", model.c_str(), horizon,
                    estimate.c_str(), stable, what.substr(0, 60).c_str());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ModelsAndHorizons, Horizons,
                         ::testing::Combine(::testing::Values("Elastic Bond Based", "Elastic"),
                                            ::testing::Values(1.01, 10.0)),
                         [](const auto& info) {
                           return std::string(std::string(std::get<0>(info.param)) == "Elastic"
                                                  ? "LPS"
                                                  : "PMB") +
                                  (std::get<1>(info.param) < 2 ? "_1_01" : "_10");
                         });

// --- large deformations ---------------------------------------------------------------------

// The shortest current bond over all ranks, relative to its reference length.
double shortestBond(Simulation& sim) {
  const Topology& t = sim.topology();
  const double* y = sim.fields().node("Coordinates", 3);
  const double* x = sim.fields().node("Model_Coordinates", 3);
  double local = 1e300;
  for (int i = 0; i < t.numOwned; ++i)
    for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
      const int j = t.neighbors[b];
      double Y = 0, X = 0;
      for (int d = 0; d < 3; ++d) {
        Y += (y[3 * j + d] - y[3 * i + d]) * (y[3 * j + d] - y[3 * i + d]);
        X += (x[3 * j + d] - x[3 * i + d]) * (x[3 * j + d] - x[3 * i + d]);
      }
      local = std::min(local, std::sqrt(Y / X));
    }
  double global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  return global;
}

// A free cube released from 50% compression or 50% tension along x and y springs back, and its
// points overshoot until some pass through each other. No NaN at any time, and momentum stays
// exact. The energy is a smooth function of the positions only while no bond passes through
// zero length: |Y| has a cone point there, the force on the bond flips direction within one
// step, and Verlet's energy error at such a crossing is first order in dt (measured: a jump of
// 2% in one step for LPS at a tenth of the estimate). So the energy is checked up to the first
// step where a bond is shorter than 5% of its reference length, where it must converge as dt^2:
// a quarter of the deviation at half the step.
class LargeStrain : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

TEST_P(LargeStrain, ReleasedFromFiftyPercentStrain) {
  const std::string model = std::get<0>(GetParam());
  const double strain = std::get<1>(GetParam());
  MeshFile mesh(
      std::string("strain_") + (model == "Elastic" ? "lps" : "pmb") + (strain < 0 ? "_c" : "_t"),
      lattice(5, 5, 5));
  double deviation[2] = {0, 0};
  for (int refinement = 0; refinement < 2; ++refinement) {
    Scene s;
    s.mesh = mesh.name;
    s.numPoints = 125;
    s.material = model;
    s.horizon = 2.015;
    const std::string e = std::to_string(strain);
    s.u[0] = e + "*(x - 2)";
    s.u[1] = e + "*(y - 2)";
    s.safety = refinement == 0 ? 0.1 : 0.05;
    s.finalTime = 1000;
    const double stable = makeSimulation(deck(s))->stableTimeStepEstimate();
    s.finalTime = 30.0 * stable;
    long long firstCollapse = -1;
    RunRecord r = run(s, [&](Simulation& sim, long long step, double) {
      if (firstCollapse < 0 && shortestBond(sim) < 0.05) firstCollapse = step;
    });
    ASSERT_TRUE(allFinite(r)) << model << " strain " << strain;
    const Energies& e0 = r.history.front();
    ASSERT_GT(e0.stored, 0.0);
    const std::size_t smooth = firstCollapse < 0 ? r.history.size() : std::size_t(firstCollapse);
    // The smooth part covers the spring-back: most of the stored energy became kinetic.
    double maxKinetic = 0;
    for (std::size_t n = 0; n < smooth; ++n) {
      maxKinetic = std::max(maxKinetic, r.history[n].kinetic);
      deviation[refinement] =
          std::max(deviation[refinement],
                   std::fabs(r.history[n].kinetic + r.history[n].stored - e0.stored) / e0.stored);
    }
    EXPECT_GT(maxKinetic, 0.5 * e0.stored) << model << " strain " << strain;
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(r.history.back().momentum[d], 0.0, 1e-12 * std::sqrt(e0.stored));
    if (myRank() == 0)
      std::printf(
          "%s, strain %g, dt = %g x estimate: %zu smooth steps of %zu, energy deviation "
          "%.3g\n",
          model.c_str(), strain, s.safety, smooth, r.history.size(), deviation[refinement]);
  }
  EXPECT_LT(deviation[0], 2e-3) << model << " strain " << strain;
  EXPECT_LT(deviation[1], 0.3 * deviation[0]) << model << " strain " << strain;
}

INSTANTIATE_TEST_SUITE_P(ModelsAndStrains, LargeStrain,
                         ::testing::Combine(::testing::Values("Elastic Bond Based", "Elastic"),
                                            ::testing::Values(-0.5, 0.5)),
                         [](const auto& info) {
                           return std::string(std::string(std::get<0>(info.param)) == "Elastic"
                                                  ? "LPS"
                                                  : "PMB") +
                                  (std::get<1>(info.param) < 0 ? "_compression" : "_tension");
                         });

// Every bond inverted by a reflection x -> -x keeps its length: no force, no stored energy
// (the models see lengths only). Collapsing the body onto the z axis (u = -x, -y) makes bonds of
// zero length: coincident ends have no direction and, by symmetry, no force — finite values,
// and the body re-expands from the collapse as stored energy is released.
TEST(Extremes, InvertedBondsCarryNoForce) {
  for (const std::string model : {"Elastic Bond Based", "Elastic"}) {
    MeshFile mesh(std::string("inverted_") + (model == "Elastic" ? "lps" : "pmb"),
                  lattice(4, 4, 4));
    Scene s;
    s.mesh = mesh.name;
    s.numPoints = 64;
    s.material = model;
    s.horizon = 2.015;
    s.u[0] = "-2*x";
    s.dt = 0.01;
    s.finalTime = 0.105;
    RunRecord r = run(s);
    ASSERT_TRUE(allFinite(r));
    for (const Energies& e : r.history) {
      EXPECT_LT(std::fabs(e.stored), 1e-24) << model;
      EXPECT_LT(e.kinetic, 1e-24) << model;
    }
  }
}

TEST(Extremes, CollapsedBodyStaysFinite) {
  for (const std::string model : {"Elastic Bond Based", "Elastic"}) {
    MeshFile mesh(std::string("collapsed_") + (model == "Elastic" ? "lps" : "pmb"),
                  lattice(4, 4, 4));
    Scene s;
    s.mesh = mesh.name;
    s.numPoints = 64;
    s.material = model;
    s.horizon = 2.015;
    s.u[0] = "-x";
    s.u[1] = "-y";
    s.dt = 0.01;
    s.finalTime = 2.005;
    RunRecord r = run(s);
    ASSERT_TRUE(allFinite(r)) << model;
    EXPECT_GT(r.history.front().stored, 0.0) << model;
    EXPECT_GT(r.history.back().kinetic, 0.0) << model;
  }
}

// A motion every point follows by prescription is the user's, not the integration's: the
// divergence check leaves prescribed components out. A 4^3 cube (spacing 1, horizon 1.75,
// Fixed dt 0.56x the estimate) stretched along x to strain `strain` over 20 steps; `free`
// leaves y and z unprescribed.
std::string prescribedStretch(double strain, bool free) {
  std::ostringstream d;
  d.precision(17);
  d << "Peridigm:\n  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
       "    TensorProduct3DMeshGenerator:\n      X Origin: 0.0\n      Y Origin: 0.0\n"
       "      Z Origin: 0.0\n      X Length: 4.0\n      Y Length: 4.0\n      Z Length: 4.0\n"
       "      Number Points X: 4\n      Number Points Y: 4\n      Number Points Z: 4\n"
       "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 7800.0\n"
       "      Young's Modulus: 200.0e9\n      Poisson's Ratio: 0.3\n"
       "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 1.75\n"
       "  Boundary Conditions:\n    All Node Set: \""
    << idList(64) << "\"\n";
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < (free ? 1 : 3); ++a) {
    d << "    U" << axes[a] << ":\n      Type: Prescribed Displacement\n      Node Set: All Node "
      << "Set\n      Coordinate: " << axes[a] << "\n      Value: \""
      << (a == 0 ? std::to_string(strain) + "*x*t/1.0e-3" : "0.0") << "\"\n";
  }
  d << "  Solver:\n    Final Time: 1.0e-3\n    Verlet:\n      Fixed dt: 5.0e-5\n";
  return d.str();
}

TEST(Extremes, AFullyPrescribedStretchIsNotADivergence) {
  // Strain 10: the reactions on the points (their accelerations) exceed the check's bound of
  // one horizon per step from step 17 on (the check stopped this run when it counted them).
  const double strain = 10.0;
  auto sim = makeSimulation(prescribedStretch(strain, false));
  std::string message;
  try {
    sim->run();
  } catch (const RunError& e) {
    message = e.what();
  }
  ASSERT_EQ(message, "");
  EXPECT_EQ(sim->numSteps(), 20);
  // The prescribed end state, u = (strain x, 0, 0), at every point.
  const double* x = sim->fields().node("Model_Coordinates", 3);
  const double* u = sim->fields().node("Displacement", 3);
  for (int i = 0; i < sim->topology().numOwned; ++i) {
    EXPECT_NEAR(u[3 * i], strain * x[3 * i], 1e-12 * strain * 4.0) << i;
    EXPECT_EQ(u[3 * i + 1], 0.0) << i;
    EXPECT_EQ(u[3 * i + 2], 0.0) << i;
  }
}

TEST(Extremes, AFreeComponentOfAPrescribedStretchIsStillChecked) {
  // The same cube at strain 100 with y and z free: the lateral forces on the free components
  // would carry points across their horizon in one step; the check stops the run.
  auto sim = makeSimulation(prescribedStretch(100.0, true));
  std::string message;
  try {
    sim->run();
  } catch (const RunError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("the run diverged at step"), std::string::npos) << message;
}

// --- rigid motion ----------------------------------------------------------------------------

// A cube spinning about z turns one full revolution at three speeds: a rim speed of 0.7 of the
// bulk wave speed (0.1 rad per step at half the estimate), 5 and 20 times slower. The models
// are objective: the rotation itself stores no energy; only the centrifugal stretch does, and
// the stored energy relative to the kinetic falls as omega^2 (x 1/16 between the slower two; a
// model that stored energy for the rotation angle would not fall). Kinetic + stored stays within
// the O(dt^2) oscillation, angular momentum is exact to rounding and the centre of mass does
// not move.
class Spinning : public ::testing::TestWithParam<const char*> {};

TEST_P(Spinning, BodyTurnsWithoutSpuriousEnergy) {
  const std::string model = GetParam();
  MeshFile mesh(std::string("spin_") + (model == "Elastic"          ? "lps"
                                        : model == "Normalized PMB" ? "npmb"
                                                                    : "pmb"),
                lattice(5, 5, 5));
  double storedOverKinetic[3] = {0, 0, 0};
  const double omegas[3] = {0.25, 0.05, 0.0125};
  for (int k = 0; k < 3; ++k) {
    Scene s;
    s.mesh = mesh.name;
    s.numPoints = 125;
    s.material = model;
    s.horizon = 2.015;
    const double omega = omegas[k];
    s.v[0] = std::to_string(-omega) + "*(y - 2)";
    s.v[1] = std::to_string(omega) + "*(x - 2)";
    s.safety = 0.5;
    s.finalTime = 1e4;  // for the estimate alone
    const double stable = makeSimulation(deck(s))->stableTimeStepEstimate();
    s.finalTime = 2 * kPi / omega + 0.25 * stable;
    RunRecord r = run(s);
    ASSERT_TRUE(allFinite(r));
    const Energies &e0 = r.history.front(), &e1 = r.history.back();
    EXPECT_LT(energyDeviation(r), 2e-3) << model << " omega " << omega;
    for (const Energies& e : r.history)
      storedOverKinetic[k] = std::max(storedOverKinetic[k], e.stored / e0.kinetic);
    EXPECT_NEAR(e1.angular[2], e0.angular[2], 1e-12 * std::fabs(e0.angular[2])) << model;
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(e1.momentum[d], 0.0, 1e-12 * std::fabs(e0.angular[2]));
    if (myRank() == 0)
      std::printf(
          "%s spinning at %g: %zu steps, energy deviation %.3g, max stored / kinetic "
          "%.3g\n",
          model.c_str(), omega, r.history.size(), energyDeviation(r), storedOverKinetic[k]);
  }
  // omega^2 scaling between the two slower spins, within 10% (measured for PMB: x3.95 per
  // halving of omega below 0.02; the fastest spin stretches the body by ~10% and is off it).
  const double expected = storedOverKinetic[1] * (omegas[2] / omegas[1]) * (omegas[2] / omegas[1]);
  EXPECT_NEAR(storedOverKinetic[2], expected, 0.1 * expected) << model;
}

INSTANTIATE_TEST_SUITE_P(Models, Spinning,
                         ::testing::Values("Elastic Bond Based", "Elastic", "Normalized PMB"),
                         [](const auto& info) {
                           const std::string m = info.param;
                           return m == "Elastic" ? "LPS" : m == "Normalized PMB" ? "NPMB" : "PMB";
                         });

// --- long: 10^7 steps ------------------------------------------------------------------------

// ctest -L long (mpi_long_studies). The two-point PMB oscillator of TwoPoints for 10^7 steps
// (about 250,000 periods): the phase still follows Verlet's discrete solution, the leapfrog
// energy does not drift, and the time per step of the last tenth is reported beside the
// first's (no slowdown; printed, not asserted).
TEST(ExtremesLong, DISABLED_TenMillionStepsOfATwoPointBody) {
  MeshFile mesh("ten_million", {{0, 0, 0, 1, 1}, {1, 0, 0, 1, 1}});
  Scene s;
  s.mesh = mesh.name;
  s.numPoints = 2;
  const double a = 1e-3;
  s.v[0] = "(2*x - 1)*" + std::to_string(a);
  const double k = 18.0 / (kPi * std::pow(1.5, 4));
  const double w = std::sqrt(2.0 * k);
  s.dt = 2 * kPi / w / 40;
  const long long steps = 10000000;
  s.finalTime = (steps + 0.5) * s.dt;
  const double wd = 2.0 / s.dt * std::asin(0.5 * w * s.dt);
  const double amplitude = 2 * a / (w * std::cos(0.5 * wd * s.dt));
  auto sim = makeSimulation(deck(s));
  ASSERT_EQ(sim->numSteps(), steps);
  double worstPhase = 0, l0 = 0, worstDrift = 0;
  // Process CPU time, not wall time: the machine may be shared.
  const std::clock_t t0 = std::clock();
  std::clock_t tenth = 0, nineTenths = 0;
  sim->setStepObserver([&](long long step, double) {
    if (step % 1000 != 0) return;
    if (step == steps / 10) tenth = std::clock();
    if (step == steps - steps / 10) nineTenths = std::clock();
    Energies e = energies(*sim);
    const double l = e.kinetic + e.stored - 0.25 * s.dt * s.dt * e.accelerationTerm;
    if (step == 0) l0 = l;
    worstDrift = std::max(worstDrift, std::fabs(l - l0) / l0);
    std::vector<double> u;
    sim->variables().nodeVariable("Displacement", u);
    const double* x = sim->fields().node("Model_Coordinates", 3);
    double local[2] = {0, 0}, both[2];
    for (int i = 0; i < sim->topology().numOwned; ++i) local[x[3 * i] > 0.5 ? 1 : 0] = u[3 * i];
    MPI_Allreduce(local, both, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    const double phase = std::fmod(wd * s.dt * double(step), 2 * kPi);
    worstPhase = std::max(worstPhase, std::fabs(both[1] - both[0] - amplitude * std::sin(phase)));
  });
  sim->run();
  const std::clock_t t1 = std::clock();
  const double first = double(tenth - t0) / CLOCKS_PER_SEC;
  const double last = double(t1 - nineTenths) / CLOCKS_PER_SEC;
  if (myRank() == 0)
    std::printf(
        "10^7 steps: phase error %.3g of the amplitude, leapfrog drift %.3g, "
        "CPU time of the first tenth %.2f s, of the last tenth %.2f s\n",
        worstPhase / amplitude, worstDrift, first, last);
  // Rounding accumulates as a random walk of the phase: ~sqrt(1e7) * 1e-16 per step.
  EXPECT_LT(worstPhase, 1e-6 * amplitude);
  EXPECT_LT(worstDrift, 1e-9);
}

}  // namespace
}  // namespace peridot
