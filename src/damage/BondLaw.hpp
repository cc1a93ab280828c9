#pragma once
// How a bond's force scalar depends on its stretch, as the block's damage model dictates.
// Plain data read inside the bond loops (no virtual call per bond):
//   Linear: the force scalar is the stretch s (every model without a smooth damage law);
//   Smooth: Du, Tao and Tian's (paper 002, eq. 5) continuous piecewise-linear F(s), with
//           thresholds S1- < S0- < 0 <= S0+ < S1+; the stored energy uses p(s), p' = F, p(0) = 0.
// The damage factor mu(S*) itself travels in the bond damage (1 - mu).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/MulAdd.hpp"

namespace peridot {

struct BondLaw {
  enum class Kind { Linear, Smooth };
  Kind kind = Kind::Linear;
  double s1Minus = -0.99, s0Minus = -0.98, s0Plus = 0.0, s1Plus = 0.0;

  // F(s).
  double forceScalar(double s) const {
    if (kind == Kind::Linear) return s;
    if (s >= s0Minus && s <= s0Plus) return s;
    if (s > s0Plus && s < s1Plus) return s0Plus * (s1Plus - s) / (s1Plus - s0Plus);
    if (s > s1Minus && s < s0Minus) return s0Minus * (s - s1Minus) / (s0Minus - s1Minus);
    return 0.0;
  }
  // 1 - mu(s) of paper 002 eq. 6 for a Smooth law: 0 below S0+, linear on [S0+, S1+], 1 beyond.
  // DTT's bond damage is the history maximum of it (the damage pass or a fused force loop).
  double brokenFraction(double s) const {
    // A product with the reciprocal (hoisted out of a bond loop), not a division per bond.
    const double r = (s - s0Plus) * (1.0 / (s1Plus - s0Plus));
    return r < 0.0 ? 0.0 : (r > 1.0 ? 1.0 : r);
  }
  // p(s) = integral of F from 0 to s.
  double potential(double s) const {
    if (kind == Kind::Linear) return 0.5 * s * s;
    if (s >= s0Minus && s <= s0Plus) return 0.5 * s * s;
    if (s > s0Plus) {
      const double t = s < s1Plus ? s : s1Plus;
      // 1/2 S0+^2 + integral_{S0+}^{t} S0+ (S1+ - x) / (S1+ - S0+) dx
      // (the multiply-adds written out as an optimised build contracts them: every build gives
      // the same bits)
      const double w = s1Plus - s0Plus, tail = (s1Plus - t) * (s1Plus - t);
      return mulAdd(0.5 * s0Plus, s0Plus, s0Plus * mulAdd(w, w, -tail) / (2.0 * w));
    }
    const double t = s > s1Minus ? s : s1Minus;
    // 1/2 S0-^2 + integral_{S0-}^{t} S0- (x - S1-) / (S0- - S1-) dx  (t < S0-, so it adds)
    const double w = s0Minus - s1Minus;
    return mulAdd(0.5 * s0Minus, s0Minus,
                  s0Minus * mulAdd(t - s1Minus, t - s1Minus, -(w * w)) / (2.0 * w));
  }
};

// A Smooth law's damage update (DTT's pass) of bond entries b0 .. b1 of point i: the bond damage
// becomes max(d, brokenFraction(s)), s = (|Y| - |xi|) / |xi|. DTT's own pass and Linearized LPS's
// dilatation loop (fused) both call it; without branches, it vectorizes.
inline void raiseBrokenFractions(const BondLaw& law, const double* y, const int* neighbors,
                                 const double* zeta, int i, std::int64_t b0, std::int64_t b1,
                                 float* bondDamage) {
  const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
  for (std::int64_t b = b0; b < b1; ++b) {
    const int j = neighbors[b];
    // Both ends of a bond form the same stretch bit for bit: y_i - y_j = -(y_j - y_i)
    // exactly, and the squares and the reference length are the same.
    const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
    const double stretch = (std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2) - zeta[b]) / zeta[b];
    // 1 - mu(S*) = max over the history of 1 - mu(s); rounding to float is monotone too.
    const float broken = static_cast<float>(law.brokenFraction(stretch));
    bondDamage[b] = std::max(bondDamage[b], broken);
  }
}

}  // namespace peridot
