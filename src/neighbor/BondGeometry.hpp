#pragma once
// The reference length of a bond, with one rounding every loop shares (stored or computed |xi|
// are the same bits).
#include <cmath>

namespace peridot {

// X0^2 + X1^2 + X2^2 in one fixed rounding. With FMA hardware the compiler may contract a sum of
// products into fused multiply-adds in any order it likes, and its choice can differ between a
// scalar and a vector loop: here the order is written out, so every caller gets the same bits.
// It is the order GCC gives `X0 * X0 + X1 * X1 + X2 * X2` in scalar code, so the stored lengths
// keep the values of earlier builds.
inline double sumOfSquares(double X0, double X1, double X2) {
#ifdef __FMA__
  return std::fma(X2, X2, std::fma(X0, X0, X1 * X1));
#else
  return X0 * X0 + X1 * X1 + X2 * X2;  // no FMA instructions: nothing to contract
#endif
}

// |xi| of the bond from i to j, from the reference coordinates. The evaluator fills the stored
// `Reference_Bond_Length` with this very function, and the loops that compute |xi| instead of
// reading the array use sumOfSquares() alike: the same bits either way.
inline double referenceBondLength(const double* x, int i, int j) {
  return std::sqrt(
      sumOfSquares(x[3 * j] - x[3 * i], x[3 * j + 1] - x[3 * i + 1], x[3 * j + 2] - x[3 * i + 2]));
}

}  // namespace peridot
