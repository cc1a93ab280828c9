// The regression deck test/regression/decks/PalsSimpleShear ("Pals" with "Interface Aware"
// damage, every point driven by a homogeneous simple shear u_x = gamma t y) run through the
// Simulation at 1, 2 and 3 ranks. Gold from the continuum, independent of the code: at every
// step the energy density of EVERY point (surface, edge and corner points included) is
// G gamma(t)^2 / 2, the dilatation 0 and the total strain energy 343 G gamma^2 / 2; no bond
// breaks and the internal forces sum to zero. The same deck with "Elastic" (LPS) misses the
// energy at the surface by tens of percent (asserted, so that the check can fail).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/RunVariables.hpp"
#include "app/Simulation.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream runLog;

struct Worst {
  double energy = 0, dilatation = 0, total = 0, damage = 0, momentum = 0;
  int steps = 0;
};

Worst runShear(const std::string& model) {
  auto deck = loadDeck(std::string(PERIDOT_TEST_DIR) +
                       "/regression/decks/PalsSimpleShear/PalsSimpleShear.yaml");
  std::ostringstream ids;
  for (int i = 1; i <= 343; ++i) ids << i << ' ';
  deck->sublist("Boundary Conditions").set("All Node Set", ids.str());
  deck->remove("Output");
  if (model != "Pals") {
    auto& m = deck->sublist("Materials").sublist("Aluminium");
    m.remove("Dilatation Influence Function");
    m.remove("Deviatoric Influence Function");
    m.set("Material Model", model);
  }
  Simulation sim(readRunConfig(*deck), MPI_COMM_WORLD, runLog);
  const double G = 25.90, rate = 1e-6;
  Worst w;
  sim.setStepObserver([&](long long, double time) {
    const double gamma = rate * time, W = 0.5 * G * gamma * gamma;
    std::vector<double> density, theta, damage, force, volume, total;
    sim.variables().nodeVariable("Strain_Energy_Density", density);
    sim.variables().nodeVariable("Dilatation", theta);
    sim.variables().nodeVariable("Damage", damage);
    sim.variables().nodeVariable("Force", force);
    sim.variables().globalVariable("Global_Strain_Energy", total);
    double sum[3] = {0, 0, 0}, largest = 0;
    for (std::size_t i = 0; i < density.size(); ++i) {
      if (W > 0) w.energy = std::max(w.energy, std::abs(density[i] / W - 1));
      w.dilatation = std::max(w.dilatation, std::abs(theta[i]) / rate);
      w.damage = std::max(w.damage, damage[i]);
      for (int d = 0; d < 3; ++d) {
        sum[d] += force[3 * i + d];
        largest = std::max(largest, std::abs(force[3 * i + d]));
      }
    }
    double all[4] = {sum[0], sum[1], sum[2], 0}, largestAll = 0;
    MPI_Allreduce(MPI_IN_PLACE, all, 3, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    MPI_Allreduce(&largest, &largestAll, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    if (largestAll > 0)
      w.momentum = std::max(
          w.momentum, std::sqrt(all[0] * all[0] + all[1] * all[1] + all[2] * all[2]) / largestAll);
    if (W > 0) w.total = std::max(w.total, std::abs(total.at(0) / (343 * W) - 1));
    ++w.steps;
  });
  sim.run();
  double local[5] = {w.energy, w.dilatation, w.total, w.damage, w.momentum}, global[5];
  MPI_Allreduce(local, global, 5, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  w.energy = global[0];
  w.dilatation = global[1];
  w.total = global[2];
  w.damage = global[3];
  w.momentum = global[4];
  return w;
}

TEST(PalsSimpleShearDeck, EnergyAtEveryPointIsTheContinuumValue) {
  const Worst pals = runShear("Pals");
  const Worst lps = runShear("Elastic");
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf(
        "  PalsSimpleShear: worst |W/W_c - 1| %.2e (LPS %.2e), |theta|/gamma %.2e, total "
        "%.2e, momentum %.2e\n",
        pals.energy, lps.energy, pals.dilatation, pals.total, pals.momentum);
  EXPECT_EQ(pals.steps, 11);  // record 0 and 10 steps
  // Exact up to the second-order terms of the extension (gamma <= 1e-6).
  EXPECT_LT(pals.energy, 1e-5);
  EXPECT_LT(pals.dilatation, 1e-5);
  EXPECT_LT(pals.total, 1e-5);
  EXPECT_EQ(pals.damage, 0.0);
  EXPECT_LT(pals.momentum, 1e-9);
  EXPECT_GT(lps.energy, 0.1);
}

}  // namespace
}  // namespace peridot
