// "Interface Aware" damage on configurations small enough to follow bond by bond: the bond
// i -> j breaks above min(s_c of the model, Critical_Stretch of j), never when j's value is 0,
// and a point left with two or fewer intact bonds loses them all.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>

#include "SerialProblem.hpp"
#include "damage/DamageModel.hpp"
#include "damage/InterfaceAware.hpp"

namespace peridot {
namespace {

using testing::Problem;

std::shared_ptr<MaterialModel> lps() {
  Teuchos::ParameterList p;
  p.set("Material Model", "Elastic");
  p.set("Density", 1.0);
  p.set("Bulk Modulus", 1.0);
  p.set("Shear Modulus", 0.6);
  ListReader r(p, "Materials -> M");
  return createMaterial(r);
}

std::shared_ptr<DamageModel> interfaceAware(double sc) {
  Teuchos::ParameterList p;
  p.set("Damage Model", "Interface Aware");
  p.set("Critical Stretch", sc);
  ListReader r(p, "Damage Models -> D");
  return createDamageModel(r);
}

// Entry i -> j of the bond lists (global ids), or -1.
long long entry(const Problem& pr, long long gi, long long gj) {
  const int i = pr.local(gi);
  for (auto b = pr.topology.bondOffsets[i]; b < pr.topology.bondOffsets[i + 1]; ++b)
    if (pr.topology.overlapGlobalId[pr.topology.neighbors[b]] == gj) return b;
  return -1;
}

TEST(InterfaceAware, SmallerEndBreaksZeroNeverBreaks) {
  std::vector<std::array<double, 3>> pts;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) pts.push_back({double(i), double(j), double(k)});
  Problem pr(pts, 1.8, lps(), interfaceAware(0.01));
  double* sc = pr.fields->node(InterfaceAware::kCriticalStretch, 1);
  for (int k = 0; k < pr.topology.numOverlap; ++k) ASSERT_EQ(sc[k], 0.01);
  const long long P = 13, Q = 0;  // the centre, a corner
  sc[pr.local(P)] = 0.005;        // as if P belonged to a weaker block
  sc[pr.local(Q)] = 0.0;          // as if Q's block had no Interface Aware model
  // Homogeneous stretch 0.007: only the entries j -> P exceed their threshold.
  double* y = pr.fields->node("Coordinates", 3);
  const double* x = pr.fields->node("Model_Coordinates", 3);
  for (int k = 0; k < 3 * pr.topology.numOverlap; ++k) y[k] = 1.007 * x[k];
  pr.evaluator->evaluate(0.0);
  const float* d = pr.fields->bondFloat("Bond_Damage").data();
  int broken = 0;
  for (long long g = 0; g < 27; ++g) {
    const int i = pr.local(g);
    for (auto b = pr.topology.bondOffsets[i]; b < pr.topology.bondOffsets[i + 1]; ++b) {
      const bool toP = pr.topology.overlapGlobalId[pr.topology.neighbors[b]] == P;
      EXPECT_EQ(d[b], toP ? 1.0f : 0.0f) << g;
      broken += d[b] > 0;
    }
  }
  EXPECT_EQ(broken, 26);  // P's neighbours within 1.8: 6 + 12 + 8
  // Stretch 0.03 along x only, for the bonds of Q: entries j -> Q stay intact.
  for (int k = 0; k < pr.topology.numOverlap; ++k) y[3 * k] = 1.03 * x[3 * k];
  pr.evaluator->evaluate(0.0);
  EXPECT_EQ(d[entry(pr, 1, Q)], 0.0f);
  EXPECT_EQ(d[entry(pr, Q, 1)], 1.0f);
}

TEST(InterfaceAware, PointWithTwoIntactBondsLosesThem) {
  // Four points, three bonds each; one entry broken leaves point 0 with two: all three go.
  Problem pr({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 1.5, lps(), interfaceAware(0.01));
  pr.fields->node(InterfaceAware::kCriticalStretch, 1)[pr.local(1)] = 0.004;
  pr.move(1, 0.005, 0, 0);  // 0 -> 1 stretched 0.005 > 0.004; 2 -> 1, 3 -> 1 only 0.0025
  pr.evaluator->evaluate(0.0);
  const float* d = pr.fields->bondFloat("Bond_Damage").data();
  for (long long g = 0; g < 4; ++g) {
    const int i = pr.local(g);
    ASSERT_EQ(pr.topology.bondOffsets[i + 1] - pr.topology.bondOffsets[i], 3);
    for (auto b = pr.topology.bondOffsets[i]; b < pr.topology.bondOffsets[i + 1]; ++b)
      EXPECT_EQ(d[b], g == 0 ? 1.0f : 0.0f) << g;
  }
}

}  // namespace
}  // namespace peridot
