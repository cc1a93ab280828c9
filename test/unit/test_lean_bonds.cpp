// The lean bond storage of bond-based runs (issue 16): |xi| computed in the loop instead of read
// from Reference_Bond_Length, and damage kept as 1-byte broken flags instead of floats. Each is
// checked against the stored form it replaces (a second code path), bit for bit, and models that
// ask for the stored forms still get them.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <tuple>
#include <vector>

#include "JitteredLattice.hpp"
#include "Materials.hpp"
#include "core/ProcessorsPerRank.hpp"
#include "damage/CriticalStretch.hpp"
#include "evaluator/ModelEvaluator.hpp"

using namespace peridot;

namespace {

using peridot::testing::criticalStretch;

// A jittered n^3 lattice (spacing 1, horizon 2.1), one block; compact damage allowed or not.
struct Lattice {
  PointCloud cloud;
  Topology topology;
  std::unique_ptr<FieldManager> fields;
  std::vector<Block> blocks;
  Timers timers;
  std::unique_ptr<ModelEvaluator> evaluator;

  // storeLengths: the default `Bond Storage: "Fast"` (|xi| stored for every model); these tests
  // mostly run the lean forms of "Compact".
  // halfList: whether bond-based runs may walk the half bond list (the default of runs); the
  // tests of the full lists' storage forms turn it off.
  Lattice(int n, std::shared_ptr<MaterialModel> material, std::shared_ptr<DamageModel> damage,
          bool allowCompact, bool storeLengths = false, bool halfList = true) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    long long id = 0;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          cloud.x.insert(cloud.x.end(), {i + jitter(rng), j + jitter(rng), k + jitter(rng)});
          cloud.volume.push_back(1.0);
          cloud.blockId.push_back(1);
          cloud.globalId.push_back(id++);
        }
    cloud.blockNames[1] = "block_1";
    std::vector<double> h(cloud.volume.size(), 2.1);
    topology = buildTopology(cloud, h, TopologyOptions(), MPI_COMM_SELF);
    fields = std::make_unique<FieldManager>(topology);
    double* x = fields->node("Model_Coordinates", 3);
    double* y = fields->node("Coordinates", 3);
    double* v = fields->node("Volume", 1);
    double* hz = fields->node("Horizon", 1);
    for (int p = 0; p < topology.numOverlap; ++p) {
      for (int d = 0; d < 3; ++d)
        x[3 * p + d] = y[3 * p + d] = topology.referencePosition[3 * p + d];
      v[p] = 1.0;
      hz[p] = 2.1;
    }
    Block b;
    b.name = "block_1";
    b.id = 1;
    b.material = std::move(material);
    b.damage = std::move(damage);
    for (int i = 0; i < topology.numOwned; ++i) b.points.push_back(i);
    blocks.push_back(b);
    evaluator = std::make_unique<ModelEvaluator>(topology, *fields, blocks, "One", timers);
    evaluator->setCompactDamageAllowed(allowCompact);
    evaluator->setStoreBondLengths(storeLengths);
    evaluator->setHalfBondListAllowed(halfList);
    evaluator->initialize();
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
  std::vector<double> force() const {
    const double* f = fields->nodeField("Force_Density").data;
    return std::vector<double>(f, f + 3 * topology.numOwned);
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

std::shared_ptr<MaterialModel> pmb() {
  return peridot::testing::material("Elastic Bond Based", "", 1.0e9);
}

}  // namespace

// PMB + critical stretch over several steps that break bonds: the compact run (no |xi| array,
// 1-byte flags) and the float run give the same forces and node damage to the bit.
TEST(LeanBonds, CompactDamageRunMatchesFloatDamageBitForBit) {
  for (const bool half : {false, true}) {
    SCOPED_TRACE(half ? "half bond list" : "full bond lists");
    Lattice compact(6, pmb(), criticalStretch(0.01), true, false, half);
    Lattice full(6, pmb(), criticalStretch(0.01), false, false, half);
    ASSERT_EQ(compact.evaluator->usesHalfBondList(), half);
    EXPECT_TRUE(compact.evaluator->compactDamage());
    EXPECT_FALSE(full.evaluator->compactDamage());
    EXPECT_EQ(compact.evaluator->state().bondLength, nullptr);
    EXPECT_EQ(compact.evaluator->state().bondDamage, nullptr);
    ASSERT_NE(compact.evaluator->state().bondBroken, nullptr);
    ASSERT_NE(full.evaluator->state().bondDamage, nullptr);
    // 5 bytes a bond less than 4 (float damage): the float run keeps no |xi| either.
    EXPECT_EQ(full.evaluator->state().bondLength, nullptr);
    const auto bonds = static_cast<std::size_t>(compact.topology.numBonds());
    EXPECT_EQ(full.fields->bytesAllocated() - compact.fields->bytesAllocated(), 3 * bonds);

    double lastDamage = 0;
    for (int step = 0; step <= 6; ++step) {
      compact.deform(step);
      full.deform(step);
      compact.evaluator->evaluate(1.0);
      full.evaluator->evaluate(1.0);
      EXPECT_TRUE(sameBits(compact.force(), full.force())) << "step " << step;
      EXPECT_TRUE(sameBits(compact.nodeDamage(), full.nodeDamage())) << "step " << step;
      double sum = 0;
      for (double d : full.nodeDamage()) sum += d;
      lastDamage = sum;
    }
    // The scene does break bonds (else the flags were never written).
    EXPECT_GT(lastDamage, 0.0);
    // Evaluations that must not break bonds (updateDamage false) read the flags alike.
    compact.deform(9);
    full.deform(9);
    compact.evaluator->evaluate(1.0, false);
    full.evaluator->evaluate(1.0, false);
    EXPECT_TRUE(sameBits(compact.force(), full.force()));
    EXPECT_TRUE(sameBits(compact.nodeDamage(), full.nodeDamage()));
    // Stored energy reads both forms alike.
    std::vector<double> wc(compact.topology.numOwned), wf(full.topology.numOwned);
    compact.evaluator->storedEnergyDensity(wc.data());
    full.evaluator->storedEnergyDensity(wf.data());
    EXPECT_TRUE(sameBits(wc, wf));
  }
}

// Node damage where horizons differ (some bonds one-sided: only the owner's side counts): the
// flags' integer counts give the float run's quotients to the bit.
TEST(LeanBonds, CompactNodeDamageWithOneSidedBondsMatchesFloatDamage) {
  peridot::testing::JitteredLattice compact(6, false, true, 5), full(6, false, true, 5);
  compact.addBlock(pmb(), criticalStretch(0.01), "One", true, true, true);
  full.addBlock(pmb(), criticalStretch(0.01), "One", true, true, false);
  ASSERT_FALSE(compact.topology.bondSides.empty());  // the scene has one-sided bonds
  ASSERT_TRUE(compact.evaluator->compactDamage());
  ASSERT_FALSE(full.evaluator->compactDamage());
  double total = 0;
  for (int step = 1; step <= 4; ++step) {
    for (auto* L : {&compact, &full}) {
      const double* x = L->fields->node("Model_Coordinates", 3);
      double* y = L->fields->node("Coordinates", 3);
      for (int p = 0; p < L->topology.numOverlap; ++p) y[3 * p] = x[3 * p] * (1 + 0.004 * step);
      L->evaluator->evaluate(1.0);
    }
    const std::vector<double> d = compact.nodeDamage();
    EXPECT_TRUE(sameBits(d, full.nodeDamage())) << "step " << step;
    total = 0;
    for (double v : d) total += v;
  }
  EXPECT_GT(total, 0.0);  // bonds broke
}

// The loop's own |xi| against a stored array the test fills independently: the force with
// state.bondLength set is the force without, to the bit.
TEST(LeanBonds, ComputedBondLengthEqualsStoredBondLength) {
  Lattice lean(5, pmb(), criticalStretch(0.01), false, false, false);
  lean.deform(4);
  lean.evaluator->evaluate(1.0, false);
  const std::vector<double> computed = lean.force();

  const Topology& t = lean.topology;
  const double* x = lean.fields->node("Model_Coordinates", 3);
  std::vector<double> zeta(static_cast<std::size_t>(t.numBonds()));
  for (int i = 0; i < t.numOwned; ++i)
    for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
      const int j = t.neighbors[b];
      // The sum in the order sumOfSquares fixes, written out here.
      const double X0 = x[3 * j] - x[3 * i], X1 = x[3 * j + 1] - x[3 * i + 1],
                   X2 = x[3 * j + 2] - x[3 * i + 2];
#ifdef __FMA__
      zeta[b] = std::sqrt(std::fma(X2, X2, std::fma(X0, X0, X1 * X1)));
#else
      zeta[b] = std::sqrt(X0 * X0 + X1 * X1 + X2 * X2);  // nothing to contract
#endif
    }
  ModelState s = lean.evaluator->state();
  ASSERT_EQ(s.bondLength, nullptr);
  s.bondLength = zeta.data();
  lean.blocks[0].material->computeForce(s, lean.blocks[0].points);
  EXPECT_TRUE(sameBits(computed, lean.force()));
  // And the stable-time-step sum, which reads |xi| off the hot path.
  std::vector<double> a(t.numOwned), b(t.numOwned);
  lean.blocks[0].material->stiffnessSum(lean.evaluator->state(), lean.blocks[0].points, a.data());
  lean.blocks[0].material->stiffnessSum(s, lean.blocks[0].points, b.data());
  EXPECT_TRUE(sameBits(a, b));
}

namespace {
// Four steps that break bonds: the same forces and node damage, to the bit.
void runAlike(Lattice& fast, Lattice& lean) {
  for (int step = 1; step <= 4; ++step) {
    fast.deform(step);
    lean.deform(step);
    fast.evaluator->evaluate(1.0);
    lean.evaluator->evaluate(1.0);
    EXPECT_EQ(fast.force(), lean.force()) << "step " << step;
    EXPECT_EQ(fast.nodeDamage(), lean.nodeDamage()) << "step " << step;
  }
}
}  // namespace

// The default storage ("Fast") keeps |xi| for PMB too, and gives the lean run's bits: in the full
// lists' loop, and in the half list's (whose pairs keep |xi| themselves then).
TEST(LeanBonds, FastStorageStoresBondLengthsWithTheSameResults) {
  for (const bool half : {false, true}) {
    SCOPED_TRACE(half ? "half bond list" : "full bond lists");
    Lattice fast(5, pmb(), criticalStretch(0.01), false, true, half);
    Lattice lean(5, pmb(), criticalStretch(0.01), false, false, half);
    ASSERT_EQ(fast.evaluator->usesHalfBondList(), half);
    ASSERT_EQ(lean.evaluator->usesHalfBondList(), half);
    if (half) {
      // The pairs hold |xi|; the full lists need none.
      EXPECT_EQ(fast.evaluator->state().bondLength, nullptr);
      // (Through the table of the lattice's distinct lengths: HalfBondList::storeLengths.)
      const HalfBondList& pairs = *fast.evaluator->halfBondList();
      EXPECT_EQ(pairs.pairLengthIndex.size(),
                static_cast<std::size_t>(pairs.numPairs() + HalfBondList::kPadding));
      EXPECT_FALSE(pairs.lengthTable.empty());
      EXPECT_FALSE(lean.evaluator->halfBondList()->storesLengths());
    } else {
      ASSERT_NE(fast.evaluator->state().bondLength, nullptr);
    }
    EXPECT_EQ(lean.evaluator->state().bondLength, nullptr);
    runAlike(fast, lean);
  }
}

// A model that reads the stored forms (LPS over the full lists) still gets them: |xi| per bond
// and float damage. (Over the half list its loops read the pairs' |xi|: HalfBondList.*.)
TEST(LeanBonds, ModelsThatNeedStoredFormsGetThem) {
  Lattice lps(4, peridot::testing::material("Elastic", "", 1.0e9, 0.25), criticalStretch(0.01),
              true, false, false);
  EXPECT_FALSE(lps.evaluator->compactDamage());
  ASSERT_NE(lps.evaluator->state().bondLength, nullptr);
  ASSERT_NE(lps.evaluator->state().bondDamage, nullptr);
  EXPECT_EQ(lps.evaluator->state().bondBroken, nullptr);
  const double* x = lps.fields->node("Model_Coordinates", 3);
  const Topology& t = lps.topology;
  for (std::int64_t b = t.bondOffsets[0]; b < t.bondOffsets[1]; ++b)
    EXPECT_EQ(lps.evaluator->state().bondLength[b], referenceBondLength(x, 0, t.neighbors[b]));
}

// The stable-time-step sum (MaterialModel::stiffnessSum: its terms in vector lanes, then summed
// in order) against the plain loop, to the bit: sum over the bonds within i's horizon of
// V_j 18 K / (pi delta^4) / |xi|, with one-sided bonds (horizons that vary), with |xi| stored
// and computed; on 5^3 points with one thread, and on 15^3 shared among three (runs of points).
class StiffnessSum : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(StiffnessSum, IsThePlainSumInOrder) {
  const auto [n, processors] = GetParam();
  setProcessorsPerRank(processors);
  struct Restore {
    ~Restore() { setProcessorsPerRank(1); }
  } restore;
  peridot::testing::JitteredLattice L(n, false, true, 3);
  L.addBlock(peridot::testing::material("Elastic", "", 1.0e9, 0.25), nullptr, "One", true, false);
  const Topology& t = L.topology;
  ModelState s = L.evaluator->state();
  ASSERT_NE(s.bondSides, nullptr);
  const double K = L.blocks[0].material->bulkModulus(), pi = 3.14159265358979323846;
  std::vector<double> zeta(static_cast<std::size_t>(t.numBonds())), expected(t.numOwned);
  for (int i = 0; i < t.numOwned; ++i) {
    const double d = s.horizon[i], c = 18.0 * K / (pi * d * d * d * d);
    double total = 0;
    for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
      zeta[b] = referenceBondLength(s.x, i, t.neighbors[b]);
      if (s.bondSides[b] & 1) total += s.volume[t.neighbors[b]] * c / zeta[b];
    }
    expected[i] = total;
  }
  for (const bool stored : {false, true}) {
    s.bondLength = stored ? zeta.data() : nullptr;
    std::vector<double> sum(t.numOwned);
    L.blocks[0].material->stiffnessSum(s, L.blocks[0].points, sum.data());
    EXPECT_TRUE(sameBits(sum, expected)) << (stored ? "stored" : "computed");
  }
}

INSTANTIATE_TEST_SUITE_P(LeanBonds, StiffnessSum,
                         ::testing::Values(std::make_tuple(5, 1), std::make_tuple(15, 3)));
