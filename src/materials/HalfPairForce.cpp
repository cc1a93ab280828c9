// Compiled without floating-point contraction (CMakeLists.txt), the fused multiply-adds written
// out: a pair's force must round alike whichever rank computes it.
#include "materials/HalfPairForce.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "neighbor/HalfBondList.hpp"

namespace peridot {

namespace {

// a b + c: one rounding with FMA hardware, two without; either way the same at every call.
inline double mulAdd(double a, double b, double c) {
#ifdef __FMA__
  return std::fma(a, b, c);
#else
  return a * b + c;
#endif
}

template <bool kOverLength, bool kDamage, bool kBreak, bool kStoredLength, typename DamageT>
void halfLoop(const ModelState& s, const double* c) {
  // The vector pass's width in pairs: 8 float damage values fill a 256-bit vector (the
  // padding of the pair arrays allows up to kPadding).
  constexpr int kLanes = 8;
  static_assert(kLanes <= HalfBondList::kPadding, "a row's vector pass reads past its end");
  const Topology& t = *s.topology;
  HalfBondList& h = *s.halfBonds;
  const int n = t.numOwned;
  const int* rowPoint = h.rowPoint.data();
  const std::int64_t* rowPairs = h.rowPairOffsets.data();
  const int* pairPoint = h.pairPoint.data();
  const double* pairLength = h.pairLength.data();
  // The pairs' copy of the damage is a float whatever the run keeps (0/1 flags are exact in it;
  // a 1-byte type here would make the vector pass 32 pairs wide).
  float* pairDamage = h.pairDamage.data();
  DamageT* full;  // the run's bond damage, written where a bond breaks
  if constexpr (std::is_same_v<DamageT, float>)
    full = s.breakableBondDamage;
  else
    full = s.breakableBondBroken;
  const double* y = s.y;
  const double* x = s.x;
  const double* volume = s.volume;
  const double criticalStretch = s.fusedCriticalStretch;
  double* f = s.forceDensity;
  std::fill(f, f + 3 * static_cast<std::size_t>(n), 0.0);

  // A row's pairs in two passes. The first computes each pair's direction and force scale in
  // vector lanes (square roots and divisions are what a pair costs; no lane reads another's
  // result, so the bits are those of a scalar loop); the second adds them to the row's point
  // and subtracts them from the later ends, in order, and records the bonds that broke.
  thread_local std::vector<double> scratch;
  thread_local std::vector<int>
      brokeNow;  // int: a 1-byte type would make the vectors 32 pairs wide
  const std::size_t rows = h.rowPoint.size();
  const auto longest = static_cast<std::size_t>((h.longestRow + kLanes - 1) / kLanes * kLanes);
  if (scratch.size() < 4 * longest) scratch.resize(4 * longest);
  if (brokeNow.size() < longest) brokeNow.resize(longest);
  double* bufY0 = scratch.data();
  double* bufY1 = bufY0 + longest;
  double* bufY2 = bufY1 + longest;
  double* bufQ = bufY2 + longest;
  int* broke = brokeNow.data();

  for (std::size_t r = 0; r < rows; ++r) {
    const int a = rowPoint[r];
    const double ya0 = y[3 * a], ya1 = y[3 * a + 1], ya2 = y[3 * a + 2];
    const double xa0 = x[3 * a], xa1 = x[3 * a + 1], xa2 = x[3 * a + 2];
    const double ca = c[a], va = volume[a];
    const std::int64_t p0 = rowPairs[r];
    const int m = static_cast<int>(rowPairs[r + 1] - p0);
    // In whole vectors: the lanes past the row's end compute what nobody reads and leave the
    // damage they read unchanged.
    const int lanes = (m + kLanes - 1) / kLanes * kLanes;
    int anyBroke = 0;
#pragma omp simd reduction(| : anyBroke)
    for (int k = 0; k < lanes; ++k) {
      const std::int64_t p = p0 + k;
      const int b = pairPoint[p];
      const double Y0 = y[3 * b] - ya0, Y1 = y[3 * b + 1] - ya1, Y2 = y[3 * b + 2] - ya2;
      const double dY = std::sqrt(sumOfSquares(Y0, Y1, Y2));
      double zb;
      if constexpr (kStoredLength)
        zb = pairLength[p];
      else
        zb = std::sqrt(sumOfSquares(x[3 * b] - xa0, x[3 * b + 1] - xa1, x[3 * b + 2] - xa2));
      double c2 = ca + c[b];
      if constexpr (kBreak) {
        // The critical stretch as the separate damage pass applies it; no branch.
        const float before = pairDamage[p];
        const float now = k < m && (dY - zb) / zb > criticalStretch ? 1.0f : before;
        pairDamage[p] = now;
        broke[k] = now != before;
        anyBroke |= static_cast<int>(now != before);
      }
      if constexpr (kDamage) c2 *= 1.0 - pairDamage[p];  // flags: 1 - 1 = 0 and 1 - 0 = 1 exactly
      // (c2 / 2) s / |Y| in one division (shared by both ends; each end then takes the other's
      // volume); none for coincident ends.
      const double safe = dY > 0 ? dY : 1.0;
      const double denominator = kOverLength ? 2.0 * zb * zb * safe : 2.0 * zb * safe;
      const double q = c2 * (dY - zb) / denominator;
      bufY0[k] = Y0;
      bufY1[k] = Y1;
      bufY2[k] = Y2;
      bufQ[k] = dY > 0 ? q : 0.0;
    }
    double f0 = 0, f1 = 0, f2 = 0;
    for (int k = 0; k < m; ++k) {
      const int b = pairPoint[p0 + k];
      const double sa = bufQ[k] * volume[b], sb = bufQ[k] * va;
      f0 = mulAdd(sa, bufY0[k], f0);
      f1 = mulAdd(sa, bufY1[k], f1);
      f2 = mulAdd(sa, bufY2[k], f2);
      if (b < n) {
        f[3 * b] = mulAdd(-sb, bufY0[k], f[3 * b]);
        f[3 * b + 1] = mulAdd(-sb, bufY1[k], f[3 * b + 1]);
        f[3 * b + 2] = mulAdd(-sb, bufY2[k], f[3 * b + 2]);
      }
    }
    if (a < n) {
      f[3 * a] += f0;
      f[3 * a + 1] += f1;
      f[3 * a + 2] += f2;
    }
    if constexpr (kBreak) {
      if (anyBroke) {
        // This rank's entries of the bonds that broke, in the full lists (once per bond).
        for (int k = 0; k < m; ++k) {
          if (!broke[k]) continue;
          const std::int64_t p = p0 + k;
          const int b = pairPoint[p];
          full[h.fullEntry(t, r, p)] = DamageT(1);
          if (a < n && b < n) {
            const std::int64_t mirror = mirrorBond(t, b, a);
            if (mirror >= 0) full[mirror] = DamageT(1);
          }
        }
      }
    }
  }
}

template <bool kOverLength, bool kStoredLength, typename DamageT>
void withDamage(const ModelState& s, const double* c) {
  constexpr bool kFloat = std::is_same_v<DamageT, float>;
  const bool damaged = kFloat ? s.bondDamage != nullptr : s.bondBroken != nullptr;
  const bool breaks = kFloat ? s.breakableBondDamage != nullptr : s.breakableBondBroken != nullptr;
  if (breaks)
    halfLoop<kOverLength, true, true, kStoredLength, DamageT>(s, c);
  else if (damaged)
    halfLoop<kOverLength, true, false, kStoredLength, DamageT>(s, c);
  else
    halfLoop<kOverLength, false, false, kStoredLength, DamageT>(s, c);
}

template <bool kOverLength>
void withStorage(const ModelState& s, const double* c) {
  const bool flags = s.bondBroken != nullptr;
  if (!s.halfBonds->pairLength.empty()) {
    if (flags)
      withDamage<kOverLength, true, unsigned char>(s, c);
    else
      withDamage<kOverLength, true, float>(s, c);
  } else {
    if (flags)
      withDamage<kOverLength, false, unsigned char>(s, c);
    else
      withDamage<kOverLength, false, float>(s, c);
  }
}

}  // namespace

void halfPairForce(const ModelState& s, const double* c, bool normalized) {
  if (normalized)
    withStorage<true>(s, c);
  else
    withStorage<false>(s, c);
}

}  // namespace peridot
