// "Gradient Order Of Accuracy" above 1 for the bond-associated correspondence models: Peridigm's
// Lagrangian higher-order gradient weights (materials/GradientOperator.hpp on the reference bonds)
// give every point's F and Fdot, and the force's S_i phi_ij. Golds are independent of the model:
// closed forms of the point and bond stresses under a displacement field u = grad(potential)
// (symmetric displacement gradient, hence no rotation: one rate-form step from rest gives
// sigma = lambda tr(L) I + 2 mu L, L = H (I + H)^-1 for y = x + u, v = u over dt = 1), the
// hypoelastic recursion of a symmetric homogeneous stretch, zero stress under a rigid spin, and
// the first-order model's force where the two orders' weights coincide.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "Materials.hpp"
#include "SerialProblem.hpp"
#include "core/Error.hpp"
#include "materials/BondAssociatedCorrespondence.hpp"
#include "materials/Correspondence.hpp"

namespace peridot {
namespace {

using testing::Problem;
using Model = BondAssociatedCorrespondence;

const double kK = 2.0, kG = 1.0;
const double kLambda = kK - 2.0 * kG / 3.0;

std::shared_ptr<MaterialModel> elastic(int order) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic Bond Associated Correspondence");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", kK);
  p.set("Shear Modulus", kG);
  p.set("Gradient Order Of Accuracy", order);
  ListReader r(p, "Materials -> M");
  return createMaterial(r);
}

// lambda tr(L) I + 2 mu L with L = H (I + H)^-1: the stress of one rate-form step (dt = 1) from
// rest to y = x + u, v = u, when H = grad u is symmetric (then L is symmetric and R stays I).
void oneStepStress(const double* H, double* sigma) {
  double F[9], Finv[9], L[9];
  for (int k = 0; k < 9; ++k) F[k] = (k % 4 == 0 ? 1.0 : 0.0) + H[k];
  correspondence::invert(F, Finv);
  correspondence::multiply(H, Finv, L);
  const double tr = L[0] + L[4] + L[8];
  for (int k = 0; k < 9; ++k) sigma[k] = 2 * kG * L[k] + (k % 4 == 0 ? kLambda * tr : 0.0);
}

double maxAbs(const double* a, int n = 9) {
  double m = 0;
  for (int k = 0; k < n; ++k) m = std::max(m, std::abs(a[k]));
  return m;
}

double maxDifference(const double* a, const double* b) {
  double m = 0;
  for (int k = 0; k < 9; ++k) m = std::max(m, std::abs(a[k] - b[k]));
  return m;
}

// A polynomial displacement u = grad(phi) about the lattice centre c,
//   phi = c2 (x^2 y + y^2 z + z^2 x + x y z) + c3 (x^3 y + y^3 z + z^3 x),
// of degree 2 (c3 = 0) or 3, with its (symmetric) gradient H.
struct PotentialField {
  double c2, c3, centre;
  void displacement(const double* X, double* u) const {
    const double x = X[0] - centre, y = X[1] - centre, z = X[2] - centre;
    u[0] = c2 * (2 * x * y + z * z + y * z) + c3 * (3 * x * x * y + z * z * z);
    u[1] = c2 * (x * x + 2 * y * z + x * z) + c3 * (x * x * x + 3 * y * y * z);
    u[2] = c2 * (y * y + 2 * z * x + x * y) + c3 * (y * y * y + 3 * z * z * x);
  }
  void gradient(const double* X, double* H) const {
    const double x = X[0] - centre, y = X[1] - centre, z = X[2] - centre;
    H[0] = c2 * 2 * y + c3 * 6 * x * y;
    H[4] = c2 * 2 * z + c3 * 6 * y * z;
    H[8] = c2 * 2 * x + c3 * 6 * z * x;
    H[1] = H[3] = c2 * (2 * x + z) + c3 * 3 * x * x;
    H[2] = H[6] = c2 * (2 * z + y) + c3 * 3 * z * z;
    H[5] = H[7] = c2 * (2 * y + x) + c3 * 3 * y * y;
  }
};

// Sets y = x + u, v = u at every point and evaluates one step of dt = 1.
void deformBy(Problem& pr, const std::function<void(const double*, double*)>& field) {
  double* y = pr.fields->node("Coordinates", 3);
  double* v = pr.fields->node("Velocity", 3);
  const double* x = pr.fields->node("Model_Coordinates", 3);
  for (int p = 0; p < pr.topology.numOverlap; ++p) {
    double u[3];
    field(x + 3 * p, u);
    for (int c = 0; c < 3; ++c) {
      y[3 * p + c] = x[3 * p + c] + u[c];
      v[3 * p + c] = u[c];
    }
  }
  pr.evaluator->evaluate(1.0);
}

// True when point p of an n^3 unit lattice has a complete (point-symmetric) family of radius
// `reach` (every coordinate at least floor(reach) from the faces).
bool inside(const double* X, int n, double reach) {
  for (int c = 0; c < 3; ++c)
    if (X[c] < std::floor(reach) || X[c] > n - 1 - std::floor(reach)) return false;
  return true;
}

struct FieldErrors {
  double pointInterior = 0, pointSurface = 0, gradientInterior = 0, gradientSurface = 0, bond = 0,
         scale = 0;
};

// The errors of every point's F (absolute: F is I + H, of order 1) and Cauchy stress and of
// every bond's unrotated stress (gold at the bond's midpoint) under the potential field, the
// stresses relative to the largest gold stress.
FieldErrors polynomialFieldErrors(int order, double horizon, const PotentialField& field, int n) {
  Problem pr(testing::cubicLattice(n), horizon, elastic(order));
  deformBy(pr, [&](const double* X, double* u) { field.displacement(X, u); });
  const double* x = pr.fields->node("Model_Coordinates", 3);
  const double* F = pr.fields->node(Model::kDeformationGradient, 9);
  const double* sigma = pr.fields->node(Model::kCauchyStress, 9);
  std::vector<const std::vector<double>*> bond(9);
  for (int k = 0; k < 9; ++k) bond[k] = &pr.fields->bond(Model::kBondUnrotatedCauchyStress[k]);
  FieldErrors e;
  for (int i = 0; i < pr.topology.numOwned; ++i) {
    double H[9], gold[9], Fgold[9];
    field.gradient(x + 3 * i, H);
    oneStepStress(H, gold);
    for (int k = 0; k < 9; ++k) Fgold[k] = (k % 4 == 0 ? 1.0 : 0.0) + H[k];
    e.scale = std::max(e.scale, maxAbs(gold));
    const bool interior = inside(x + 3 * i, n, horizon);
    const double dPoint = maxDifference(sigma + 9 * i, gold);
    const double dGradient = maxDifference(F + 9 * i, Fgold);
    (interior ? e.pointInterior : e.pointSurface) =
        std::max(interior ? e.pointInterior : e.pointSurface, dPoint);
    (interior ? e.gradientInterior : e.gradientSurface) =
        std::max(interior ? e.gradientInterior : e.gradientSurface, dGradient);
    for (std::int64_t b = pr.topology.bondOffsets[i]; b < pr.topology.bondOffsets[i + 1]; ++b) {
      const int j = pr.topology.neighbors[b];
      const double mid[3] = {0.5 * (x[3 * i] + x[3 * j]), 0.5 * (x[3 * i + 1] + x[3 * j + 1]),
                             0.5 * (x[3 * i + 2] + x[3 * j + 2])};
      double Hb[9], bondGold[9], bondSigma[9];
      field.gradient(mid, Hb);
      oneStepStress(Hb, bondGold);
      for (int k = 0; k < 9; ++k) bondSigma[k] = (*bond[k])[b];
      e.bond = std::max(e.bond, maxDifference(bondSigma, bondGold));
    }
  }
  e.pointInterior /= e.scale;
  e.pointSurface /= e.scale;
  e.bond /= e.scale;
  return e;
}

// A quadratic displacement's gradient is exact at every point with order 2, surface and corners
// included; so is every bond's F_b (the mean of its ends' F corrected along the bond is the
// exact F at the bond's midpoint when F is linear), hence every point and bond stress. Order 1
// is exact only where the family is point-symmetric.
TEST(BondAssociatedGradientOrder, QuadraticFieldIsExactAtEveryPointAndBondWithOrderTwo) {
  const PotentialField quadratic{1e-4, 0.0, 4.0};
  const FieldErrors first = polynomialFieldErrors(1, 2.015, quadratic, 9);
  const FieldErrors second = polynomialFieldErrors(2, 2.015, quadratic, 9);
  for (const auto& [name, e] : {std::pair<const char*, FieldErrors>{"order 1", first},
                                std::pair<const char*, FieldErrors>{"order 2", second}})
    std::printf(
        "  quadratic u (|H| <= 1.2e-3), %s: |F - gold| interior %.2e, surface %.2e; |sigma - gold| "
        "/ "
        "|sigma| points interior %.2e, surface %.2e, bonds %.2e\n",
        name, e.gradientInterior, e.gradientSurface, e.pointInterior, e.pointSurface, e.bond);
  // F to rounding (F ~ 1; a corner's moment matrix amplifies the rounding of its sums by its
  // condition number: a few ulps of 1).
  EXPECT_LT(second.gradientInterior, 1e-14);
  EXPECT_LT(second.gradientSurface, 1e-14);
  EXPECT_LT(second.pointInterior, 1e-12);
  EXPECT_LT(second.pointSurface, 1e-12);
  EXPECT_LT(second.bond, 1e-12);
  // Order 1: exact inside, not at the surface (an error of the order of delta times the
  // second derivatives of u, 2e-4 here).
  EXPECT_LT(first.gradientInterior, 1e-14);
  EXPECT_LT(first.pointInterior, 1e-12);
  EXPECT_GT(first.gradientSurface, 1e-5);
  EXPECT_GT(first.pointSurface, 1e-2);
}

// Order 3 reproduces the gradient of a cubic displacement at every point (a larger horizon:
// a corner's family must fit the 19 monomials); order 2 does not, at the surface.
TEST(BondAssociatedGradientOrder, CubicFieldIsExactAtEveryPointWithOrderThree) {
  const PotentialField cubic{1e-4, 1e-5, 4.0};
  const FieldErrors second = polynomialFieldErrors(2, 3.015, cubic, 9);
  const FieldErrors third = polynomialFieldErrors(3, 3.015, cubic, 9);
  for (const auto& [name, e] : {std::pair<const char*, FieldErrors>{"order 2", second},
                                std::pair<const char*, FieldErrors>{"order 3", third}})
    std::printf(
        "  cubic u (|H| <= 2.2e-3), %s: |F - gold| interior %.2e, surface %.2e; |sigma - gold| / "
        "|sigma| "
        "interior %.2e, surface %.2e\n",
        name, e.gradientInterior, e.gradientSurface, e.pointInterior, e.pointSurface);
  EXPECT_LT(third.gradientInterior, 1e-14);
  EXPECT_LT(third.gradientSurface, 1e-14);
  EXPECT_LT(third.pointSurface, 1e-11);
  EXPECT_GT(second.gradientSurface, 1e-5);
}

// A symmetric homogeneous stretch F = I + t E (no rotation: L = E (I + t E)^-1 is symmetric and
// commutes with V): every point and every bond, surface and corners included, carries the
// hypoelastic recursion sigma += dt (lambda tr L I + 2 mu L) to rounding, at orders 1 and 2
// (the first-order gradient is exact for affine fields too); the centre's force is zero.
TEST(BondAssociatedGradientOrder, HomogeneousStretchGivesTheRecursionAtEveryPointAndBond) {
  const double E[9] = {0.04, 0.01, 0.0, 0.01, -0.02, 0.015, 0.0, 0.015, 0.03};
  const int steps = 20, n = 9;
  const double dt = 1.0 / steps;
  const long long centre = 4 * n * n + 4 * n + 4;
  for (int order : {1, 2}) {
    Problem pr(testing::cubicLattice(n), 2.015, elastic(order));
    double hand[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    double worst = 0, worstForce = 0;
    for (int step = 1; step <= steps; ++step) {
      const double t = step * dt;
      double F[9], Finv[9], L[9];
      for (int k = 0; k < 9; ++k) F[k] = (k % 4 == 0 ? 1.0 : 0.0) + t * E[k];
      correspondence::invert(F, Finv);
      correspondence::multiply(E, Finv, L);
      const double tr = L[0] + L[4] + L[8];
      for (int k = 0; k < 9; ++k) hand[k] += dt * (2 * kG * L[k] + (k % 4 == 0 ? kLambda * tr : 0));
      pr.evaluateAffine(F, E, dt);
      const double* sigma = pr.fields->node(Model::kCauchyStress, 9);
      for (int i = 0; i < pr.topology.numOwned; ++i) {
        worst = std::max(worst, maxDifference(sigma + 9 * i, hand));
        for (std::int64_t b = pr.topology.bondOffsets[i]; b < pr.topology.bondOffsets[i + 1]; ++b) {
          double s[9];
          for (int k = 0; k < 9; ++k)
            s[k] = pr.fields->bond(Model::kBondUnrotatedCauchyStress[k])[b];
          worst = std::max(worst, maxDifference(s, hand));
        }
      }
      worstForce = std::max(worstForce, maxAbs(pr.force(centre), 3));
    }
    std::printf(
        "  homogeneous stretch, order %d: max |sigma - recursion| / |sigma| over all points and "
        "bonds %.2e, max |f_centre| / K %.2e\n",
        order, worst / maxAbs(hand), worstForce / kK);
    EXPECT_LT(worst / maxAbs(hand), 1e-12) << order;
    EXPECT_LT(worstForce / kK, 1e-13) << order;
  }
}

// A rigid spin (3.9 rad about (1, 1, 1)) with order 2: no stress at any point or bond and no
// force anywhere.
TEST(BondAssociatedGradientOrder, RigidRotationGivesNoStressWithOrderTwo) {
  Problem pr(testing::cubicLattice(9), 2.015, elastic(2));
  const double n[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  const double rate = 1.3, dt = 0.02;
  const double W[9] = {
      0, -n[2] * rate, n[1] * rate, n[2] * rate, 0, -n[0] * rate, -n[1] * rate, n[0] * rate, 0};
  double worst = 0, worstForce = 0;
  for (int step = 1; step <= 150; ++step) {
    double Q[9], Fdot[9];
    testing::rodriguesRotation(n, rate * step * dt, Q);
    correspondence::multiply(W, Q, Fdot);
    pr.evaluateAffine(Q, Fdot, dt);
    const double* sigma = pr.fields->node(Model::kCauchyStress, 9);
    const double* f = pr.fields->node("Force_Density", 3);
    for (int i = 0; i < pr.topology.numOwned; ++i) {
      worst = std::max(worst, maxAbs(sigma + 9 * i));
      worstForce = std::max(worstForce, maxAbs(f + 3 * i, 3));
    }
    for (int k = 0; k < 9; ++k)
      for (double s : pr.fields->bond(Model::kBondUnrotatedCauchyStress[k]))
        worst = std::max(worst, std::abs(s));
  }
  std::printf(
      "  rigid spin, order 2: max |stress| / K over all points and bonds %.2e, max |f| / K over "
      "all points %.2e\n",
      worst / kK, worstForce / kK);
  EXPECT_LT(worst / kK, 1e-13);
  EXPECT_LT(worstForce / kK, 1e-12);
}

// Where every family within two horizons is point-symmetric the second-order weights equal the
// first-order ones (the moment matrix has no odd moments: its quadratic block decouples), so the
// centre of a 13^3 lattice must get the first-order model's force to rounding under any field:
// a check of the order-2 force (S phi from i, the reverse weight from j's ghosted B = S Zs)
// against the independently tested order-1 one. A surface point differs. The pairwise form
// conserves linear momentum at both orders.
TEST(BondAssociatedGradientOrder, SecondOrderForceIsTheFirstOrderOneWhereWeightsCoincide) {
  const int n = 13;
  const long long centre = 6 * n * n + 6 * n + 6, face = 6 * n * n + 6 * n;
  auto field = [](const double* X, double* u) {
    u[0] = 1e-3 * std::sin(0.7 * X[0] + 0.3 * X[1]) + 2e-4 * X[2] * X[2] / 10;
    u[1] = 8e-4 * std::cos(0.5 * X[1] - 0.4 * X[2]) * std::sin(0.2 * X[0]);
    u[2] = 6e-4 * std::sin(0.9 * X[2]) + 3e-4 * std::cos(0.6 * X[0] + 0.8 * X[1]);
  };
  double fCentre[2][3], fFace[2][3], momentum[2] = {0, 0}, scale[2] = {0, 0};
  for (int order : {1, 2}) {
    Problem pr(testing::cubicLattice(n), 2.015, elastic(order));
    deformBy(pr, field);
    for (int a = 0; a < 3; ++a) {
      fCentre[order - 1][a] = pr.force(centre)[a];
      fFace[order - 1][a] = pr.force(face)[a];
    }
    const double* f = pr.fields->node("Force_Density", 3);
    double total[3] = {0, 0, 0};
    for (int i = 0; i < pr.topology.numOwned; ++i)
      for (int a = 0; a < 3; ++a) {
        total[a] += f[3 * i + a];  // unit volumes
        scale[order - 1] = std::max(scale[order - 1], std::abs(f[3 * i + a]));
      }
    momentum[order - 1] = maxAbs(total, 3);
  }
  double centreDiff = 0, faceDiff = 0;
  for (int a = 0; a < 3; ++a) {
    centreDiff = std::max(centreDiff, std::abs(fCentre[1][a] - fCentre[0][a]));
    faceDiff = std::max(faceDiff, std::abs(fFace[1][a] - fFace[0][a]));
  }
  const double centreScale = maxAbs(fCentre[0], 3), faceScale = maxAbs(fFace[0], 3);
  std::printf(
      "  smooth field, 13^3: |f2 - f1| / |f1| centre %.2e (|f1| = %.3e), face centre %.2e; "
      "|sum f V| / max |f|: order 1 %.2e, order 2 %.2e\n",
      centreDiff / centreScale, centreScale, faceDiff / faceScale, momentum[0] / scale[0],
      momentum[1] / scale[1]);
  EXPECT_GT(centreScale, 1e-6);
  EXPECT_LT(centreDiff / centreScale, 1e-10);
  EXPECT_GT(faceDiff / faceScale, 1e-3);
  EXPECT_LT(momentum[1] / scale[1], 1e-12);
}

// Keys and families: orders 1-4 are accepted, 0 and 5 refused naming the limit; models of
// different orders are of different families (their points may not be bonded: the force reads
// the far end's B, whose layout is the order's); a horizon too small for the order's monomials
// stops at initialization naming the point and the order.
TEST(BondAssociatedGradientOrder, KeysFamiliesAndSingularMomentMatrices) {
  for (int order : {0, 5}) {
    try {
      elastic(order);
      FAIL() << "order " << order << " accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("Gradient Order Of Accuracy"), std::string::npos) << what;
      if (order == 5) {
        EXPECT_NE(what.find("up to order 4"), std::string::npos) << what;
      }
    }
  }
  for (int order = 1; order <= 4; ++order)
    EXPECT_EQ(static_cast<Model&>(*elastic(order)).gradientOrder(), order);
  EXPECT_EQ(elastic(1)->family(), "bond-associated correspondence");
  EXPECT_NE(elastic(2)->family(), elastic(1)->family());
  EXPECT_NE(elastic(3)->family(), elastic(2)->family());
  try {
    Problem pr(testing::cubicLattice(9), 2.015, elastic(3));
    FAIL() << "order 3 with a corner of 10 bonds accepted";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    std::printf("  order 3, horizon 2.015: %s\n", what.c_str());
    EXPECT_NE(what.find("moment matrix"), std::string::npos) << what;
    EXPECT_NE(what.find("Gradient Order Of Accuracy\" 3"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace peridot
