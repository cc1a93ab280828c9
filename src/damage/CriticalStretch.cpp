#include "damage/CriticalStretch.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "damage/FractureEnergy.hpp"

namespace peridot {

namespace {

template <bool kThermal, bool kStoredLength>
void breakLoop(const ModelState& s, const std::vector<int>& points, double sc, double alpha,
               float* bondDamage) {
  for (int i : points) breakStretchedBondsOf<kThermal, kStoredLength>(s, i, sc, alpha, bondDamage);
}

}  // namespace

void breakStretchedBonds(const ModelState& s, const std::vector<int>& points,
                         double criticalStretch, double alpha, float* bondDamage) {
  const bool stored = s.bondLength != nullptr;
  if (alpha != 0.0 && s.temperatureChange) {
    if (stored)
      breakLoop<true, true>(s, points, criticalStretch, alpha, bondDamage);
    else
      breakLoop<true, false>(s, points, criticalStretch, alpha, bondDamage);
  } else if (stored) {
    breakLoop<false, true>(s, points, criticalStretch, 0.0, bondDamage);
  } else {
    breakLoop<false, false>(s, points, criticalStretch, 0.0, bondDamage);
  }
}

CriticalStretch::CriticalStretch(ListReader& p) : criticalStretch_(p) {
  alpha_ = p.number("Thermal Expansion Coefficient", 0.0);
  p.boolean("Verbose", false);
}

void CriticalStretch::bind(const MaterialModel& material, double horizon,
                           const std::string& blockName, std::ostream& log) {
  criticalStretch_.bind(material, horizon, blockName, log);
}

void CriticalStretch::computeDamage(const ModelState& s, const std::vector<int>& points,
                                    float* bondDamage) {
  breakStretchedBonds(s, points, criticalStretch_.value(), alpha_, bondDamage);
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
        {"Thermal Expansion Coefficient",
         "number, default 0: alpha; the stretch compared with s_c is taken from the length "
         "less alpha Delta T_i |xi| (Delta T_i of the list's owner, as Peridigm)"},
        {"Verbose", "bool, default false"}}))

}  // namespace peridot
