#include "solvers/VerletLimit.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "evaluator/ModelEvaluator.hpp"
#include "parallel/ExactSum.hpp"

namespace peridot {

namespace {

// A deterministic start vector: a hash of the global id and component, the same on any rank count.
double startValue(long long globalId, int d) {
  std::uint64_t z = static_cast<std::uint64_t>(globalId) * 3u + static_cast<std::uint64_t>(d) +
                    0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53 * 2.0 - 1.0;
}

// Number of eigenvalues of the tridiagonal matrix below x (Sturm sequence count).
int countBelow(const double* alpha, const double* beta, int n, double x) {
  int count = 0;
  double q = 1.0;
  for (int k = 0; k < n; ++k) {
    const double b2 = k > 0 ? beta[k - 1] * beta[k - 1] : 0.0;
    q = alpha[k] - x - (k > 0 ? b2 / q : 0.0);
    if (q == 0.0) q = 1e-300;
    if (q < 0) ++count;
  }
  return count;
}

// Norm of the last component of the unit eigenvector of T for eigenvalue theta (inverse
// iteration with a shift just above theta; the Thomas algorithm without pivoting is enough
// for the few steps needed).
double lastEigenvectorComponent(const double* alpha, const double* beta, int n, double theta) {
  const double shift = theta + 1e-10 * std::max(1.0, std::fabs(theta));
  std::vector<double> s(n, 1.0), c(n), d(n);
  for (int iteration = 0; iteration < 3; ++iteration) {
    // Solve (T - shift I) z = s.
    for (int k = 0; k < n; ++k) {
      const double diag = alpha[k] - shift - (k > 0 ? beta[k - 1] * c[k - 1] : 0.0);
      const double pivot = diag == 0.0 ? 1e-300 : diag;
      c[k] = k + 1 < n ? beta[k] / pivot : 0.0;
      d[k] = (s[k] - (k > 0 ? beta[k - 1] * d[k - 1] : 0.0)) / pivot;
    }
    for (int k = n - 2; k >= 0; --k) d[k] -= c[k] * d[k + 1];
    double norm = 0;
    for (double v : d) norm += v * v;
    norm = std::sqrt(norm);
    if (!(norm > 0) || !std::isfinite(norm)) return 1.0;  // unknown: the full bound
    for (int k = 0; k < n; ++k) s[k] = d[k] / norm;
  }
  return std::fabs(s[n - 1]);
}

}  // namespace

double largestTridiagonalEigenvalue(const double* alpha, const double* beta, int n) {
  // Gershgorin interval, then bisection for the point below which all n eigenvalues lie.
  double lo = alpha[0], hi = alpha[0];
  for (int k = 0; k < n; ++k) {
    const double r =
        (k > 0 ? std::fabs(beta[k - 1]) : 0.0) + (k + 1 < n ? std::fabs(beta[k]) : 0.0);
    lo = std::min(lo, alpha[k] - r);
    hi = std::max(hi, alpha[k] + r);
  }
  for (int iteration = 0;
       iteration < 200 && hi - lo > 1e-15 * std::max(std::fabs(lo), std::fabs(hi)); ++iteration) {
    const double mid = 0.5 * (lo + hi);
    if (countBelow(alpha, beta, n, mid) >= n)
      hi = mid;
    else
      lo = mid;
  }
  return hi;
}

VerletLimitResult estimateVerletLimit(
    const Topology& t, const double* density, const double* volume, int dimension,
    const std::function<void(const double*, double*)>& applyStiffness, int maxIterations,
    double tolerance) {
  const int n = t.numOwned;
  const int n3 = 3 * n;
  const long long count = 3 * t.globalNumPoints;
  std::vector<double> mass(n);
  for (int i = 0; i < n; ++i) mass[i] = density[i] * volume[i];
  std::vector<double> terms(n);
  auto dot = [&](const std::vector<double>& u, const std::vector<double>& w) {
    for (int i = 0; i < n; ++i) {
      double s = 0;
      for (int d = 0; d < 3; ++d) s += u[3 * i + d] * w[3 * i + d];
      terms[i] = mass[i] * s;
    }
    return exactSum(terms, count, t.comm);
  };
  auto planar = [&](std::vector<double>& v) {
    if (dimension == 2)
      for (int i = 0; i < n; ++i) v[3 * i + 2] = 0.0;
  };

  std::vector<double> q(n3), previous(n3, 0.0), w(n3), kq(n3);
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) q[3 * i + d] = startValue(t.overlapGlobalId[i], d);
  planar(q);
  {
    const double norm = std::sqrt(dot(q, q));
    for (double& v : q) v /= norm;
  }
  std::vector<double> alpha, beta;
  VerletLimitResult result;
  double lastTheta = 0;
  int steady = 0;
  for (int j = 0; j < maxIterations; ++j) {
    applyStiffness(q.data(), kq.data());
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) w[3 * i + d] = kq[3 * i + d] / density[i];
    planar(w);
    if (j > 0)
      for (int k = 0; k < n3; ++k) w[k] -= beta.back() * previous[k];
    const double a = dot(w, q);
    alpha.push_back(a);
    for (int k = 0; k < n3; ++k) w[k] -= a * q[k];
    const double b = std::sqrt(std::max(0.0, dot(w, w)));
    const int m = static_cast<int>(alpha.size());
    const double theta = largestTridiagonalEigenvalue(alpha.data(), beta.data(), m);
    const double residual = b * lastEigenvectorComponent(alpha.data(), beta.data(), m, theta);
    result.lambdaMax = theta;
    result.residual = residual;
    result.iterations = j + 1;
    steady = std::fabs(theta - lastTheta) <= tolerance * theta ? steady + 1 : 0;
    lastTheta = theta;
    if (residual <= 1e-5 * theta || steady >= 20 || !(b > 0)) {
      result.converged = true;
      break;
    }
    beta.push_back(b);
    previous.swap(q);
    for (int k = 0; k < n3; ++k) q[k] = w[k] / b;
  }
  // An eigenvalue lies within the residual of the Ritz value; taking the top of that interval
  // keeps the step on the safe side of the limit when the iteration stopped early.
  const double lambda = result.lambdaMax + std::min(result.residual, result.lambdaMax);
  result.stableStep = lambda > 0 ? 2.0 / std::sqrt(lambda) : 0.0;
  return result;
}

VerletLimitResult estimateVerletLimitAbout(const Topology& t, ModelEvaluator& evaluator,
                                           const double* base, double* y, double* f,
                                           const double* density, const double* volume,
                                           int dimension) {
  const int n3 = 3 * t.numOwned;
  double smallestHorizon = t.numOwned > 0 ? t.horizon[0] : 1e300;
  for (int i = 0; i < t.numOwned; ++i) smallestHorizon = std::min(smallestHorizon, t.horizon[i]);
  MPI_Allreduce(MPI_IN_PLACE, &smallestHorizon, 1, MPI_DOUBLE, MPI_MIN, t.comm);
  const std::vector<double> savedY(y, y + 3 * t.numOverlap);
  const std::vector<double> savedF(f, f + n3);
  std::vector<double> plus(n3);
  auto applyStiffness = [&](const double* v, double* kv) {
    double largest = 0;
    for (int k = 0; k < n3; ++k) largest = std::max(largest, std::fabs(v[k]));
    MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, t.comm);
    const double eps = largest > 0 ? 1e-6 * smallestHorizon / largest : 0.0;
    for (int k = 0; k < n3; ++k) y[k] = base[k] + eps * v[k];
    evaluator.evaluate(0.0, false, false);  // a trial: no bond breaks, no history moves
    std::copy(f, f + n3, plus.begin());
    for (int k = 0; k < n3; ++k) y[k] = base[k] - eps * v[k];
    evaluator.evaluate(0.0, false, false);  // a trial: no bond breaks, no history moves
    for (int k = 0; k < n3; ++k) kv[k] = eps > 0 ? -(plus[k] - f[k]) / (2.0 * eps) : 0.0;
  };
  const VerletLimitResult r = estimateVerletLimit(t, density, volume, dimension, applyStiffness);
  std::copy(savedY.begin(), savedY.end(), y);
  std::copy(savedF.begin(), savedF.end(), f);
  return r;
}

}  // namespace peridot
