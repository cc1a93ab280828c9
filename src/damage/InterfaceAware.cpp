#include "damage/InterfaceAware.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace peridot {

InterfaceAware::InterfaceAware(ListReader& p) {
  criticalStretch_ = p.positiveNumber("Critical Stretch");
  alpha_ = p.number("Thermal Expansion Coefficient", 0.0);
  p.boolean("Verbose", false);
}

void InterfaceAware::initializeDamage(const ModelState& s, const std::vector<int>& points,
                                      float* /*bondDamage*/) {
  // Allocated (zero) on first request, on every rank: points of other blocks keep 0.
  double* sc = s.fields->node(kCriticalStretch, 1);
  for (int i : points) sc[i] = criticalStretch_;
  // Collective; every rank sets up the same blocks in the same order, so the last block's
  // refresh leaves every ghost with its owner's value.
  s.fields->refreshGhosts(kCriticalStretch);
}

void InterfaceAware::computeDamage(const ModelState& s, const std::vector<int>& points,
                                   float* bondDamage) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* sc = s.fields->node(kCriticalStretch, 1);
  const double* y = s.y;
  const double* zeta = s.bondLength;
  const bool thermal = alpha_ != 0.0 && s.temperatureChange;
  for (int i : points) {
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    const double expansion = thermal ? alpha_ * s.temperatureChange[i] : 0.0;
    double broken = 0, count = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const bool own = s.topology->ownSide(b);
      count += own ? 1 : 0;
      const int j = neighbors[b];
      // Already broken, or a neighbour that does not let its bonds break.
      if (bondDamage[b] != 0.0f || sc[j] == 0.0) {
        broken += own ? bondDamage[b] : 0.0;
        continue;
      }
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      const double length = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2) - expansion * zeta[b];
      const double stretch = (length - zeta[b]) / zeta[b];
      if (stretch > std::min(sc[j], criticalStretch_)) bondDamage[b] = 1.0f;
      broken += own ? bondDamage[b] : 0.0;
    }
    // Two or fewer intact bonds left: break them all (Peridigm's rank-deficient point).
    if (broken >= count - 2)
      for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b)
        if (s.topology->ownSide(b)) bondDamage[b] = 1.0f;
  }
}

PERIDOT_REGISTER_DAMAGE(
    "Interface Aware", InterfaceAware,
    "Critical stretch per point; a bond breaks above the smaller of its two ends' values",
    (std::vector<ParameterDoc>{
        {"Critical Stretch",
         "positive number, required: s_c of the block's points (output Critical_Stretch); a "
         "bond breaks when its stretch exceeds the smaller s_c of its ends, never when the "
         "other end's block has no Interface Aware model"},
        {"Thermal Expansion Coefficient",
         "number, default 0: alpha; the stretch is taken from the length less "
         "alpha Delta T_i |xi| (as Critical Stretch)"},
        {"Verbose", "bool, default false"}}))

}  // namespace peridot
