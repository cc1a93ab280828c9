#include "neighbor/PartialVolume.hpp"

#include <algorithm>
#include <cmath>

namespace peridot {

double cellEdge(double volume, int dimension, double thickness) {
  return dimension == 2 ? std::sqrt(volume / thickness) : std::cbrt(volume);
}

double cellOverlapReach(double h, int dimension) { return 0.5 * std::sqrt(double(dimension)) * h; }

bool cellOverlapsHorizon(const double xi[3], double h, double horizon, int dimension) {
  double nearest2 = 0;
  for (int k = 0; k < dimension; ++k) {
    const double gap = std::max(std::fabs(xi[k]) - 0.5 * h, 0.0);
    nearest2 += gap * gap;
  }
  return nearest2 < horizon * horizon;
}

std::size_t CellFractionCache::Hash::operator()(const Key& k) const {
  std::size_t s = std::hash<double>()(k.h) ^ (std::hash<double>()(k.horizon) << 1);
  for (long long q : k.q) s = s * 1000003u ^ std::hash<long long>()(q);
  return s;
}

double CellFractionCache::fraction(const double xi[3], double h, double horizon, int dimension) {
  // Cells wholly inside or outside need no cache (most bonds; all of them could be unique on an
  // unstructured mesh, and the cache is bounded for the same reason).
  const double zeta0 = std::sqrt(xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]);
  const double reach = cellOverlapReach(h, dimension);
  if (zeta0 + reach <= horizon) return 1.0;
  if (zeta0 - reach >= horizon) return 0.0;
  constexpr double kSteps = 1048576.0;  // 2^20 per cell edge
  constexpr std::size_t kMaxEntries = 1 << 20;
  Key key{{0, 0, 0}, h, horizon};
  double rounded[3] = {0, 0, 0};
  for (int k = 0; k < dimension; ++k) {
    key.q[k] = std::llround(xi[k] / h * kSteps);
    rounded[k] = static_cast<double>(key.q[k]) / kSteps * h;
  }
  const auto found = cache_.find(key);
  if (found != cache_.end()) return found->second;
  const double zeta =
      std::sqrt(rounded[0] * rounded[0] + rounded[1] * rounded[1] + rounded[2] * rounded[2]);
  const double f = zeta > 0 ? cellFractionInHorizon(rounded, zeta, h, horizon, dimension) : 1.0;
  if (cache_.size() < kMaxEntries) cache_.emplace(key, f);
  return f;
}

namespace {

// Volume of {u in [0,1]^d : a.u <= T} for a_k > 0, by inclusion-exclusion over the corners:
// (1 / (d! prod a)) sum_S (-1)^|S| max(0, T - sum_{k in S} a_k)^d.
double unitCubeBelowPlane(const double* a, int d, double T) {
  double sum = 0;
  for (int mask = 0; mask < (1 << d); ++mask) {
    double v = T;
    int sign = 1;
    for (int k = 0; k < d; ++k)
      if (mask & (1 << k)) {
        v -= a[k];
        sign = -sign;
      }
    if (v > 0) sum += sign * (d == 3 ? v * v * v : d == 2 ? v * v : v);
  }
  double denominator = 1;
  for (int k = 0; k < d; ++k) denominator *= (k + 1) * a[k];
  return sum / denominator;
}

// The plane cut of one cell: coordinates u in [-1/2, 1/2]^d, inside when n.u <= t, n = xi / zeta.
double planeCut(const double xi[3], double zeta, double h, double horizon, int dimension) {
  const double t = (horizon - zeta) / h;
  // Components of n too small to tilt the plane within the cell drop out (that axis is fully
  // inside or out together with the rest): it keeps the closed form well conditioned.
  double a[3];
  int d = 0;
  double halfWidth = 0;
  for (int k = 0; k < dimension; ++k) {
    const double n = std::fabs(xi[k]) / zeta;
    if (n > 1e-9) {
      a[d++] = n;
      halfWidth += 0.5 * n;
    }
  }
  if (t >= halfWidth) return 1.0;
  if (t <= -halfWidth) return 0.0;
  // Shift to [0,1]^d: n.u <= t becomes a.(u + 1/2) <= t + sum(a)/2.
  return std::clamp(unitCubeBelowPlane(a, d, t + halfWidth), 0.0, 1.0);
}

}  // namespace

double cellFractionInHorizon(const double xi[3], double zeta, double h, double horizon,
                             int dimension) {
  const double reach = cellOverlapReach(h, dimension);
  if (zeta + reach <= horizon) return 1.0;
  if (zeta - reach >= horizon) return 0.0;
  // A cell the sphere crosses: its kSub^d sub-cells are each cut by their own tangent plane,
  // which divides the curvature error of one plane by kSub^2.
  constexpr int kSub = 4;
  const double hs = h / kSub;
  double sum = 0;
  int count = 0;
  for (int a = 0; a < kSub; ++a)
    for (int b = 0; b < kSub; ++b)
      for (int c = 0; c < (dimension == 3 ? kSub : 1); ++c) {
        const double x[3] = {xi[0] + ((a + 0.5) / kSub - 0.5) * h,
                             xi[1] + ((b + 0.5) / kSub - 0.5) * h,
                             dimension == 3 ? xi[2] + ((c + 0.5) / kSub - 0.5) * h : 0.0};
        const double z = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        sum += z > 0 ? planeCut(x, z, hs, horizon, dimension) : 1.0;
        ++count;
      }
  return sum / count;
}

}  // namespace peridot
