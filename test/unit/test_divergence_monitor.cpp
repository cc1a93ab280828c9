// DivergenceMonitor on synthetic acceleration histories (one rank, MPI_COMM_SELF): it must stop
// the sign-reversing geometric growth of an unstable Verlet step and the one-horizon bound, and
// must not stop smooth loading that grows from rest, a steady oscillation at the highest
// frequency, or a beat of such oscillations.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "solvers/DivergenceMonitor.hpp"

namespace peridot {
namespace {

constexpr int kPoints = 4;
constexpr double kDt = 0.1, kHorizon = 2.0;

// Runs `steps` checks with a_x(point, step) from `field`; returns the step of the RunError
// (-1 when none) and its message.
// `prescribed`: 3 per point, non-zero where the component is prescribed (null: none).
long long firstFailure(const std::function<double(int, long long)>& field, long long steps,
                       std::string* message = nullptr, const double* prescribed = nullptr) {
  std::vector<double> horizon(kPoints, kHorizon);
  DivergenceMonitor monitor(
      kPoints, horizon.data(), [](int i) { return "point " + std::to_string(i + 1); }, kDt,
      kDt / 2.1, MPI_COMM_SELF, prescribed);
  std::vector<double> a(3 * kPoints, 0.0);
  for (long long n = 0; n <= steps; ++n) {
    for (int i = 0; i < kPoints; ++i) a[3 * i] = field(i, n);
    try {
      monitor.check(n, n * kDt, a.data());
    } catch (const RunError& e) {
      if (message) *message = e.what();
      return n;
    }
  }
  return -1;
}

// q = dt^2 |a| / horizon for an acceleration a: the amplitude giving q.
double amplitude(double q) { return q * kHorizon / (kDt * kDt); }

TEST(DivergenceMonitor, StopsSignReversingGrowth) {
  // A physical level of 1e-5 for 50 steps, then a mode at point 3 growing x1.25 per step with
  // alternating sign from 1e-7: it passes the physical level after ~21 steps and x100 after
  // ~21 more.
  auto field = [](int i, long long n) {
    double value = i == 0 ? amplitude(1e-5) : 0.0;
    if (i == 2 && n >= 50) value += amplitude(1e-7) * std::pow(-1.25, static_cast<double>(n - 50));
    return value;
  };
  std::string message;
  const long long step = firstFailure(field, 400, &message);
  ASSERT_GT(step, 50);
  EXPECT_LT(step, 110);
  EXPECT_NE(message.find("the run diverged at step " + std::to_string(step)), std::string::npos)
      << message;
  EXPECT_NE(message.find("the force on point 3"), std::string::npos) << message;
  EXPECT_NE(message.find("x1.25 per step"), std::string::npos) << message;
  EXPECT_NE(message.find("is 2.1 x the stable estimate"), std::string::npos) << message;
}

TEST(DivergenceMonitor, StopsAForceBeyondOneHorizonPerStep) {
  auto field = [](int i, long long n) { return i == 1 && n == 7 ? amplitude(1.5) : 0.0; };
  std::string message;
  EXPECT_EQ(firstFailure(field, 20, &message), 7);
  EXPECT_NE(message.find("point 2"), std::string::npos) << message;
}

TEST(DivergenceMonitor, LetsLoadingFromRestGrow) {
  // Smooth loading: cubic growth from zero to q = 0.5 over 300 steps, no reversal.
  auto field = [](int i, long long n) {
    const double t = static_cast<double>(n) / 300.0;
    return amplitude(0.5) * t * t * t * (i + 1) / kPoints;
  };
  EXPECT_EQ(firstFailure(field, 300), -1);
}

TEST(DivergenceMonitor, LetsAStableHighModeOscillateAndBeat) {
  // The highest stable mode flips sign each step at constant amplitude; two such modes of
  // slightly different frequency beat: the amplitude rises from nearly zero to its peak over
  // 100 steps while the sign still alternates.
  auto steady = [](int, long long n) { return amplitude(1e-3) * (n % 2 ? -1.0 : 1.0); };
  EXPECT_EQ(firstFailure(steady, 500), -1);
  auto beat = [](int i, long long n) {
    const double envelope = std::fabs(std::sin(0.0157 * static_cast<double>(n) + 1e-3 * i));
    return amplitude(1e-3) * envelope * (n % 2 ? -1.0 : 1.0);
  };
  EXPECT_EQ(firstFailure(beat, 1000), -1);
}

TEST(DivergenceMonitor, PrescribedComponentsAreLeftOut) {
  // The bound (q = 2 at point 3) and sign-reversing growth (point 2), both along x: each stops
  // the run when x is free, and neither when x of that point is prescribed; a prescribed y or
  // z does not hide a free x.
  auto beyondBound = [](int i, long long) { return i == 2 ? amplitude(2.0) : 0.0; };
  auto growing = [](int i, long long n) {
    return i == 1 ? amplitude(1e-7) * std::pow(-1.25, static_cast<double>(n)) : 0.0;
  };
  std::vector<double> none(3 * kPoints, 0.0), xOf3(none), yzOf3(none), xOf2(none), all(none);
  xOf3[3 * 2] = 1.0;
  yzOf3[3 * 2 + 1] = yzOf3[3 * 2 + 2] = 1.0;
  xOf2[3 * 1] = 1.0;
  std::fill(all.begin(), all.end(), 1.0);
  EXPECT_EQ(firstFailure(beyondBound, 50, nullptr, none.data()), 0);
  EXPECT_EQ(firstFailure(beyondBound, 50, nullptr, yzOf3.data()), 0);
  EXPECT_EQ(firstFailure(beyondBound, 50, nullptr, xOf3.data()), -1);
  EXPECT_EQ(firstFailure(beyondBound, 50, nullptr, all.data()), -1);
  const long long step = firstFailure(growing, 200, nullptr, none.data());
  EXPECT_GT(step, 0);
  EXPECT_LT(step, 100);
  EXPECT_EQ(firstFailure(growing, 200, nullptr, xOf3.data()), step);
  EXPECT_EQ(firstFailure(growing, 200, nullptr, xOf2.data()), -1);
  EXPECT_EQ(firstFailure(growing, 200, nullptr, all.data()), -1);
}

}  // namespace
}  // namespace peridot
