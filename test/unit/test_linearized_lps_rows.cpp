// Linearized LPS's two-pass bond rows (materials/LinearizedLpsRows.hpp) against a plain scalar
// loop written here, bit for bit: dilatation, force density and stored energy over steps that
// damage and break bonds, with and without damage (Critical Stretch, DTT, LSJ-T, fused into the
// dilatation loop or not), in 3D, plane stress and plane strain, with omega = 1 and with
// influence functions, with one-sided bonds (differing horizons).
//
// The reference is the one-pass loop of paper 001 eqs. 17-18 with the roundings the earlier
// scalar loops had (the multiply-adds GCC fused there are written as std::fma; this file is
// compiled without contraction, test/CMakeLists.txt, so nothing else is fused): a change of the
// rows' order of operations, a vector reduction, or a multiply-add fused or split differently
// changes some bit and fails the test.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstring>
#include <memory>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "JitteredLattice.hpp"
#include "Materials.hpp"
#include "core/MulAdd.hpp"
#include "damage/DamageModel.hpp"
#include "evaluator/ModelEvaluator.hpp"
#include "materials/LinearizedLPS.hpp"

using namespace peridot;

namespace {

struct Options {
  std::string damage;  // "" (none), "Critical Stretch", "DTT" or "LSJ-T"
  std::string influence = "One";
  bool varyingHorizon = false;  // horizons 1.9..2.3: one-sided bonds (Topology::bondSides)
  std::string mode = "";        // "", "Plane Stress" or "Plane Strain" (a 2D lattice)
  bool fuse = true;             // DTT / LSJ-T in the dilatation loop (the default) or apart
};

void PrintTo(const Options& o, std::ostream* os) {
  *os << (o.damage.empty() ? "no damage" : o.damage) << (o.fuse ? "" : " (separate pass)") << ", "
      << (o.mode.empty() ? "3D" : o.mode) << ", influence " << o.influence
      << (o.varyingHorizon ? ", varying horizon" : "");
}

std::shared_ptr<DamageModel> damageModel(const std::string& name, double sc) {
  if (name.empty()) return nullptr;
  Teuchos::ParameterList p;
  p.set("Damage Model", name);
  p.set("Critical Stretch", sc);
  ListReader r(p, "Damage Models -> D");
  return createDamageModel(r);
}

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

struct Lattice : peridot::testing::JitteredLattice {
  std::shared_ptr<MaterialModel> model;
  std::shared_ptr<DamageModel> damage;

  Lattice(int n, const Options& o) : JitteredLattice(n, !o.mode.empty(), o.varyingHorizon, 5) {
    model = peridot::testing::material("Linearized LPS", o.mode, 1.0e9, 0.3);
    damage = damageModel(o.damage, 0.01);
    addBlock(model, damage, o.influence, o.fuse);
  }
  const LinearizedLPS& llps() const { return static_cast<const LinearizedLPS&>(*model); }
  // y = x + a stretch along x growing with `step` plus a random field that differs per step.
  void deform(int step) {
    std::mt19937 rng(3 + step);
    std::uniform_real_distribution<double> noise(-0.004, 0.004);
    const double* x = fields->node("Model_Coordinates", 3);
    double* y = fields->node("Coordinates", 3);
    for (int p = 0; p < topology.numOwned; ++p)
      for (int d = 0; d < 3; ++d)
        y[3 * p + d] = x[3 * p + d] + (d == 0 ? 0.003 * step * x[3 * p] : 0.0) +
                       (d < cloud.dimension ? noise(rng) : 0.0);
  }
  std::vector<double> node(const char* name, int components) const {
    const double* f = fields->nodeField(name).data;
    return std::vector<double>(f, f + components * topology.numOwned);
  }
};

// The one-pass scalar loops: what the rows must reproduce to the bit.
struct Reference {
  const ModelState& s;
  const double *m, *alpha, *beta;
  double kappa, c1;
  BondLaw law;

  double omega(std::int64_t b) const { return s.influence ? s.influence[b] : 1.0; }
  double mu(std::int64_t b) const { return s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0; }
  // xi.eta and xi of bond entry b of point i.
  double xiEta(int i, std::int64_t b, double xi[3]) const {
    const int j = s.topology->neighbors[b];
    double dot = 0.0;
    for (int d = 0; d < 3; ++d) {
      xi[d] = s.x[3 * j + d] - s.x[3 * i + d];
      dot = mulAdd(xi[d], (s.y[3 * j + d] - s.y[3 * i + d]) - xi[d], dot);
    }
    return dot;
  }
  std::vector<double> dilatation() const {
    const int n = s.topology->numOwned;
    std::vector<double> theta(n);
    for (int i = 0; i < n; ++i) {
      double sum = 0.0, xi[3];
      for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
        if (!s.topology->ownSide(b)) continue;
        const int j = s.topology->neighbors[b];
        sum = mulAdd(omega(b) * mu(b) * xiEta(i, b, xi), s.volume[j], sum);
      }
      theta[i] = m[i] > 0 ? kappa * sum / m[i] : 0.0;
    }
    return theta;
  }
  std::vector<double> force(const std::vector<double>& theta) const {
    const int n = s.topology->numOwned;
    std::vector<double> f(3 * n);
    for (int i = 0; i < n; ++i) {
      double fi[3] = {0, 0, 0}, xi[3];
      for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
        const int j = s.topology->neighbors[b];
        const double eps = xiEta(i, b, xi) / (s.bondLength[b] * s.bondLength[b]);
        const double F = law.forceScalar(eps);
        double ti = mulAdd(alpha[i], F, mu(b) * (beta[i] * theta[i]));
        double tj = mulAdd(mu(b) * beta[j], theta[j], alpha[j] * F);
        if (s.bondSides) {
          ti *= s.bondSides[b] & 1;
          tj *= (s.bondSides[b] >> 1) & 1;
        }
        const double t = omega(b) * mu(b) * (ti + tj) * s.volume[j];
        for (int d = 0; d < 3; ++d) fi[d] = mulAdd(t, xi[d], fi[d]);
      }
      for (int d = 0; d < 3; ++d) f[3 * i + d] = fi[d];
    }
    return f;
  }
  // p(eps) of the bond law (BondLaw::potential) with the multiply-adds GCC fused in it.
  double potential(double e) const {
    if (law.kind == BondLaw::Kind::Linear || (e >= law.s0Minus && e <= law.s0Plus))
      return 0.5 * e * e;
    if (e > law.s0Plus) {
      const double t = e < law.s1Plus ? e : law.s1Plus, w = law.s1Plus - law.s0Plus;
      const double tail = (law.s1Plus - t) * (law.s1Plus - t);
      return mulAdd(0.5 * law.s0Plus, law.s0Plus, law.s0Plus * mulAdd(w, w, -tail) / (2.0 * w));
    }
    const double t = e > law.s1Minus ? e : law.s1Minus, w = law.s0Minus - law.s1Minus;
    return mulAdd(0.5 * law.s0Minus, law.s0Minus,
                  law.s0Minus * mulAdd(t - law.s1Minus, t - law.s1Minus, -(w * w)) / (2.0 * w));
  }
  // W = c1 / (2 kappa) theta^2 + alpha sum omega |xi|^2 p(eps) mu V over i's own horizon.
  std::vector<double> energy(const std::vector<double>& theta) const {
    const int n = s.topology->numOwned;
    std::vector<double> W(n);
    for (int i = 0; i < n; ++i) {
      double bonds = 0.0, xi[3];
      for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
        if (!s.topology->ownSide(b)) continue;
        const int j = s.topology->neighbors[b];
        const double z2 = s.bondLength[b] * s.bondLength[b];
        const double eps = xiEta(i, b, xi) / z2;
        bonds = mulAdd(omega(b) * z2 * potential(eps) * mu(b), s.volume[j], bonds);
      }
      W[i] = mulAdd(c1 / (2.0 * kappa) * theta[i], theta[i], alpha[i] * bonds);
    }
    return W;
  }
};

class LinearizedLpsRows : public ::testing::TestWithParam<Options> {};

}  // namespace

TEST_P(LinearizedLpsRows, MatchOnePassScalarLoopsBitForBit) {
  const Options o = GetParam();
  Lattice lattice(o.mode.empty() ? 6 : 12, o);
  const ModelState& s = lattice.evaluator->state();
  ASSERT_EQ(o.varyingHorizon, s.bondSides != nullptr);
  ASSERT_EQ(o.influence != "One", s.influence != nullptr);
  const double* m = lattice.fields->nodeField(LinearizedLPS::kWeightedVolume).data;
  const double* alpha = lattice.fields->nodeField(LinearizedLPS::kAlpha).data;
  const double* beta = lattice.fields->nodeField(LinearizedLPS::kBeta).data;
  const Reference reference{s,
                            m,
                            alpha,
                            beta,
                            lattice.llps().kappa(),
                            lattice.llps().c1(),
                            lattice.damage ? lattice.damage->bondLaw() : BondLaw()};
  const int n = lattice.topology.numOwned;
  const std::int64_t bonds = lattice.topology.bondOffsets[n];
  std::int64_t damaged = 0, broken = 0;
  for (int step = 0; step <= 6; ++step) {
    lattice.deform(step);
    lattice.evaluator->evaluate(0.5);
    const std::string when = "step " + std::to_string(step);
    // The damage the evaluation applied is the damage the loops read (the separate pass runs
    // before them, a fused update before each point's sum).
    const std::vector<double> theta = reference.dilatation();
    EXPECT_TRUE(sameBits(theta, lattice.node(LinearizedLPS::kDilatation, 1))) << when;
    EXPECT_TRUE(sameBits(reference.force(theta), lattice.node("Force_Density", 3))) << when;
    std::vector<double> W(n);
    std::vector<int> points(n);
    for (int i = 0; i < n; ++i) points[i] = i;
    lattice.model->storedEnergyDensity(s, points, W.data());
    EXPECT_TRUE(sameBits(reference.energy(theta), W)) << when;
    damaged = broken = 0;
    if (s.bondDamage)
      for (std::int64_t b = 0; b < bonds; ++b) {
        damaged += s.bondDamage[b] > 0.0f;
        broken += s.bondDamage[b] == 1.0f;
      }
  }
  // With a damage model, bonds broke (or softened) and not all of them.
  if (!o.damage.empty()) {
    EXPECT_GT(damaged, 0);
    EXPECT_LT(damaged, bonds);
  }
  if (o.damage == "Critical Stretch" || o.damage == "DTT") {
    EXPECT_GT(broken, 0);
  }
  if (o.damage == "DTT" || o.damage == "LSJ-T") {
    EXPECT_GT(damaged, broken);  // partial damage
  }
}

INSTANTIATE_TEST_SUITE_P(
    Configurations, LinearizedLpsRows,
    ::testing::Values(Options{"", "One", false, ""}, Options{"", "Parabolic Decay", true, ""},
                      Options{"", "One", false, "Plane Stress"},
                      Options{"Critical Stretch", "One", false, ""},
                      Options{"Critical Stretch", "1.0/zeta", true, ""},
                      Options{"Critical Stretch", "Conical", true, "Plane Strain"},
                      Options{"DTT", "One", true, ""},
                      Options{"DTT", "Parabolic Decay", false, "Plane Stress", false},
                      Options{"LSJ-T", "One", false, ""},
                      Options{"LSJ-T", "Conical Over Zeta", true, "Plane Stress"},
                      Options{"LSJ-T", "One", true, "Plane Strain", false}));
