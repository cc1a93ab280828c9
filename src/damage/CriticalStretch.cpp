#include "damage/CriticalStretch.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "damage/FractureEnergy.hpp"

namespace peridot {

namespace {

// kStoredLength: |xi| from state.bondLength, else from the reference coordinates (same bits).
template <bool kThermal, bool kStoredLength>
void breakLoop(const ModelState& s, const std::vector<int>& points, double sc, double alpha,
               float* bondDamage) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* y = s.y;
  const double* x = s.x;
  const double* zetaStored = s.bondLength;
  for (int i : points) {
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
      double length = std::sqrt(sumOfSquares(Y0, Y1, Y2));
      if (kThermal) length -= thermal * zeta;
      const double stretch = (length - zeta) / zeta;
      // max() keeps a broken bond broken without a branch the compiler cannot vectorize.
      bondDamage[b] = stretch > sc ? 1.0f : bondDamage[b];
    }
  }
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
