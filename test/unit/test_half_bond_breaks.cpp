// The half bond list's loops note their breaks in its rows only (HalfBondList::breakPairs); the
// full lists' damage is brought up to date when it is read (HalfBondList::recordBreaks, called
// by ModelEvaluator::state() and by every request for the damage field by name). These tests
// check that every break reaches the full lists, also when breaks come in several rounds between
// reads, and that a reader that asks the fields by name (a checkpoint) sees them all.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "JitteredLattice.hpp"
#include "Materials.hpp"
#include "damage/CriticalStretch.hpp"
#include "neighbor/HalfBondList.hpp"

using namespace peridot;
using peridot::testing::JitteredLattice;

namespace {

// The full lists' damage the rows say: 1 at both entries of every broken pair (the other end's
// where it is owned), 0 elsewhere. Built from the rows and the topology alone.
template <typename DamageT>
std::vector<DamageT> damageOfTheRows(const Topology& t, const HalfBondList& h) {
  std::vector<DamageT> expected(static_cast<std::size_t>(t.numBonds()), DamageT(0));
  for (std::size_t r = 0; r < h.rowPoint.size(); ++r) {
    const int a = h.rowPoint[r];
    for (std::int64_t p = h.rowPairOffsets[r] + h.rowIntact[r]; p < h.rowPairOffsets[r + 1]; ++p) {
      const int b = h.pairPoint[p];
      expected[h.fullEntry(t, r, p)] = DamageT(1);
      if (a < t.numOwned && b < t.numOwned) expected[mirrorBond(t, b, a)] = DamageT(1);
    }
  }
  return expected;
}

// Breaks every `every`-th intact pair of every row whose index is a multiple of `rowStride`.
void breakSome(HalfBondList& h, int every, std::size_t rowStride) {
  std::vector<int> broke;
  for (std::size_t r = 0; r < h.rowPoint.size(); r += rowStride) {
    broke.assign(static_cast<std::size_t>(h.rowIntact[r]), 0);
    for (std::size_t k = 0; k < broke.size(); k += static_cast<std::size_t>(every)) broke[k] = 1;
    h.breakPairs(r, broke.data());
  }
}

template <typename DamageT>
void recordInRounds() {
  JitteredLattice L(6, false, false, 5);
  const Topology& t = L.topology;
  HalfBondList h;
  ASSERT_TRUE(buildHalfBondList(t, h));
  std::vector<DamageT> full(static_cast<std::size_t>(t.numBonds()), DamageT(0));
  EXPECT_FALSE(h.breaksPending());
  // The first round breaks pairs of every row, the second of every other row only (so the
  // second's pending rows are a part of the rows), the third of every row again.
  const int every[] = {3, 2, 4};
  const std::size_t stride[] = {1, 2, 1};
  for (int round = 0; round < 3; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    breakSome(h, every[round], stride[round]);
    ASSERT_TRUE(h.breaksPending());
    h.recordBreaks(t, full.data());
    EXPECT_FALSE(h.breaksPending());
    const std::vector<DamageT> expected = damageOfTheRows<DamageT>(t, h);
    std::size_t ones = 0;
    for (DamageT d : expected) ones += d == DamageT(1);
    ASSERT_GT(ones, std::size_t{0});
    EXPECT_EQ(full, expected);
  }
  // Read again from full lists that were rewritten (a restored trial): nothing pending, and
  // nothing recorded by a later call.
  std::vector<float> mended(full.size(), 0.0f);
  breakSome(h, 5, 1);
  ASSERT_TRUE(h.breaksPending());
  h.gatherDamage(t, mended.data(), nullptr);
  EXPECT_FALSE(h.breaksPending());
  h.recordBreaks(t, mended.data());
  for (float d : mended) ASSERT_EQ(d, 0.0f);
}

}  // namespace

TEST(HalfBondListBreaks, EveryBreakReachesTheFullListsWhenRecorded) {
  {
    SCOPED_TRACE("float damage");
    recordInRounds<float>();
  }
  {
    SCOPED_TRACE("broken-bond flags");
    recordInRounds<unsigned char>();
  }
}

// A run's loops break bonds over the half list; whoever asks the fields for the damage by name
// (a checkpoint writer does) gets the same damage as a run over the full lists, at every step.
TEST(HalfBondListBreaks, TheDamageFieldAskedByNameIsCurrent) {
  for (const bool compact : {false, true}) {
    SCOPED_TRACE(compact ? "flags" : "float damage");
    JitteredLattice half(6, false, false, 9), full(6, false, false, 9);
    half.addBlock(peridot::testing::material("Elastic Bond Based", "", 1.0e9),
                  peridot::testing::criticalStretch(0.01), "One", true, true, compact);
    full.addBlock(peridot::testing::material("Elastic Bond Based", "", 1.0e9),
                  peridot::testing::criticalStretch(0.01), "One", true, false, compact);
    ASSERT_TRUE(half.evaluator->usesHalfBondList());
    ASSERT_FALSE(full.evaluator->usesHalfBondList());
    ASSERT_EQ(half.evaluator->compactDamage(), compact);
    const auto byName = [&](JitteredLattice& L) {
      std::vector<float> d;
      if (compact) {
        const auto& flags = L.fields->bondByte("Bond_Broken");
        for (std::size_t b = 0; b < flags.size(); ++b) d.push_back(flags[b]);
      } else {
        d = L.fields->bondFloat("Bond_Damage");
      }
      return d;
    };
    double broken = 0;
    for (int step = 0; step <= 6; ++step) {
      for (JitteredLattice* L : {&half, &full}) {
        const double* x = L->fields->node("Model_Coordinates", 3);
        double* y = L->fields->node("Coordinates", 3);
        for (int p = 0; p < L->topology.numOwned; ++p)
          for (int d = 0; d < 3; ++d)
            y[3 * p + d] = x[3 * p + d] + (d == 0 ? 0.004 * step * x[3 * p] : 0.0) +
                           0.02 * std::sin(7.0 * p + 3.0 * d);
        L->evaluator->evaluate(1.0);
      }
      const std::vector<float> d = byName(half);
      EXPECT_EQ(d, byName(full)) << "step " << step;
      broken = 0;
      for (float v : d) broken += v;
    }
    EXPECT_GT(broken, 0.0);
    EXPECT_LT(broken, static_cast<double>(half.topology.numBonds()));
  }
}
