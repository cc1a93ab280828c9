// The LPS ("Elastic") bond loops made faster for issue 16 (item 3), each checked bit for bit
// against a second code path that computes the same thing the plain way: the critical stretch
// folded into the dilatation loop against the separate damage pass, and the force loop against
// a scalar loop written here with Peridigm's per-bond order of operations. Also the bond-based
// (PMB, normalized PMB) force loops with DTT's damage folded in, against DTT's own pass.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstring>
#include <memory>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "JitteredLattice.hpp"
#include "Materials.hpp"
#include "damage/CriticalStretch.hpp"
#include "damage/DTT.hpp"
#include "evaluator/ModelEvaluator.hpp"
#include "materials/Elastic.hpp"

using namespace peridot;

namespace {

using peridot::testing::criticalStretch;

std::shared_ptr<DamageModel> dtt(double sc) {
  Teuchos::ParameterList p;
  p.set("Damage Model", std::string("DTT"));
  p.set("Critical Stretch", sc);
  ListReader r(p, "Damage Models -> D");
  return std::make_shared<DTT>(r);
}

struct Options {
  std::string influence = "One";
  bool varyingHorizon = false;  // horizons 1.9..2.3: one-sided bonds (Topology::bondSides)
  bool fuse = true;             // the evaluator's default: the damage in the bond loop
  std::string model = "Elastic";
  bool smoothDamage = false;  // DTT instead of Critical Stretch
};

// A jittered n^3 lattice (spacing 1), one LPS block with a critical stretch, over the full
// lists (the half list's loops are checked against these in test_half_bond_list.cpp).
struct Lattice : peridot::testing::JitteredLattice {
  Lattice(int n, const Options& o) : JitteredLattice(n, false, o.varyingHorizon, 5) {
    addBlock(o.model == "Elastic" ? peridot::testing::material("Elastic", "", 1.0e9, 0.3)
                                  : peridot::testing::material(o.model, "", 1.0e9),
             o.smoothDamage ? dtt(0.01) : criticalStretch(0.01), o.influence, o.fuse, false);
  }
  // y = x + a stretch along x growing with `step` plus a fixed random field.
  void deform(int step) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> noise(-0.02, 0.02);
    const double* x = fields->node("Model_Coordinates", 3);
    double* y = fields->node("Coordinates", 3);
    for (int p = 0; p < topology.numOwned; ++p)
      for (int d = 0; d < 3; ++d)
        y[3 * p + d] = x[3 * p + d] + (d == 0 ? 0.004 * step * x[3 * p] : 0.0) + noise(rng);
  }
  std::vector<double> node(const char* name, int components) const {
    const double* f = fields->nodeField(name).data;
    return std::vector<double>(f, f + components * topology.numOwned);
  }
  std::vector<double> nodeDamage() const {
    std::vector<double> d(topology.numOwned);
    evaluator->nodeDamage(d.data());
    return d;
  }
};

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

void PrintTo(const Options& o, std::ostream* os) {
  *os << o.model << (o.smoothDamage ? ", DTT" : "") << ", influence " << o.influence
      << (o.varyingHorizon ? ", varying horizon" : "");
}

class LpsCriticalStretchFold : public ::testing::TestWithParam<Options> {};
class DttFold : public ::testing::TestWithParam<Options> {};

}  // namespace

// The critical stretch applied in the dilatation loop (the default) against the separate damage
// pass before it: the same bonds break, and the dilatations, forces and node damage are the
// same to the bit, step after step, as bonds break.
TEST_P(LpsCriticalStretchFold, MatchesTheSeparateDamagePassBitForBit) {
  Options fusedOptions = GetParam(), separateOptions = GetParam();
  fusedOptions.fuse = true;
  separateOptions.fuse = false;
  Lattice fused(6, fusedOptions), separate(6, separateOptions);
  EXPECT_EQ(GetParam().varyingHorizon, fused.evaluator->state().bondSides != nullptr);
  double damage = 0;
  for (int step = 0; step <= 6; ++step) {
    fused.deform(step);
    separate.deform(step);
    fused.evaluator->evaluate(1.0);
    separate.evaluator->evaluate(1.0);
    EXPECT_TRUE(
        sameBits(fused.node(Elastic::kDilatation, 1), separate.node(Elastic::kDilatation, 1)))
        << "step " << step;
    EXPECT_TRUE(sameBits(fused.node("Force_Density", 3), separate.node("Force_Density", 3)))
        << "step " << step;
    EXPECT_TRUE(sameBits(fused.nodeDamage(), separate.nodeDamage())) << "step " << step;
    damage = 0;
    for (double d : fused.nodeDamage()) damage += d;
  }
  // Bonds did break (else the fold was never exercised) and not all of them.
  EXPECT_GT(damage, 0.0);
  EXPECT_LT(damage, fused.topology.numOwned);
  // An evaluation that must not break bonds (the implicit solvers' probes) breaks none.
  fused.deform(12);
  const std::vector<double> before = fused.nodeDamage();
  fused.evaluator->evaluate(1.0, false);
  EXPECT_TRUE(sameBits(before, fused.nodeDamage()));
}

INSTANTIATE_TEST_SUITE_P(Options, LpsCriticalStretchFold,
                         ::testing::Values(Options{"One", false, true},
                                           Options{"Parabolic Decay", false, true},
                                           Options{"1.0/zeta", true, true}));

// DTT's damage applied in the bond-based force loops (the default) against DTT's own pass
// before them: the same bond damage (partly broken bonds included), forces and node damage to
// the bit, step after step, as bonds soften and break.
TEST_P(DttFold, MatchesTheSeparateDamagePassBitForBit) {
  Options fusedOptions = GetParam(), separateOptions = GetParam();
  fusedOptions.fuse = true;
  separateOptions.fuse = false;
  Lattice fused(6, fusedOptions), separate(6, separateOptions);
  EXPECT_EQ(GetParam().varyingHorizon, fused.evaluator->state().bondSides != nullptr);
  const std::int64_t bonds = fused.topology.bondOffsets[fused.topology.numOwned];
  long long partial = 0, broken = 0;
  for (int step = 0; step <= 6; ++step) {
    fused.deform(step);
    separate.deform(step);
    fused.evaluator->evaluate(1.0);
    separate.evaluator->evaluate(1.0);
    EXPECT_TRUE(sameBits(fused.node("Force_Density", 3), separate.node("Force_Density", 3)))
        << "step " << step;
    EXPECT_TRUE(sameBits(fused.nodeDamage(), separate.nodeDamage())) << "step " << step;
    const float* a = fused.evaluator->state().bondDamage;
    const float* b = separate.evaluator->state().bondDamage;
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(std::memcmp(a, b, sizeof(float) * bonds), 0) << "step " << step;
    partial = broken = 0;
    for (std::int64_t k = 0; k < bonds; ++k) {
      if (a[k] > 0.0f && a[k] < 1.0f) ++partial;
      if (a[k] == 1.0f) ++broken;
    }
  }
  // Bonds did soften (the smooth part of the law) and break, and not all of them.
  EXPECT_GT(partial, 0);
  EXPECT_GT(broken, 0);
  EXPECT_LT(partial + broken, bonds);
  // An evaluation that must not break bonds (the implicit solvers' probes) changes no damage.
  fused.deform(12);
  const std::vector<float> before(fused.evaluator->state().bondDamage,
                                  fused.evaluator->state().bondDamage + bonds);
  fused.evaluator->evaluate(1.0, false);
  EXPECT_EQ(std::memcmp(before.data(), fused.evaluator->state().bondDamage, sizeof(float) * bonds),
            0);
}

INSTANTIATE_TEST_SUITE_P(Models, DttFold,
                         ::testing::Values(Options{"One", false, true, "Elastic Bond Based", true},
                                           Options{"One", true, true, "Elastic Bond Based", true},
                                           Options{"One", false, true, "Normalized PMB", true},
                                           Options{"1.0/zeta", true, true, "Normalized PMB",
                                                   true}));
