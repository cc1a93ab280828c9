// Material and damage kernels on configurations small enough to compute by hand.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <sstream>

#include "SerialProblem.hpp"
#include "core/Error.hpp"
#include "damage/CriticalStretch.hpp"
#include "evaluator/ModelEvaluator.hpp"
#include "materials/Elastic.hpp"
#include "materials/ElasticBondBased.hpp"

namespace peridot {
namespace {

using testing::Problem;

const double kPi = 3.14159265358979323846;

std::shared_ptr<MaterialModel> pmb(double K) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic Bond Based");
  p.set("Density", 1000.0);
  p.set("Bulk Modulus", K);
  ListReader r(p, "Materials -> PMB");
  return createMaterial(r);
}

std::shared_ptr<MaterialModel> lps(double K, double G) {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic");
  p.set("Density", 1000.0);
  p.set("Bulk Modulus", K);
  p.set("Shear Modulus", G);
  ListReader r(p, "Materials -> LPS");
  return createMaterial(r);
}

TEST(ElasticBondBased, TwoPointsUnderTension) {
  const double K = 100.0, delta = 1.5, s = 0.01;
  Problem pr({{0, 0, 0}, {1, 0, 0}}, delta, pmb(K));
  pr.move(1, s, 0, 0);
  pr.evaluator->evaluate(1.0);
  const double c = 18.0 * K / (kPi * std::pow(delta, 4));
  // Each point is pulled toward the other with c s V.
  EXPECT_NEAR(pr.force(0)[0], c * s, 1e-12 * c);
  EXPECT_NEAR(pr.force(1)[0], -c * s, 1e-12 * c);
  EXPECT_EQ(pr.force(0)[1], 0.0);
  EXPECT_EQ(pr.force(0)[2], 0.0);
}

TEST(ElasticBondBased, ThreePointsHandComputation) {
  const double K = 3.0, delta = 2.0;
  Problem pr({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, delta, pmb(K));
  pr.move(2, 0.1, 0.2, 0.0);  // point 2 to (0.1, 1.2, 0)
  pr.evaluator->evaluate(1.0);
  const double c = 18.0 * K / (kPi * std::pow(delta, 4));
  // Bond 0-2: length 1 -> sqrt(0.01 + 1.44); bond 1-2: sqrt(2) -> sqrt(0.81 + 1.44); 0-1 unchanged.
  const double l02 = std::sqrt(1.45), l12 = std::sqrt(2.25);
  const double s02 = (l02 - 1.0) / 1.0, s12 = (l12 - std::sqrt(2.0)) / std::sqrt(2.0);
  const double f0[2] = {c * s02 * 0.1 / l02, c * s02 * 1.2 / l02};
  const double f1[2] = {c * s12 * (0.1 - 1.0) / l12, c * s12 * 1.2 / l12};
  EXPECT_NEAR(pr.force(0)[0], f0[0], 1e-12);
  EXPECT_NEAR(pr.force(0)[1], f0[1], 1e-12);
  EXPECT_NEAR(pr.force(1)[0], f1[0], 1e-12);
  EXPECT_NEAR(pr.force(1)[1], f1[1], 1e-12);
  EXPECT_NEAR(pr.force(2)[0], -f0[0] - f1[0], 1e-12);
  EXPECT_NEAR(pr.force(2)[1], -f0[1] - f1[1], 1e-12);
}

TEST(Elastic, TwoPointsUnderTension) {
  const double K = 10.0, G = 4.0, s = 0.01;
  Problem pr({{0, 0, 0}, {1, 0, 0}}, 1.5, lps(K, G));
  pr.move(1, s, 0, 0);
  pr.evaluator->evaluate(1.0);
  // m = 1, theta = 3 |xi| e V / m = 3 s, e^d = e - theta |xi| / 3 = 0: t = 3 K theta / m = 9 K s
  // on each side; the pair force is the sum of both.
  EXPECT_NEAR(pr.fields->nodeField("Weighted_Volume").data[0], 1.0, 1e-15);
  EXPECT_NEAR(pr.fields->nodeField("Dilatation").data[pr.local(0)], 3 * s, 1e-14);
  EXPECT_NEAR(pr.force(0)[0], 18 * K * s, 1e-12);
  EXPECT_NEAR(pr.force(1)[0], -18 * K * s, 1e-12);
}

TEST(Elastic, ThreePointsShear) {
  // Moving one point sideways changes its bond lengths; check against the LPS formulas
  // evaluated by hand for each point's force state.
  const double K = 7.0, G = 3.0;
  Problem pr({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 2.0, lps(K, G));
  pr.move(1, 0.0, 0.05, 0.0);
  pr.evaluator->evaluate(1.0);
  const double X[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const double Y[3][3] = {{0, 0, 0}, {1, 0.05, 0}, {0, 1, 0}};
  double m[3] = {0, 0, 0}, theta[3] = {0, 0, 0};
  auto len = [](const double* a, const double* b) {
    return std::sqrt(std::pow(b[0] - a[0], 2) + std::pow(b[1] - a[1], 2) +
                     std::pow(b[2] - a[2], 2));
  };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) m[i] += std::pow(len(X[i], X[j]), 2);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      if (i != j) theta[i] += 3.0 / m[i] * len(X[i], X[j]) * (len(Y[i], Y[j]) - len(X[i], X[j]));
  }
  auto t = [&](int i, int j) {
    const double z = len(X[i], X[j]), e = len(Y[i], Y[j]) - z;
    return 3 * K * theta[i] / m[i] * z + 15 * G / m[i] * (e - theta[i] * z / 3);
  };
  for (int i = 0; i < 3; ++i) {
    double f[2] = {0, 0};
    for (int j = 0; j < 3; ++j) {
      if (i == j) continue;
      const double l = len(Y[i], Y[j]);
      for (int d = 0; d < 2; ++d) f[d] += (t(i, j) + t(j, i)) * (Y[j][d] - Y[i][d]) / l;
    }
    EXPECT_NEAR(pr.force(i)[0], f[0], 1e-12) << "point " << i;
    EXPECT_NEAR(pr.force(i)[1], f[1], 1e-12) << "point " << i;
    EXPECT_NEAR(pr.fields->nodeField("Dilatation").data[pr.local(i)], theta[i], 1e-14);
  }
}

TEST(Elastic, HomogeneousExpansionDilatationIsThreeTimesStretch) {
  std::vector<std::array<double, 3>> pts;
  // 13^3 points: the centre's neighbours have complete neighbourhoods themselves.
  for (int i = 0; i < 13; ++i)
    for (int j = 0; j < 13; ++j)
      for (int k = 0; k < 13; ++k) pts.push_back({double(i), double(j), double(k)});
  Problem pr(pts, 3.015, lps(1.0, 1.0));
  const double s = 0.002;
  double* y = pr.fields->node("Coordinates", 3);
  const double* x = pr.fields->node("Model_Coordinates", 3);
  for (int k = 0; k < 3 * pr.topology.numOverlap; ++k) y[k] = (1 + s) * x[k];
  pr.evaluator->evaluate(1.0);
  const double* theta = pr.fields->nodeField("Dilatation").data;
  for (int i = 0; i < pr.topology.numOwned; ++i) EXPECT_NEAR(theta[i], 3 * s, 1e-13);
  // In the bulk the force of a homogeneous deformation vanishes by symmetry.
  const long long centre = 6 * 169 + 6 * 13 + 6;
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(pr.force(centre)[d], 0.0, 1e-12);
  // Near a surface it does not (the surface effect of peridynamics): the test can fail.
  EXPECT_GT(std::fabs(pr.force(0)[0]), 1e-6);
}

TEST(ElasticBondBased, StoredEnergyOfIsotropicStretchInTheBulk) {
  // W = 9 K s^2 / 2 for a full continuum sphere; the discrete sum on a grid with m = 3 is close.
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < 13; ++i)
    for (int j = 0; j < 13; ++j)
      for (int k = 0; k < 13; ++k) pts.push_back({double(i), double(j), double(k)});
  const double K = 2.0, s = 0.001;
  Problem pr(pts, 3.0, pmb(K));
  double* y = pr.fields->node("Coordinates", 3);
  const double* x = pr.fields->node("Model_Coordinates", 3);
  for (int k = 0; k < 3 * pr.topology.numOverlap; ++k) y[k] = (1 + s) * x[k];
  std::vector<double> w(pr.topology.numOverlap);
  pr.evaluator->storedEnergyDensity(w.data());
  const double exact = 4.5 * K * s * s;
  EXPECT_NEAR(w[pr.local(6 * 169 + 6 * 13 + 6)] / exact, 1.0, 0.15);
}

TEST(CriticalStretch, BreaksInTensionOnlyAndForever) {
  Teuchos::ParameterList p;
  p.set("Damage Model", "Critical Stretch");
  p.set("Critical Stretch", 0.01);
  ListReader r(p, "Damage Models -> CS");
  std::shared_ptr<DamageModel> damage = createDamageModel(r);
  Problem pr({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 1.2, pmb(1.0), damage);
  std::vector<double> nodeDamage(3);
  pr.move(1, 0.009, 0, 0);  // stretch 0.009 < 0.01
  pr.move(2, 0, -0.5, 0);   // strong compression: never breaks
  pr.evaluator->evaluate(1.0);
  pr.evaluator->nodeDamage(nodeDamage.data());
  EXPECT_EQ(nodeDamage[pr.local(0)], 0.0);
  pr.move(1, 0.002, 0, 0);  // stretch 0.011
  pr.evaluator->evaluate(1.0);
  pr.evaluator->nodeDamage(nodeDamage.data());
  EXPECT_DOUBLE_EQ(nodeDamage[pr.local(1)], 1.0);  // its only bond broke
  EXPECT_DOUBLE_EQ(nodeDamage[pr.local(0)], 0.5);  // one of two bonds
  EXPECT_EQ(nodeDamage[pr.local(2)], 0.0);
  EXPECT_EQ(pr.force(1)[0], 0.0);
  pr.move(1, -0.011, 0, 0);  // back home: the bond stays broken
  pr.evaluator->evaluate(1.0);
  pr.evaluator->nodeDamage(nodeDamage.data());
  EXPECT_DOUBLE_EQ(nodeDamage[pr.local(1)], 1.0);
}

}  // namespace
}  // namespace peridot

namespace peridot {
namespace {

TEST(CriticalStretch, FromFractureEnergyFor3DPMB) {
  Teuchos::ParameterList p;
  p.set("Damage Model", "Critical Stretch");
  p.set("Fracture Energy", 12.0);
  ListReader r(p, "Damage Models -> CS");
  auto damage = createDamageModel(r);
  ASSERT_TRUE(damage->bindsToBlock());
  std::ostringstream log;
  const double K = 50.0, delta = 1.5;
  damage->bind(*pmb(K), delta, "block_1", log);
  const double expected = std::sqrt(5.0 * 12.0 / (9.0 * K * delta));
  EXPECT_DOUBLE_EQ(static_cast<CriticalStretch&>(*damage).criticalStretch(), expected);
  EXPECT_NE(log.str().find("block_1"), std::string::npos);
  // A model without a formula (a material whose influence function has no closed-form
  // moments) is a clear error, not a silent default.
  auto gaussianPmb = pmb(K);
  gaussianPmb->setInfluenceFunction("Gaussian");
  EXPECT_THROW(damage->bind(*gaussianPmb, delta, "block_2", log), InputError);
}

}  // namespace
}  // namespace peridot
