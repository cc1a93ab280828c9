#pragma once
// Du, Tao and Tian's bond-breaking rule (paper 002, eqs. 5-6; paper 001, eqs. 9-11), "DTT":
// the bond force is omega F(s) mu(S*) along the deformed bond, with F the continuous
// piecewise-linear force scalar of BondLaw (Smooth) and mu the damage factor of the history
// maximum stretch S*:
//   mu(S*) = 1 for S* < S0+, (S1+ - S*) / (S1+ - S0+) on [S0+, S1+], 0 beyond S1+.
// The bond damage holds 1 - mu(S*). Because mu is nonincreasing, mu(max_t s) = min_t mu(s): the
// bond damage itself is the history variable (d <- max(d, 1 - mu(s))), and this equals
// rounding 1 - mu(S*) with S* kept in double, bit for bit (see doc/theory/damage.md).
#include "damage/DamageModel.hpp"
#include "damage/FractureEnergy.hpp"

namespace peridot {

// 1 - mu(s) of paper 002 eq. 6: 0 below S0+, linear on [S0+, S1+], 1 beyond (BondLaw's
// brokenFraction, which a fused force loop applies).
inline double dttBrokenFraction(double s, double s0Plus, double s1Plus) {
  BondLaw law;
  law.kind = BondLaw::Kind::Smooth;
  law.s0Plus = s0Plus;
  law.s1Plus = s1Plus;
  return law.brokenFraction(s);
}

class DTT : public DamageModel {
 public:
  explicit DTT(ListReader& params);
  void computeDamage(const ModelState& state, const std::vector<int>& points,
                     float* bondDamage) override;
  bool bindsToBlock() const override { return criticalStretch_.fromFractureEnergy(); }
  bool fusesIntoSmoothBondLaw() const override { return true; }
  void bind(const MaterialModel& material, double horizon, const std::string& blockName,
            std::ostream& log) override;
  BondLaw bondLaw() const override;
  double criticalStretch() const { return criticalStretch_.value(); }
  // mu(S*) of paper 002 eq. 6.
  double damageFactor(double sStar) const {
    return 1.0 - dttBrokenFraction(sStar, s0PlusFactor_ * criticalStretch_.value(),
                                   s1PlusFactor_ * criticalStretch_.value());
  }

 private:
  CriticalStretchInput criticalStretch_;
  double s0PlusFactor_ = 0.95, s1PlusFactor_ = 1.05;  // S0+ and S1+ over S_c
  double s0Minus_ = -0.98, s1Minus_ = -0.99;
};

}  // namespace peridot
