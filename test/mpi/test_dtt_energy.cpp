// Whole runs with the DTT damage law (paper 002) on a pre-cracked thin plate pulled by a
// constant traction (nonlocal Neumann layers), on 1, 2 and 3 ranks:
//  * Theorem 4: the total energy E = stored + kinetic - sum V u.b never increases while the crack
//    grows (bonds pass through the S0+..S1+ window);
//  * the two ends of every bond hold the same damage, and the run on several ranks gives the same
//    bits as the same run on one rank;
//  * Table 2: the L2 differences of displacement and damage between the windows {0.85, 1.15},
//    {0.9, 1.1}, {0.95, 1.05} and the reference {0.98, 1.02} S_c shrink as the window narrows.
// The material is "Linearized LPS" at nu = 1/4 (K = 5, G = 3: c1 = 0 exactly), a linear
// bond-based model F(eps) mu omega xi that applies DTT's smooth law: Theorem 4's setting (p >= 0,
// mu nonincreasing in time). The PMB kernels honour the smooth law on the materials branch.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "app/Simulation.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream runLog;

int rankOf(MPI_Comm comm) {
  int r = 0;
  MPI_Comm_rank(comm, &r);
  return r;
}

struct Plate {
  int nx = 40, ny = 20, nz = 2;
  double horizon = 2.015;
  double sigma = 0.035, sc = 0.01;
  double f0 = 0.95, f1 = 1.05;
  double dt = 0.1, finalTime = 12.0;
  std::string file = "dtt_plate.txt";
  bool lsjt = false;  // LSJ-T damage (and nu = 0.22) instead of DTT
  std::string material = "Linearized LPS";
  // Paper 002's own setting: a planar plate (z = 0, one layer, thickness 1) in plane stress,
  // where the bond-based models have nu = 1/3 and the linearized model's c1 vanishes at 1/3.
  bool planar = false;
};

// Points at cell centres of an nx x ny x nz lattice (spacing 1); a pre-crack at y = ny/2 from
// the left edge to x = nx/4; traction +-sigma on the layers within the horizon of the top and
// bottom faces.
std::string plateDeck(const Plate& p, bool writeFile = true) {
  // ctest runs this executable at 1, 2 and 3 ranks at once in one folder: one file per job.
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const std::string file = "np" + std::to_string(ranks) + "_" + p.file;
  if (writeFile && rankOf(MPI_COMM_WORLD) == 0) {
    FILE* f = std::fopen(file.c_str(), "w");
    for (int k = 0; k < p.nz; ++k)
      for (int j = 0; j < p.ny; ++j)
        for (int i = 0; i < p.nx; ++i) {
          if (p.planar)
            std::fprintf(f, "%d.5 %d.5 0 1 1\n", i, j);
          else
            std::fprintf(f, "%d.5 %d.5 %d.5 1 1\n", i, j, k);
        }
    std::fclose(f);
  }
  if (writeFile) MPI_Barrier(MPI_COMM_WORLD);
  std::ostringstream top, bottom;
  int id = 1;
  for (int k = 0; k < p.nz; ++k)
    for (int j = 0; j < p.ny; ++j)
      for (int i = 0; i < p.nx; ++i, ++id) {
        if (j + 0.5 > p.ny - p.horizon) top << id << " ";
        if (j + 0.5 < p.horizon) bottom << id << " ";
      }
  std::ostringstream d;
  d << "Peridigm:\n"
       "  Discretization:\n    Type: Text File\n    Input Mesh File: "
    << file << (p.planar ? "\n    Dimension: 2\n    Thickness: 1.0" : "")
    << "\n"
       "    Bond Filters:\n      Crack:\n        Type: Rectangular_Plane\n"
       "        Normal_X: 0.0\n        Normal_Y: 1.0\n        Normal_Z: 0.0\n"
       "        Lower_Left_Corner_X: -1.0\n        Lower_Left_Corner_Y: "
    << 0.5 * p.ny << "\n        Lower_Left_Corner_Z: " << p.nz + 1.0
    << "\n"
       "        Bottom_Unit_Vector_X: 1.0\n        Bottom_Unit_Vector_Y: 0.0\n"
       "        Bottom_Unit_Vector_Z: 0.0\n        Bottom_Length: "
    << 0.25 * p.nx + 1.0 << "\n        Side_Length: " << p.nz + 2.0
    << "\n"
       "  Materials:\n    M:\n      Material Model: "
    << p.material << "\n      Density: 1.0\n"
    << (p.planar ? "      Plane Stress: true\n" : "")
    << (p.lsjt ? "      Young's Modulus: 7.5\n      Poisson's Ratio: 0.22\n"
        : p.planar
            ? (p.material == "Elastic Bond Based"
                   ? "      Young's Modulus: 7.5\n"
                   : "      Young's Modulus: 7.5\n      Poisson's Ratio: 0.3333333333333333\n")
        : p.material == "Elastic Bond Based"
            ? "      Bulk Modulus: 5.0\n"
            : "      Bulk Modulus: 5.0\n      Shear Modulus: 3.0\n")
    << "  Damage Models:\n    D:\n      Damage Model: " << (p.lsjt ? "LSJ-T" : "DTT")
    << "\n      Critical Stretch: " << p.sc << "\n";
  if (!p.lsjt)
    d << "      S0 Plus Over Critical Stretch: " << p.f0
      << "\n      S1 Plus Over Critical Stretch: " << p.f1 << "\n";
  d << "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Damage Model: D\n"
       "      Horizon: "
    << p.horizon << "\n  Boundary Conditions:\n    Top Node Set: \"" << top.str()
    << "\"\n    Bottom Node Set: \"" << bottom.str()
    << "\"\n"
       "    Up:\n      Type: Traction\n      Node Set: Top Node Set\n      Coordinate: y\n"
       "      Value: "
    << p.sigma << "\n      Surface Area: " << p.nx * p.nz
    << "\n"
       "    Down:\n      Type: Traction\n      Node Set: Bottom Node Set\n      Coordinate: y\n"
       "      Value: "
    << -p.sigma << "\n      Surface Area: " << p.nx * p.nz
    << "\n"
       "  Solver:\n    Final Time: "
    << p.finalTime << "\n    Verlet:\n      Fixed dt: " << p.dt << "\n";
  return d.str();
}

std::unique_ptr<Simulation> makeSimulation(const std::string& yaml, MPI_Comm comm) {
  return std::make_unique<Simulation>(readRunConfig(*parseDeck(yaml, "yaml")), comm, runLog);
}

struct Energies {
  double stored, kinetic, work;  // work = sum V u.b
  double accelerationTerm;       // 1/2 sum m |a|^2
  double total() const { return stored + kinetic - work; }
};

Energies energies(Simulation& sim, MPI_Comm comm) {
  FieldManager& f = sim.fields();
  const double* u = f.node("Displacement", 3);
  const double* b = f.node("External_Force_Density", 3);
  const double* a = f.node("Acceleration", 3);
  const double* vol = f.node("Volume", 1);
  double local[2] = {0, 0}, global[2];
  for (int i = 0; i < sim.topology().numOwned; ++i)
    for (int d = 0; d < 3; ++d) {
      local[0] += vol[i] * u[3 * i + d] * b[3 * i + d];
      local[1] += 0.5 * vol[i] * a[3 * i + d] * a[3 * i + d];  // density 1
    }
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, comm);
  Energies e;
  e.work = global[0];
  e.accelerationTerm = global[1];
  std::vector<double> g;
  sim.variables().globalVariable("Global_Stored_Elastic_Energy", g);
  e.stored = g[0];
  sim.variables().globalVariable("Global_Kinetic_Energy", g);
  e.kinetic = g[0];
  return e;
}

// Per bond (global ids of both ends) values, gathered on every rank.
template <class T>
std::map<std::pair<long long, long long>, double> gatherBonds(Simulation& sim,
                                                              const std::vector<T>& d,
                                                              MPI_Comm comm) {
  const Topology& t = sim.topology();
  std::vector<double> mine;
  for (int i = 0; i < t.numOwned; ++i)
    for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
      mine.push_back(static_cast<double>(t.overlapGlobalId[i]));
      mine.push_back(static_cast<double>(t.overlapGlobalId[t.neighbors[b]]));
      mine.push_back(d[b]);
    }
  int size = 0;
  MPI_Comm_size(comm, &size);
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(size), offsets(size, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(offsets[size - 1] + counts[size - 1]);
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 comm);
  std::map<std::pair<long long, long long>, double> out;
  for (std::size_t k = 0; k < all.size(); k += 3)
    out[{static_cast<long long>(all[k]), static_cast<long long>(all[k + 1])}] = all[k + 2];
  return out;
}

std::map<std::pair<long long, long long>, double> bondDamages(Simulation& sim, MPI_Comm comm) {
  return gatherBonds(sim, sim.fields().bondFloat("Bond_Damage"), comm);
}

// Displacement (3) and damage of every point by global id, gathered on every rank.
std::map<long long, std::vector<double>> gatherNodal(Simulation& sim, MPI_Comm comm) {
  std::vector<double> u, d, mine;
  sim.variables().nodeVariable("Displacement", u);
  sim.variables().nodeVariable("Damage", d);
  const Topology& t = sim.topology();
  for (int i = 0; i < t.numOwned; ++i)
    mine.insert(mine.end(), {static_cast<double>(t.overlapGlobalId[i]), u[3 * i], u[3 * i + 1],
                             u[3 * i + 2], d[i]});
  int size = 0;
  MPI_Comm_size(comm, &size);
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(size), offsets(size, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(offsets[size - 1] + counts[size - 1]);
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 comm);
  std::map<long long, std::vector<double>> out;
  for (std::size_t k = 0; k < all.size(); k += 5)
    out[static_cast<long long>(all[k])] = {all[k + 1], all[k + 2], all[k + 3], all[k + 4]};
  return out;
}

// Theorem 4 and the bond-end symmetry on a run in which the crack grows, for each material that
// applies the smooth law at nu = 1/4 (where the state-based ones are bond-based): the linearized
// model, PMB (Elastic Bond Based) and LPS-T (Elastic).
class DTTEnergy : public ::testing::TestWithParam<std::string> {};

TEST_P(DTTEnergy, TotalEnergyNeverIncreasesWhileTheCrackGrows) {
  Plate p;
  p.material = GetParam();
  auto sim = makeSimulation(plateDeck(p), MPI_COMM_WORLD);
  // Largest rise of E above its smallest earlier value, and the energy scale.
  double lowest = 0, worstRise = 0, largestStored = 0;
  double lowestShadow = 0, worstShadowRise = 0, largestAccelerationTerm = 0;
  const double h2 = 0.25 * p.dt * p.dt;
  long long partialSeen = 0;
  std::vector<double> totals;
  sim->setStepObserver([&](long long step, double) {
    const Energies e = energies(*sim, MPI_COMM_WORLD);
    totals.push_back(e.total());
    if (step == 0) lowest = e.total();
    worstRise = std::max(worstRise, e.total() - lowest);
    lowest = std::min(lowest, e.total());
    const double shadow = e.total() - h2 * e.accelerationTerm;
    if (step == 0) lowestShadow = shadow;
    worstShadowRise = std::max(worstShadowRise, shadow - lowestShadow);
    lowestShadow = std::min(lowestShadow, shadow);
    largestStored = std::max(largestStored, e.stored);
    largestAccelerationTerm = std::max(largestAccelerationTerm, e.accelerationTerm);
    const std::vector<float>& d = sim->fields().bondFloat("Bond_Damage");
    long long partial = 0;
    for (float v : d) partial += (v > 0.0f && v < 1.0f) ? 1 : 0;
    long long sum = 0;
    MPI_Allreduce(&partial, &sum, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    partialSeen += sum;
  });
  sim->run();
  auto damages = bondDamages(*sim, MPI_COMM_WORLD);
  long long broken = 0;
  for (const auto& kv : damages) {
    auto reverse = damages.find({kv.first.second, kv.first.first});
    ASSERT_NE(reverse, damages.end());
    ASSERT_EQ(kv.second, reverse->second) << kv.first.first << " " << kv.first.second;
    broken += kv.second == 1.0 ? 1 : 0;
  }
  const double dissipated = totals.front() - totals.back();
  if (rankOf(MPI_COMM_WORLD) == 0)
    std::printf(
        "DTT plate, %s: E(0) = %.6g, E(end) = %.6g, largest stored %.6g, largest rise of E %.3g "
        "(%.3g of the stored energy), of the shadow energy %.3g, broken bond entries %lld, partly "
        "broken seen %lld, dt %.3g of the stable estimate\n",
        p.material.c_str(), totals.front(), totals.back(), largestStored, worstRise,
        worstRise / largestStored, worstShadowRise, broken, partialSeen,
        p.dt / sim->stableTimeStepEstimate());
  // The crack grew through the window, or the test proves nothing.
  EXPECT_GT(broken, 50);
  EXPECT_GT(partialSeen, 50);
  EXPECT_GT(dissipated, 0.0);
  // E may rise by at most the Verlet oscillation (dt^2/8) sum m |a|^2: E minus that term is
  // the shadow energy velocity Verlet conserves for a linear system. Measured rises of E over
  // the stored energy at dt = 0.36 / 0.18 / 0.09 of the stable estimate: 1.3e-4 / 3.3e-5 /
  // 8.3e-6 (linearized, LPS-T), 6.7e-4 / 1.7e-4 / 4.3e-5 (PMB): O(dt^2), the integrator's.
  const double roundOff = 1e-12 * largestStored;
  EXPECT_LE(worstRise, h2 * largestAccelerationTerm + roundOff);
  // The linearized model is a linear system between damage events, so its shadow energy is
  // exact: softening and breaking bonds may only take energy out, and it rises by round-off
  // only (sums of ~1e4 terms: 1e-12 of the energy; measured 3e-15). PMB and LPS-T are
  // geometrically nonlinear: their shadow energy is printed, not asserted.
  if (p.material == "Linearized LPS") {
    EXPECT_LE(worstShadowRise, roundOff);
  }
  RecordProperty("energy_rise_over_stored", std::to_string(worstRise / largestStored));
  RecordProperty("shadow_energy_rise", std::to_string(worstShadowRise));

  // The same run on one rank (rank 0 alone) gives the same bits, node by node.
  auto nodal = gatherNodal(*sim, MPI_COMM_WORLD);
  if (rankOf(MPI_COMM_WORLD) == 0) {
    auto serial = makeSimulation(plateDeck(p, false), MPI_COMM_SELF);
    serial->run();
    auto reference = gatherNodal(*serial, MPI_COMM_SELF);
    ASSERT_EQ(nodal.size(), reference.size());
    for (const auto& kv : reference) {
      const auto& got = nodal.at(kv.first);
      for (std::size_t c = 0; c < got.size(); ++c)
        ASSERT_EQ(got[c], kv.second[c]) << "point " << kv.first << " component " << c;
    }
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

INSTANTIATE_TEST_SUITE_P(Materials, DTTEnergy,
                         ::testing::Values("Linearized LPS", "Elastic Bond Based", "Elastic"),
                         [](const auto& info) {
                           std::string n = info.param;
                           n.erase(std::remove(n.begin(), n.end(), ' '), n.end());
                           return n;
                         });

}  // namespace
}  // namespace peridot

namespace peridot {
namespace {

// Paper 002's Table 2: L2 differences (sqrt of sum V (a - b)^2) of u_x, u_y and the damage index
// between the windows {0.85, 1.15}, {0.9, 1.1}, {0.95, 1.05} S_c and the reference {0.98, 1.02}.
struct WindowErrors {
  double ux[3], uy[3], damage[3];
};

WindowErrors windowStudy(Plate p) {
  const double windows[4][2] = {{0.85, 1.15}, {0.9, 1.1}, {0.95, 1.05}, {0.98, 1.02}};
  std::map<long long, std::vector<double>> result[4];
  for (int w = 0; w < 4; ++w) {
    p.f0 = windows[w][0];
    p.f1 = windows[w][1];
    auto sim = makeSimulation(plateDeck(p), MPI_COMM_WORLD);
    sim->run();
    result[w] = gatherNodal(*sim, MPI_COMM_WORLD);
  }
  WindowErrors e{};
  for (int w = 0; w < 3; ++w) {
    double sum[3] = {0, 0, 0};
    for (const auto& kv : result[3]) {
      const auto& a = result[w].at(kv.first);
      const auto& r = kv.second;
      sum[0] += (a[0] - r[0]) * (a[0] - r[0]);  // unit volumes
      sum[1] += (a[1] - r[1]) * (a[1] - r[1]);
      sum[2] += (a[3] - r[3]) * (a[3] - r[3]);
    }
    e.ux[w] = std::sqrt(sum[0]);
    e.uy[w] = std::sqrt(sum[1]);
    e.damage[w] = std::sqrt(sum[2]);
  }
  if (rankOf(MPI_COMM_WORLD) == 0) {
    std::printf(
        "Window study, %s (%d x %d x %d, delta %.3f, t = %g): L2 differences to {0.98, "
        "1.02}\n",
        p.material.c_str(), p.nx, p.ny, p.nz, p.horizon, p.finalTime);
    std::printf("  window         e_x         e_y         e_damage\n");
    for (int w = 0; w < 3; ++w)
      std::printf("  {%.2f, %.2f}  %.3e  %.3e  %.3e\n", windows[w][0], windows[w][1], e.ux[w],
                  e.uy[w], e.damage[w]);
  }
  return e;
}

TEST(DTTWindow, DifferencesShrinkAsTheWindowNarrows) {
  for (const std::string material : {"Linearized LPS", "Elastic Bond Based"}) {
    Plate p;
    p.material = material;
    const WindowErrors e = windowStudy(p);
    for (int w = 0; w < 2; ++w) {
      EXPECT_GT(e.ux[w], e.ux[w + 1]) << w;
      EXPECT_GT(e.uy[w], e.uy[w + 1]) << w;
      EXPECT_GT(e.damage[w], e.damage[w + 1]) << w;
    }
    EXPECT_GT(e.uy[2], 0.0);  // the windows do change the result
  }
}

}  // namespace
}  // namespace peridot

namespace peridot {
namespace {

// Paper 002's setting, planar (plane stress, one layer of points in z = 0): Theorem 4 and the
// window study again, for the linearized model (c1 = 0 at nu = 1/3) and PMB.
TEST(DTTPlanar, EnergyNeverIncreasesAndWindowDifferencesShrink) {
  for (const std::string material : {"Linearized LPS", "Elastic Bond Based"}) {
    Plate p;
    p.material = material;
    p.planar = true;
    p.nz = 1;
    p.file = "dtt_plate_planar.txt";
    auto sim = makeSimulation(plateDeck(p), MPI_COMM_WORLD);
    double lowest = 0, worstRise = 0, largestStored = 0, largestAccelerationTerm = 0;
    long long steps = 0;
    sim->setStepObserver([&](long long step, double) {
      const Energies e = energies(*sim, MPI_COMM_WORLD);
      if (step == 0) lowest = e.total();
      worstRise = std::max(worstRise, e.total() - lowest);
      lowest = std::min(lowest, e.total());
      largestStored = std::max(largestStored, e.stored);
      largestAccelerationTerm = std::max(largestAccelerationTerm, e.accelerationTerm);
      ++steps;
    });
    sim->run();
    long long broken = 0;
    for (const auto& kv : bondDamages(*sim, MPI_COMM_WORLD)) broken += kv.second == 1.0 ? 1 : 0;
    if (rankOf(MPI_COMM_WORLD) == 0)
      std::printf(
          "DTT planar plate, %s: largest rise of E %.3g (%.3g of the stored energy), "
          "broken bond entries %lld\n",
          material.c_str(), worstRise, worstRise / largestStored, broken);
    EXPECT_GT(broken, 50);
    EXPECT_LE(worstRise, 0.25 * p.dt * p.dt * largestAccelerationTerm + 1e-12 * largestStored);
    const WindowErrors e = windowStudy(p);
    for (int w = 0; w < 2; ++w) {
      EXPECT_GT(e.ux[w], e.ux[w + 1]) << material << " " << w;
      EXPECT_GT(e.uy[w], e.uy[w + 1]) << material << " " << w;
      EXPECT_GT(e.damage[w], e.damage[w + 1]) << material << " " << w;
    }
  }
}

// The full study (ctest -L long): a larger plate, delta = 3 dx, a longer run.
TEST(DTTWindow, DISABLED_LongStudyOnALargerPlate) {
  for (const std::string material : {"Linearized LPS", "Elastic Bond Based"}) {
    Plate p;
    p.material = material;
    p.nx = 100;
    p.ny = 40;
    p.nz = 3;
    p.horizon = 3.015;
    p.finalTime = 30.0;
    p.file = "dtt_plate_long.txt";
    const WindowErrors e = windowStudy(p);
    for (int w = 0; w < 2; ++w) {
      EXPECT_GT(e.ux[w], e.ux[w + 1]) << material << " " << w;
      EXPECT_GT(e.uy[w], e.uy[w + 1]) << material << " " << w;
      EXPECT_GT(e.damage[w], e.damage[w + 1]) << material << " " << w;
    }
  }
}

}  // namespace
}  // namespace peridot

namespace peridot {
namespace {

// LSJ-T (Linearized LPS at nu = 0.22 + LSJ-T damage) on the same plate: the crack grows, each
// bond's history integral never decreases, both ends of a bond hold the same integral and
// damage, and the result has the serial bits on any rank count.
TEST(LSJTRun, CrackGrowsHistoryPersistsAndRanksAgree) {
  Plate p;
  p.lsjt = true;
  p.file = "lsjt_plate.txt";
  auto sim = makeSimulation(plateDeck(p), MPI_COMM_WORLD);
  std::vector<double> previous;
  long long decreases = 0;
  sim->setStepObserver([&](long long, double) {
    const std::vector<double>& X = sim->fields().bond("LSJT_History_Integral");
    if (previous.size() == X.size())
      for (std::size_t b = 0; b < X.size(); ++b) decreases += X[b] < previous[b] ? 1 : 0;
    previous = X;
  });
  sim->run();
  EXPECT_EQ(decreases, 0);
  auto X = gatherBonds(*sim, sim->fields().bond("LSJT_History_Integral"), MPI_COMM_WORLD);
  auto d = bondDamages(*sim, MPI_COMM_WORLD);
  long long accumulated = 0, broken = 0, partial = 0;
  for (const auto& kv : X) {
    const std::pair<long long, long long> reverse{kv.first.second, kv.first.first};
    ASSERT_EQ(kv.second, X.at(reverse));
    ASSERT_EQ(d.at(kv.first), d.at(reverse));
    accumulated += kv.second > 0 ? 1 : 0;
    broken += d.at(kv.first) == 1.0 ? 1 : 0;
    partial += d.at(kv.first) > 0.0 && d.at(kv.first) < 1.0 ? 1 : 0;
  }
  if (rankOf(MPI_COMM_WORLD) == 0)
    std::printf("LSJ-T plate: bond entries with a history %lld, broken %lld, partly broken %lld\n",
                accumulated, broken, partial);
  EXPECT_GT(broken, 50);
  auto nodal = gatherNodal(*sim, MPI_COMM_WORLD);
  if (rankOf(MPI_COMM_WORLD) == 0) {
    auto serial = makeSimulation(plateDeck(p, false), MPI_COMM_SELF);
    serial->run();
    auto reference = gatherNodal(*serial, MPI_COMM_SELF);
    for (const auto& kv : reference)
      for (std::size_t c = 0; c < kv.second.size(); ++c)
        ASSERT_EQ(nodal.at(kv.first)[c], kv.second[c]) << "point " << kv.first;
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

}  // namespace
}  // namespace peridot
