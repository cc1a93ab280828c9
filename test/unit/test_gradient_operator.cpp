// The higher-order peridynamic gradient (materials/GradientOperator.hpp) on its own: exact
// gradients of polynomials up to the order (interior and one-sided neighbourhoods), a singular
// neighbourhood reported, and the error's rate with the spacing at fixed horizon / spacing.
// Golds are the analytic gradients of the fields.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "materials/GradientOperator.hpp"

namespace peridot {
namespace {

using Field = std::function<double(const double*)>;
using Gradient = std::function<void(const double*, double*)>;

// The bonds of the point at `centre` on the lattice of spacing h, points (i, j, k) h for
// 0 <= i, j, k < n (k = 0 only in 2D), within the horizon delta.
struct Family {
  std::vector<double> xi, w, volume;
  std::array<double, 3> centre;
};

Family family(const std::array<int, 3>& at, int n, double h, double delta, int dimension) {
  Family f;
  for (int d = 0; d < 3; ++d) f.centre[d] = at[d] * h;
  const int nz = dimension == 2 ? 1 : n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < nz; ++k) {
        const double e[3] = {(i - at[0]) * h, (j - at[1]) * h, (k - at[2]) * h};
        const double r = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        if (r == 0 || r > delta) continue;
        f.xi.insert(f.xi.end(), e, e + 3);
        f.w.push_back(1.0);
        f.volume.push_back(dimension == 2 ? h * h : h * h * h);
      }
  return f;
}

// max_a |sum_b g_b (f_b - f_i) V_b - grad f|_a
double error(gradient::Operator& op, const Family& fam, double delta, const Field& f,
             const Gradient& grad) {
  const std::size_t count = fam.w.size();
  std::vector<double> g(3 * count);
  EXPECT_TRUE(op.weights(count, fam.xi.data(), fam.w.data(), fam.volume.data(), delta, g.data()));
  const double fi = f(fam.centre.data());
  double approx[3] = {0, 0, 0};
  for (std::size_t b = 0; b < count; ++b) {
    const double x[3] = {fam.centre[0] + fam.xi[3 * b], fam.centre[1] + fam.xi[3 * b + 1],
                         fam.centre[2] + fam.xi[3 * b + 2]};
    const double df = f(x) - fi;
    for (int a = 0; a < 3; ++a) approx[a] += g[3 * b + a] * df * fam.volume[b];
  }
  double exact[3];
  grad(fam.centre.data(), exact);
  double worst = 0;
  for (int a = 0; a < 3; ++a) worst = std::max(worst, std::abs(approx[a] - exact[a]));
  return worst;
}

const Field kLinear = [](const double* x) { return 0.3 + 1.7 * x[0] - 0.4 * x[1] + 2.1 * x[2]; };
const Gradient kLinearGradient = [](const double*, double* g) {
  g[0] = 1.7, g[1] = -0.4, g[2] = 2.1;
};
const Field kQuadratic = [](const double* x) {
  return 0.5 + x[0] - 2 * x[1] + 0.7 * x[0] * x[0] - 1.3 * x[0] * x[1] + 0.9 * x[1] * x[2] +
         0.4 * x[2] * x[2] - 0.8 * x[0] * x[2] + 0.2 * x[1] * x[1];
};
const Gradient kQuadraticGradient = [](const double* x, double* g) {
  g[0] = 1 + 1.4 * x[0] - 1.3 * x[1] - 0.8 * x[2];
  g[1] = -2 - 1.3 * x[0] + 0.9 * x[2] + 0.4 * x[1];
  g[2] = 0.9 * x[1] + 0.8 * x[2] - 0.8 * x[0];
};

TEST(GradientOperator, BasisSizes) {
  EXPECT_EQ(gradient::basisSize(1, 3), 3);
  EXPECT_EQ(gradient::basisSize(2, 3), 9);
  EXPECT_EQ(gradient::basisSize(3, 3), 19);
  EXPECT_EQ(gradient::basisSize(2, 2), 5);
  EXPECT_THROW(gradient::Operator(0, 3), std::invalid_argument);
}

// Order 1 is exact for linear fields, order 2 for quadratic ones, at an interior point and at a
// corner (a one-sided family); order 1 is not exact for the quadratic at the corner.
TEST(GradientOperator, ExactForPolynomialsUpToTheOrder) {
  const double h = 0.1, delta = 3.015 * h;
  for (auto at : {std::array<int, 3>{4, 4, 4}, std::array<int, 3>{0, 0, 0}}) {
    const Family fam = family(at, 9, h, delta, 3);
    gradient::Operator first(1, 3), second(2, 3);
    EXPECT_LT(error(first, fam, delta, kLinear, kLinearGradient), 1e-12);
    EXPECT_LT(error(second, fam, delta, kLinear, kLinearGradient), 1e-11);
    EXPECT_LT(error(second, fam, delta, kQuadratic, kQuadraticGradient), 1e-11);
    if (at[0] == 0) {
      EXPECT_GT(error(first, fam, delta, kQuadratic, kQuadraticGradient), 1e-2);
    }
  }
  // Planar: the monomials of (x, y).
  const Family plane = family({0, 3, 0}, 9, h, delta, 2);
  const Field planar = [](const double* x) { return 1 + x[0] * x[0] - 3 * x[0] * x[1]; };
  const Gradient planarGradient = [](const double* x, double* g) {
    g[0] = 2 * x[0] - 3 * x[1], g[1] = -3 * x[0], g[2] = 0;
  };
  gradient::Operator planarOp(2, 2);
  EXPECT_LT(error(planarOp, plane, delta, planar, planarGradient), 1e-11);
}

// All bonds on one line: the moment matrix is singular; weights false and zero, never a NaN.
TEST(GradientOperator, SingularNeighbourhoodIsReported) {
  std::vector<double> xi = {1, 0, 0, -1, 0, 0, 2, 0, 0}, w = {1, 1, 1}, v = {1, 1, 1};
  std::vector<double> g(9, 7.0);
  gradient::Operator op(1, 3);
  EXPECT_FALSE(op.weights(3, xi.data(), w.data(), v.data(), 2.5, g.data()));
  for (double x : g) EXPECT_EQ(x, 0.0);
}

// A smooth field at a corner point, horizon fixed at 3 spacings: the error falls as h^order
// (first order for order 1, second for order 2) when the spacing is halved.
TEST(GradientOperator, ErrorFallsAtTheOrderOfAccuracy) {
  const Field f = [](const double* x) {
    return std::sin(x[0]) * std::cos(2 * x[1]) * std::exp(x[2]);
  };
  const Gradient grad = [](const double* x, double* g) {
    g[0] = std::cos(x[0]) * std::cos(2 * x[1]) * std::exp(x[2]);
    g[1] = -2 * std::sin(x[0]) * std::sin(2 * x[1]) * std::exp(x[2]);
    g[2] = std::sin(x[0]) * std::cos(2 * x[1]) * std::exp(x[2]);
  };
  for (int order : {1, 2}) {
    double errors[2];
    int k = 0;
    for (double h : {0.02, 0.01}) {
      const double delta = 3.015 * h;
      // The corner point (0.3, 0.3, 0.3) of the block [0.3, 0.3 + 8h]^3.
      Family fam = family({0, 0, 0}, 9, h, delta, 3);
      for (int d = 0; d < 3; ++d) fam.centre[d] = 0.3;
      gradient::Operator op(order, 3);
      errors[k++] = error(op, fam, delta, f, grad);
    }
    const double rate = std::log(errors[0] / errors[1]) / std::log(2.0);
    std::printf("  gradient order %d at a corner: error %.3e -> %.3e, rate %.2f\n", order,
                errors[0], errors[1], rate);
    EXPECT_NEAR(rate, order, 0.25);
  }
}

}  // namespace
}  // namespace peridot
