// VerletStep's fused passes against the velocity Verlet step written as separate passes (the
// loops Simulation ran before): the same u, v, y and a to the bit, with prescribed components,
// contact and body forces, and in a plane; its finiteness test; and its divergence sums, which
// must drive DivergenceMonitor exactly as check() does, over several blocks of points.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "solvers/DivergenceMonitor.hpp"
#include "solvers/VerletStep.hpp"

namespace peridot {
namespace {

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// A state of n points (more than one block of the monitor, and not a whole number of them).
struct State {
  explicit State(int n, unsigned seed) : n(n) {
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> r(-1.0, 1.0);
    auto fill = [&](std::vector<double>& v, std::size_t size, double scale, double offset) {
      v.resize(size);
      for (auto& e : v) e = offset + scale * r(gen);
    };
    const std::size_t n3 = 3 * static_cast<std::size_t>(n);
    fill(x, n3, 1.0, 0.0);
    fill(u, n3, 1e-3, 0.0);
    fill(v, n3, 1.0, 0.0);
    fill(a, n3, 1e3, 0.0);
    fill(f, n3, 1e6, 0.0);
    fill(fc, n3, 1e5, 0.0);
    fill(b, n3, 1e4, 0.0);
    fill(density, n, 100.0, 2000.0);
    fill(horizon, n, 1e-3, 3e-3);
    y.assign(n3, 0.0);
    for (std::size_t k = 0; k < n3; ++k) y[k] = x[k] + u[k];
  }
  VerletArrays arrays(bool contact, bool body, bool planar) {
    VerletArrays p;
    p.numOwned = n;
    p.x = x.data(), p.u = u.data(), p.v = v.data(), p.y = y.data(), p.a = a.data();
    p.force = f.data(), p.contactForce = contact ? fc.data() : nullptr;
    p.bodyForce = body ? b.data() : nullptr;
    p.density = density.data();
    p.planar = planar;
    return p;
  }
  int n;
  std::vector<double> x, u, v, y, a, f, fc, b, density, horizon;
};

// The step as separate passes, in Simulation's former order and expressions.
void separatePasses(State& s, double dt, const std::vector<int>& prescribed,
                    const std::vector<double>& prescribedVelocity, bool contact, bool body,
                    bool planar) {
  const double half = 0.5 * dt;
  const int n3 = 3 * s.n;
  for (int k = 0; k < n3; ++k) s.v[k] += half * s.a[k];
  for (std::size_t m = 0; m < prescribed.size(); ++m) s.v[prescribed[m]] = prescribedVelocity[m];
  for (int k = 0; k < n3; ++k) {
    s.y[k] = s.x[k] + s.u[k] + dt * s.v[k];
    s.u[k] += dt * s.v[k];
  }
  for (int i = 0; i < s.n; ++i) {
    for (int d = 0; d < 3; ++d) {
      double force = s.f[3 * i + d];
      if (contact) force += s.fc[3 * i + d];
      if (body) force += s.b[3 * i + d];
      s.a[3 * i + d] = force / s.density[i];
    }
  }
  if (planar)
    for (int i = 0; i < s.n; ++i) s.a[3 * i + 2] = 0.0;
  for (int k = 0; k < n3; ++k) s.v[k] += half * s.a[k];
}

DivergenceMonitor monitorOf(const State& s, double dt, const double* prescribed) {
  return DivergenceMonitor(
      s.n, s.horizon.data(), [](int i) { return "point " + std::to_string(i + 1); }, dt, dt,
      MPI_COMM_SELF, prescribed);
}

TEST(VerletStep, FusedPassesMatchTheSeparatePassesToTheBit) {
  const int n = 1000;
  const double dt = 3.7e-3;
  for (const bool planar : {false, true})
    for (const bool contact : {false, true})
      for (const bool body : {false, true})
        for (const bool withPrescribed : {false, true}) {
          State fused(n, 7), separate(n, 7);
          std::vector<double> mask(3 * n, 0.0);
          std::vector<int> prescribed;
          std::vector<double> prescribedVelocity;
          if (withPrescribed) {
            // The first and last components, a run of components, and one in the middle.
            for (int k : {0, 1, 2, 400, 401, 402, 403, 1234, 2999}) {
              mask[k] = 1.0;
              prescribed.push_back(k);
              prescribedVelocity.push_back(0.25 * k);
            }
          }
          separatePasses(separate, dt, prescribed, prescribedVelocity, contact, body, planar);

          VerletStep step(fused.arrays(contact, body, planar), dt, mask.data());
          DivergenceMonitor monitor = monitorOf(fused, dt, mask.data());
          step.kickAndDrift();
          for (std::size_t m = 0; m < prescribed.size(); ++m)
            fused.v[prescribed[m]] = prescribedVelocity[m];  // what the conditions do
          step.driftPrescribed();
          DivergenceMonitor::LocalSums sums;
          EXPECT_TRUE(step.accelerate(true, monitor, sums));
          const std::string what = std::string(planar ? "planar" : "3D") +
                                   (contact ? " contact" : "") + (body ? " body" : "") +
                                   (withPrescribed ? " prescribed" : "");
          EXPECT_TRUE(sameBits(fused.u, separate.u)) << what;
          EXPECT_TRUE(sameBits(fused.v, separate.v)) << what;
          EXPECT_TRUE(sameBits(fused.y, separate.y)) << what;
          EXPECT_TRUE(sameBits(fused.a, separate.a)) << what;
        }
}

TEST(VerletStep, ReportsANonFiniteForceOrDisplacement) {
  const int n = 600;
  const double dt = 1e-3;
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int which = 0; which < 4; ++which) {
    State s(n, 3);
    VerletStep step(s.arrays(false, false, false), dt, nullptr);
    DivergenceMonitor monitor = monitorOf(s, dt, nullptr);
    DivergenceMonitor::LocalSums sums;
    if (which == 1) s.a[3 * 517 + 1] = inf;  // the drift makes u infinite there
    step.kickAndDrift();
    step.driftPrescribed();
    if (which == 2) s.f[3 * 300 + 2] = nan;
    if (which == 3) s.f[3 * 599] = -inf;
    EXPECT_EQ(step.accelerate(true, monitor, sums), which == 0) << which;
  }
  // The step the run starts from has no drift before it: its displacements are checked too.
  State s(n, 3);
  s.u[3 * 12] = nan;
  VerletStep step(s.arrays(false, false, false), dt, nullptr);
  DivergenceMonitor monitor = monitorOf(s, dt, nullptr);
  DivergenceMonitor::LocalSums sums;
  EXPECT_FALSE(step.accelerate(false, monitor, sums));
}

// A diverging field (the bound, then sign-reversing growth): monitors fed by VerletStep and by
// check() must agree at every step on q and on the run of growth, and fail at the same step
// with the same message. The largest q_i lies in the third block and ties with a later point.
TEST(VerletStep, DrivesTheDivergenceMonitorAsCheckDoes) {
  const int n = 1000;
  const double dt = 1e-3;
  for (const bool withPrescribed : {false, true}) {
    State s(n, 11);
    std::vector<double> mask(3 * n, 0.0);
    if (withPrescribed) mask[3 * 100] = mask[3 * 777 + 1] = 1.0;
    s.density[900] = s.density[600];  // the two points' q_i then tie exactly
    s.horizon[900] = s.horizon[600];
    VerletStep step(s.arrays(false, false, false), dt, mask.data());
    DivergenceMonitor fused = monitorOf(s, dt, mask.data());
    DivergenceMonitor plain = monitorOf(s, dt, mask.data());
    std::string fusedError, plainError;
    long long fusedStep = -1, plainStep = -1;
    for (long long n_ = 0; n_ < 200 && fusedStep < 0; ++n_) {
      // Forces: small and smooth, plus a mode at points 600 and 900 of equal size that grows
      // x1.3 per step with alternating sign.
      const double mode = 1e-3 * std::pow(-1.3, static_cast<double>(n_));
      for (int i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d)
          s.f[3 * i + d] = s.density[i] * (1e-2 * std::sin(0.01 * (3 * i + d) + 0.05 * n_));
      for (int i : {600, 900})
        for (int d = 0; d < 3; ++d) s.f[3 * i + d] = s.density[i] * mode / (dt * dt) * s.horizon[i];
      if (n_ > 0) step.kickAndDrift(), step.driftPrescribed();
      DivergenceMonitor::LocalSums sums;
      ASSERT_TRUE(step.accelerate(n_ > 0, fused, sums));
      try {
        fused.conclude(n_, n_ * dt, sums);
      } catch (const RunError& e) {
        fusedError = e.what();
        fusedStep = n_;
      }
      try {
        plain.check(n_, n_ * dt, s.a.data());
      } catch (const RunError& e) {
        plainError = e.what();
        plainStep = n_;
      }
      ASSERT_EQ(fused.lastMaximum(), plain.lastMaximum()) << "step " << n_;
      ASSERT_EQ(fused.runLength(), plain.runLength()) << "step " << n_;
    }
    EXPECT_GT(fusedStep, 5);
    EXPECT_EQ(fusedStep, plainStep);
    EXPECT_EQ(fusedError, plainError);
    // The tie between points 601 and 901 goes to the first, as one serial pass finds it.
    EXPECT_NE(fusedError.find("the force on point 601 "), std::string::npos) << fusedError;
  }
}

}  // namespace
}  // namespace peridot
