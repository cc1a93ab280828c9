#include "solvers/VerletStep.hpp"

#include <algorithm>
#include <cstddef>

namespace peridot {

namespace {

// Components [begin, end): v += dt/2 a, y = x + u + dt v, u += dt v, each written as the separate
// passes wrote it (the same contractions into fused multiply-adds). Returns the sum of u - u:
// 0 when every u written is finite, NaN otherwise (a test with no branch in the loop).
double kickDriftRange(std::size_t begin, std::size_t end, double half, double dt,
                      const VerletArrays& p) {
  const double* a = p.a;
  const double* x = p.x;
  double *v = p.v, *u = p.u, *y = p.y;
  double check = 0;
#pragma omp simd reduction(+ : check)
  for (std::size_t k = begin; k < end; ++k) {
    const double vk = v[k] + half * a[k];
    v[k] = vk;
    y[k] = x[k] + u[k] + dt * vk;
    const double uk = u[k] + dt * vk;
    u[k] = uk;
    check += uk - uk;
  }
  return check;
}

// Points [begin, begin + count): the accelerations (the previous ones saved to `previous`), and
// the half-kick when kKick. Returns the sum of f - f (0 when every force component is finite).
template <bool kKick, bool kContact, bool kBody>
double accelerateBlock(int begin, int count, double half, const VerletArrays& p, double* previous) {
  const std::size_t at = 3 * static_cast<std::size_t>(begin);
  const double* f = p.force + at;
  const double* fc = kContact ? p.contactForce + at : nullptr;
  const double* b = kBody ? p.bodyForce + at : nullptr;
  const double* rho = p.density + begin;
  double* a = p.a + at;
  double* v = p.v + at;
  const bool planar = p.planar;
  double check = 0;
#pragma omp simd reduction(+ : check)
  for (int i = 0; i < count; ++i) {
    for (int d = 0; d < 3; ++d) {
      const int k = 3 * i + d;
      previous[k] = a[k];
      double force = f[k];
      if (kContact) force += fc[k];
      if (kBody) force += b[k];
      // Planar: nothing moves out of the plane, whatever a model computes along z.
      const double ak = planar && d == 2 ? 0.0 : force / rho[i];
      a[k] = ak;
      if (kKick) v[k] += half * ak;
      check += f[k] - f[k];
    }
  }
  return check;
}

template <bool kKick, bool kContact, bool kBody>
double accelerateAll(double half, const VerletArrays& p, const DivergenceMonitor& monitor,
                     DivergenceMonitor::LocalSums& sums) {
  constexpr int kBlock = DivergenceMonitor::kBlock;
  double previous[3 * kBlock];
  double check = 0;
  for (int begin = 0; begin < p.numOwned; begin += kBlock) {
    const int count = std::min(kBlock, p.numOwned - begin);
    check += accelerateBlock<kKick, kContact, kBody>(begin, count, half, p, previous);
    monitor.accumulate(begin, count, p.a + 3 * static_cast<std::size_t>(begin), previous, sums);
  }
  return check;
}

template <bool kKick>
double accelerateAll(double half, const VerletArrays& p, const DivergenceMonitor& monitor,
                     DivergenceMonitor::LocalSums& sums) {
  if (p.contactForce && p.bodyForce)
    return accelerateAll<kKick, true, true>(half, p, monitor, sums);
  if (p.contactForce) return accelerateAll<kKick, true, false>(half, p, monitor, sums);
  if (p.bodyForce) return accelerateAll<kKick, false, true>(half, p, monitor, sums);
  return accelerateAll<kKick, false, false>(half, p, monitor, sums);
}

}  // namespace

VerletStep::VerletStep(const VerletArrays& arrays, double dt, const double* prescribed)
    : p_(arrays), dt_(dt), half_(0.5 * dt) {
  for (int k = 0; prescribed && k < 3 * p_.numOwned; ++k)
    if (prescribed[k] != 0.0) prescribed_.push_back(k);
}

void VerletStep::kickAndDrift() {
  // The free runs between prescribed components in one pass each; a prescribed component gets
  // its half-kick only (the conditions then overwrite that velocity anyway).
  double check = 0;
  std::size_t begin = 0;
  for (int k : prescribed_) {
    check += kickDriftRange(begin, static_cast<std::size_t>(k), half_, dt_, p_);
    p_.v[k] += half_ * p_.a[k];
    begin = static_cast<std::size_t>(k) + 1;
  }
  check += kickDriftRange(begin, 3 * static_cast<std::size_t>(p_.numOwned), half_, dt_, p_);
  displacementFinite_ = check == 0;
  drifted_ = true;
}

void VerletStep::driftPrescribed() {
  double check = 0;
  for (int k : prescribed_) {
    p_.y[k] = p_.x[k] + p_.u[k] + dt_ * p_.v[k];
    p_.u[k] += dt_ * p_.v[k];
    check += p_.u[k] - p_.u[k];
  }
  if (!(check == 0)) displacementFinite_ = false;
}

bool VerletStep::accelerate(bool kick, const DivergenceMonitor& monitor,
                            DivergenceMonitor::LocalSums& sums) {
  if (!drifted_) {
    // The step the run starts from (or a restart's): its displacements were not drifted here.
    double check = 0;
    for (int k = 0; k < 3 * p_.numOwned; ++k) check += p_.u[k] - p_.u[k];
    displacementFinite_ = check == 0;
  }
  drifted_ = false;
  const double check = kick ? accelerateAll<true>(half_, p_, monitor, sums)
                            : accelerateAll<false>(half_, p_, monitor, sums);
  return check == 0 && displacementFinite_;
}

}  // namespace peridot
