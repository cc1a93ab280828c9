// Compiled without floating-point contraction (CMakeLists.txt): the fused multiply-adds are
// written out (mulAdd, _mm256_fmadd_pd) where the one-pass loops this replaces had them, so the
// bits stay theirs.
#include "materials/LinearizedLpsRows.hpp"

#include "materials/BondOptions.hpp"
#include "materials/HalfLoop.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#define PERIDOT_LLPS_LANES 1
#endif

namespace peridot::llps {

namespace {

using half::mulAdd;

// What a row of the force loop reads: the arrays, and the row point's own values.
struct ForceRow {
  const double *x = nullptr, *y = nullptr, *volume = nullptr, *zeta = nullptr;
  const double *influence = nullptr, *theta = nullptr, *alpha = nullptr, *beta = nullptr;
  const float* damage = nullptr;
  const unsigned char* sides = nullptr;
  BondLaw law;
  double xi0 = 0, xi1 = 0, xi2 = 0, yi0 = 0, yi1 = 0, yi2 = 0, betaThetaI = 0, alphaI = 0;
};

// xi.eta of the bond to j, xi = x_j - x_i and eta = (y_j - y_i) - xi, summed over the
// components as a chain of multiply-adds from 0 (the one-pass loops' rounding).
inline double xiDotEta(const double* x, const double* y, int j, double xi0, double xi1, double xi2,
                       double yi0, double yi1, double yi2, double& X0, double& X1, double& X2) {
  X0 = x[3 * j] - xi0;
  X1 = x[3 * j + 1] - xi1;
  X2 = x[3 * j + 2] - xi2;
  const double dot = mulAdd(X0, (y[3 * j] - yi0) - X0, 0.0);
  return mulAdd(X2, (y[3 * j + 2] - yi2) - X2, mulAdd(X1, (y[3 * j + 1] - yi1) - X1, dot));
}

// The pair scalar mu omega (t_i + t_j) V_j of bond entry b (to j) and its xi: paper 001 eq. 18
// as printed, mu twice on the dilatation term; an end whose horizon does not hold the bond
// (bond sides) exerts no t.
template <typename Options, bool kSmooth>
inline double pairScalar(const ForceRow& r, std::int64_t b, int j, double& X0, double& X1,
                         double& X2) {
  const double dot = xiDotEta(r.x, r.y, j, r.xi0, r.xi1, r.xi2, r.yi0, r.yi1, r.yi2, X0, X1, X2);
  const double eps = dot / (r.zeta[b] * r.zeta[b]);
  const double F = kSmooth ? r.law.forceScalar(eps) : eps;
  const double mu = Options::damage ? 1.0 - r.damage[b] : 1.0;
  double ti = mulAdd(r.alphaI, F, mu * r.betaThetaI);
  double tj = mulAdd(mu * r.beta[j], r.theta[j], r.alpha[j] * F);
  if constexpr (Options::sides) {
    ti *= r.sides[b] & 1;
    tj *= (r.sides[b] >> 1) & 1;
  }
  const double omega = Options::influence ? r.influence[b] : 1.0;
  return omega * mu * (ti + tj) * r.volume[j];
}

#ifdef PERIDOT_LLPS_LANES
// Four bonds at a time in 256-bit lanes, each lane the very operations of the scalar code above
// (so the same bits); the neighbours' values are loaded by hand: GCC's emulated gathers (this
// CPU has no fast gather) cost more than the scalar loop saved.

// Components 0, 1, 2 of p[3 j[l] ..] for the four points j[l]: two 2-double loads and a
// transpose, and four single loads (nothing past a point's three values is read).
inline void load3(const double* p, const int* j, __m256d c[3]) {
  const __m256d a = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p + 3 * j[0])),
                                         _mm_loadu_pd(p + 3 * j[2]), 1);
  const __m256d b = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p + 3 * j[1])),
                                         _mm_loadu_pd(p + 3 * j[3]), 1);
  c[0] = _mm256_unpacklo_pd(a, b);
  c[1] = _mm256_unpackhi_pd(a, b);
  c[2] = _mm256_set_pd(p[3 * j[3] + 2], p[3 * j[2] + 2], p[3 * j[1] + 2], p[3 * j[0] + 2]);
}

inline __m256d gather(const double* p, const int* j) {
  return _mm256_set_pd(p[j[3]], p[j[2]], p[j[1]], p[j[0]]);
}

// xiDotEta for the four bonds to j[0..3].
inline __m256d xiDotEta4(const double* x, const double* y, const int* j, const __m256d xi[3],
                         const __m256d yi[3], __m256d X[3]) {
  __m256d xj[3], yj[3];
  load3(x, j, xj);
  load3(y, j, yj);
  __m256d dot = _mm256_setzero_pd();
  for (int d = 0; d < 3; ++d) {
    X[d] = _mm256_sub_pd(xj[d], xi[d]);
    dot = _mm256_fmadd_pd(X[d], _mm256_sub_pd(_mm256_sub_pd(yj[d], yi[d]), X[d]), dot);
  }
  return dot;
}

// 1 - d of entries b .. b + 3.
inline __m256d intact4(const float* damage, std::int64_t b) {
  return _mm256_sub_pd(_mm256_set1_pd(1.0), _mm256_cvtps_pd(_mm_loadu_ps(damage + b)));
}

// BondLaw::forceScalar of a Smooth law, its branches as selects (the intervals are disjoint;
// outside them, and for NaN, 0).
inline __m256d smoothForceScalar(const BondLaw& law, __m256d s) {
  const __m256d s0m = _mm256_set1_pd(law.s0Minus), s0p = _mm256_set1_pd(law.s0Plus);
  const __m256d s1m = _mm256_set1_pd(law.s1Minus), s1p = _mm256_set1_pd(law.s1Plus);
  const __m256d inner =
      _mm256_and_pd(_mm256_cmp_pd(s, s0m, _CMP_GE_OQ), _mm256_cmp_pd(s, s0p, _CMP_LE_OQ));
  const __m256d rising =
      _mm256_and_pd(_mm256_cmp_pd(s, s0p, _CMP_GT_OQ), _mm256_cmp_pd(s, s1p, _CMP_LT_OQ));
  const __m256d falling =
      _mm256_and_pd(_mm256_cmp_pd(s, s1m, _CMP_GT_OQ), _mm256_cmp_pd(s, s0m, _CMP_LT_OQ));
  const __m256d tension = _mm256_div_pd(_mm256_mul_pd(s0p, _mm256_sub_pd(s1p, s)),
                                        _mm256_set1_pd(law.s1Plus - law.s0Plus));
  const __m256d compression = _mm256_div_pd(_mm256_mul_pd(s0m, _mm256_sub_pd(s, s1m)),
                                            _mm256_set1_pd(law.s0Minus - law.s1Minus));
  __m256d F = _mm256_and_pd(falling, compression);
  F = _mm256_blendv_pd(F, tension, rising);
  return _mm256_blendv_pd(F, s, inner);
}

// The side bit (0 or 1) of entries b .. b + 3 at `shift`, as doubles.
inline __m256d side4(const unsigned char* sides, std::int64_t b, int shift) {
  return _mm256_set_pd((sides[b + 3] >> shift) & 1, (sides[b + 2] >> shift) & 1,
                       (sides[b + 1] >> shift) & 1, (sides[b] >> shift) & 1);
}

// pairScalar for entries b .. b + 3 (to j[0..3]).
template <typename Options, bool kSmooth>
inline __m256d pairScalar4(const ForceRow& r, std::int64_t b, const int* j, const __m256d xi[3],
                           const __m256d yi[3], __m256d X[3]) {
  const __m256d dot = xiDotEta4(r.x, r.y, j, xi, yi, X);
  const __m256d z = _mm256_loadu_pd(r.zeta + b);
  const __m256d eps = _mm256_div_pd(dot, _mm256_mul_pd(z, z));
  __m256d F = eps;
  if constexpr (kSmooth) F = smoothForceScalar(r.law, eps);
  const __m256d alphaI = _mm256_set1_pd(r.alphaI), betaThetaI = _mm256_set1_pd(r.betaThetaI);
  const __m256d betaJ = gather(r.beta, j), thetaJ = gather(r.theta, j);
  const __m256d alphaJ = gather(r.alpha, j), volumeJ = gather(r.volume, j);
  __m256d ti, tj, weight;  // weight: omega mu (1 when neither)
  if constexpr (Options::damage) {
    const __m256d mu = intact4(r.damage, b);
    ti = _mm256_fmadd_pd(alphaI, F, _mm256_mul_pd(mu, betaThetaI));
    tj = _mm256_fmadd_pd(_mm256_mul_pd(mu, betaJ), thetaJ, _mm256_mul_pd(alphaJ, F));
    weight = Options::influence ? _mm256_mul_pd(_mm256_loadu_pd(r.influence + b), mu) : mu;
  } else {
    ti = _mm256_fmadd_pd(alphaI, F, betaThetaI);
    tj = _mm256_fmadd_pd(betaJ, thetaJ, _mm256_mul_pd(alphaJ, F));
    weight = Options::influence ? _mm256_loadu_pd(r.influence + b) : _mm256_set1_pd(1.0);
  }
  if constexpr (Options::sides) {
    ti = _mm256_mul_pd(ti, side4(r.sides, b, 0));
    tj = _mm256_mul_pd(tj, side4(r.sides, b, 1));
  }
  __m256d t = _mm256_add_pd(ti, tj);
  if constexpr (Options::influence || Options::damage) t = _mm256_mul_pd(weight, t);
  return _mm256_mul_pd(t, volumeJ);
}
#endif

template <typename Options, bool kGiven>
double dilatationSum(const DilatationInputs& in, int i, std::int64_t b0, std::int64_t b1,
                     const double* xiEta) {
  const int* neighbors = in.neighbors;
  const double *x = in.x, *y = in.y, *volume = in.volume;
  const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
  const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
  double sum = 0;
  std::int64_t b = b0;
#ifdef PERIDOT_LLPS_LANES
  const __m256d xi[3] = {_mm256_set1_pd(xi0), _mm256_set1_pd(xi1), _mm256_set1_pd(xi2)};
  const __m256d yi[3] = {_mm256_set1_pd(yi0), _mm256_set1_pd(yi1), _mm256_set1_pd(yi2)};
  for (; b + 4 <= b1; b += 4) {
    const int* j = neighbors + b;
    __m256d dot, X[3];
    if constexpr (kGiven)
      dot = _mm256_loadu_pd(xiEta + (b - b0));
    else
      dot = xiDotEta4(x, y, j, xi, yi, X);
    // omega mu xi.eta (omega, mu: 1 when absent, a product that changes nothing)
    if constexpr (Options::influence && Options::damage)
      dot = _mm256_mul_pd(_mm256_mul_pd(_mm256_loadu_pd(in.influence + b), intact4(in.damage, b)),
                          dot);
    else if constexpr (Options::influence)
      dot = _mm256_mul_pd(_mm256_loadu_pd(in.influence + b), dot);
    else if constexpr (Options::damage)
      dot = _mm256_mul_pd(intact4(in.damage, b), dot);
    alignas(32) double q[4];
    _mm256_store_pd(q, dot);
    // times V_j, in the list's order, over i's own horizon
    for (int l = 0; l < 4; ++l) {
      if (Options::sides && !(in.sides[b + l] & 1)) continue;
      sum = mulAdd(q[l], volume[j[l]], sum);
    }
  }
#endif
  for (; b < b1; ++b) {
    if (Options::sides && !(in.sides[b] & 1)) continue;
    const int j = neighbors[b];
    double dot;
    if constexpr (kGiven) {
      dot = xiEta[b - b0];
    } else {
      double X0, X1, X2;
      dot = xiDotEta(x, y, j, xi0, xi1, xi2, yi0, yi1, yi2, X0, X1, X2);
    }
    const double omega = Options::influence ? in.influence[b] : 1.0;
    const double mu = Options::damage ? 1.0 - in.damage[b] : 1.0;
    sum = mulAdd(omega * mu * dot, volume[j], sum);
  }
  return sum;
}

template <typename Options, bool kSmooth>
void forceLoop(const ModelState& s, const std::vector<int>& points, const double* theta,
               const double* alpha, const double* beta) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  ForceRow r;
  r.x = s.x;
  r.y = s.y;
  r.volume = s.volume;
  r.zeta = s.bondLength;
  r.influence = s.influence;
  r.theta = theta;
  r.alpha = alpha;
  r.beta = beta;
  r.damage = s.bondDamage;
  r.sides = s.bondSides;
  r.law = s.bondLaw;
  const double *x = s.x, *y = s.y;
  double* f = s.forceDensity;
  for (int i : points) {
    r.xi0 = x[3 * i], r.xi1 = x[3 * i + 1], r.xi2 = x[3 * i + 2];
    r.yi0 = y[3 * i], r.yi1 = y[3 * i + 1], r.yi2 = y[3 * i + 2];
    r.betaThetaI = beta[i] * theta[i];
    r.alphaI = alpha[i];
    double f0 = 0, f1 = 0, f2 = 0;
    std::int64_t b = offsets[i];
    const std::int64_t b1 = offsets[i + 1];
#ifdef PERIDOT_LLPS_LANES
    const __m256d xi[3] = {_mm256_set1_pd(r.xi0), _mm256_set1_pd(r.xi1), _mm256_set1_pd(r.xi2)};
    const __m256d yi[3] = {_mm256_set1_pd(r.yi0), _mm256_set1_pd(r.yi1), _mm256_set1_pd(r.yi2)};
    for (; b + 4 <= b1; b += 4) {
      __m256d X[3];
      const __m256d t = pairScalar4<Options, kSmooth>(r, b, neighbors + b, xi, yi, X);
      alignas(32) double tl[4], X0[4], X1[4], X2[4];
      _mm256_store_pd(tl, t);
      _mm256_store_pd(X0, X[0]);
      _mm256_store_pd(X1, X[1]);
      _mm256_store_pd(X2, X[2]);
      // the sum in the list's order
      for (int l = 0; l < 4; ++l) {
        f0 = mulAdd(tl[l], X0[l], f0);
        f1 = mulAdd(tl[l], X1[l], f1);
        f2 = mulAdd(tl[l], X2[l], f2);
      }
    }
#endif
    for (; b < b1; ++b) {
      double X0, X1, X2;
      const double t = pairScalar<Options, kSmooth>(r, b, neighbors[b], X0, X1, X2);
      f0 = mulAdd(t, X0, f0);
      f1 = mulAdd(t, X1, f1);
      f2 = mulAdd(t, X2, f2);
    }
    f[3 * i] = f0;
    f[3 * i + 1] = f1;
    f[3 * i + 2] = f2;
  }
}

}  // namespace

DilatationRow dilatationRow(const DilatationInputs& in, bool xiEtaGiven) {
  ModelState options;  // only the option pointers matter to withBondOptions
  options.influence = in.influence;
  options.bondDamage = in.damage;
  options.bondSides = in.sides;
  DilatationRow row = nullptr;
  withBondOptions(options, [&](auto o) {
    using Options = decltype(o);
    row = xiEtaGiven ? &dilatationSum<Options, true> : &dilatationSum<Options, false>;
  });
  return row;
}

void force(const ModelState& s, const std::vector<int>& points, const double* theta,
           const double* alpha, const double* beta) {
  const bool smooth = s.bondLaw.kind == BondLaw::Kind::Smooth;
  // (The run's damage is a float here: Linearized LPS takes no broken-bond flags.)
  withBondOptions(s, [&](auto o) {
    using Options = decltype(o);
    if (smooth)
      forceLoop<Options, true>(s, points, theta, alpha, beta);
    else
      forceLoop<Options, false>(s, points, theta, alpha, beta);
  });
}

}  // namespace peridot::llps
