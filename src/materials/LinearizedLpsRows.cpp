// Compiled without floating-point contraction (CMakeLists.txt): the fused multiply-adds are
// written out (mulAdd) where the one-pass loops this replaces had them, so the bits stay theirs.
#include "materials/LinearizedLpsRows.hpp"

#include <cstddef>

#include "materials/BondOptions.hpp"
#include "materials/HalfLoop.hpp"

namespace peridot::llps {

namespace {

using half::mulAdd;

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

// The row buffers of the force loop (X, the pair scalar t), grown to the longest row seen.
struct ForceBuffers {
  std::vector<double> storage;
  double *X0 = nullptr, *X1 = nullptr, *X2 = nullptr, *t = nullptr;
  void reserve(std::int64_t m) {
    const auto n = static_cast<std::size_t>(m);
    if (storage.size() >= 4 * n && X0) return;
    storage.resize(4 * n);
    X0 = storage.data();
    X1 = X0 + n;
    X2 = X1 + n;
    t = X2 + n;
  }
};

template <typename Options, bool kGiven>
double dilatationSum(const DilatationInputs& in, int i, std::int64_t b0, std::int64_t b1,
                     const double* xiEta, double* q) {
  const int* neighbors = in.neighbors + b0;
  const double *x = in.x, *y = in.y;
  const double* influence = in.influence + (Options::influence ? b0 : 0);
  const float* damage = in.damage + (Options::damage ? b0 : 0);
  const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
  const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
  const int m = static_cast<int>(b1 - b0);
  // Vector pass: omega mu xi.eta of every entry (one-sided ones too: skipped below).
#pragma omp simd
  for (int k = 0; k < m; ++k) {
    double dot;
    if constexpr (kGiven) {
      dot = xiEta[k];
    } else {
      double X0, X1, X2;
      dot = xiDotEta(x, y, neighbors[k], xi0, xi1, xi2, yi0, yi1, yi2, X0, X1, X2);
    }
    double w = Options::influence ? influence[k] : 1.0;
    if constexpr (Options::damage) w *= 1.0 - damage[k];
    q[k] = w * dot;
  }
  // Scalar pass, in the list's order: times V_j, over i's own horizon.
  const double* volume = in.volume;
  const unsigned char* sides = in.sides + (Options::sides ? b0 : 0);
  double sum = 0;
  for (int k = 0; k < m; ++k) {
    if (Options::sides && !(sides[k] & 1)) continue;
    sum = mulAdd(q[k], volume[neighbors[k]], sum);
  }
  return sum;
}

template <typename Options, bool kSmooth>
void forceLoop(const ModelState& s, const std::vector<int>& points, const double* theta,
               const double* alpha, const double* beta) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double *x = s.x, *y = s.y, *volume = s.volume, *zeta = s.bondLength;
  const double* influence = s.influence;
  const float* damage = s.bondDamage;
  const unsigned char* sides = s.bondSides;
  const BondLaw law = s.bondLaw;
  double* f = s.forceDensity;
  thread_local ForceBuffers buffers;
  for (int i : points) {
    const std::int64_t b0 = offsets[i];
    const int m = static_cast<int>(offsets[i + 1] - b0);
    buffers.reserve(m);
    double *bufX0 = buffers.X0, *bufX1 = buffers.X1, *bufX2 = buffers.X2, *bufT = buffers.t;
    const int* nb = neighbors + b0;
    const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    const double betaThetaI = beta[i] * theta[i], alphaI = alpha[i];
    // Vector pass: the bond vector xi and the pair scalar mu omega (t_i + t_j) V_j.
#pragma omp simd
    for (int k = 0; k < m; ++k) {
      const std::int64_t b = b0 + k;
      const int j = nb[k];
      double X0, X1, X2;
      const double dot = xiDotEta(x, y, j, xi0, xi1, xi2, yi0, yi1, yi2, X0, X1, X2);
      const double eps = dot / (zeta[b] * zeta[b]);
      const double F = kSmooth ? law.forceScalar(eps) : eps;
      const double mu = Options::damage ? 1.0 - damage[b] : 1.0;
      // t_i<xi> + t_j<-xi> over |xi|: paper 001 eq. 18 as printed, mu twice on the dilatation
      // term.
      double ti = mulAdd(alphaI, F, mu * betaThetaI);
      double tj = mulAdd(mu * beta[j], theta[j], alpha[j] * F);
      if constexpr (Options::sides) {  // an end whose horizon does not hold the bond: no t
        ti *= sides[b] & 1;
        tj *= (sides[b] >> 1) & 1;
      }
      const double omega = Options::influence ? influence[b] : 1.0;
      bufX0[k] = X0;
      bufX1[k] = X1;
      bufX2[k] = X2;
      bufT[k] = omega * mu * (ti + tj) * volume[j];
    }
    // Scalar pass, in the list's order.
    double f0 = 0, f1 = 0, f2 = 0;
    for (int k = 0; k < m; ++k) {
      f0 = mulAdd(bufT[k], bufX0[k], f0);
      f1 = mulAdd(bufT[k], bufX1[k], f1);
      f2 = mulAdd(bufT[k], bufX2[k], f2);
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
