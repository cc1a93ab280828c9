// The load-step schedule of Adaptive Load-Stepping against step sequences worked out by hand
// from Peridigm's rule (halve a failed step, retry; Reduce all remaining load steps re-spaces
// the rest at the converged step's length; the limits per step and in all).
#include <gtest/gtest.h>

#include <vector>

#include "solvers/AdaptiveLoadStepping.hpp"

namespace peridot {
namespace {

AdaptiveLoadSteppingConfig limits(int inOne, int total, bool reduceAll) {
  AdaptiveLoadSteppingConfig c;
  c.enabled = true;
  c.maxReductionsInOneStep = inOne;
  c.maxTotalReductions = total;
  c.reduceAllRemaining = reduceAll;
  return c;
}

// Runs the schedule; `fails(start, end)` says whether an attempt fails. Returns the ends of the
// converged steps (or stops at the first refused cut, recording -1).
template <class Fails>
std::vector<double> run(LoadSchedule& s, Fails fails) {
  std::vector<double> ends;
  while (!s.done()) {
    if (fails(s.start(), s.end())) {
      if (!s.cut()) {
        ends.push_back(-1);
        break;
      }
      continue;
    }
    ends.push_back(s.end());
    s.accept();
  }
  return ends;
}

TEST(LoadSchedule, ReduceAllRemainingChangesTheStepCountAsTheRuleSays) {
  // Four steps of 0.25; the first attempt of the second step (0.25 -> 0.5) fails once.
  const std::vector<double> times{0, 0.25, 0.5, 0.75, 1.0};
  auto failOnce = [] {
    bool failed = false;
    return [failed](double a, double b) mutable {
      if (a == 0.25 && b == 0.5 && !failed) return failed = true;
      return false;
    };
  };
  LoadSchedule keep(times, limits(3, 10, false));
  // Halved: 0.25 -> 0.375, then the rest of that step, then the original steps.
  EXPECT_EQ(run(keep, failOnce()), (std::vector<double>{0.25, 0.375, 0.5, 0.75, 1.0}));
  EXPECT_EQ(keep.totalReductions(), 1);
  LoadSchedule all(times, limits(3, 10, true));
  // Every step after the cut one takes its length, 0.125: seven steps in all.
  EXPECT_EQ(run(all, failOnce()), (std::vector<double>{0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0}));
}

TEST(LoadSchedule, RepeatedHalvingAndTheLimits) {
  // A step converges only when at most 0.1 long: 1 -> 0.5 -> 0.25 -> 0.125 -> 0.0625.
  auto tooLong = [](double a, double b) { return b - a > 0.1; };
  LoadSchedule fourCuts({0, 1}, limits(4, 100, true));
  const auto ends = run(fourCuts, tooLong);
  ASSERT_EQ(ends.size(), 16u);
  EXPECT_EQ(ends.front(), 0.0625);
  EXPECT_EQ(ends.back(), 1.0);
  EXPECT_EQ(fourCuts.totalReductions(), 4);
  // Three cuts allowed in one step: the fourth failure is refused (the schedule unchanged).
  LoadSchedule threeCuts({0, 1}, limits(3, 100, true));
  EXPECT_EQ(run(threeCuts, tooLong), (std::vector<double>{-1}));
  EXPECT_EQ(threeCuts.reductionsThisStep(), 3);
  EXPECT_EQ(threeCuts.start(), 0.0);
  EXPECT_EQ(threeCuts.end(), 0.125);
  // Without re-spacing each 0.5-long original step needs its own cuts; the total limit of 5
  // is reached in the second original step (2 + 1 + 2 cuts, the sixth refused).
  LoadSchedule total({0, 0.5, 1.0}, limits(10, 5, false));
  auto tooLong2 = [](double a, double b) { return b - a > 0.2; };
  const auto partial = run(total, tooLong2);
  ASSERT_FALSE(partial.empty());
  EXPECT_EQ(partial.back(), -1);
  EXPECT_EQ(total.totalReductions(), 5);
}

TEST(LoadSchedule, ReSpacingEndsAtTheFinalTime) {
  // 0 -> 0.3 fails once: 0.15 converges; the rest (0.85) is not a multiple of 0.15: five steps
  // of 0.15 and a last one ending at 1.0 exactly.
  LoadSchedule s({0, 0.3, 1.0}, limits(2, 2, true));
  bool failed = false;
  const auto ends = run(s, [&](double a, double) {
    if (a == 0 && !failed) return failed = true;
    return false;
  });
  ASSERT_EQ(ends.size(), 7u);
  EXPECT_EQ(ends.back(), 1.0);
  EXPECT_NEAR(ends[5], 0.9, 1e-12);
}

}  // namespace
}  // namespace peridot
