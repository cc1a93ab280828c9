#pragma once
// The LSJ-T damage of Aguiar and Patriota (paper 001, eqs. 19-20), after Lipton, Said and Jha:
// a bond's damage factor is a smooth function of the time integral of its overstretch,
//   mu~ = h(X),  X(t) = integral_0^t j_s(eps) dtau,
//   j_s(x) = (x/S_c - 1)^5 / (1 + (x/S_c)^5) for x >= S_c, else 0,
//   h(X) = exp[1 - 1/(1 - (X/x_c)^2.01)] on (0, x_c), 1 for X <= 0, 0 for X >= x_c,
//   x_c = j_s(1.05 S_c) dt  (a bond held at 1.05 S_c breaks within one step),
// with eps the linearized bond strain xi.eta/|xi|^2 of the step just taken. The integral X is a
// double bond field ("LSJT_History_Integral", the state a restart must save); the bond damage
// holds 1 - mu~. Used with the "Linearized LPS" material this is paper 001's LSJ-T model.
#include "damage/DamageModel.hpp"
#include "damage/FractureEnergy.hpp"
#include "damage/LsjtStep.hpp"

namespace peridot {

class LSJT : public DamageModel {
 public:
  explicit LSJT(ListReader& params);
  void computeDamage(const ModelState& state, const std::vector<int>& points,
                     float* bondDamage) override;
  // One instance per block: the first evaluation of a run (the initial state) starts that
  // block's integral, and the critical stretch may depend on the block.
  bool bindsToBlock() const override { return true; }
  void bind(const MaterialModel& material, double horizon, const std::string& blockName,
            std::ostream& log) override;
  double criticalStretch() const { return criticalStretch_.value(); }
  void resume() override { started_ = true; }
  bool integratesInTime() const override { return true; }
  // Linearized LPS's dilatation loop forms the same linearized strain: it may apply the update
  // there (one walk over the bonds less), the same bits as computeDamage.
  bool fusesIntoLinearizedStrain() const override { return true; }
  LsjtStep beginLsjtStep(const ModelState& state) override;

  static constexpr const char* kHistoryIntegral = "LSJT_History_Integral";

 private:
  CriticalStretchInput criticalStretch_;
  bool started_ = false;
  std::vector<double> scratch_;  // one point's strains and integrals (3 x its bond count)
};

}  // namespace peridot
