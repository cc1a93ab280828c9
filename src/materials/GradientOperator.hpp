#pragma once
// The higher-order peridynamic gradient (the "PD differential operator" of Madenci, Barut and
// Futch, 2016, as Peridigm's hypoelastic and bond-associated correspondence models use it with
// "Gradient Order Of Accuracy"; theory in doc/theory/hypoelastic-correspondence.md).
//
// For a point i with bonds xi_b (to neighbours b, volumes V_b, influence w_b, damage included),
// the gradient of any field f at x_i is approximated by
//
//     grad f(x_i) ~ sum_b g_b (f_b - f_i) V_b,
//
// with one weight vector g_b per bond. The weights come from the moment (Gram) matrix of the
// monomials of degree 1..n of the scaled bond s = xi / delta,
//
//     Q(s) = (s_x, s_y, s_z, s_x^2, s_x s_y, ...),   M = sum_b w_b Q(s_b) Q(s_b)^T V_b,
//     g_b = w_b / delta * [M^-1 Q(s_b)]_{first three components}.
//
// Taylor's expansion f_b - f_i = Q(s_b) . a (a the derivatives times delta^k / k!) is exact for
// polynomials of degree <= n, and then sum_b w_b Q(s_b) (f_b - f_i) V_b = M a recovers a
// exactly: the operator reproduces the gradient of every polynomial of degree <= n, at any point
// whose moment matrix is regular (interior or not), with error O(delta^n) for smooth fields.
// Order 1 is the plain correspondence gradient K^-1 sum w xi (f_b - f_i) V_b.
//
// Planar runs (dimension 2) use the monomials of (s_x, s_y) only; g_z is then zero.
// All tensors and vectors as in materials/Correspondence.hpp (row-major, xyz).
#include <cstddef>
#include <vector>

namespace peridot {
namespace gradient {

// The largest order accepted (Q has 34 components in 3D at order 4).
constexpr int kMaxOrder = 4;

// Number of monomials of degrees 1..order in `dimension` (2 or 3) variables: 3, 9, 19, 34 in 3D;
// 2, 5, 9, 14 in 2D.
int basisSize(int order, int dimension);

// Weights of one point. Reuse one object across points: its scratch space is kept.
class Operator {
 public:
  Operator(int order, int dimension);
  int order() const { return order_; }
  int dimension() const { return dimension_; }

  // The weights g_b (3 per bond, written to g[3 b..3 b+2]) of a point with `count` bonds xi_b
  // (3 per bond, xi[3 b..]), influence w_b (damage included; 0 drops a bond) and neighbour
  // volumes V_b, horizon delta. Returns false, with g zero, when the moment matrix is singular
  // (too few bonds, or bonds that do not span the monomials: e.g. all coplanar in 3D); the
  // test is relative, pivot <= 1e-12 times the largest diagonal entry.
  bool weights(std::size_t count, const double* xi, const double* w, const double* volume,
               double delta, double* g);

  // The rows z_a = M^-1 e_a (a < dimension; basisSize values each, row-major) of the last
  // successful weights() call: g_b = w_b / delta (z_a . Q(s_b)). A caller that needs the weight
  // of a bond it did not pass (the reverse bond of a neighbour) keeps these.
  const double* rows() const { return rows_.data(); }
  int size() const { return size_; }

  // The monomials Q(xi / delta) of one bond (basisSize values).
  void monomials(const double* xi, double delta, double* q) const;

 private:
  int order_, dimension_, size_;
  // Exponents (px, py, pz) of each monomial, in the order of Q.
  std::vector<int> powers_;
  // Moment matrix, its Cholesky factor, the three rows of M^-1 that give the gradient, and one
  // bond's Q.
  std::vector<double> moment_, rows_, q_;
  bool factorAndSolve();
};

}  // namespace gradient
}  // namespace peridot
