#pragma once
// The pairwise bond loops shared by the bond-based models (PMB and normalized PMB). Each is
// instantiated for the scene's options, so that the loop body has no branch on them.
//   force density on i:  sum_j (c2 / 2) s V_j e_ij    [PMB]
//                        sum_j (c2 / 2) s / |xi| V_j e_ij    [normalized PMB: kOverLength]
//   energy density of i: sum_j (c2 / 8) s^2 |xi| V_j  [PMB] or without |xi|  [normalized]
// with c2 = c_i + c_j (each end's half of the pair constant; with kSides only the ends whose
// horizon holds the bond), s the bond stretch, times (1 - bond damage) with kDamage.
#include <cmath>
#include <vector>

#include "materials/MaterialModel.hpp"

namespace peridot {

template <bool kDamage, bool kSides, bool kOverLength>
void pairForceLoop(const ModelState& s, const std::vector<int>& points, const double* c) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* y = s.y;
  const double* volume = s.volume;
  const double* zeta = s.bondLength;
  const float* damage = s.bondDamage;
  const unsigned char* sides = s.bondSides;
  for (int i : points) {
    double f0 = 0, f1 = 0, f2 = 0;
    const double ci = c[i], yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      const double dY = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
      double c2 = kSides ? ci * (sides[b] & 1) + c[j] * ((sides[b] >> 1) & 1) : ci + c[j];
      if (kDamage) c2 *= 1.0 - damage[b];
      // (c2 / 2) s V_j / |Y| in one division; coincident ends have no direction and, by
      // symmetry, no force.
      const double denominator = kOverLength ? 2.0 * zeta[b] * zeta[b] * dY : 2.0 * zeta[b] * dY;
      const double scale = dY > 0 ? c2 * (dY - zeta[b]) * volume[j] / denominator : 0.0;
      f0 += scale * Y0;
      f1 += scale * Y1;
      f2 += scale * Y2;
    }
    s.forceDensity[3 * i] = f0;
    s.forceDensity[3 * i + 1] = f1;
    s.forceDensity[3 * i + 2] = f2;
  }
}

template <bool kOverLength>
void pairForce(const ModelState& s, const std::vector<int>& points, const double* c) {
  if (s.bondDamage) {
    s.bondSides ? pairForceLoop<true, true, kOverLength>(s, points, c)
                : pairForceLoop<true, false, kOverLength>(s, points, c);
  } else {
    s.bondSides ? pairForceLoop<false, true, kOverLength>(s, points, c)
                : pairForceLoop<false, false, kOverLength>(s, points, c);
  }
}

template <bool kOverLength>
void pairEnergyDensity(const ModelState& s, const std::vector<int>& points, const double* c,
                       double* energyDensity) {
  for (int i : points) {
    double w = 0;
    for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
      const int j = s.topology->neighbors[b];
      double Y2 = 0;
      for (int d = 0; d < 3; ++d)
        Y2 += (s.y[3 * j + d] - s.y[3 * i + d]) * (s.y[3 * j + d] - s.y[3 * i + d]);
      const double zeta = s.bondLength[b];
      const double stretch = (std::sqrt(Y2) - zeta) / zeta;
      double c2 = c[i] + c[j];
      if (s.bondSides) c2 = c[i] * (s.bondSides[b] & 1) + c[j] * ((s.bondSides[b] >> 1) & 1);
      double wb = 0.125 * c2 * stretch * stretch * (kOverLength ? 1.0 : zeta);
      if (s.bondDamage) wb *= 1.0 - s.bondDamage[b];
      w += wb * s.volume[j];
    }
    energyDensity[i] = w;
  }
}

}  // namespace peridot
