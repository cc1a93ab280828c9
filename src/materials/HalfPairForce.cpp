// Compiled without floating-point contraction (CMakeLists.txt), the fused multiply-adds written
// out: a pair's force must round alike whichever rank computes it.
#include "materials/HalfPairForce.hpp"

#include <algorithm>
#include <cmath>

#include "materials/HalfLoop.hpp"

namespace peridot {

namespace {

using half::mulAdd;

template <bool kOverLength, bool kDamage, bool kBreak, int kLength, bool kUniform>
void halfLoop(const ModelState& s, const double* c) {
  constexpr int kLanes = half::kLanes;
  const Topology& t = *s.topology;
  HalfBondList& h = *s.halfBonds;
  const int n = t.numOwned;
  const int* rowPoint = h.rowPoint.data();
  const std::int64_t* rowPairs = h.rowPairOffsets.data();
  const int* rowIntact = h.rowIntact.data();
  const int* pairPoint = h.pairPoint.data();
  const half::PairLengths lengths = half::pairLengths(h);
  // The pairs' copy of the damage, if any, is a float whatever the run keeps (a 1-byte type here
  // would make the vector pass 32 pairs wide).
  float* pairDamage = h.pairDamage.data();
  const double* y = s.y;
  const double* x = s.x;
  const double* volume = s.volume;
  const double criticalStretch = s.fusedCriticalStretch;
  double* f = s.forceDensity;
  std::fill(f, f + 3 * static_cast<std::size_t>(n), 0.0);

  // A row's pairs in two passes (materials/HalfLoop.hpp).
  const half::RowBuffers buffers = half::rowBuffers(h);
  double *bufY01 = buffers.Y01, *bufY2 = buffers.Y2, *bufQ = buffers.q;
  int* broke = buffers.broke;
  const std::size_t rows = h.rowPoint.size();

  for (std::size_t r = 0; r < rows; ++r) {
    const int a = rowPoint[r];
    const double ya0 = y[3 * a], ya1 = y[3 * a + 1], ya2 = y[3 * a + 2];
    const double* xa = x + 3 * a;
    const double ca = c[a];
    const std::int64_t p0 = rowPairs[r];
    const int m = rowIntact[r];  // its broken pairs, after these, add exact zeros: skipped
    // In whole vectors: the lanes past the row's end compute what nobody reads and leave the
    // damage they read unchanged.
    const int lanes = (m + kLanes - 1) / kLanes * kLanes;
    const double* rowLength = half::rowLengths<kLength>(lengths, p0, lanes, buffers.zeta);
    int anyBroke = 0;
#pragma omp simd reduction(| : anyBroke)
    for (int k = 0; k < lanes; ++k) {
      const std::int64_t p = p0 + k;
      const int b = pairPoint[p];
      const double Y0 = y[3 * b] - ya0, Y1 = y[3 * b + 1] - ya1, Y2 = y[3 * b + 2] - ya2;
      const double dY = std::sqrt(sumOfSquares(Y0, Y1, Y2));
      const double zb = half::pairZeta<kLength>(rowLength, k, b, x, xa);
      // One micromodulus everywhere (one material and horizon): ca + ca, the same bits as
      // ca + c[b], without gathering c[b].
      double c2 = kUniform ? ca + ca : ca + c[b];
      // The damage factor 1 - d (exact for d = 0 or 1). Without a damage copy (no partly
      // damaged bond) the row's first m pairs are intact: d = 0 until this pass breaks one.
      if constexpr (kBreak) {
        // The critical stretch as the separate damage pass applies it; no branch.
        const float before = kDamage ? pairDamage[p] : 0.0f;
        const float now = k < m && (dY - zb) / zb > criticalStretch ? 1.0f : before;
        if constexpr (kDamage) pairDamage[p] = now;
        broke[k] = now != before;
        anyBroke |= static_cast<int>(now != before);
        if constexpr (!kDamage) c2 *= 1.0 - now;
      }
      if constexpr (kDamage) c2 *= 1.0 - pairDamage[p];
      // (c2 / 2) s / |Y| in one division (shared by both ends; each end then takes the other's
      // volume); none for coincident ends, which divide by infinity (half::kCoincident).
      const double safe = dY > 0 ? dY : half::kCoincident;
      const double denominator = kOverLength ? 2.0 * zb * zb * safe : 2.0 * zb * safe;
      bufY01[2 * k] = Y0;
      bufY01[2 * k + 1] = Y1;
      bufY2[k] = Y2;
      bufQ[k] = c2 * (dY - zb) / denominator;
    }
    half::scatterForceRow(a, n, pairPoint + p0, m, volume, buffers, f);
    if constexpr (kBreak) {
      if (anyBroke) {
        // Out of the loop from now on; in the full lists when they are read.
        h.breakPairs(r, broke);
      }
    }
  }
}

template <bool kOverLength, int kLength, bool kUniform>
void withDamage(const ModelState& s, const double* c) {
  const bool breaks = half::breaksBonds(s);
  // Damage read per pair only where some bond is partly damaged (HalfBondList::pairDamage).
  const bool partial = !s.halfBonds->pairDamage.empty();
  if (breaks && partial)
    halfLoop<kOverLength, true, true, kLength, kUniform>(s, c);
  else if (breaks)
    halfLoop<kOverLength, false, true, kLength, kUniform>(s, c);
  else if (partial)
    halfLoop<kOverLength, true, false, kLength, kUniform>(s, c);
  else
    halfLoop<kOverLength, false, false, kLength, kUniform>(s, c);
}

// Whether every point the loop reads (owned and ghosts) has the same micromodulus: a pass over
// the points, against a gather per pair.
bool uniform(const Topology& t, const double* c) {
  const int points = t.numOwned + t.numGhosts;
  for (int i = 1; i < points; ++i)
    if (c[i] != c[0]) return false;
  return true;
}

}  // namespace

void halfPairForce(const ModelState& s, const double* c, bool normalized) {
  half::withLengthSource(*s.halfBonds, [&](auto source) {
    constexpr int kLength = decltype(source)::value;
    const bool same = uniform(*s.topology, c);
    if (normalized && same)
      withDamage<true, kLength, true>(s, c);
    else if (normalized)
      withDamage<true, kLength, false>(s, c);
    else if (same)
      withDamage<false, kLength, true>(s, c);
    else
      withDamage<false, kLength, false>(s, c);
  });
}

}  // namespace peridot
