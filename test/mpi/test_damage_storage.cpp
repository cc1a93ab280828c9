// How a run keeps its bond damage, chosen by the Simulation: 1-byte broken flags wherever
// nothing needs floats (a Verlet run whose damage is a critical stretch fused into the force
// loop), with either bond storage; floats where a damage model other than the critical stretch
// reads and writes them.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "app/Simulation.hpp"
#include "deck/Deck.hpp"

namespace peridot {
namespace {

std::ostringstream quiet;

Simulation* build(const std::string& storage, const std::string& damageModel) {
  const std::string deck =
      "Peridigm:\n"
      "  Discretization:\n"
      "    Type: PdQuickGrid\n"
      "    NeighborhoodType: Spherical\n" +
      storage +
      "    TensorProduct3DMeshGenerator:\n"
      "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
      "      X Length: 6.0\n      Y Length: 6.0\n      Z Length: 6.0\n"
      "      Number Points X: 6\n      Number Points Y: 6\n      Number Points Z: 6\n"
      "  Materials:\n    M:\n      Material Model: Elastic Bond Based\n      Density: 2.0\n"
      "      Bulk Modulus: 5.0\n"
      "  Damage Models:\n    D:\n      Damage Model: " +
      damageModel +
      "\n      Critical Stretch: 0.01\n"
      "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Damage Model: D\n"
      "      Horizon: 2.1\n"
      "  Solver:\n    Final Time: 1.0\n    Verlet:\n      Fixed dt: 0.5\n";
  return new Simulation(readRunConfig(*parseDeck(deck, "yaml")), MPI_COMM_WORLD, quiet);
}

}  // namespace

TEST(DamageStorage, FlagsWhereNothingNeedsFloats) {
  for (const std::string storage : {"", "    Bond Storage: Compact\n"}) {
    SCOPED_TRACE(storage.empty() ? "default storage" : "Compact storage");
    std::unique_ptr<Simulation> sim(build(storage, "Critical Stretch"));
    EXPECT_TRUE(sim->evaluator().compactDamage());
  }
  // A damage model with its own pass over the float damage keeps floats.
  std::unique_ptr<Simulation> sim(build("", "Interface Aware"));
  EXPECT_FALSE(sim->evaluator().compactDamage());
}

}  // namespace peridot
