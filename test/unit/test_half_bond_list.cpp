// The half bond list (neighbor/HalfBondList.hpp) and the loops over it (the bond-based force,
// materials/HalfPairForce.cpp; LPS, materials/HalfLps.cpp): every bond once, with the right
// full-list entries, in curve order; the same forces as the full lists' loop to rounding (another
// summation order) and the same broken bonds to the bit; only where the scene allows it. Rank-count
// identity is checked by the identical_DamageCube test (1 to 4 ranks, the run's log says the half
// list ran).
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "JitteredLattice.hpp"
#include "Materials.hpp"
#include "damage/CriticalStretch.hpp"
#include "neighbor/BondGeometry.hpp"
#include "neighbor/HalfBondList.hpp"
#include "parallel/Partition.hpp"

using namespace peridot;
using peridot::testing::JitteredLattice;

namespace {

using peridot::testing::criticalStretch;

// y = x + a stretch along x that grows with `step`, plus a fixed random-looking field.
void deform(JitteredLattice& L, int step) {
  const double* x = L.fields->node("Model_Coordinates", 3);
  double* y = L.fields->node("Coordinates", 3);
  for (int p = 0; p < L.topology.numOwned; ++p)
    for (int d = 0; d < 3; ++d)
      y[3 * p + d] = x[3 * p + d] + (d == 0 ? 0.004 * step * x[3 * p] : 0.0) +
                     0.02 * std::sin(7.0 * p + 3.0 * d);
}

// The bond damage the full lists hold (either form), as floats.
std::vector<float> bondDamage(const JitteredLattice& L) {
  const ModelState& s = L.evaluator->state();
  std::vector<float> d(static_cast<std::size_t>(L.topology.numBonds()));
  for (std::size_t b = 0; b < d.size(); ++b)
    d[b] = s.bondDamage ? s.bondDamage[b] : (s.bondBroken ? s.bondBroken[b] : 0.0f);
  return d;
}

// max |a - b| over max |b|.
double relativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0, scale = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    diff = std::max(diff, std::fabs(a[k] - b[k]));
    scale = std::max(scale, std::fabs(b[k]));
  }
  return diff / scale;
}

// Steps that stretch until bonds break, the half list against the full lists: the force (and
// the node field `also`, if any) to rounding, the same bond and node damage to the bit; some
// bonds break, not all.
void stepAlike(JitteredLattice& half, JitteredLattice& full, const char* also) {
  const auto field = [&](const JitteredLattice& L) {
    const double* v = L.fields->nodeField(also).data;
    return std::vector<double>(v, v + L.topology.numOwned);
  };
  double broken = 0;
  for (int step = 0; step <= 6; ++step) {
    deform(half, step);
    deform(full, step);
    half.evaluator->evaluate(1.0);
    full.evaluator->evaluate(1.0);
    if (also) {
      EXPECT_LT(relativeDifference(field(half), field(full)), 1e-13) << also << ", step " << step;
    }
    EXPECT_LT(relativeDifference(half.force(), full.force()), 1e-13) << "step " << step;
    EXPECT_EQ(bondDamage(half), bondDamage(full)) << "step " << step;
    EXPECT_EQ(half.nodeDamage(), full.nodeDamage()) << "step " << step;
    broken = 0;
    for (float d : bondDamage(full)) broken += d;
  }
  EXPECT_GT(broken, 0.0);
  EXPECT_LT(broken, static_cast<double>(full.topology.numBonds()));
}

}  // namespace

// Every bond once, in curve order, each pair's full-list entries found (HalfBondList::fullEntry).
static void expectEveryBondOnceInCurveOrder(const Topology& t, const HalfBondList& h) {
  EXPECT_EQ(2 * h.numPairs(), t.numBonds());
  const auto key = [&](int k) {
    return std::make_pair(mortonKey(&t.referencePosition[3 * k], t.curveLo, t.curveHi),
                          t.overlapGlobalId[k]);
  };
  std::set<std::pair<long long, long long>> seen;
  for (std::size_t r = 0; r < h.rowPoint.size(); ++r) {
    const int a = h.rowPoint[r];
    if (r > 0) {
      EXPECT_LT(key(h.rowPoint[r - 1]), key(a)) << "rows out of curve order at " << r;
    }
    long long previousId = -1;
    for (std::int64_t p = h.rowPairOffsets[r]; p < h.rowPairOffsets[r + 1]; ++p) {
      const int b = h.pairPoint[p];
      EXPECT_LT(key(a), key(b)) << "a pair belongs to its earlier end's row";
      // Within a row, pairs in global-id order (the order of the row's own force sum).
      EXPECT_LT(previousId, t.overlapGlobalId[b]);
      previousId = t.overlapGlobalId[b];
      // Its entry in the full lists, and the other end's entry.
      const std::int64_t e = h.fullEntry(t, r, p);
      ASSERT_EQ(t.neighbors[e], b);
      if (b < t.numOwned) {
        const std::int64_t mirror = mirrorBond(t, b, a);
        ASSERT_GE(mirror, 0);
        ASSERT_EQ(t.neighbors[mirror], a);
      }
      const long long i = t.overlapGlobalId[a], j = t.overlapGlobalId[b];
      EXPECT_TRUE(seen.insert({std::min(i, j), std::max(i, j)}).second) << "a bond twice";
    }
  }
  EXPECT_EQ(static_cast<std::int64_t>(seen.size()), h.numPairs());
}

TEST(HalfBondList, EveryBondOnceWithItsFullListEntriesInCurveOrder) {
  JitteredLattice L(6, false, false, 5);
  HalfBondList h;
  ASSERT_TRUE(buildHalfBondList(L.topology, h));
  EXPECT_TRUE(h.pairSlotHigh.empty()) << "rows of ~33 bonds need one byte a slot";
  expectEveryBondOnceInCurveOrder(L.topology, h);
}

// Full rows past 256 entries: a slot's high byte is kept too. A one-byte slot would find the
// wrong entry for every bond past the 256th of its row (checked by dropping pairSlotHigh).
TEST(HalfBondList, SlotsPastTheFirstByteWhereRowsAreLong) {
  JitteredLattice L(11, false, false, 7, 4.5);  // ~380 neighbours inside
  const Topology& t = L.topology;
  int longest = 0;
  for (int i = 0; i < t.numOwned; ++i) longest = std::max(longest, t.numNeighbors(i));
  ASSERT_GT(longest, 256);
  HalfBondList h;
  ASSERT_TRUE(buildHalfBondList(t, h));
  ASSERT_FALSE(h.pairSlotHigh.empty());
  expectEveryBondOnceInCurveOrder(t, h);
  // Breaking pairs moves them behind their row's intact ones: both bytes of the slot move along.
  std::vector<int> broke;
  for (std::size_t r = 0; r < h.rowPoint.size(); ++r) {
    broke.assign(static_cast<std::size_t>(h.rowIntact[r]), 0);
    for (std::size_t k = 0; k < broke.size(); k += 3) broke[k] = 1;
    h.breakPairs(r, broke.data());
    for (std::int64_t p = h.rowPairOffsets[r]; p < h.rowPairOffsets[r + 1]; ++p)
      ASSERT_EQ(t.neighbors[h.fullEntry(t, r, p)],
                h.rowPoint[r] < t.numOwned ? h.pairPoint[p] : h.rowPoint[r]);
  }
}

// PMB and normalized PMB with the fused critical stretch, float damage and broken-bond flags,
// over steps that break bonds: the half list's force is the full lists' to rounding, and the
// same bonds break in both (the same stretch test), to the bit.
TEST(HalfBondList, ForceMatchesTheFullListsAndTheSameBondsBreak) {
  for (const char* model : {"Elastic Bond Based", "Normalized PMB"})
    for (const bool compact : {false, true}) {
      SCOPED_TRACE(std::string(model) + (compact ? ", flags" : ", float damage"));
      JitteredLattice half(6, false, false, 9), full(6, false, false, 9);
      half.addBlock(peridot::testing::material(model, "", 1.0e9), criticalStretch(0.01), "One",
                    true, true, compact);
      full.addBlock(peridot::testing::material(model, "", 1.0e9), criticalStretch(0.01), "One",
                    true, false, compact);
      ASSERT_TRUE(half.evaluator->usesHalfBondList());
      ASSERT_FALSE(full.evaluator->usesHalfBondList());
      ASSERT_EQ(half.evaluator->compactDamage(), compact);
      stepAlike(half, full, nullptr);
    }
}

// LPS ("Elastic") in 3D and in plane stress, with omega = 1 and omega per pair (an expression in
// zeta, Gaussian), over steps that break bonds: over the half list its dilatation and force are
// the full lists' to rounding, and the same bonds break to the bit.
TEST(HalfBondList, LpsMatchesTheFullListsAndTheSameBondsBreak) {
  struct Case {
    const char* mode;
    bool planar;
    const char* influence;
  };
  for (const Case c : {Case{"", false, "One"}, Case{"", false, "1.0/zeta"},
                       Case{"Plane Stress", true, "Gaussian"}}) {
    SCOPED_TRACE(std::string(c.mode) + " " + c.influence);
    const int n = c.planar ? 14 : 6;
    JitteredLattice half(n, c.planar, false, 9), full(n, c.planar, false, 9);
    half.addBlock(peridot::testing::material("Elastic", c.mode, 1.0e9, 0.25), criticalStretch(0.01),
                  c.influence, true, true);
    full.addBlock(peridot::testing::material("Elastic", c.mode, 1.0e9, 0.25), criticalStretch(0.01),
                  c.influence, true, false);
    ASSERT_TRUE(half.evaluator->usesHalfBondList());
    ASSERT_FALSE(full.evaluator->usesHalfBondList());
    EXPECT_EQ(half.evaluator->halfBondList()->pairInfluence.empty(),
              std::string(c.influence) == "One");
    EXPECT_EQ(half.evaluator->state().bondLength, nullptr);  // the pairs keep |xi|
    stepAlike(half, full, "Dilatation");
  }
}

// |xi| read through the table of the rank's distinct lengths (the default where they fit), per
// pair (too many distinct lengths: here a table limit of 1), or computed in the loop: the same
// forces, dilatations and broken bonds to the bit, PMB and LPS, with flags and float damage.
TEST(HalfBondList, LengthsTabledPerPairOrComputedGiveTheSameBits) {
  for (const char* model : {"Elastic Bond Based", "Elastic"})
    for (const bool flags : {false, true}) {
      SCOPED_TRACE(std::string(model) + (flags ? ", flags" : ", float damage"));
      JitteredLattice tabled(6, false, false, 3), perPair(6, false, false, 3),
          computed(6, false, false, 3);
      for (JitteredLattice* L : {&tabled, &perPair, &computed})
        L->addBlock(std::string(model) == "Elastic"
                        ? peridot::testing::material(model, "", 1.0e9, 0.25)
                        : peridot::testing::material(model, "", 1.0e9),
                    criticalStretch(0.01), "One", true, true, flags);
      const double* x = tabled.fields->node("Model_Coordinates", 3);
      HalfBondList& table = *tabled.evaluator->halfBondList();
      HalfBondList& pairs = *perPair.evaluator->halfBondList();
      HalfBondList& none = *computed.evaluator->halfBondList();
      // The jittered lattice's lengths are nearly all distinct, and fewer than the limit.
      ASSERT_FALSE(table.pairLengthIndex.empty());
      EXPECT_TRUE(table.pairLength.empty());
      EXPECT_GT(table.lengthTable.size(), static_cast<std::size_t>(table.numPairs() / 2));
      // More than 256 of them: the index's high byte is kept.
      ASSERT_GT(table.lengthTable.size(), 256u);
      EXPECT_EQ(table.pairLengthIndexHigh.size(), table.pairLengthIndex.size());
      pairs.storeLengths(x, 1);
      ASSERT_TRUE(pairs.pairLengthIndex.empty());
      ASSERT_EQ(pairs.pairLength.size(),
                static_cast<std::size_t>(pairs.numPairs() + HalfBondList::kPadding));
      none.pairLengthIndex.clear();
      none.pairLengthIndexHigh.clear();
      none.lengthTable.clear();
      ASSERT_FALSE(none.storesLengths());
      for (std::int64_t p = 0; p < table.numPairs(); ++p)
        ASSERT_EQ(table.lengthTable[table.lengthIndex(p)], pairs.pairLength[p]) << p;
      double broken = 0;
      for (int step = 0; step <= 6; ++step) {
        for (JitteredLattice* L : {&tabled, &perPair, &computed}) {
          deform(*L, step);
          L->evaluator->evaluate(1.0);
        }
        EXPECT_EQ(tabled.force(), perPair.force()) << "step " << step;
        EXPECT_EQ(tabled.force(), computed.force()) << "step " << step;
        EXPECT_EQ(bondDamage(tabled), bondDamage(perPair)) << "step " << step;
        EXPECT_EQ(bondDamage(tabled), bondDamage(computed)) << "step " << step;
        broken = 0;
        for (float d : bondDamage(tabled)) broken += d;
      }
      EXPECT_GT(broken, 0.0);
    }
}

// LPS over the half list (omega = 1/zeta) is the gradient of LPS's stored energy, which is summed
// over the full lists: V_k f_k = -dE/dy_k with E = sum V_i W_i, by central differences.
// The table index in one byte while the table has at most 256 entries, with a second byte from
// the first pair past that on: every pair still finds its own |xi|.
TEST(HalfBondList, LengthIndexInOneByteUnlessTheTableOutgrowsIt) {
  for (const int distinct : {200, 255, 256, 700}) {
    SCOPED_TRACE(std::to_string(distinct) + " distinct lengths");
    // Points on the x axis (point k at x = 0.37 k^1.5): row 0 pairs point 0 with points
    // 1 .. distinct (that many lengths, all different); a second row, of point n = -x_1, pairs
    // it with point 0 at a length row 0 has. The table: those lengths and the padding's 1.
    const int n = distinct + 1;
    std::vector<double> x(3 * static_cast<std::size_t>(n + 1), 0.0);
    for (int k = 0; k < n; ++k) x[3 * k] = 0.37 * std::pow(k, 1.5);
    x[3 * n] = -x[3];  // point n, the mirror of point 1 about point 0
    HalfBondList h;
    h.rowPoint = {0, n};
    h.rowPairOffsets = {0, n - 1, n};
    for (int b = 1; b < n; ++b) h.pairPoint.push_back(b);
    h.pairPoint.push_back(0);  // row n: point 0, at the distance of point 1
    h.pairPoint.resize(h.pairPoint.size() + HalfBondList::kPadding, 0);
    h.storeLengths(x.data());
    ASSERT_FALSE(h.pairLengthIndex.empty());
    ASSERT_EQ(h.lengthTable.size(), static_cast<std::size_t>(distinct) + 1);
    EXPECT_EQ(h.pairLengthIndexHigh.empty(), distinct < 256);
    for (std::size_t r = 0; r < 2; ++r)
      for (std::int64_t p = h.rowPairOffsets[r]; p < h.rowPairOffsets[r + 1]; ++p)
        ASSERT_EQ(h.lengthTable[h.lengthIndex(p)],
                  std::fabs(x[3 * h.pairPoint[p]] - x[3 * h.rowPoint[r]]))
            << p;
    for (std::int64_t p = h.numPairs(); p < h.numPairs() + HalfBondList::kPadding; ++p)
      EXPECT_EQ(h.lengthTable[h.lengthIndex(p)], 1.0);
  }
}

// Threads share storeLengths by runs of rows, each with a table of its own, joined afterwards:
// the table, the indices (one byte or two) and the per-pair fallback are one thread's. Rows of
// 4 pairs over 5000 points, each pair a few steps along a grid of unit spacing (tens of distinct
// lengths, met in a different order by each run), jittered (thousands: two-byte indices), and
// jittered past a table limit of 3000 (one double per pair).
TEST(HalfBondList, LengthsStoredByThreadsAreOneThreads) {
  const int n = 5000;
  for (const bool jittered : {false, true})
    for (const std::size_t limit : {HalfBondList::kLengthTableLimit, std::size_t{3000}}) {
      SCOPED_TRACE(std::string(jittered ? "jittered" : "grid") + ", limit " +
                   std::to_string(limit));
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> jitter(-0.05, 0.05);
      const int offsets[8] = {1, 2, 16, 17, 18, 288, 289, 290};
      std::uniform_int_distribution<int> pick(0, 7);
      std::vector<double> x(3 * static_cast<std::size_t>(n));
      for (int k = 0; k < n; ++k) {
        const int c[3] = {k % 17, (k / 17) % 17, k / 289};
        for (int d = 0; d < 3; ++d) x[3 * k + d] = c[d] + (jittered ? jitter(rng) : 0.0);
      }
      HalfBondList one;
      one.rowPairOffsets.push_back(0);
      for (int r = 0; r < n; ++r) {
        one.rowPoint.push_back(r);
        for (int m = 0; m < 4; ++m) one.pairPoint.push_back((r + offsets[pick(rng)]) % n);
        one.rowPairOffsets.push_back(static_cast<std::int64_t>(one.pairPoint.size()));
      }
      one.pairPoint.resize(one.pairPoint.size() + HalfBondList::kPadding, 0);
      HalfBondList many = one;
      one.storeLengths(x.data(), limit, 1);
      if (limit == 3000 && jittered) {
        ASSERT_FALSE(one.pairLength.empty());  // past the limit: per pair
      } else {
        ASSERT_FALSE(one.pairLengthIndex.empty());
        EXPECT_EQ(one.pairLengthIndexHigh.empty(), !jittered);
      }
      for (std::int64_t p = 0; p < one.numPairs(); ++p) {
        const double expected =
            referenceBondLength(x.data(), one.rowPoint[static_cast<std::size_t>(p / 4)],
                                one.pairPoint[static_cast<std::size_t>(p)]);
        ASSERT_EQ(one.pairLength.empty() ? one.lengthTable[one.lengthIndex(p)] : one.pairLength[p],
                  expected)
            << p;
      }
      for (const int threads : {2, 3, 4}) {
        many.storeLengths(x.data(), limit, threads);
        EXPECT_EQ(many.lengthTable, one.lengthTable) << threads;
        EXPECT_EQ(many.pairLengthIndex, one.pairLengthIndex) << threads;
        EXPECT_EQ(many.pairLengthIndexHigh, one.pairLengthIndexHigh) << threads;
        EXPECT_EQ(many.pairLength, one.pairLength) << threads;
      }
    }
}

TEST(HalfBondList, LpsForceIsMinusTheGradientOfTheStoredEnergy) {
  JitteredLattice L(5, false, false, 4);
  L.addBlock(peridot::testing::material("Elastic", "", 2.0, 0.3), nullptr, "1.0/zeta", true);
  ASSERT_TRUE(L.evaluator->usesHalfBondList());
  double* y = L.fields->node("Coordinates", 3);
  const double* volume = L.fields->node("Volume", 1);
  const int n = L.topology.numOwned;
  for (int k = 0; k < 3 * n; ++k) y[k] += 2e-3 * std::sin(1.7 * k + 0.3);
  const auto energy = [&]() {
    L.evaluator->evaluate(1.0);
    std::vector<double> w(n);
    L.blocks[0].material->storedEnergyDensity(L.evaluator->state(), L.blocks[0].points, w.data());
    double e = 0;
    for (int i = 0; i < n; ++i) e += volume[i] * w[i];
    return e;
  };
  L.evaluator->evaluate(1.0);
  const std::vector<double> f = L.force();
  double worst = 0, scale = 0;
  for (int i = 0; i < n; i += 3)
    for (int a = 0; a < 3; ++a) {
      const double h = 1e-7, keep = y[3 * i + a];
      y[3 * i + a] = keep + h;
      const double ep = energy();
      y[3 * i + a] = keep - h;
      const double em = energy();
      y[3 * i + a] = keep;
      worst = std::max(worst, std::fabs(-(ep - em) / (2 * h) - volume[i] * f[3 * i + a]));
      scale = std::max(scale, std::fabs(volume[i] * f[3 * i + a]));
    }
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(worst, 1e-6 * scale);
}

// A solver that rejects a trial restores the bond damage: the half list reads it again.
// Float damage and broken-bond flags: a restored damage state is read into the rows again, and
// the node damage (with flags counted from the rows' broken pairs) is the full lists' to the bit
// before and after.
TEST(HalfBondList, RestoredDamageIsReadAgain) {
  for (const bool compact : {false, true}) {
    SCOPED_TRACE(compact ? "flags" : "float damage");
    JitteredLattice half(5, false, false, 2), full(5, false, false, 2);
    half.addBlock(peridot::testing::material("Elastic Bond Based", "", 1.0e9),
                  criticalStretch(0.01), "One", true, true, compact);
    full.addBlock(peridot::testing::material("Elastic Bond Based", "", 1.0e9),
                  criticalStretch(0.01), "One", true, false, compact);
    ASSERT_TRUE(half.evaluator->usesHalfBondList());
    ASSERT_EQ(half.evaluator->compactDamage(), compact);
    ModelEvaluator::DamageSnapshot savedHalf, savedFull;
    half.evaluator->saveDamage(savedHalf);
    full.evaluator->saveDamage(savedFull);
    deform(half, 6);
    deform(full, 6);
    half.evaluator->evaluate(1.0);  // breaks bonds
    full.evaluator->evaluate(1.0);
    double broken = 0;
    for (float d : bondDamage(half)) broken += d;
    ASSERT_GT(broken, 0.0);
    EXPECT_EQ(half.nodeDamage(), full.nodeDamage());
    half.evaluator->restoreDamage(savedHalf);
    full.evaluator->restoreDamage(savedFull);
    EXPECT_EQ(half.nodeDamage(), full.nodeDamage());
    for (double d : half.nodeDamage()) EXPECT_EQ(d, 0.0);
    half.evaluator->evaluate(1.0, false);  // at the same state, nothing broken
    full.evaluator->evaluate(1.0, false);
    EXPECT_LT(relativeDifference(half.force(), full.force()), 1e-13);
    EXPECT_EQ(bondDamage(half), bondDamage(full));
  }
}

// Broken pairs leave the loops (HalfBondList::rowIntact): each row keeps its intact pairs first,
// in the row's order, and its broken ones after them; skipping those changes no bit of the force
// or the dilatation (their terms are zeros); a restored damage state mends them, and the rows are
// again the ones built at the start. PMB and LPS (influence per pair), float damage and flags.
TEST(HalfBondList, BrokenPairsLeaveTheLoopsWithoutChangingABit) {
  struct Case {
    const char* model;
    const char* influence;
    bool compact;
  };
  for (const Case c :
       {Case{"Elastic Bond Based", "One", false}, Case{"Elastic Bond Based", "One", true},
        Case{"Elastic", "1.0/zeta", false}}) {
    SCOPED_TRACE(std::string(c.model) + (c.compact ? ", flags" : ", float damage"));
    JitteredLattice L(6, false, false, 9);
    const double nu = std::string(c.model) == "Elastic" ? 0.25 : -1.0;
    L.addBlock(peridot::testing::material(c.model, "", 1.0e9, nu), criticalStretch(0.01),
               c.influence, true, true, c.compact);
    ASSERT_TRUE(L.evaluator->usesHalfBondList());
    HalfBondList& h = *L.evaluator->halfBondList();
    const HalfBondList built = h;
    const Topology& t = L.topology;
    ModelEvaluator::DamageSnapshot intact;
    L.evaluator->saveDamage(intact);
    const auto nodeField = [&](const char* name) {
      const double* v = L.fields->nodeField(name).data;
      return std::vector<double>(v, v + t.numOwned);
    };
    std::int64_t dropped = 0;
    for (int step = 0; step <= 6; ++step) {
      deform(L, step);
      L.evaluator->evaluate(1.0);
      // Every row: the same pairs as built, the intact ones first and in the row's order.
      const std::vector<float> damage = bondDamage(L);
      dropped = 0;
      for (std::size_t r = 0; r < h.rowPoint.size(); ++r) {
        const std::int64_t p0 = h.rowPairOffsets[r], p1 = h.rowPairOffsets[r + 1];
        ASSERT_GE(h.rowIntact[r], 0);
        ASSERT_LE(h.rowIntact[r], p1 - p0);
        std::vector<std::pair<int, int>> pairs, pairsBuilt;
        std::int64_t previous = -1;
        for (std::int64_t p = p0; p < p1; ++p) {
          const bool isIntact = p < p0 + h.rowIntact[r];
          // No damage copy (no bond partly damaged); a pair is skipped if and only if broken.
          ASSERT_TRUE(h.pairDamage.empty());
          ASSERT_EQ(damage[h.fullEntry(t, r, p)] == 1.0f, !isIntact)
              << "row " << r << " pair " << p - p0;
          if (isIntact) {
            const std::int64_t e = h.fullEntry(t, r, p);
            ASSERT_LT(previous, h.rowPoint[r] < t.numOwned ? e : h.pairPoint[p]);
            previous = h.rowPoint[r] < t.numOwned ? e : h.pairPoint[p];
          }
          pairs.emplace_back(h.pairPoint[p], h.slot(p));
          pairsBuilt.emplace_back(built.pairPoint[p], built.slot(p));
        }
        std::sort(pairs.begin(), pairs.end());
        std::sort(pairsBuilt.begin(), pairsBuilt.end());
        ASSERT_EQ(pairs, pairsBuilt) << "row " << r;
        dropped += p1 - p0 - h.rowIntact[r];
      }
      // The same state walked over every pair, broken ones included, their damage read from a
      // copy: the same bits.
      const std::vector<double> force = L.force();
      const std::vector<double> theta =
          std::string(c.model) == "Elastic" ? nodeField("Dilatation") : std::vector<double>();
      const HalfBondList skipping = h;
      h.pairDamage.assign(static_cast<std::size_t>(h.numPairs() + HalfBondList::kPadding), 0.0f);
      for (std::size_t r = 0; r < h.rowPoint.size(); ++r) {
        h.rowIntact[r] = static_cast<int>(h.rowPairOffsets[r + 1] - h.rowPairOffsets[r]);
        for (std::int64_t p = h.rowPairOffsets[r]; p < h.rowPairOffsets[r + 1]; ++p)
          h.pairDamage[p] = damage[h.fullEntry(t, r, p)];
      }
      L.evaluator->evaluate(1.0, false);
      EXPECT_EQ(L.force(), force) << "step " << step;
      if (!theta.empty()) {
        EXPECT_EQ(nodeField("Dilatation"), theta) << "step " << step;
      }
      h = skipping;
    }
    EXPECT_GT(dropped, 0);
    EXPECT_LT(dropped, h.numPairs());
    // Mended: the rows as built, every pair walked again.
    L.evaluator->restoreDamage(intact);
    EXPECT_EQ(h.pairPoint, built.pairPoint);
    EXPECT_EQ(h.pairSlot, built.pairSlot);
    EXPECT_EQ(h.pairLength, built.pairLength);
    EXPECT_EQ(h.pairLengthIndex, built.pairLengthIndex);
    EXPECT_EQ(h.pairLengthIndexHigh, built.pairLengthIndexHigh);
    EXPECT_EQ(h.pairInfluence, built.pairInfluence);
    EXPECT_EQ(h.rowIntact, built.rowIntact);
    for (std::size_t r = 0; r < h.rowPoint.size(); ++r) {
      ASSERT_EQ(h.rowIntact[r], h.rowPairOffsets[r + 1] - h.rowPairOffsets[r]);
    }
  }
}

// Partly damaged bonds (0 < d < 1, here from a restored damage state): the pairs keep a copy of
// the damage and the loop reads it; the force is the full lists' to rounding, and the same bonds
// break. Mended again, the copy goes.
TEST(HalfBondList, PartlyDamagedBondsKeepACopy) {
  for (const char* model : {"Elastic Bond Based", "Elastic"}) {
    SCOPED_TRACE(model);
    const double nu = std::string(model) == "Elastic" ? 0.25 : -1.0;
    JitteredLattice half(6, false, false, 9), full(6, false, false, 9);
    half.addBlock(peridot::testing::material(model, "", 1.0e9, nu), criticalStretch(0.01), "One",
                  true, true);
    full.addBlock(peridot::testing::material(model, "", 1.0e9, nu), criticalStretch(0.01), "One",
                  true, false);
    ASSERT_TRUE(half.evaluator->usesHalfBondList());
    ModelEvaluator::DamageSnapshot intact, partly;
    half.evaluator->saveDamage(intact);
    half.evaluator->saveDamage(partly);
    // Damage 1/2 on every third bond, the same from either end.
    const Topology& t = half.topology;
    ASSERT_EQ(partly.bondDamage.size(), static_cast<std::size_t>(t.numBonds()));
    for (int i = 0; i < t.numOwned; ++i)
      for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b)
        if ((t.overlapGlobalId[i] + t.overlapGlobalId[t.neighbors[b]]) % 3 == 0)
          partly.bondDamage[b] = 0.5f;
    half.evaluator->restoreDamage(partly);
    full.evaluator->restoreDamage(partly);
    EXPECT_FALSE(half.evaluator->halfBondList()->pairDamage.empty());
    for (int step = 0; step <= 4; ++step) {
      deform(half, step);
      deform(full, step);
      half.evaluator->evaluate(1.0, step > 0);
      full.evaluator->evaluate(1.0, step > 0);
      EXPECT_LT(relativeDifference(half.force(), full.force()), 1e-13) << "step " << step;
      EXPECT_EQ(bondDamage(half), bondDamage(full)) << "step " << step;
    }
    double broken = 0;
    for (float d : bondDamage(half)) broken += d == 1.0f;
    EXPECT_GT(broken, 0.0);
    half.evaluator->restoreDamage(intact);
    EXPECT_TRUE(half.evaluator->halfBondList()->pairDamage.empty());
  }
}

// Where a pair's force is not the same read from either end, or damage might differ between a
// bond's two entries, the full lists' loop runs.
TEST(HalfBondList, OnlyWhereTheSceneAllowsIt) {
  const auto uses = [](const char* model, const char* influence, bool varyingHorizon, bool fuse,
                       bool damage) {
    JitteredLattice L(4, false, varyingHorizon, 1);
    L.addBlock(peridot::testing::material(
                   model, "", 1.0e9,
                   std::string(model).find("PMB") == std::string::npos &&
                           std::string(model).find("Bond Based") == std::string::npos
                       ? 0.25
                       : -1),
               damage ? criticalStretch(0.01) : nullptr, influence, fuse);
    return L.evaluator->usesHalfBondList();
  };
  EXPECT_TRUE(uses("Elastic Bond Based", "One", false, true, true));
  EXPECT_TRUE(uses("Elastic Bond Based", "One", false, true, false));
  EXPECT_TRUE(uses("Normalized PMB", "One", false, true, true));
  EXPECT_FALSE(uses("Elastic Bond Based", "Conical", false, true, true));  // omega per bond
  EXPECT_FALSE(uses("Elastic Bond Based", "One", true, true, true));       // one-sided bonds
  EXPECT_FALSE(uses("Elastic Bond Based", "One", false, false, true));     // a separate pass
  EXPECT_TRUE(uses("Elastic", "One", false, true, true));
  EXPECT_TRUE(uses("Elastic", "Conical", false, true, true));  // omega per pair
  EXPECT_FALSE(uses("Elastic", "One", true, true, true));
  EXPECT_FALSE(uses("Linearized LPS", "One", false, true, true));  // its own loops
  // Horizons that differ from point to point, though every bond is within both (no one-sided
  // bonds): an omega of zeta and the horizon would differ between a bond's ends.
  JitteredLattice L(4, false, false, 1);
  double* horizon = L.fields->node("Horizon", 1);
  horizon[0] = 2.2;
  L.addBlock(peridot::testing::material("Elastic", "", 1.0e9, 0.25), criticalStretch(0.01),
             "Conical", true);
  EXPECT_FALSE(L.evaluator->usesHalfBondList());
  // Peridigm's partial stress is summed per block over the full lists.
  JitteredLattice P(4, false, false, 1);
  P.addBlock(peridot::testing::material("Elastic", "Compute Partial Stress", 1.0e9, 0.25),
             criticalStretch(0.01), "One", true);
  EXPECT_FALSE(P.evaluator->usesHalfBondList());
}

// Blocks that share a material entry (Peridigm's "Block Names: block_1 block_2") are walked by
// one loop over the half list; blocks with their own materials keep the full lists.
TEST(HalfBondList, BlocksSharingAMaterialShareTheLoop) {
  const auto run = [](bool shared, bool half) {
    auto L = std::make_unique<JitteredLattice>(5, false, false, 4);
    auto material = peridot::testing::material("Elastic Bond Based", "", 1.0e9);
    for (int k = 0; k < 2; ++k) {
      Block b;
      b.name = "block_" + std::to_string(k + 1);
      b.id = k + 1;
      b.material =
          shared || k == 0 ? material : peridot::testing::material("Elastic Bond Based", "", 2.0e9);
      b.damage = criticalStretch(0.01);
      for (int i = 0; i < L->topology.numOwned; ++i)
        if ((L->topology.referencePosition[3 * i] < 2.0) == (k == 0)) b.points.push_back(i);
      L->blocks.push_back(b);
    }
    L->evaluator =
        std::make_unique<ModelEvaluator>(L->topology, *L->fields, L->blocks, "One", L->timers);
    L->evaluator->setHalfBondListAllowed(half);
    L->evaluator->initialize();
    return L;
  };
  EXPECT_FALSE(run(false, true)->evaluator->usesHalfBondList());
  auto half = run(true, true), full = run(true, false);
  ASSERT_TRUE(half->evaluator->usesHalfBondList());
  for (int step = 0; step <= 6; ++step) {
    deform(*half, step);
    deform(*full, step);
    half->evaluator->evaluate(1.0);
    full->evaluator->evaluate(1.0);
    EXPECT_LT(relativeDifference(half->force(), full->force()), 1e-13) << "step " << step;
    EXPECT_EQ(bondDamage(*half), bondDamage(*full)) << "step " << step;
  }
}

// Thermal strains (set after initialize) take the full lists' loop, which has them; the half
// list is dropped.
TEST(HalfBondList, ThermalStrainsTakeTheFullLists) {
  JitteredLattice L(4, false, false, 6);
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic Bond Based");
  p.set("Density", 1.0);
  p.set("Young's Modulus", 1.0e9);
  p.set("Thermal Expansion Coefficient", 1.0e-5);
  ListReader r(p, "Materials -> M");
  L.addBlock(createMaterial(r), criticalStretch(0.01), "One", true);
  ASSERT_TRUE(L.evaluator->usesHalfBondList());
  std::vector<double> temperature(static_cast<std::size_t>(L.topology.numOverlap), 50.0);
  L.evaluator->setThermal(temperature.data());
  EXPECT_FALSE(L.evaluator->usesHalfBondList());
  EXPECT_EQ(L.evaluator->halfBondListBytes(), 0u);
  // The free expansion of a uniformly heated body: no force, as the full lists' loop gives it.
  double* y = L.fields->node("Coordinates", 3);
  const double* x = L.fields->node("Model_Coordinates", 3);
  for (int k = 0; k < 3 * L.topology.numOverlap; ++k) y[k] = x[k] * (1.0 + 50.0 * 1.0e-5);
  L.evaluator->evaluate(1.0);
  for (double f : L.force()) EXPECT_NEAR(f, 0.0, 1e-3);
}
