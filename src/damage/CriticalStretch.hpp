#pragma once
// Peridigm's "Critical Stretch": a bond breaks for good once its stretch exceeds the critical
// stretch (tension only). With its own `Thermal Expansion Coefficient` alpha the stretch is
// measured from the thermally expanded length: s = (|Y| - alpha Delta T_i |xi| - |xi|) / |xi|,
// Delta T_i the temperature change of the list's owner (Peridigm's convention).
#include "damage/DamageModel.hpp"
#include "damage/FractureEnergy.hpp"

namespace peridot {

// Breaks (irreversibly) the bonds of `points` whose stretch exceeds `criticalStretch`, the
// stretch less alpha Delta T_i when `alpha` is not 0 (state.temperatureChange then required).
// Shared with the time-dependent variant.
void breakStretchedBonds(const ModelState& state, const std::vector<int>& points,
                         double criticalStretch, double alpha, float* bondDamage);

class CriticalStretch : public DamageModel {
 public:
  explicit CriticalStretch(ListReader& params);
  void computeDamage(const ModelState& state, const std::vector<int>& points,
                     float* bondDamage) override;
  bool needsBondLength() const override { return false; }  // breakStretchedBonds computes it
  double criticalStretch() const { return criticalStretch_.value(); }
  // The fused force-loop check has no thermal term: only without one.
  double fusableCriticalStretch() const override {
    return alpha_ == 0.0 ? criticalStretch_.value() : 0.0;
  }
  bool bindsToBlock() const override { return criticalStretch_.fromFractureEnergy(); }
  // With `Fracture Energy`, derives the critical stretch from the block's material and horizon.
  void bind(const MaterialModel& material, double horizon, const std::string& blockName,
            std::ostream& log) override;
  double thermalExpansionCoefficient() const { return alpha_; }

 private:
  CriticalStretchInput criticalStretch_;
  double alpha_ = 0.0;
};

}  // namespace peridot
