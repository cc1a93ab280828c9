// Block_Data and Node_Set_Data reductions and influence functions, through the Simulation on
// 1, 2 and 3 ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "app/Simulation.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream quiet;

std::unique_ptr<Simulation> build(const std::string& extraDiscretization,
                                  const std::string& computes) {
  const std::string deck =
      "Peridigm:\n"
      "  Discretization:\n"
      "    Type: PdQuickGrid\n"
      "    NeighborhoodType: Spherical\n" +
      extraDiscretization +
      "    TensorProduct3DMeshGenerator:\n"
      "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
      "      X Length: 4.0\n      Y Length: 4.0\n      Z Length: 4.0\n"
      "      Number Points X: 4\n      Number Points Y: 4\n      Number Points Z: 4\n"
      "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 2.0\n"
      "      Bulk Modulus: 5.0\n      Shear Modulus: 3.0\n"
      "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 2.1\n"
      "  Boundary Conditions:\n    Corner Node Set: \"1 2 5 64\"\n"
      "    V:\n      Type: Initial Velocity\n      Node Set: Corner Node Set\n"
      "      Coordinate: y\n      Value: \"x + 10*z\"\n"
      "  Compute Class Parameters:\n" +
      computes + "  Solver:\n    Final Time: 1.0\n    Verlet:\n      Fixed dt: 0.5\n";
  return std::make_unique<Simulation>(readRunConfig(*parseDeck(deck, "yaml")), MPI_COMM_WORLD,
                                      quiet);
}

std::string compute(const std::string& label, const std::string& cls, const std::string& calc,
                    const std::string& region, const std::string& variable) {
  return "    " + label + ":\n      Compute Class: " + cls + "\n      Calculation Type: " + calc +
         "\n      " + (cls == "Block_Data" ? "Block" : "Node Set") + ": " + region +
         "\n      Variable: " + variable + "\n      Output Label: " + label + "\n";
}

TEST(Computes, BlockAndNodeSetReductions) {
  auto sim = build(
      "", compute("TotalVolume", "Block_Data", "Sum", "block_1", "Volume") +
              compute("MaxVy", "Node_Set_Data", "Maximum", "Corner Node Set", "Velocity") +
              compute("MinVy", "Node_Set_Data", "Minimum", "Corner Node Set", "Velocity") +
              compute("Neighbours", "Block_Data", "Maximum", "block_1", "Number_Of_Neighbors"));
  std::vector<double> g;
  sim->variables().globalVariable("TotalVolume", g);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_DOUBLE_EQ(g[0], 64.0);
  // Corner set: points 1, 2, 5, 64 at (0.5,0.5,0.5), (1.5,0.5,0.5), (0.5,1.5,0.5), (3.5,3.5,3.5):
  // v_y = x + 10 z = 5.5, 6.5, 5.5, 38.5.
  sim->variables().globalVariable("MaxVy", g);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_DOUBLE_EQ(g[1], 38.5);
  EXPECT_DOUBLE_EQ(g[0], 0.0);
  sim->variables().globalVariable("MinVy", g);
  EXPECT_DOUBLE_EQ(g[1], 5.5);
  // Horizon 2.1 on the 4^3 unit grid: the best-placed points ((1,1,1)-like) reach offsets -1..2
  // per axis; of those 63 points, 29 have |xi|^2 <= 4.41 (enumerated by hand: 6 at 1, 12 at 2,
  // 8 at 3, 3 at 4).
  sim->variables().globalVariable("Neighbours", g);
  EXPECT_DOUBLE_EQ(g[0], 29.0);
}

TEST(Computes, InfluenceFunctionsScaleTheWeightedVolume) {
  // Weighted volume of the corner point (id 1) under each influence function, by hand: its
  // neighbours within 2.1 on the unit grid, sum of omega(|xi|) |xi|^2.
  const double delta = 2.1;
  std::vector<double> r2;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const int d2 = i * i + j * j + k * k;
        if (d2 > 0 && d2 <= 4.41) r2.push_back(d2);
      }
  auto expected = [&](auto omega) {
    double m = 0;
    for (double q : r2) m += omega(std::sqrt(q)) * q;
    return m;
  };
  struct Case {
    std::string deckValue;
    double m;
  } cases[] = {
      {"One", expected([](double) { return 1.0; })},
      {"Parabolic Decay", expected([&](double z) {
         const double r = z / delta;
         return r < 0.5 ? 1.0 : -4 * r * r + 4 * r;
       })},
      {"Gaussian", expected([&](double z) { return std::exp(-z * z / (0.16 * delta * delta)); })},
      {"1.0/zeta", expected([](double z) { return 1.0 / z; })},
      {"1 - zeta/horizon", expected([&](double z) { return 1 - z / delta; })},
      {"Conical", expected([&](double z) { return 1 - z / delta; })},
      {"Conical Over Zeta", expected([&](double z) { return (1 - z / delta) / z; })},
  };
  for (const auto& c : cases) {
    auto sim =
        build("    Influence Function: \"" + c.deckValue + "\"\n",
              compute("MinM", "Node_Set_Data", "Minimum", "Corner Node Set", "Weighted_Volume"));
    std::vector<double> m;
    sim->variables().globalVariable("MinM", m);
    // The corners (points 1 and 64) have the smallest neighbourhoods in the set.
    EXPECT_NEAR(m[0], c.m, 1e-12 * c.m) << c.deckValue;
  }
}

}  // namespace
}  // namespace peridot

namespace peridot {
namespace {

TEST(Computes, TractionGivesSigmaTimesAreaInTotal) {
  std::string top;
  for (int id = 49; id <= 64; ++id) top += std::to_string(id) + (id < 64 ? " " : "");
  const std::string deck =
      "Peridigm:\n"
      "  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
      "    TensorProduct3DMeshGenerator:\n"
      "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
      "      X Length: 4.0\n      Y Length: 4.0\n      Z Length: 2.0\n"
      "      Number Points X: 4\n      Number Points Y: 4\n      Number Points Z: 4\n"
      "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 2.0\n"
      "      Bulk Modulus: 5.0\n      Shear Modulus: 3.0\n"
      "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 1.1\n"
      "  Boundary Conditions:\n    Top Node Set: \"" +
      top +
      "\"\n"
      "    Pull:\n      Type: Traction\n      Node Set: Top Node Set\n      Coordinate: z\n"
      "      Value: \"2.5 + 0*x\"\n      Surface Area: 16.0\n"
      "  Compute Class Parameters:\n" +
      compute("TopForceDensity", "Node_Set_Data", "Sum", "Top Node Set", "External_Force_Density") +
      "  Solver:\n    Final Time: 0.4\n    Verlet:\n      Fixed dt: 0.2\n";
  Simulation sim(readRunConfig(*parseDeck(deck, "yaml")), MPI_COMM_WORLD, quiet);
  sim.run();
  std::vector<double> g;
  sim.variables().globalVariable("TopForceDensity", g);
  // 16 points of volume 4*4*2/64 = 0.5: total force = sum(b) * 0.5 = sigma * A = 40.
  EXPECT_NEAR(g[2] * 0.5, 2.5 * 16.0, 1e-12);
  EXPECT_EQ(g[0], 0.0);
}

}  // namespace
}  // namespace peridot

namespace peridot {
namespace {

TEST(Computes, MomentaAndNeighborhoodVolumeByHand) {
  // At t = 0 only the corner set moves: v = (0, x + 10 z, 0) at (0.5,0.5,0.5), (1.5,0.5,0.5),
  // (0.5,1.5,0.5), (3.5,3.5,3.5), so v_y = 5.5, 6.5, 5.5, 38.5; mass = density 2 x volume 1.
  auto sim = build(
      "",
      compute("NeighbourhoodMax", "Block_Data", "Maximum", "block_1", "Neighborhood_Volume") +
          compute("NeighbourhoodMin", "Block_Data", "Minimum", "block_1", "Neighborhood_Volume") +
          compute("P", "Block_Data", "Sum", "block_1", "Linear_Momentum") +
          compute("L", "Block_Data", "Sum", "block_1", "Angular_Momentum"));
  std::vector<double> g;
  sim->variables().globalVariable("P", g);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_DOUBLE_EQ(g[0], 0.0);
  EXPECT_DOUBLE_EQ(g[1], 2.0 * (5.5 + 6.5 + 5.5 + 38.5));
  EXPECT_DOUBLE_EQ(g[2], 0.0);
  sim->variables().globalVariable("Global_Linear_Momentum", g);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_DOUBLE_EQ(g[0], 112.0);
  // m v x y with v = (0, v_y, 0): (v_y z, 0, -v_y x) per point.
  const double Lx = 2.0 * (5.5 * 0.5 + 6.5 * 0.5 + 5.5 * 0.5 + 38.5 * 3.5);
  const double Lz = -2.0 * (5.5 * 0.5 + 6.5 * 1.5 + 5.5 * 0.5 + 38.5 * 3.5);
  sim->variables().globalVariable("L", g);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_DOUBLE_EQ(g[0], Lx);
  EXPECT_DOUBLE_EQ(g[1], 0.0);
  EXPECT_DOUBLE_EQ(g[2], Lz);
  sim->variables().globalVariable("Global_Angular_Momentum", g);
  EXPECT_NEAR(g[0], std::sqrt(Lx * Lx + Lz * Lz), 1e-12 * std::abs(Lz));
  // Unit volumes: the family volume is the neighbour count, 29 at best (see above), and at a
  // corner of the 4^3 grid, offsets 0..2 per axis with 0 < |xi|^2 <= 4.41: 3 at 1, 3 at 2, 1 at
  // 3 and 3 at 4, 10 in all.
  sim->variables().globalVariable("NeighbourhoodMax", g);
  EXPECT_DOUBLE_EQ(g[0], 29.0);
  sim->variables().globalVariable("NeighbourhoodMin", g);
  EXPECT_DOUBLE_EQ(g[0], 10.0);
}

TEST(Computes, ContactForceFollowsTheShortRangeLaw) {
  // Four points 1 apart on a line, horizon 0.5 (no bonds), contact radius 1.2: each neighbouring
  // pair pushes apart with 18 k (r_c - r) / (pi delta^5) V (force density), times V for the
  // force. One step of 1e-9 moves the points by ~1e-16: r stays 1 to round-off.
  const std::string deck =
      "Peridigm:\n"
      "  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
      "    TensorProduct3DMeshGenerator:\n"
      "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
      "      X Length: 4.0\n      Y Length: 1.0\n      Z Length: 1.0\n"
      "      Number Points X: 4\n      Number Points Y: 1\n      Number Points Z: 1\n"
      "  Materials:\n    M:\n      Material Model: Elastic\n      Density: 2.0\n"
      "      Bulk Modulus: 5.0\n      Shear Modulus: 3.0\n"
      "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 0.5\n"
      "  Contact:\n    Search Radius: 1.5\n    Search Frequency: 1\n"
      "    Models:\n      C:\n        Contact Model: Short Range Force\n"
      "        Contact Radius: 1.2\n        Spring Constant: 3.0\n"
      "    Interactions:\n      General Contact:\n        Contact Model: C\n"
      "  Solver:\n    Final Time: 1.0e-9\n    Verlet:\n      Fixed dt: 1.0e-9\n";
  Simulation sim(readRunConfig(*parseDeck(deck, "yaml")), MPI_COMM_WORLD, quiet);
  sim.run();
  const double pi = std::acos(-1.0);
  const double pair = 18.0 * 3.0 * (1.2 - 1.0) / (pi * std::pow(0.5, 5));
  std::vector<double> f, x;
  sim.variables().nodeVariable("Contact_Force", f);
  sim.variables().nodeVariable("Model_Coordinates", x);
  for (std::size_t i = 0; i < x.size() / 3; ++i) {
    // The end points are pushed outwards, the inner ones equally both ways.
    const double expected = x[3 * i] == 0.5 ? -pair : x[3 * i] == 3.5 ? pair : 0.0;
    EXPECT_NEAR(f[3 * i], expected, 1e-9 * pair) << "point at x = " << x[3 * i];
    EXPECT_EQ(f[3 * i + 1], 0.0);
    EXPECT_EQ(f[3 * i + 2], 0.0);
  }
}

}  // namespace
}  // namespace peridot
