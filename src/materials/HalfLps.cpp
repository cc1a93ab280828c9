// Compiled without floating-point contraction (CMakeLists.txt), the fused multiply-adds written
// out: a pair's terms must round alike whichever rank computes them.
#include "materials/HalfLps.hpp"

#include <algorithm>
#include <cmath>

#include "materials/HalfLoop.hpp"

namespace peridot {

namespace {

using half::mulAdd;

template <bool kInfluence, bool kDamage, bool kBreak, int kLength>
void dilatationLoop(const ModelState& s, const double* weightedVolume, double thetaFactor,
                    double* theta) {
  constexpr int kLanes = half::kLanes;
  const Topology& t = *s.topology;
  HalfBondList& h = *s.halfBonds;
  const int n = t.numOwned;
  const int* rowPoint = h.rowPoint.data();
  const std::int64_t* rowPairs = h.rowPairOffsets.data();
  const int* rowIntact = h.rowIntact.data();
  const int* pairPoint = h.pairPoint.data();
  const half::PairLengths lengths = half::pairLengths(h);
  const double* pairInfluence = h.pairInfluence.data();
  float* pairDamage = h.pairDamage.data();
  const double *y = s.y, *x = s.x, *volume = s.volume;
  const double criticalStretch = s.fusedCriticalStretch;
  // The sums sum omega (1 - d) |xi| e V_j first, scaled by c / m at the end.
  std::fill(theta, theta + n, 0.0);
  const half::RowBuffers buffers = half::rowBuffers(h);
  double* bufQ = buffers.q;
  int* broke = buffers.broke;
  const std::size_t rows = h.rowPoint.size();

  for (std::size_t r = 0; r < rows; ++r) {
    const int a = rowPoint[r];
    const double ya0 = y[3 * a], ya1 = y[3 * a + 1], ya2 = y[3 * a + 2];
    const double* xa = x + 3 * a;
    const double va = volume[a];
    const std::int64_t p0 = rowPairs[r];
    const int m = rowIntact[r];  // its broken pairs, after these, add exact zeros: skipped
    const int lanes = (m + kLanes - 1) / kLanes * kLanes;  // past the end: read, not used
    const double* rowLength = half::rowLengths<kLength>(lengths, p0, lanes, buffers.zeta);
    int anyBroke = 0;
#pragma omp simd reduction(| : anyBroke)
    for (int k = 0; k < lanes; ++k) {
      const std::int64_t p = p0 + k;
      const int b = pairPoint[p];
      const double Y0 = y[3 * b] - ya0, Y1 = y[3 * b + 1] - ya1, Y2 = y[3 * b + 2] - ya2;
      const double dY = std::sqrt(sumOfSquares(Y0, Y1, Y2));
      const double zb = half::pairZeta<kLength>(rowLength, k, b, x, xa);
      // 1 - d; without a damage copy the row's first m pairs are intact until this pass breaks
      // one (HalfBondList::pairDamage).
      double intact = 1.0;
      if constexpr (kBreak) {
        // The critical stretch as the separate damage pass applies it; no branch.
        const float before = kDamage ? pairDamage[p] : 0.0f;
        const float now = k < m && (dY - zb) / zb > criticalStretch ? 1.0f : before;
        if constexpr (kDamage) pairDamage[p] = now;
        broke[k] = now != before;
        anyBroke |= static_cast<int>(now != before);
        if constexpr (!kDamage) intact = 1.0 - now;
      }
      if constexpr (kDamage) intact = 1.0 - pairDamage[p];
      const double omega = kInfluence ? pairInfluence[p] : 1.0;
      bufQ[k] = omega * intact * zb * (dY - zb);
    }
    double sum = 0;
    for (int k = 0; k < m; ++k) {
      const int b = pairPoint[p0 + k];
      sum = mulAdd(bufQ[k], volume[b], sum);
      if (b < n) theta[b] = mulAdd(bufQ[k], va, theta[b]);
    }
    if (a < n) theta[a] += sum;
    if constexpr (kBreak) {
      if (anyBroke) {
        h.breakPairs(r, broke);
      }
    }
  }
  // A point without bonds has no weighted volume and no dilatation.
  for (int i = 0; i < n; ++i)
    theta[i] = weightedVolume[i] > 0 ? thetaFactor * theta[i] / weightedVolume[i] : 0.0;
}

template <bool kInfluence, bool kDamage, int kLength>
void forceLoop(const ModelState& s, const double* thetaBeta, const double* alpha) {
  constexpr int kLanes = half::kLanes;
  const Topology& t = *s.topology;
  const HalfBondList& h = *s.halfBonds;
  const int n = t.numOwned;
  const int* rowPoint = h.rowPoint.data();
  const std::int64_t* rowPairs = h.rowPairOffsets.data();
  const int* rowIntact = h.rowIntact.data();
  const int* pairPoint = h.pairPoint.data();
  const half::PairLengths lengths = half::pairLengths(h);
  const double* pairInfluence = h.pairInfluence.data();
  const float* pairDamage = h.pairDamage.data();
  const double *y = s.y, *x = s.x, *volume = s.volume;
  double* f = s.forceDensity;
  std::fill(f, f + 3 * static_cast<std::size_t>(n), 0.0);
  const half::RowBuffers buffers = half::rowBuffers(h);
  double *bufY01 = buffers.Y01, *bufY2 = buffers.Y2, *bufQ = buffers.q;
  const std::size_t rows = h.rowPoint.size();

  for (std::size_t r = 0; r < rows; ++r) {
    const int a = rowPoint[r];
    const double ya0 = y[3 * a], ya1 = y[3 * a + 1], ya2 = y[3 * a + 2];
    const double* xa = x + 3 * a;
    const double thetaBetaA = thetaBeta[a], alphaA = alpha[a];
    const std::int64_t p0 = rowPairs[r];
    const int m = rowIntact[r];  // its broken pairs, after these, add exact zeros: skipped
    const int lanes = (m + kLanes - 1) / kLanes * kLanes;
    const double* rowLength = half::rowLengths<kLength>(lengths, p0, lanes, buffers.zeta);
#pragma omp simd
    for (int k = 0; k < lanes; ++k) {
      const std::int64_t p = p0 + k;
      const int b = pairPoint[p];
      const double Y0 = y[3 * b] - ya0, Y1 = y[3 * b + 1] - ya1, Y2 = y[3 * b + 2] - ya2;
      const double dY = std::sqrt(sumOfSquares(Y0, Y1, Y2));
      const double zb = half::pairZeta<kLength>(rowLength, k, b, x, xa);
      const double intact = kDamage ? 1.0 - pairDamage[p] : 1.0;
      const double omega = kInfluence ? pairInfluence[p] : 1.0;
      // t_a + t_b = (1 - d) omega ((theta beta_a + theta beta_b) |xi| + (1 - d) (alpha_a +
      // alpha_b) e), over |Y| for the direction; none for coincident ends.
      const double tension =
          intact * omega *
          ((thetaBetaA + thetaBeta[b]) * zb + intact * (alphaA + alpha[b]) * (dY - zb));
      const double safe = dY > 0 ? dY : half::kCoincident;  // none for coincident ends
      bufY01[2 * k] = Y0;
      bufY01[2 * k + 1] = Y1;
      bufY2[k] = Y2;
      bufQ[k] = tension / safe;
    }
    half::scatterForceRow(a, n, pairPoint + p0, m, volume, buffers, f);
  }
}

}  // namespace

void halfLpsDilatation(const ModelState& s, const double* weightedVolume, double thetaFactor,
                       double* dilatation) {
  const bool influence = !s.halfBonds->pairInfluence.empty();
  half::withLengthSource(*s.halfBonds, [&](auto source) {
    constexpr int kLength = decltype(source)::value;
    const bool breaks = half::breaksBonds(s);
    // Damage read per pair only where some bond is partly damaged (HalfBondList::pairDamage).
    const bool partial = !s.halfBonds->pairDamage.empty();
    const auto run = [&](auto withInfluence) {
      constexpr bool kInfluence = decltype(withInfluence)::value;
      if (breaks && partial)
        dilatationLoop<kInfluence, true, true, kLength>(s, weightedVolume, thetaFactor, dilatation);
      else if (breaks)
        dilatationLoop<kInfluence, false, true, kLength>(s, weightedVolume, thetaFactor,
                                                         dilatation);
      else if (partial)
        dilatationLoop<kInfluence, true, false, kLength>(s, weightedVolume, thetaFactor,
                                                         dilatation);
      else
        dilatationLoop<kInfluence, false, false, kLength>(s, weightedVolume, thetaFactor,
                                                          dilatation);
    };
    if (influence)
      run(std::true_type{});
    else
      run(std::false_type{});
  });
}

void halfLpsForce(const ModelState& s, const double* thetaBeta, const double* alpha) {
  const bool influence = !s.halfBonds->pairInfluence.empty();
  const bool damaged = !s.halfBonds->pairDamage.empty();  // some bond partly damaged
  const auto run = [&](auto withInfluence, auto withDamage) {
    constexpr bool kInfluence = decltype(withInfluence)::value;
    constexpr bool kDamage = decltype(withDamage)::value;
    half::withLengthSource(*s.halfBonds, [&](auto source) {
      forceLoop<kInfluence, kDamage, decltype(source)::value>(s, thetaBeta, alpha);
    });
  };
  if (influence && damaged)
    run(std::true_type{}, std::true_type{});
  else if (influence)
    run(std::true_type{}, std::false_type{});
  else if (damaged)
    run(std::false_type{}, std::true_type{});
  else
    run(std::false_type{}, std::false_type{});
}

}  // namespace peridot
