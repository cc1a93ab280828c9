#include "damage/CriticalStretch.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace peridot {

CriticalStretch::CriticalStretch(ListReader& p) {
  criticalStretch_ = p.positiveNumber("Critical Stretch");
  if (p.has("Thermal Expansion Coefficient") && p.number("Thermal Expansion Coefficient") != 0.0) {
    throw InputError(p.pathOf("Thermal Expansion Coefficient"),
                     "thermal strains are not supported by Peridot yet");
  }
  p.boolean("Verbose", false);
}

void CriticalStretch::computeDamage(const ModelState& s, const std::vector<int>& points,
                                    double* bondDamage) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double sc = criticalStretch_;
  for (int i : points) {
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      if (bondDamage[b] == 1.0) continue;
      const int j = neighbors[b];
      double X2 = 0, Y2 = 0;
      for (int d = 0; d < 3; ++d) {
        const double X = s.x[3 * j + d] - s.x[3 * i + d];
        const double Y = s.y[3 * j + d] - s.y[3 * i + d];
        X2 += X * X;
        Y2 += Y * Y;
      }
      const double zeta = std::sqrt(X2);
      if ((std::sqrt(Y2) - zeta) / zeta > sc) bondDamage[b] = 1.0;
    }
  }
}

PERIDOT_REGISTER_DAMAGE("Critical Stretch", CriticalStretch,
                        "Bonds break irreversibly when their stretch exceeds the critical stretch",
                        (std::vector<ParameterDoc>{
                            {"Critical Stretch", "positive number, required: s_c"},
                            {"Thermal Expansion Coefficient", "number: only 0 is supported yet"},
                            {"Verbose", "bool, default false"}}))

}  // namespace peridot
