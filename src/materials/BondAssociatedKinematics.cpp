#include "materials/BondAssociatedKinematics.hpp"

namespace peridot {
namespace bondassociated {

double weightedVolume(const ModelState& s, int i) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  double m = 0;
  for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
    double w = s.volume[neighbors[b]];
    if (s.influence) w *= s.influence[b];
    if (s.bondDamage) w *= 1.0 - s.bondDamage[b];
    if (s.bondSides) w *= (s.bondSides[b] & 1);
    m += w;
  }
  return m;
}

}  // namespace bondassociated
}  // namespace peridot
