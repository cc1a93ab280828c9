#include "damage/CriticalStretch.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "damage/FractureEnergy.hpp"

namespace peridot {

CriticalStretch::CriticalStretch(ListReader& p) : criticalStretch_(p) {
  if (p.has("Thermal Expansion Coefficient") && p.number("Thermal Expansion Coefficient") != 0.0) {
    throw InputError(p.pathOf("Thermal Expansion Coefficient"),
                     "thermal strains are not supported by Peridot yet");
  }
  p.boolean("Verbose", false);
}

void CriticalStretch::bind(const MaterialModel& material, double horizon,
                           const std::string& blockName, std::ostream& log) {
  criticalStretch_.bind(material, horizon, blockName, log);
}

void CriticalStretch::computeDamage(const ModelState& s, const std::vector<int>& points,
                                    float* bondDamage) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* y = s.y;
  const double* zeta = s.bondLength;
  const double sc = criticalStretch_.value();
  for (int i : points) {
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      const double stretch = (std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2) - zeta[b]) / zeta[b];
      // max() keeps a broken bond broken without a branch the compiler cannot vectorize.
      bondDamage[b] = stretch > sc ? 1.0f : bondDamage[b];
    }
  }
}

PERIDOT_REGISTER_DAMAGE(
    "Critical Stretch", CriticalStretch,
    "Bonds break irreversibly when their stretch exceeds the critical stretch",
    (std::vector<ParameterDoc>{
        {"Critical Stretch", "positive number: s_c (or give Fracture Energy)"},
        {"Fracture Energy",
         "positive number: G0, from which s_c is derived per block from its "
         "material, dimension and influence function (3D PMB: "
         "sqrt(5 G0 / (9 K delta)); see doc/theory/planar-and-fracture-energy.md)"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported yet"},
        {"Verbose", "bool, default false"}}))

}  // namespace peridot
