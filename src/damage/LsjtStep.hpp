#pragma once
// One step of LSJ-T's bond update (paper 001, eqs. 19-20; damage/LSJT.hpp), as plain data and
// one inline function per bond: LSJ-T's own damage pass and a material loop that forms the same
// linearized strain (Linearized LPS's dilatation loop, fused) both apply lsjtUpdateBond, so the
// two give the same bits.
#include <algorithm>
#include <cstdint>

namespace peridot {

// j_s of paper 001 eq. 20: (x/S_c - 1)^5 / (1 + (x/S_c)^5) for x >= S_c, else 0.
inline double lsjtOverstretchRate(double x, double criticalStretch) {
  if (!(x >= criticalStretch)) return 0.0;
  const double r = x / criticalStretch, a = r - 1.0;
  const double a2 = a * a, r2 = r * r;
  return a2 * a2 * a / (1.0 + r2 * r2 * r);
}

// h of paper 001 eq. 20 (damage/LSJT.cpp).
double lsjtDamageFactor(double integral, double xc);

// What one evaluation's update needs: the step dt over which the rate is integrated (the step
// that just closed), S_c, x_c = j_s(1.05 S_c) dt, the history integral (one double per bond
// entry) and whether to store it (a trial evaluation does not). `historyIntegral` null: this
// evaluation updates nothing (the initial state, or dt = 0).
struct LsjtStep {
  double* historyIntegral = nullptr;
  double dt = 0.0;
  double criticalStretch = 0.0;
  double xc = 0.0;
  bool commit = true;
  bool active() const { return historyIntegral != nullptr; }
};

// Bond entry b with linearized strain eps (xi.eta / |xi|^2): below S_c nothing accumulates (the
// common case); else X_b + dt j_s(eps), stored if the step commits, and the bond damage becomes
// max(damage, 1 - h(X)).
inline void lsjtUpdateBond(const LsjtStep& k, std::int64_t b, double eps, float* bondDamage) {
  if (!(eps >= k.criticalStretch)) return;
  const double integral = k.historyIntegral[b] + k.dt * lsjtOverstretchRate(eps, k.criticalStretch);
  if (k.commit) k.historyIntegral[b] = integral;
  const float broken = static_cast<float>(1.0 - lsjtDamageFactor(integral, k.xc));
  bondDamage[b] = std::max(bondDamage[b], broken);
}

}  // namespace peridot
