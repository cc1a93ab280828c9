// Linearized LPS with its damage update folded into the dilatation loop (issue 16, item 3):
// LSJ-T's history integral and DTT's broken fraction applied there (the evaluator's default)
// against each model's own damage pass before the loop, bit for bit, over steps that soften
// and break bonds: 3D and 2D (plane stress, plane strain), influence functions, one-sided bonds
// (differing horizons), trial evaluations that must leave the history alone, and evaluations
// that must break nothing.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cstring>
#include <memory>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "JitteredLattice.hpp"
#include "Materials.hpp"
#include "damage/LSJT.hpp"
#include "evaluator/ModelEvaluator.hpp"
#include "materials/LinearizedLPS.hpp"

using namespace peridot;

namespace {

struct Options {
  std::string damage = "LSJ-T";  // or "DTT"
  std::string influence = "One";
  bool varyingHorizon = false;  // horizons 1.9..2.3: one-sided bonds (Topology::bondSides)
  std::string mode = "";        // "", "Plane Stress" or "Plane Strain" (a 2D lattice)
  bool fuse = true;             // the evaluator's default: the damage in the dilatation loop
};

std::shared_ptr<DamageModel> damageModel(const std::string& name, double sc) {
  Teuchos::ParameterList p;
  p.set("Damage Model", name);
  p.set("Critical Stretch", sc);
  ListReader r(p, "Damage Models -> D");
  return createDamageModel(r);
}

// A jittered n^3 (or n^2 in z = 0) lattice of spacing 1, one Linearized LPS block.
struct Lattice : peridot::testing::JitteredLattice {
  bool lsjt;

  Lattice(int n, const Options& o)
      : JitteredLattice(n, !o.mode.empty(), o.varyingHorizon, 7), lsjt(o.damage == "LSJ-T") {
    addBlock(peridot::testing::material("Linearized LPS", o.mode, 1.0e9, 0.3),
             damageModel(o.damage, 0.01), o.influence, o.fuse);
  }
  // y = x + a stretch along x growing with `step` plus a random field that differs per step.
  void deform(int step) {
    std::mt19937 rng(11 + step);
    std::uniform_real_distribution<double> noise(-0.004, 0.004);
    const double* x = fields->node("Model_Coordinates", 3);
    double* y = fields->node("Coordinates", 3);
    for (int p = 0; p < topology.numOwned; ++p)
      for (int d = 0; d < 3; ++d)
        y[3 * p + d] = x[3 * p + d] + (d == 0 ? 0.0025 * step * x[3 * p] : 0.0) +
                       (d < cloud.dimension ? noise(rng) : 0.0);
  }
  std::vector<double> node(const char* name, int components) const {
    const double* f = fields->nodeField(name).data;
    return std::vector<double>(f, f + components * topology.numOwned);
  }
  std::int64_t bonds() const { return topology.bondOffsets[topology.numOwned]; }
  std::vector<float> bondDamage() const {
    const float* d = evaluator->state().bondDamage;
    return std::vector<float>(d, d + bonds());
  }
  std::vector<double> history() const {
    if (!lsjt) return {};
    const std::vector<double>& X = fields->bond(LSJT::kHistoryIntegral);
    return std::vector<double>(X.begin(), X.begin() + bonds());
  }
};

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  // (Empty vectors may hold null data, which memcmp must not be given even for 0 bytes.)
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void PrintTo(const Options& o, std::ostream* os) {
  *os << o.damage << ", " << (o.mode.empty() ? "3D" : o.mode) << ", influence " << o.influence
      << (o.varyingHorizon ? ", varying horizon" : "");
}

class LinearizedLpsDamageFold : public ::testing::TestWithParam<Options> {};

}  // namespace

TEST_P(LinearizedLpsDamageFold, MatchesTheSeparateDamagePassBitForBit) {
  Options fusedOptions = GetParam(), separateOptions = GetParam();
  fusedOptions.fuse = true;
  separateOptions.fuse = false;
  const int n = GetParam().mode.empty() ? 6 : 12;
  Lattice fused(n, fusedOptions), separate(n, separateOptions);
  EXPECT_EQ(GetParam().varyingHorizon, fused.evaluator->state().bondSides != nullptr);
  const bool lsjt = GetParam().damage == "LSJ-T";
  long long partial = 0, broken = 0;
  for (int step = 0; step <= 8; ++step) {
    fused.deform(step);
    separate.deform(step);
    // On odd steps a trial (a solver's probe) first: it breaks bonds but must not store
    // LSJ-T's history, fused or not.
    for (const bool commit : {false, true}) {
      if (!commit && step % 2 == 0) continue;
      fused.evaluator->evaluate(0.5, true, commit);
      separate.evaluator->evaluate(0.5, true, commit);
      const std::string when = (commit ? "step " : "trial, step ") + std::to_string(step);
      EXPECT_TRUE(sameBits(fused.node(LinearizedLPS::kDilatation, 1),
                           separate.node(LinearizedLPS::kDilatation, 1)))
          << when;
      EXPECT_TRUE(sameBits(fused.node("Force_Density", 3), separate.node("Force_Density", 3)))
          << when;
      EXPECT_TRUE(sameBits(fused.bondDamage(), separate.bondDamage())) << when;
      EXPECT_TRUE(sameBits(fused.history(), separate.history())) << when;
    }
    partial = broken = 0;
    for (float d : fused.bondDamage()) {
      if (d > 0.0f && d < 1.0f) ++partial;
      if (d == 1.0f) ++broken;
    }
  }
  // Bonds did soften (a partial damage: LSJ-T's h, DTT's linear part) and break, and not all.
  EXPECT_GT(partial, 0);
  EXPECT_GT(broken, 0);
  EXPECT_LT(partial + broken, fused.bonds());
  if (lsjt) {
    long long accumulated = 0;
    for (double X : fused.history()) accumulated += X > 0;
    EXPECT_GT(accumulated, 0);
  }
  // An evaluation that must not break bonds (the implicit solvers' probes) changes no damage
  // and no history.
  fused.deform(14);
  const std::vector<float> before = fused.bondDamage();
  const std::vector<double> history = fused.history();
  fused.evaluator->evaluate(0.5, false);
  EXPECT_TRUE(sameBits(before, fused.bondDamage()));
  EXPECT_TRUE(sameBits(history, fused.history()));
}

INSTANTIATE_TEST_SUITE_P(
    Configurations, LinearizedLpsDamageFold,
    ::testing::Values(Options{"LSJ-T", "One", false, ""},
                      Options{"LSJ-T", "Parabolic Decay", false, ""},
                      Options{"LSJ-T", "1.0/zeta", true, ""},
                      Options{"LSJ-T", "Conical Over Zeta", false, "Plane Stress"},
                      Options{"LSJ-T", "One", true, "Plane Strain"},
                      Options{"DTT", "One", false, ""}, Options{"DTT", "1.0/zeta", true, ""},
                      Options{"DTT", "Conical", true, "Plane Stress"}));
