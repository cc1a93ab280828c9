// "Johnson Cook" and "Von Mises Stress" damage (damage/JohnsonCook.hpp, damage/VonMisesStress.hpp)
// on a 5^3 lattice whose every point follows a homogeneous motion y = F x (the correspondence
// F, stress and plastic strain are then exact at every point), against values computed here
// from the closed-form continuum response:
//   Johnson Cook: "Elastic Plastic Correspondence" (Green strain form, perfect plasticity) in
//     uniaxial tension. Green strain E = diag(Ex, Ex, Ez) with Ex = (sigma_y / (3K) - Ez) / 2
//     keeps S = diag(0, 0, sigma_y) once yielding (mean S = K tr E = sigma_y / 3, the radial
//     return puts the deviator on the yield surface), so sigma_xx = 0, the triaxiality is
//     exactly 1/3, and eps_p = 2/3 (Ez - Ex) - sigma_y / (3 mu). The damage reads the previous
//     evaluation's fields: after evaluation n, D = eps_p(n-1) / eps_f(1/3), and each bond's
//     damage is the ramp of Threshold / Critical Damage of D.
//   Von Mises Stress: "Elastic Correspondence" in uniaxial strain E_zz = g: sigma_zz = F_zz
//     (lambda + 2 mu) g, sigma_xx = lambda g / F_zz; bonds break at the first evaluation after
//     the one whose von Mises stress |sigma_zz - sigma_xx| passed the critical value.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <sstream>
#include <string>

#include "Materials.hpp"
#include "SerialProblem.hpp"
#include "core/Error.hpp"
#include "damage/DamageModel.hpp"
#include "damage/JohnsonCook.hpp"

namespace peridot {
namespace {

using testing::Problem;

const double kK = 5.0 / 3.0, kG = 1.0, kYield = 1e-3;

std::shared_ptr<DamageModel> damageModel(const Teuchos::ParameterList& p) {
  ListReader r(p, "Damage Models -> D");
  return createDamageModel(r);
}

Teuchos::ParameterList johnsonCookParameters(double neglect) {
  Teuchos::ParameterList p;
  p.set("Damage Model", "Johnson Cook");
  p.set("Damage Parameter 1", 0.002);
  p.set("Damage Parameter 2", 0.01);
  p.set("Damage Parameter 3", 1.5);
  p.set("Threshold Damage", 0.5);
  p.set("Critical Damage", 0.8);
  p.set("Critical Damage To Neglect Material Point", neglect);
  return p;
}

// y = diag(fx, fx, fz) x at every point, then one evaluation.
void stretch(Problem& pr, double fx, double fz) {
  const double F[9] = {fx, 0, 0, 0, fx, 0, 0, 0, fz}, Fdot[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  pr.evaluateAffine(F, Fdot, 1.0);
}

void runJohnsonCook(double neglect) {
  auto material = testing::correspondence("Elastic Plastic Correspondence", kK, kG, 0.0,
                                          "Total Lagrangian Green Strain", kYield);
  auto damage = damageModel(johnsonCookParameters(neglect));
  std::ostringstream log;
  damage->bind(*material, 1.75, "block_1", log);
  Problem pr(testing::cubicLattice(5), 1.75, material, damage);
  // eps_f at sigma* = 1/3, from the deck's constants (Peridigm's sign: exp(-D3 sigma*)).
  const double epsF = 0.002 + 0.01 * std::exp(-1.5 / 3.0);
  const double threshold = 0.5, critical = 0.8;
  auto ramp = [&](double D) {
    return D >= critical ? 1.0 : D <= threshold ? 0.0 : (D - threshold) / (critical - threshold);
  };
  const float* bondDamage = pr.fields->bondFloat("Bond_Damage").data();
  double epsPrevious = 0.0;  // eps_p of the previous evaluation
  int firstBroken = -1, ramped = 0;
  for (int n = 1; n <= 40; ++n) {
    const double Ez = 1e-3 + 2e-4 * (n - 1);  // plastic from the first step on
    const double Ex = (kYield / (3 * kK) - Ez) / 2;
    stretch(pr, std::sqrt(1 + 2 * Ex), std::sqrt(1 + 2 * Ez));
    const double D = std::min(1.0, epsPrevious / epsF);
    double phi = ramp(D);
    if (phi > neglect) phi = 1.0;  // the point's Damage passes the limit: all bonds break
    const double* damageParameter = pr.fields->node(JohnsonCook::kDamageParameter, 1);
    for (int i = 0; i < pr.topology.numOwned; ++i) {
      ASSERT_NEAR(damageParameter[i], D, 1e-12 * (1 + D)) << "evaluation " << n;
      for (auto b = pr.topology.bondOffsets[i]; b < pr.topology.bondOffsets[i + 1]; ++b)
        ASSERT_NEAR(bondDamage[b], phi, 1e-6) << "evaluation " << n << " D " << D;
    }
    if (phi > 0 && phi < 1) ++ramped;
    if (phi == 1.0 && firstBroken < 0) {
      firstBroken = n;
      if (neglect >= 1.0) {
        EXPECT_GE(D, critical);
      }
    }
    if (firstBroken < 0) {
      // Still bonded: the material's own response is the closed form (the path is as meant).
      const double eps = 2.0 / 3.0 * (Ez - Ex) - kYield / (3 * kG);
      const double* eqps = pr.fields->node("Equivalent_Plastic_Strain", 1);
      const double* sigma = pr.fields->node("Cauchy_Stress", 9);
      for (int i = 0; i < pr.topology.numOwned; ++i) {
        ASSERT_NEAR(eqps[i], eps, 1e-12) << "evaluation " << n;
        ASSERT_NEAR(sigma[9 * i], 0.0, 1e-12) << "evaluation " << n;
        ASSERT_NEAR(sigma[9 * i + 8], kYield * std::sqrt(1 + 2 * Ez) / (1 + 2 * Ex), 1e-12);
      }
      epsPrevious = eps;
    } else {
      // Cut loose: every point lost all its bonds, carries no stress, and is no error.
      const double* sigma = pr.fields->node("Cauchy_Stress", 9);
      for (int i = 0; i < pr.topology.numOwned; ++i) ASSERT_EQ(sigma[9 * i + 8], 0.0);
    }
  }
  ASSERT_GT(firstBroken, 0) << "the bonds never broke";
  EXPECT_GT(ramped, 3);  // the ramp between threshold and critical was seen
  if (neglect >= 1.0) {
    // Broken at the first evaluation whose D (the previous step's eps_p / eps_f) reaches
    // Critical Damage, and not before.
    int expected = -1;
    for (int n = 2; expected < 0 && n <= 40; ++n) {
      const double Ez = 1e-3 + 2e-4 * (n - 2), Ex = (kYield / (3 * kK) - Ez) / 2;
      if ((2.0 / 3.0 * (Ez - Ex) - kYield / (3 * kG)) / epsF >= critical) expected = n;
    }
    EXPECT_EQ(firstBroken, expected);
  }
}

TEST(JohnsonCookDamage, UniaxialTensionFollowsTheHandIntegratedLaw) { runJohnsonCook(1.0); }

TEST(JohnsonCookDamage, NeglectedPointsLoseEveryBond) { runJohnsonCook(0.95); }

TEST(VonMisesStressDamage, BondsBreakWhenTheStressPassesTheCriticalValue) {
  auto material = testing::correspondence("Elastic Correspondence", kK, kG, 0.0,
                                          "Total Lagrangian Green Strain");
  const double lambda = kK - 2 * kG / 3;
  auto vonMises = [&](double g) {
    const double Fz = std::sqrt(1 + 2 * g);
    return std::abs(Fz * (lambda + 2 * kG) * g - lambda * g / Fz);
  };
  const double step = 1e-4;
  const double critical = 0.5 * (vonMises(5 * step) + vonMises(6 * step));
  Teuchos::ParameterList p;
  p.set("Damage Model", "Von Mises Stress");
  p.set("Critical Von Mises Stress", critical);
  p.set("Threshold Damage", 1.0);
  p.set("Critical Damage", 1.0);
  auto damage = damageModel(p);
  std::ostringstream log;
  damage->bind(*material, 1.75, "block_1", log);
  Problem pr(testing::cubicLattice(5), 1.75, material, damage);
  const float* bondDamage = pr.fields->bondFloat("Bond_Damage").data();
  for (int n = 1; n <= 8; ++n) {
    stretch(pr, 1.0, std::sqrt(1 + 2 * n * step));
    // The damage of evaluation n reads the von Mises stress of evaluation n - 1.
    const float expected = vonMises((n - 1) * step) >= critical ? 1.0f : 0.0f;
    for (std::int64_t b = 0; b < pr.topology.numBonds(); ++b)
      ASSERT_EQ(bondDamage[b], expected) << "evaluation " << n;
    // The stress crossed sigma_c between evaluations 5 and 6.
    if (n == 6) {
      EXPECT_EQ(expected, 0.0f);
    }
    if (n == 7) {
      EXPECT_EQ(expected, 1.0f);
    }
  }
}

// The ramp between Peridigm's defaults (Threshold 0.99, Critical 1): linear in sigma_vm/sigma_c.
TEST(VonMisesStressDamage, DefaultRampIsLinearBetweenThresholdAndCritical) {
  auto material = testing::correspondence("Elastic Correspondence", kK, kG, 0.0,
                                          "Total Lagrangian Green Strain");
  const double lambda = kK - 2 * kG / 3, g = 1e-4;
  const double Fz = std::sqrt(1 + 2 * g);
  const double vm = std::abs(Fz * (lambda + 2 * kG) * g - lambda * g / Fz);
  Teuchos::ParameterList p;
  p.set("Damage Model", "Von Mises Stress");
  p.set("Critical Von Mises Stress", vm / 0.995);  // ratio 0.995: damage 1/2
  auto damage = damageModel(p);
  Problem pr(testing::cubicLattice(5), 1.75, material, damage);
  stretch(pr, 1.0, Fz);
  stretch(pr, 1.0, Fz);
  const float* bondDamage = pr.fields->bondFloat("Bond_Damage").data();
  for (std::int64_t b = 0; b < pr.topology.numBonds(); ++b) ASSERT_NEAR(bondDamage[b], 0.5, 1e-5);
}

void expectRefused(const std::string& damageName, const std::string& materialName,
                   const std::string& missing) {
  Teuchos::ParameterList p = johnsonCookParameters(0.95);
  if (damageName == "Von Mises Stress") {
    p = Teuchos::ParameterList();
    p.set("Damage Model", "Von Mises Stress");
    p.set("Critical Von Mises Stress", 1.0);
  }
  auto damage = damageModel(p);
  auto material = materialName == "Elastic"
                      ? testing::material("Elastic", "", 1.0, 0.25)
                      : testing::correspondence(materialName, kK, kG, 0.0, "Hypoelastic Rate");
  std::ostringstream log;
  try {
    damage->bind(*material, 1.75, "block_7", log);
    FAIL() << damageName << " on " << materialName << " must be refused";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Damage Models -> D: the damage model \"" + damageName + "\" reads"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find(missing), std::string::npos) << what;
    EXPECT_NE(what.find("block \"block_7\""), std::string::npos) << what;
  }
}

TEST(DuctileDamage, MaterialWithoutTheFieldsIsAClearError) {
  expectRefused("Johnson Cook", "Elastic", "Equivalent_Plastic_Strain, Cauchy_Stress");
  expectRefused("Johnson Cook", "Elastic Correspondence",
                "reads the material's "
                "Equivalent_Plastic_Strain, which");
  expectRefused("Von Mises Stress", "Elastic", "Von_Mises_Stress");
}

TEST(DuctileDamage, BadRampsAreRefused) {
  Teuchos::ParameterList p = johnsonCookParameters(0.95);
  p.set("Threshold Damage", 0.9);
  EXPECT_THROW(damageModel(p), InputError);
  p = johnsonCookParameters(0.95);
  p.set("Critical Damage", 1.5);
  EXPECT_THROW(damageModel(p), InputError);
  Teuchos::ParameterList v;
  v.set("Damage Model", "Von Mises Stress");
  v.set("Critical Von Mises Stress", 1.0);
  v.set("Critical Damage", 0.5);  // below the default threshold 0.99, as Peridigm refuses
  EXPECT_THROW(damageModel(v), InputError);
}

}  // namespace
}  // namespace peridot
