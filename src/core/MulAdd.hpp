#pragma once
// a b + c with one rounding where the CPU has fused multiply-add instructions (what GCC contracts
// the plain expression to in an optimised build), two without. Written out where a result must
// have the same bits in every build (an unoptimised one does not contract) or at two places that
// must round alike.
#include <cmath>

namespace peridot {

inline double mulAdd(double a, double b, double c) {
#ifdef __FMA__
  return std::fma(a, b, c);
#else
  return a * b + c;
#endif
}

}  // namespace peridot
