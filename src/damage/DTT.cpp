#include "damage/DTT.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "core/Format.hpp"
#include "damage/FractureEnergy.hpp"

namespace peridot {

DTT::DTT(ListReader& p) : criticalStretch_(p) {
  s0PlusFactor_ = p.number("S0 Plus Over Critical Stretch", 0.95);
  s1PlusFactor_ = p.number("S1 Plus Over Critical Stretch", 1.05);
  s0Minus_ = p.number("S0 Minus", -0.98);
  s1Minus_ = p.number("S1 Minus", -0.99);
  // Paper 002: -1 < S1- < S0- < 0 <= S0+ < S1+, and S_c lies in [S0+, S1+] (Remark 5).
  if (!(s0PlusFactor_ >= 0.0 && s0PlusFactor_ <= 1.0)) {
    throw InputError(p.pathOf("S0 Plus Over Critical Stretch"),
                     "expected a number in [0, 1] (S0+ = factor x S_c, 0 <= S0+ <= S_c), got " +
                         formatNumber(s0PlusFactor_));
  }
  if (!(s1PlusFactor_ >= 1.0 && s1PlusFactor_ > s0PlusFactor_ && std::isfinite(s1PlusFactor_))) {
    throw InputError(p.pathOf("S1 Plus Over Critical Stretch"),
                     "expected a finite number >= 1 and greater than S0 Plus Over Critical "
                     "Stretch (" +
                         formatNumber(s0PlusFactor_) + "), got " + formatNumber(s1PlusFactor_));
  }
  if (!(s0Minus_ > -1.0 && s0Minus_ < 0.0)) {
    throw InputError(p.pathOf("S0 Minus"),
                     "expected a number in (-1, 0), got " + formatNumber(s0Minus_));
  }
  if (!(s1Minus_ > -1.0 && s1Minus_ < s0Minus_)) {
    throw InputError(p.pathOf("S1 Minus"),
                     "expected a number in (-1, S0 Minus = " + formatNumber(s0Minus_) + "), got " +
                         formatNumber(s1Minus_));
  }
  if (p.has("Thermal Expansion Coefficient") && p.number("Thermal Expansion Coefficient") != 0.0) {
    throw InputError(p.pathOf("Thermal Expansion Coefficient"),
                     "thermal strains are not supported by Peridot yet");
  }
  p.boolean("Verbose", false);
}

void DTT::bind(const MaterialModel& material, double horizon, const std::string& blockName,
               std::ostream& log) {
  criticalStretch_.bind(material, horizon, blockName, log);
}

BondLaw DTT::bondLaw() const {
  BondLaw law;
  law.kind = BondLaw::Kind::Smooth;
  law.s1Minus = s1Minus_;
  law.s0Minus = s0Minus_;
  law.s0Plus = s0PlusFactor_ * criticalStretch_.value();
  law.s1Plus = s1PlusFactor_ * criticalStretch_.value();
  return law;
}

void DTT::computeDamage(const ModelState& s, const std::vector<int>& points, float* bondDamage) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  // The law the fused loops apply (BondLaw::brokenFraction): one definition for both.
  const BondLaw law = bondLaw();
  for (int i : points)
    raiseBrokenFractions(law, s.y, s.topology->neighbors.data(), s.bondLength, i, offsets[i],
                         offsets[i + 1], bondDamage);
}

PERIDOT_REGISTER_DAMAGE(
    "DTT", DTT,
    "Du-Tao-Tian bond breaking (paper 002): continuous force scalar F(s) and damage factor "
    "mu(S*) of the history maximum stretch; needs a material that applies the smooth law",
    (std::vector<ParameterDoc>{
        {"Critical Stretch", "positive number: S_c (or give Fracture Energy)"},
        {"Fracture Energy",
         "positive number: G0, from which S_c is derived per block from its material, dimension "
         "and influence function (doc/theory/planar-and-fracture-energy.md)"},
        {"S0 Plus Over Critical Stretch",
         "number in [0, 1], default 0.95: S0+ = this x S_c, where the force starts to soften and "
         "the bond to break"},
        {"S1 Plus Over Critical Stretch",
         "number >= 1 and > S0 Plus Over Critical Stretch, default 1.05: S1+ = this x S_c, "
         "where the bond is fully broken"},
        {"S0 Minus",
         "number in (-1, 0), default -0.98: absolute compressive stretch where the force starts "
         "to vanish (against interpenetration; no damage in compression)"},
        {"S1 Minus", "number in (-1, S0 Minus), default -0.99: absolute stretch of zero force"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported yet"},
        {"Verbose", "bool, default false"}}))

}  // namespace peridot
