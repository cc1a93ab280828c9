#pragma once
// Peridigm's "Critical Stretch": a bond breaks for good once its stretch exceeds the critical
// stretch (tension only). With its own `Thermal Expansion Coefficient` alpha the stretch is
// measured from the thermally expanded length: s = (|Y| - alpha Delta T_i |xi| - |xi|) / |xi|,
// Delta T_i the temperature change of the list's owner (Peridigm's convention).
#include <cmath>
#include <cstdint>

#include "damage/DamageModel.hpp"
#include "damage/FractureEnergy.hpp"

namespace peridot {

// Breaks (irreversibly) the bonds of `points` whose stretch exceeds `criticalStretch`, the
// stretch less alpha Delta T_i when `alpha` is not 0 (state.temperatureChange then required).
// Shared with the time-dependent variant.
void breakStretchedBonds(const ModelState& state, const std::vector<int>& points,
                         double criticalStretch, double alpha, float* bondDamage);

// The same for one point i's bond entries: the loop of breakStretchedBonds, which calls it, and
// of a material that applies the critical stretch in its own first bond loop (Linearized LPS's
// dilatation loop, fused), so that both break the same bonds. kThermal: the stretch less alpha
// Delta T_i; kStoredLength: |xi| from state.bondLength, else from the reference coordinates
// (the same bits). Without branches: it vectorizes.
template <bool kThermal, bool kStoredLength>
inline void breakStretchedBondsOf(const ModelState& s, int i, double sc, double alpha,
                                  float* bondDamage) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* y = s.y;
  const double* x = s.x;
  const double* zetaStored = s.bondLength;
  const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
  const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
  const double thermal = kThermal ? alpha * s.temperatureChange[i] : 0.0;
  for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
    const int j = neighbors[b];
    double zeta;
    if constexpr (kStoredLength) {
      zeta = zetaStored[b];
    } else {
      const double X0 = x[3 * j] - xi0, X1 = x[3 * j + 1] - xi1, X2 = x[3 * j + 2] - xi2;
      zeta = std::sqrt(sumOfSquares(X0, X1, X2));
    }
    const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
    double length = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
    if (kThermal) length -= thermal * zeta;
    const double stretch = (length - zeta) / zeta;
    // max() keeps a broken bond broken without a branch the compiler cannot vectorize.
    bondDamage[b] = stretch > sc ? 1.0f : bondDamage[b];
  }
}

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
