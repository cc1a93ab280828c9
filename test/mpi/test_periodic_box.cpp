// A deformable periodic box (`Periodic Box Deformation Gradient ..`, issue 14 item 3): images sit
// at F(t) s from their point, so a homogeneous deformation is a scene a deck can express.
//   * V1 as paper 000 states it: a periodic cube under isotropic stretch 1.05 has, at every point,
//     the normalized PMB's energy density 9 K s^2 / 2 and no force; with a rigid box (the images
//     one undeformed length away) it has neither.
//   * A box stretching at a constant rate carries the homogeneous motion y = F(t) x, an exact
//     solution: every point follows it.
// Whole runs through the Simulation class at 1, 2 and 3 ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "app/Simulation.hpp"
#include "core/Error.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream runLog;

std::unique_ptr<Simulation> makeSimulation(const std::string& yaml) {
  auto deck = parseDeck(yaml, "yaml");
  return std::make_unique<Simulation>(readRunConfig(*deck), MPI_COMM_WORLD, runLog);
}

// A periodic 6 x 6 x 6 lattice (unit spacing, box [0, 6)^3), normalized PMB, K = 10.
std::string periodicCube(const std::string& boxKeys, const std::string& conditions, double dt,
                         double finalTime) {
  std::ostringstream d;
  d << "Peridigm:\n  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
       "    Periodic X: true\n    Periodic Y: true\n    Periodic Z: true\n"
    << boxKeys
    << "    TensorProduct3DMeshGenerator:\n"
       "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
       "      X Length: 6.0\n      Y Length: 6.0\n      Z Length: 6.0\n"
       "      Number Points X: 6\n      Number Points Y: 6\n      Number Points Z: 6\n"
       "  Materials:\n    M:\n      Material Model: \"Normalized PMB\"\n      Density: 1.0\n"
       "      Bulk Modulus: 10.0\n"
       "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 2.015\n"
       "  Boundary Conditions:\n    All Node Set: \"";
  for (int i = 1; i <= 216; ++i) d << i << (i < 216 ? " " : "\"\n");
  d << conditions << "  Solver:\n    Final Time: " << finalTime
    << "\n    Verlet:\n      Fixed dt: " << dt << "\n";
  return d.str();
}

std::string condition(const std::string& name, const std::string& type, const char* axis,
                      const std::string& value) {
  return "    " + name + ":\n      Type: " + type + "\n      Node Set: All Node Set\n" +
         "      Coordinate: " + axis + "\n      Value: \"" + value + "\"\n";
}

const char* kIsotropic =
    "    Periodic Box Deformation Gradient XX: 1.05\n"
    "    Periodic Box Deformation Gradient YY: 1.05\n"
    "    Periodic Box Deformation Gradient ZZ: 1.05\n";

std::string stretchConditions() {
  return condition("UX", "Initial Displacement", "x", "0.05*x") +
         condition("UY", "Initial Displacement", "y", "0.05*y") +
         condition("UZ", "Initial Displacement", "z", "0.05*z");
}

// Largest |energy density - 9 K s^2 / 2| and largest |force density| over all points, after the
// initial force evaluation.
void stretchedCube(const std::string& boxKeys, double& energyError, double& force) {
  auto sim = makeSimulation(periodicCube(boxKeys, stretchConditions(), 1e-3, 1.5e-3));
  const double exact = 4.5 * 10.0 * 0.05 * 0.05;
  double local[2] = {0, 0};
  bool seen = false;
  sim->setStepObserver([&](long long step, double) {
    if (step != 0) return;
    seen = true;
    std::vector<double> w, f;
    sim->variables().nodeVariable("Stored_Elastic_Energy_Density", w);
    sim->variables().nodeVariable("Force_Density", f);
    for (double v : w) local[0] = std::max(local[0], std::fabs(v - exact) / exact);
    for (double v : f) local[1] = std::max(local[1], std::fabs(v));
  });
  sim->run();
  ASSERT_TRUE(seen);
  double global[2];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  energyError = global[0];
  force = global[1];
}

TEST(DeformablePeriodicBox, CarriesV1IsotropicStretchAtEveryPoint) {
  double energyError = 1, force = 1;
  stretchedCube(kIsotropic, energyError, force);
  EXPECT_LT(energyError, 1e-12);
  // Force density scale: c s V / |xi| summed ~ K s = 0.5; rounding only.
  EXPECT_LT(force, 1e-12);
  // The rigid box cannot: its images sit one undeformed length away, so bonds across the
  // boundary are compressed against the stretched interior.
  double rigidError = 0, rigidForce = 0;
  stretchedCube("", rigidError, rigidForce);
  EXPECT_GT(rigidError, 0.1);
  EXPECT_GT(rigidForce, 1e-2);
}

// The box stretches along x at a constant rate: F_xx = 1 + r t. With the initial velocity r x the
// homogeneous motion y = F(t) x has no force anywhere (an exact solution), so each point's
// displacement stays r t x.
TEST(DeformablePeriodicBox, StretchRateIsFollowedByEveryPoint) {
  const double rate = 0.01, dt = 0.01;
  const long long steps = 500;
  auto sim = makeSimulation(
      periodicCube("    Periodic Box Deformation Gradient XX: \"1 + 0.01*t\"\n",
                   condition("VX", "Initial Velocity", "x", "0.01*x"), dt, (steps + 0.5) * dt));
  ASSERT_EQ(sim->numSteps(), steps);
  double worst = 0;
  sim->setStepObserver([&](long long, double t) {
    std::vector<double> u;
    sim->variables().nodeVariable("Displacement", u);
    const double* x = sim->fields().node("Model_Coordinates", 3);
    for (int i = 0; i < sim->topology().numOwned; ++i) {
      worst = std::max(worst, std::fabs(u[3 * i] - rate * t * x[3 * i]));
      worst = std::max(worst, std::fabs(u[3 * i + 1]) + std::fabs(u[3 * i + 2]));
    }
  });
  sim->run();
  double global = 0;
  MPI_Allreduce(&worst, &global, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  // Final displacement up to 0.25; rounding only.
  EXPECT_LT(global, 1e-12);
  // Without the box's motion the boundary holds the body back: the same deck with a rigid box
  // departs from the homogeneous motion.
  auto rigid = makeSimulation(
      periodicCube("", condition("VX", "Initial Velocity", "x", "0.01*x"), dt, (steps + 0.5) * dt));
  double departure = 0;
  rigid->setStepObserver([&](long long, double t) {
    std::vector<double> u;
    rigid->variables().nodeVariable("Displacement", u);
    const double* x = rigid->fields().node("Model_Coordinates", 3);
    for (int i = 0; i < rigid->topology().numOwned; ++i)
      departure = std::max(departure, std::fabs(u[3 * i] - rate * t * x[3 * i]));
  });
  rigid->run();
  double rigidGlobal = 0;
  MPI_Allreduce(&departure, &rigidGlobal, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_GT(rigidGlobal, 1e-3);
}

TEST(DeformablePeriodicBox, NeedsAPeriodicAxisAndAFiniteGradient) {
  std::string deck = periodicCube(kIsotropic, "", 1e-3, 1.5e-3);
  // No periodic axis: the keys are an error naming them.
  for (const char* axis : {"X", "Y", "Z"}) {
    const std::string from = std::string("    Periodic ") + axis + ": true\n";
    deck.replace(deck.find(from), from.size(), "");
  }
  try {
    makeSimulation(deck);
    FAIL() << "box deformation without a periodic axis was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Periodic Box Deformation Gradient"), std::string::npos)
        << e.what();
  }
  // An expression of something other than t is refused with the deck.
  EXPECT_THROW(makeSimulation(periodicCube("    Periodic Box Deformation Gradient XY: \"x\"\n", "",
                                           1e-3, 1.5e-3)),
               InputError);
  // A gradient that stops being finite stops the run with a message naming the key.
  auto sim = makeSimulation(periodicCube(
      "    Periodic Box Deformation Gradient YY: \"1/(t - 0.002)\"\n", "", 1e-3, 3.5e-3));
  try {
    sim->run();
    FAIL() << "a non-finite box gradient ran";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("Periodic Box Deformation Gradient YY"), std::string::npos)
        << e.what();
  }
}

// The correspondence rate form reads velocities, which the images of a deforming box do not
// carry with the box's rate: refused with the way out; the Green strain form runs.
TEST(DeformablePeriodicBox, RefusesTheCorrespondenceRateForm) {
  std::string deck = periodicCube(kIsotropic, stretchConditions(), 1e-3, 1.5e-3);
  const std::string pmb = "      Material Model: \"Normalized PMB\"\n";
  deck.replace(deck.find(pmb), pmb.size(),
               "      Material Model: \"Elastic Correspondence\"\n"
               "      Shear Modulus: 6.0\n      Hourglass Coefficient: 0.0\n");
  try {
    makeSimulation(deck);
    FAIL() << "the rate form ran in a deforming periodic box";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Total Lagrangian Green Strain"), std::string::npos)
        << e.what();
  }
  const std::string hourglass = "      Hourglass Coefficient: 0.0\n";
  deck.replace(deck.find(hourglass), hourglass.size(),
               hourglass + "      Stress Integration: \"Total Lagrangian Green Strain\"\n");
  EXPECT_NO_THROW(makeSimulation(deck)->run());
}

}  // namespace
}  // namespace peridot
