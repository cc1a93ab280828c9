// Thermal loading through the Simulation on 1, 2 and 3 ranks: Prescribed / Initial Temperature
// conditions, thermal expansion in "Elastic" (LPS) and "Elastic Bond Based", and the thermal term
// of "Critical Stretch". Golds are closed forms: a body in the uniform strain alpha Delta T is
// free of force (free expansion); held at u = 0 its LPS dilatation is -3 alpha Delta T at every
// point and its energy density 9/2 K (alpha Delta T)^2 (the hydrostatic thermal stress
// -3 K alpha Delta T).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "app/Simulation.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream quiet;

std::unique_ptr<Simulation> run(const std::string& deck) {
  return std::make_unique<Simulation>(readRunConfig(*parseDeck(deck, "yaml")), MPI_COMM_WORLD,
                                      quiet);
}

const double kStrain = 0.1;  // alpha Delta T = 1e-3 x 100

// A 5^3 grid (centres -2 .. 2), horizon 1.75, started at t = 1 where the temperature 100 t has
// risen by Delta T = 100 from its value at t = 0; `displaced`: u = alpha Delta T x.
std::string cube(const std::string& material, double alpha, bool displaced) {
  std::ostringstream a;
  a.precision(17);
  a << alpha;
  std::string d =
      "Peridigm:\n"
      "  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
      "    TensorProduct3DMeshGenerator:\n"
      "      X Origin: -2.5\n      Y Origin: -2.5\n      Z Origin: -2.5\n"
      "      X Length: 5.0\n      Y Length: 5.0\n      Z Length: 5.0\n"
      "      Number Points X: 5\n      Number Points Y: 5\n      Number Points Z: 5\n"
      "  Materials:\n    M:\n      Material Model: " +
      material + "\n      Density: 1.0\n      Bulk Modulus: 1.0\n" +
      (material == "Elastic" ? "      Shear Modulus: 0.6\n" : "") +
      "      Thermal Expansion Coefficient: " + a.str() +
      "\n  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n"
      "      Horizon: 1.75\n"
      "  Boundary Conditions:\n"
      "    Heat:\n      Type: Prescribed Temperature\n      Node Set: Full Domain\n"
      "      Value: \"100.0*t\"\n";
  if (displaced) {
    for (const char* c : {"x", "y", "z"})
      d += std::string("    U") + c +
           ":\n      Type: Initial Displacement\n"
           "      Node Set: Full Domain\n      Coordinate: " +
           c + "\n      Value: \"0.1*" + c + "\"\n";
  }
  d += "  Solver:\n    Initial Time: 1.0\n    Final Time: 1.1\n    Verlet:\n      Fixed dt: 0.1\n";
  return d;
}

// The values of node variables at step 0 (after the initial force evaluation), then the run.
std::map<std::string, std::vector<double>> atStepZero(Simulation& sim,
                                                      const std::vector<std::string>& names) {
  std::map<std::string, std::vector<double>> values;
  sim.setStepObserver([&](long long step, double) {
    if (step != 0) return;
    for (const auto& n : names) sim.variables().nodeVariable(n, values[n]);
  });
  sim.run();
  return values;
}

double maxAbs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return m;
}

TEST(Thermal, FreeExpansionIsForceFree) {
  for (const std::string material : {"Elastic", "Elastic Bond Based"}) {
    auto sim = run(cube(material, 1e-3, true));
    auto v = atStepZero(*sim, {"Force_Density", "Temperature", "Temperature_Change", "Dilatation"});
    EXPECT_LT(maxAbs(v["Force_Density"]), 1e-13) << material;
    for (double T : v["Temperature"]) EXPECT_EQ(T, 100.0);
    for (double dT : v["Temperature_Change"]) EXPECT_EQ(dT, 100.0);
    if (material == "Elastic") {
      EXPECT_LT(maxAbs(v["Dilatation"]), 1e-14);
    }
    // Control: the same strain without thermal expansion is far from force-free.
    auto control = run(cube(material, 0.0, true));
    EXPECT_GT(maxAbs(atStepZero(*control, {"Force_Density"})["Force_Density"]), 1e-3) << material;
  }
}

TEST(Thermal, HeldBodyCarriesTheHydrostaticThermalStress) {
  auto sim = run(cube("Elastic", 1e-3, false));
  auto v = atStepZero(
      *sim, {"Dilatation", "Stored_Elastic_Energy_Density", "Force_Density", "Model_Coordinates"});
  const auto &theta = v["Dilatation"], &energy = v["Stored_Elastic_Energy_Density"];
  const auto &f = v["Force_Density"], &x = v["Model_Coordinates"];
  for (std::size_t i = 0; i < theta.size(); ++i) {
    EXPECT_NEAR(theta[i], -3.0 * kStrain, 1e-14);
    EXPECT_NEAR(energy[i], 4.5 * 1.0 * kStrain * kStrain, 1e-14);
    // The centre point has a full, symmetric neighbourhood: no net force.
    if (x[3 * i] == 0.0 && x[3 * i + 1] == 0.0 && x[3 * i + 2] == 0.0) {
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(f[3 * i + d], 0.0, 1e-14);
    }
  }
  // The surface points are pushed out by the compressed interior.
  EXPECT_GT(maxAbs(f), 1e-3);
}

// Two points 1 apart, both held; the temperature falls by 10^4 per unit time from t = 0, so with
// alpha = 1e-5 the bond's stretch less its thermal part is 0.1 t: it exceeds s_c = 0.05 first at
// t = 0.51, step 17 (dt = 0.03; 0.048 at step 16).
long long thermalBreakingStep(const std::string& material) {
  auto sim =
      run("Peridigm:\n"
          "  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
          "    TensorProduct3DMeshGenerator:\n"
          "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
          "      X Length: 2.0\n      Y Length: 1.0\n      Z Length: 1.0\n"
          "      Number Points X: 2\n      Number Points Y: 1\n      Number Points Z: 1\n"
          "  Materials:\n    M:\n      Material Model: " +
          material + "\n      Density: 1.0\n      Bulk Modulus: 1.0\n" +
          (material == "Elastic" ? "      Shear Modulus: 0.6\n" : "") +
          "  Damage Models:\n    D:\n      Damage Model: Critical Stretch\n"
          "      Critical Stretch: 0.05\n      Thermal Expansion Coefficient: 1.0e-5\n"
          "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n"
          "      Damage Model: D\n      Horizon: 1.1\n"
          "  Boundary Conditions:\n    Both Node Set: \"1 2\"\n"
          "    Cool:\n      Type: Prescribed Temperature\n      Node Set: FULL_domain\n"
          "      Value: \"10000.0 - 10000.0*t\"\n"
          "    Start:\n      Type: Initial Temperature\n      Node Set: Both Node Set\n"
          "      Value: \"300.0\"\n"
          "    Hold:\n      Type: Prescribed Displacement\n      Node Set: Both Node Set\n"
          "      Coordinate: x\n      Value: \"0.0\"\n"
          "  Solver:\n    Final Time: 0.9\n    Verlet:\n      Fixed dt: 0.03\n");
  long long first = 1LL << 60;
  sim->setStepObserver([&](long long step, double t) {
    std::vector<double> damage, temperature, change;
    sim->variables().nodeVariable("Damage", damage);
    sim->variables().nodeVariable("Temperature", temperature);
    sim->variables().nodeVariable("Temperature_Change", change);
    for (std::size_t i = 0; i < damage.size(); ++i) {
      if (damage[i] == 1.0) first = std::min(first, step);
      // The prescribed value overrides the initial one (initial conditions first, then the
      // prescribed ones, at t0 and at every step, as Peridigm).
      EXPECT_NEAR(temperature[i], 10000.0 - 10000.0 * t, 1e-9);
      EXPECT_NEAR(change[i], -10000.0 * t, 1e-9);
    }
  });
  sim->run();
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
  return first;
}

TEST(Thermal, CriticalStretchMeasuresTheStretchLessTheThermalStrain) {
  EXPECT_EQ(thermalBreakingStep("Elastic"), 17);
  EXPECT_EQ(thermalBreakingStep("Elastic Bond Based"), 17);
}

TEST(Thermal, InitialTemperatureSetsTheTemperatureOnly) {
  auto sim =
      run("Peridigm:\n"
          "  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
          "    TensorProduct3DMeshGenerator:\n"
          "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
          "      X Length: 3.0\n      Y Length: 1.0\n      Z Length: 1.0\n"
          "      Number Points X: 3\n      Number Points Y: 1\n      Number Points Z: 1\n"
          "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 1.0\n"
          "      Bulk Modulus: 1.0\n      Shear Modulus: 0.6\n"
          "      Thermal Expansion Coefficient: 0.01\n"
          "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 1.1\n"
          "  Boundary Conditions:\n    Two Node Set: \"2 3\"\n"
          "    Start:\n      Type: Initial Temperature\n      Node Set: Two Node Set\n"
          "      Value: \"100.0*x\"\n"
          "  Solver:\n    Final Time: 0.2\n    Verlet:\n      Fixed dt: 0.1\n");
  sim->run();
  std::vector<double> temperature, change, f, x;
  sim->variables().nodeVariable("Temperature", temperature);
  sim->variables().nodeVariable("Temperature_Change", change);
  sim->variables().nodeVariable("Force_Density", f);
  sim->variables().nodeVariable("Model_Coordinates", x);
  for (std::size_t i = 0; i < temperature.size(); ++i) {
    // Point 1 (x = 0.5) is in no set; points 2, 3 at x = 1.5, 2.5 start at 100 x.
    EXPECT_EQ(temperature[i], x[3 * i] < 1.0 ? 0.0 : 100.0 * x[3 * i]);
    EXPECT_EQ(change[i], 0.0);
  }
  EXPECT_EQ(maxAbs(f), 0.0);  // no change of temperature, no thermal strain
}

}  // namespace
}  // namespace peridot
