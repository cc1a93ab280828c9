#pragma once
// One step of LSJ-T's bond update (paper 001, eqs. 19-20; damage/LSJT.hpp), as plain data and
// two inline functions over one point's bonds: LSJ-T's own damage pass and a material loop that
// forms the same linearized strain (Linearized LPS's dilatation loop, fused) both call
// lsjtStrains and lsjtUpdateBonds, so the two give the same bits.
#include <algorithm>
#include <cstdint>

#include "core/MulAdd.hpp"

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

// The linearized strains of bond entries b0 .. b1 of point i: dot[k] = xi.eta, eps[k] =
// xi.eta / |xi|^2 for entry b0 + k (xi = x_j - x_i, eta = (y_j - y_i) - xi; the same bits from
// both ends of a bond). Returns whether some eps >= S_c: if none, the update changes nothing and
// may be skipped (most points of most steps). A loop without branches: it vectorizes.
inline int lsjtStrains(const double* x, const double* y, const int* neighbors, const double* zeta,
                       int i, std::int64_t b0, std::int64_t b1, double* __restrict dot,
                       double* __restrict eps, double criticalStretch) {
  const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
  const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
  int over = 0;  // an int: a bool reduction stops GCC vectorizing the loop
  for (std::int64_t b = b0; b < b1; ++b) {
    const int j = neighbors[b];
    const double X0 = x[3 * j] - xi0, X1 = x[3 * j + 1] - xi1, X2 = x[3 * j + 2] - xi2;
    // The multiply-adds written out (what an optimised build contracts them to): the dilatation
    // that reads this xi.eta has the same bits as the one that forms it (LinearizedLpsRows), in
    // every build.
    double d = mulAdd(X0, (y[3 * j] - yi0) - X0, 0.0);
    d = mulAdd(X1, (y[3 * j + 1] - yi1) - X1, d);
    d = mulAdd(X2, (y[3 * j + 2] - yi2) - X2, d);
    dot[b - b0] = d;
    eps[b - b0] = d / (zeta[b] * zeta[b]);
    over |= eps[b - b0] >= criticalStretch ? 1 : 0;
  }
  return over;
}

// The update of bond entries b0 .. b1 (one point's) from their strains eps[0 .. b1 - b0): where
// eps >= S_c, X_b + dt j_s(eps), stored if the step commits, and the bond damage becomes
// max(damage, 1 - h(X)); below S_c nothing changes (the common case). In two loops: the first,
// without branches, vectorizes (j_s for every entry, the stores masked); h, which needs exp and
// pow, only where 0 < X < x_c (a bond on its way to breaking: few), where the second takes the
// integral the first left in `integral` (X >= x_c: h = 0, damage 1, set by the first; X <= 0:
// h = 1, nothing to raise).
inline void lsjtUpdateBonds(const LsjtStep& k, std::int64_t b0, std::int64_t b1,
                            const double* __restrict eps, double* __restrict integral,
                            float* __restrict bondDamage) {
  double* __restrict X = k.historyIntegral;
  const double sc = k.criticalStretch, dt = k.dt, xc = k.xc;
  const bool commit = k.commit;
  int pending = 0;  // an int: a bool reduction stops GCC vectorizing the loop
  for (std::int64_t b = b0; b < b1; ++b) {
    const bool over = eps[b - b0] >= sc;
    const double value = X[b] + dt * lsjtOverstretchRate(eps[b - b0], sc);
    if (over && commit) X[b] = value;
    if (over && value >= xc) bondDamage[b] = 1.0f;  // max(d, 1 - h) with h = 0
    const bool partial = over && value > 0.0 && value < xc;
    integral[b - b0] = partial ? value : -1.0;
    pending |= partial ? 1 : 0;
  }
  if (!pending) return;
  for (std::int64_t b = b0; b < b1; ++b) {
    if (!(integral[b - b0] > 0.0)) continue;
    const float broken = static_cast<float>(1.0 - lsjtDamageFactor(integral[b - b0], xc));
    bondDamage[b] = std::max(bondDamage[b], broken);
  }
}

}  // namespace peridot
