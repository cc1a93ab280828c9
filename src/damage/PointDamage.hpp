#pragma once
// What Peridigm's two ductile damage models ("Johnson Cook", "Von Mises Stress") share: a value
// per material point (the Johnson-Cook damage parameter D, or the von Mises stress over its
// critical value) turned into bond damage by the ramp of `Threshold Damage` and `Critical
// Damage`, and `Critical Damage To Neglect Material Point`. Theory and the differences from
// Peridigm in doc/theory/damage.md.
//
// A bond takes the larger value of its two end points: the material at either end failing
// fails the bond, from both sides alike (point i's bond to j and j's bond to i get the same
// damage, so a failed point is cut loose from its neighbours' families too).
#include <algorithm>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "materials/MaterialModel.hpp"

namespace peridot {

struct PointDamageRamp {
  double threshold = 0.0;  // `Threshold Damage`: below it the bond is intact
  double critical = 1.0;   // `Critical Damage`: at or above it the bond is broken
  // `Critical Damage To Neglect Material Point`: a point whose Damage (the mean damage of its
  // bonds) exceeds it has all its bonds broken.
  double neglect = 0.95;

  // 0 at or below the threshold, 1 at or above the critical value, linear between (a step at
  // the critical value when the two coincide).
  double operator()(double value) const {
    if (value >= critical) return 1.0;
    if (value <= threshold) return 0.0;
    return (value - threshold) / (critical - threshold);
  }

  // Bond damage of the points' bonds from the ghosted point values `value` (never decreasing),
  // then the neglected points.
  void apply(const ModelState& s, const std::vector<int>& points, const double* value,
             float* bondDamage) const {
    const std::int64_t* offsets = s.topology->bondOffsets.data();
    const int* neighbors = s.topology->neighbors.data();
    for (int i : points) {
      double broken = 0.0, count = 0.0;
      for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
        const double phi = (*this)(std::max(value[i], value[neighbors[b]]));
        bondDamage[b] = std::max(bondDamage[b], static_cast<float>(phi));
        if (s.topology->ownSide(b)) {
          broken += bondDamage[b];
          count += 1.0;
        }
      }
      if (count > 0.0 && broken > neglect * count)
        for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b)
          if (s.topology->ownSide(b)) bondDamage[b] = 1.0f;
    }
  }
};

// Throws InputError (at `path`) unless the block's material maintains every field in `needed`
// (MaterialModel::outputFields): the damage model reads them as the material left them at the
// end of the previous evaluation.
inline void requireMaterialFields(const MaterialModel& material,
                                  const std::vector<std::string>& needed, const std::string& path,
                                  const std::string& damageName, const std::string& blockName,
                                  const std::string& suggestion) {
  const std::vector<std::string> provided = material.outputFields();
  std::string missing;
  for (const auto& f : needed)
    if (std::find(provided.begin(), provided.end(), f) == provided.end())
      missing += (missing.empty() ? "" : ", ") + f;
  if (missing.empty()) return;
  throw InputError(path, "the damage model \"" + damageName + "\" reads the material's " + missing +
                             ", which the material of block \"" + blockName +
                             "\" does not compute; " + suggestion);
}

}  // namespace peridot
