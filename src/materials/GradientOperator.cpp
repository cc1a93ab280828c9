#include "materials/GradientOperator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace peridot {
namespace gradient {

int basisSize(int order, int dimension) {
  int n = 0;
  for (int degree = 1; degree <= order; ++degree)
    n += dimension == 2 ? degree + 1 : (degree + 1) * (degree + 2) / 2;
  return n;
}

Operator::Operator(int order, int dimension)
    : order_(order), dimension_(dimension), size_(basisSize(order, dimension)) {
  if (order < 1 || order > kMaxOrder || (dimension != 2 && dimension != 3))
    throw std::invalid_argument("gradient::Operator: order 1..4, dimension 2 or 3");
  // Degree by degree, x power falling first: degree 1 is (x, y, z), so the gradient's rows are
  // the first `dimension` entries of Q.
  for (int degree = 1; degree <= order; ++degree)
    for (int px = degree; px >= 0; --px)
      for (int py = degree - px; py >= 0; --py) {
        const int pz = degree - px - py;
        if (dimension == 2 && pz > 0) continue;
        powers_.insert(powers_.end(), {px, py, pz});
      }
  moment_.resize(static_cast<std::size_t>(size_) * size_);
  rows_.resize(static_cast<std::size_t>(3) * size_);
  q_.resize(size_);
}

void Operator::monomials(const double* xi, double delta, double* q) const {
  const double s[3] = {xi[0] / delta, xi[1] / delta, xi[2] / delta};
  for (int k = 0; k < size_; ++k) {
    double value = 1.0;
    for (int d = 0; d < 3; ++d)
      for (int p = 0; p < powers_[3 * k + d]; ++p) value *= s[d];
    q[k] = value;
  }
}

// Cholesky factor M = L L^T in place (lower triangle), then rows_[a] = M^-1 e_a for the first
// `dimension_` unit vectors (M is symmetric: they are the rows of M^-1 as well).
bool Operator::factorAndSolve() {
  const int n = size_;
  double* A = moment_.data();
  double largest = 0;
  for (int k = 0; k < n; ++k) largest = std::max(largest, A[n * k + k]);
  if (!(largest > 0)) return false;
  for (int c = 0; c < n; ++c) {
    double pivot = A[n * c + c];
    for (int k = 0; k < c; ++k) pivot -= A[n * c + k] * A[n * c + k];
    if (!(pivot > 1e-12 * largest)) return false;
    const double root = std::sqrt(pivot);
    A[n * c + c] = root;
    for (int r = c + 1; r < n; ++r) {
      double sum = A[n * r + c];
      for (int k = 0; k < c; ++k) sum -= A[n * r + k] * A[n * c + k];
      A[n * r + c] = sum / root;
    }
  }
  for (int a = 0; a < dimension_; ++a) {
    double* z = rows_.data() + static_cast<std::size_t>(n) * a;
    for (int r = 0; r < n; ++r) {  // L u = e_a
      double sum = r == a ? 1.0 : 0.0;
      for (int k = 0; k < r; ++k) sum -= A[n * r + k] * z[k];
      z[r] = sum / A[n * r + r];
    }
    for (int r = n - 1; r >= 0; --r) {  // L^T z = u
      double sum = z[r];
      for (int k = r + 1; k < n; ++k) sum -= A[n * k + r] * z[k];
      z[r] = sum / A[n * r + r];
    }
  }
  return true;
}

bool Operator::weights(std::size_t count, const double* xi, const double* w, const double* volume,
                       double delta, double* g) {
  const int n = size_;
  std::fill(moment_.begin(), moment_.end(), 0.0);
  double* q = q_.data();
  for (std::size_t b = 0; b < count; ++b) {
    const double weight = w[b] * volume[b];
    if (weight == 0.0) continue;
    monomials(xi + 3 * b, delta, q);
    for (int r = 0; r < n; ++r) {
      const double wr = weight * q[r];
      for (int c = 0; c <= r; ++c) moment_[n * r + c] += wr * q[c];
    }
  }
  for (int r = 0; r < n; ++r)
    for (int c = r + 1; c < n; ++c) moment_[n * r + c] = moment_[n * c + r];
  if (!factorAndSolve()) {
    std::fill(g, g + 3 * count, 0.0);
    return false;
  }
  for (std::size_t b = 0; b < count; ++b) {
    double* gb = g + 3 * b;
    gb[0] = gb[1] = gb[2] = 0.0;
    if (w[b] == 0.0) continue;
    monomials(xi + 3 * b, delta, q);
    const double scale = w[b] / delta;
    for (int a = 0; a < dimension_; ++a) {
      const double* z = rows_.data() + static_cast<std::size_t>(n) * a;
      double sum = 0;
      for (int k = 0; k < n; ++k) sum += z[k] * q[k];
      gb[a] = scale * sum;
    }
  }
  return true;
}

}  // namespace gradient
}  // namespace peridot
