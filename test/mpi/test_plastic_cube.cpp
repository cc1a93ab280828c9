// The regression deck test/regression/decks/PlasticCube ("Elastic Plastic", every point driven
// by a homogeneous uniaxial strain that goes past yield, reverses and yields again) run through
// the Simulation at 1, 2 and 3 ranks. Gold, computed here independently of the model's code: a
// hand computation on the lattice — the sums m = sum zeta^2, S = sum g^2 with
// g = zeta n.D.n over the integer bond vectors |xi| < delta, and the scalar return mapping along
// the path's one deviatoric direction — gives the plastic multiplier Lambda of a bulk point at
// every step; the 8 central points of the cube (2 horizons from every face) must follow it.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/Simulation.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

const double kPi = 3.14159265358979323846;

std::ostringstream runLog;

TEST(PlasticCubeDeck, BulkLambdaFollowsTheLatticeHandComputation) {
  auto deck =
      loadDeck(std::string(PERIDOT_TEST_DIR) + "/regression/decks/PlasticCube/PlasticCube.xml");
  std::ostringstream ids;
  for (int i = 1; i <= 2744; ++i) ids << i << ' ';
  deck->sublist("Boundary Conditions").set("All Node Set", ids.str());
  deck->remove("Output");
  Simulation sim(readRunConfig(*deck), MPI_COMM_WORLD, runLog);

  // The deck's constants.
  const double G = 1.0, sigmaY = 1e-7, delta = 3.015, rate = 2.5e-7;
  // Lattice sums for uniaxial strain along z: D = diag(-1/3, -1/3, 2/3).
  double m = 0, S = 0;
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j)
      for (int k = -3; k <= 3; ++k) {
        const double z2 = i * i + j * j + k * k;
        if (z2 == 0 || z2 >= delta * delta) continue;
        const double g = (k * k - z2 / 3) / std::sqrt(z2);  // zeta n.D.n
        m += z2;
        S += g * g;
      }
  const double alpha = 15 * G / m;
  const double psi0 = 25 * sigmaY * sigmaY / (8 * kPi * std::pow(delta, 5));
  double p = 0, lambdaGold = 0;  // plastic strain amplitude and multiplier of the bulk point

  const Topology& t = sim.topology();
  const double* x = sim.fields().node("Model_Coordinates", 3);
  std::vector<int> centre;
  for (int i = 0; i < t.numOwned; ++i) {
    bool inside = true;
    for (int d = 0; d < 3; ++d) inside = inside && std::abs(x[3 * i + d] - 7.0) < 0.6;
    if (inside) centre.push_back(i);
  }
  int count = static_cast<int>(centre.size()), total = 0;
  MPI_Allreduce(&count, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  ASSERT_EQ(total, 8);

  double worstLambda = 0, worstTheta = 0, largestLambda = 0;
  int steps = 0;
  sim.setStepObserver([&](long long, double time) {
    const double eps = time < 1.0 ? rate * time : rate * (2.0 - time);
    // Scalar return mapping (perfect plasticity): |t_d trial| = alpha |eps - p| sqrt(S).
    const double trial = alpha * std::abs(eps - p) * std::sqrt(S);
    if (trial * trial / 2 > psi0) {
      const double dLambda = (trial / std::sqrt(2 * psi0) - 1) / alpha;
      p += dLambda * alpha * (eps - p) / (1 + alpha * dLambda);
      lambdaGold += dLambda;
    }
    largestLambda = std::max(largestLambda, lambdaGold);
    const double* lambda = sim.fields().node("Lambda", 1);
    const double* theta = sim.fields().node("Dilatation", 1);
    for (int i : centre) {
      worstLambda = std::max(worstLambda, std::abs(lambda[i] - lambdaGold));
      worstTheta = std::max(worstTheta, std::abs(theta[i] - eps));
    }
    ++steps;
  });
  sim.run();
  double local[2] = {worstLambda, worstTheta}, global[2];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf(
        "  PlasticCube: largest Lambda %.6g, bulk |Lambda - gold| / largest %.2e, "
        "|theta - eps| / eps_max %.2e\n",
        largestLambda, global[0] / largestLambda, global[1] / rate);
  EXPECT_EQ(steps, 61);
  EXPECT_GT(largestLambda, 100.0);  // the path is well past yield, both ways
  // Relative to the largest values: the gold is small-strain, the run's bonds stretch by up to
  // 5e-7 relative, and Lambda is a difference of norms ~ 1/alpha ~ 40 per yield strain.
  EXPECT_LT(global[0] / largestLambda, 1e-5) << global[0];
  EXPECT_LT(global[1] / rate, 1e-5) << global[1];
}

}  // namespace
}  // namespace peridot
