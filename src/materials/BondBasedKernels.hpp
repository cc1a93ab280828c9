#pragma once
// The pairwise bond loops shared by the bond-based models (PMB and normalized PMB). Each is
// instantiated for the scene's options, so that the loop body has no branch on them.
//   force density on i:  sum_j (c2 / 2) omega F(s) V_j e_ij           [PMB]
//                        sum_j (c2 / 2) omega F(s) / |xi| V_j e_ij    [normalized PMB: kOverLength]
//   energy density of i: sum_j (c2 / 4) omega p(s) |xi| V_j           [PMB] or without |xi|
// with c2 = c_i + c_j (each end's half of the pair constant; with kSides only the ends whose
// horizon holds the bond), s the bond stretch, times (1 - bond damage) with kDamage, omega the
// bond influence with kInfluence (else 1), and the block's bond law: F(s) = s, p(s) = s^2/2
// (Linear) or DTT's smooth F and p (kSmooth). With kBreak the loop also applies the block's
// damage (fused: one pass over the bonds instead of two), computed exactly as the separate damage
// loop computes it before the bond's force is taken, so the bonds break alike: with the linear law
// the critical stretch ("Critical Stretch": a bond whose stretch exceeds it gets damage 1), with
// the smooth law DTT's d <- max(d, brokenFraction(s)). The inner loop is a
// SIMD loop: the per-point force sum runs in vector lanes (`omp simd reduction`), which fixes its
// order by the bond list alone, so nodal results stay identical at any rank count.
#include <cmath>
#include <type_traits>
#include <vector>

#include "materials/BondOptions.hpp"
#include "materials/MaterialModel.hpp"

namespace peridot {

// kThermal (linear law only): each end's half of the pair force is taken from its stretch less
// its own thermal strain alpha Delta T (state.thermalStrain), the convention of Peridigm's LPS:
// (c_i (s - eps_i) + c_j (s - eps_j)) / 2 in place of c2 s / 2.
// kStoredLength: read |xi| from state.bondLength; otherwise compute it from the reference
// coordinates in the loop, with referenceBondLength()'s arithmetic (the same bits; 8 bytes a bond
// less memory for a square root and three more gathered loads per bond).
// DamageT: float (state.bondDamage, 0..1) or unsigned char (state.bondBroken, 0/1 flags); both
// enter the force as the same factor 1 - d.
template <bool kDamage, bool kSides, bool kOverLength, bool kInfluence, bool kSmooth,
          bool kBreak = false, bool kThermal = false, bool kStoredLength = true,
          typename DamageT = float>
void pairForceLoop(const ModelState& s, const std::vector<int>& points, const double* c) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* y = s.y;
  const double* x = s.x;
  const double* volume = s.volume;
  const double* zeta = s.bondLength;
  const DamageT* damage;
  DamageT* breakable;
  if constexpr (std::is_same_v<DamageT, float>) {
    damage = s.bondDamage;
    breakable = s.breakableBondDamage;
  } else {
    damage = s.bondBroken;
    breakable = s.breakableBondBroken;
  }
  const double criticalStretch = s.fusedCriticalStretch;
  const unsigned char* sides = s.bondSides;
  const double* influence = s.influence;
  const BondLaw law = s.bondLaw;
  const double* strain = s.thermalStrain;
  for (int i : points) {
    double f0 = 0, f1 = 0, f2 = 0;
    const double ci = c[i], yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
    const double strainI = kThermal ? strain[i] : 0.0;
#pragma omp simd reduction(+ : f0, f1, f2)
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      double zb;
      if constexpr (kStoredLength) {
        zb = zeta[b];
      } else {
        const double X0 = x[3 * j] - xi0, X1 = x[3 * j + 1] - xi1, X2 = x[3 * j + 2] - xi2;
        zb = std::sqrt(sumOfSquares(X0, X1, X2));
      }
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      const double dY = std::sqrt(sumOfSquares(Y0, Y1, Y2));
      double c2 = kSides ? ci * (sides[b] & 1) + c[j] * ((sides[b] >> 1) & 1) : ci + c[j];
      // The ends' thermal part c_i eps_i + c_j eps_j, scaled as c2 is below.
      double th = 0.0;
      if constexpr (kThermal)
        th = kSides ? ci * (sides[b] & 1) * strainI + c[j] * ((sides[b] >> 1) & 1) * strain[j]
                    : ci * strainI + c[j] * strain[j];
      if constexpr (kBreak && kSmooth) {
        static_assert(std::is_same_v<DamageT, float>, "a smooth law's damage is a float");
        const float broken = static_cast<float>(law.brokenFraction((dY - zb) / zb));
        const float d = breakable[b] < broken ? broken : breakable[b];  // std::max's choice
        if (d != breakable[b]) breakable[b] = d;                        // a masked store, as below
        c2 *= 1.0 - d;
      } else if constexpr (kBreak) {
        const bool breaks = (dY - zb) / zb > criticalStretch;
        double d;
        if constexpr (std::is_same_v<DamageT, float>) {
          d = breaks ? 1.0f : breakable[b];
          if (breaks) breakable[b] = 1.0f;  // a masked store: intact bonds' lines stay clean
        } else {
          d = (breaks || breakable[b]) ? 1.0 : 0.0;
          if (breaks) breakable[b] = 1;
        }
        c2 *= 1.0 - d;
        if constexpr (kThermal) th *= 1.0 - d;
      } else if (kDamage) {
        double d;
        if constexpr (std::is_same_v<DamageT, float>)
          d = damage[b];
        else
          d = damage[b] ? 1.0 : 0.0;
        c2 *= 1.0 - d;
        if constexpr (kThermal) th *= 1.0 - d;
      }
      if (kInfluence) c2 *= influence[b];
      if (kThermal && kInfluence) th *= influence[b];
      double scale;
      if constexpr (kSmooth) {
        // (c2 / 2) F(s) V_j / |Y| (normalized: also / |xi|).
        const double F = law.forceScalar((dY - zb) / zb);
        const double denominator = kOverLength ? 2.0 * zb * dY : 2.0 * dY;
        scale = dY > 0 ? c2 * F * volume[j] / denominator : 0.0;
      } else {
        // (c2 / 2) s V_j / |Y| in one division; coincident ends have no direction and, by
        // symmetry, no force. The division always runs (on 1 for coincident ends) and the
        // select follows: no branch, so the loop vectorizes.
        const double safe = dY > 0 ? dY : 1.0;
        const double denominator = kOverLength ? 2.0 * zb * zb * safe : 2.0 * zb * safe;
        const double extension = kThermal ? c2 * (dY - zb) - th * zb : c2 * (dY - zb);
        const double q = extension * volume[j] / denominator;
        scale = dY > 0 ? q : 0.0;
      }
      f0 += scale * Y0;
      f1 += scale * Y1;
      f2 += scale * Y2;
    }
    s.forceDensity[3 * i] = f0;
    s.forceDensity[3 * i + 1] = f1;
    s.forceDensity[3 * i + 2] = f2;
  }
}

template <bool kOverLength, bool kDamage, bool kSides, bool kInfluence, bool kStoredLength,
          typename DamageT>
void pairForceWithLaw(const ModelState& s, const std::vector<int>& points, const double* c) {
  constexpr bool kFloat = std::is_same_v<DamageT, float>;
  const bool breaks = kFloat ? s.breakableBondDamage != nullptr : s.breakableBondBroken != nullptr;
  // Thermal strains come with the linear law only (a smooth law is refused at set-up).
  if (s.thermalStrain && s.bondLaw.kind == BondLaw::Kind::Linear) {
    if (kDamage && breaks)
      pairForceLoop<kDamage, kSides, kOverLength, kInfluence, false, true, true, kStoredLength,
                    DamageT>(s, points, c);
    else
      pairForceLoop<kDamage, kSides, kOverLength, kInfluence, false, false, true, kStoredLength,
                    DamageT>(s, points, c);
    return;
  }
  if (kDamage && breaks && s.bondLaw.kind == BondLaw::Kind::Linear)
    pairForceLoop<kDamage, kSides, kOverLength, kInfluence, false, true, false, kStoredLength,
                  DamageT>(s, points, c);
  else if (kFloat && kDamage && breaks && s.bondLaw.kind == BondLaw::Kind::Smooth)
    pairForceLoop<kDamage, kSides, kOverLength, kInfluence, true, true, false, kStoredLength,
                  float>(s, points, c);
  else if (kFloat && s.bondLaw.kind == BondLaw::Kind::Smooth)  // flags come with Linear only
    pairForceLoop<kDamage, kSides, kOverLength, kInfluence, true, false, false, kStoredLength,
                  DamageT>(s, points, c);
  else
    pairForceLoop<kDamage, kSides, kOverLength, kInfluence, false, false, false, kStoredLength,
                  DamageT>(s, points, c);
}

template <bool kOverLength, bool kDamage, bool kSides, bool kInfluence>
void pairForceWithStorage(const ModelState& s, const std::vector<int>& points, const double* c) {
  const bool flags = kDamage && s.bondBroken;
  if (s.bondLength) {
    if (flags)
      pairForceWithLaw<kOverLength, kDamage, kSides, kInfluence, true, unsigned char>(s, points, c);
    else
      pairForceWithLaw<kOverLength, kDamage, kSides, kInfluence, true, float>(s, points, c);
  } else {
    if (flags)
      pairForceWithLaw<kOverLength, kDamage, kSides, kInfluence, false, unsigned char>(s, points,
                                                                                       c);
    else
      pairForceWithLaw<kOverLength, kDamage, kSides, kInfluence, false, float>(s, points, c);
  }
}

template <bool kOverLength>
void pairForce(const ModelState& s, const std::vector<int>& points, const double* c) {
  withBondOptions(s, [&](auto o) {
    using O = decltype(o);
    pairForceWithStorage<kOverLength, O::damage, O::sides, O::influence>(s, points, c);
  });
}

template <bool kOverLength>
void pairEnergyDensity(const ModelState& s, const std::vector<int>& points, const double* c,
                       double* energyDensity) {
  const bool smooth = s.bondLaw.kind == BondLaw::Kind::Smooth;
  for (int i : points) {
    double w = 0;
    for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
      const int j = s.topology->neighbors[b];
      double Y2 = 0;
      for (int d = 0; d < 3; ++d)
        Y2 += (s.y[3 * j + d] - s.y[3 * i + d]) * (s.y[3 * j + d] - s.y[3 * i + d]);
      const double zeta = bondLengthOf(s, i, b);
      const double stretch = (std::sqrt(Y2) - zeta) / zeta;
      double c2 = c[i] + c[j];
      if (s.bondSides) c2 = c[i] * (s.bondSides[b] & 1) + c[j] * ((s.bondSides[b] >> 1) & 1);
      // 1/4 c2 p(s), p = s^2/2 for the linear law (kept as 1/8 c2 s^2, the same bits as before).
      double wb = smooth ? 0.25 * c2 * s.bondLaw.potential(stretch) * (kOverLength ? 1.0 : zeta)
                         : 0.125 * c2 * stretch * stretch * (kOverLength ? 1.0 : zeta);
      if (s.thermalStrain && !smooth) {
        // Each end's half from its own elastic stretch s - eps.
        const double wi = s.bondSides ? c[i] * (s.bondSides[b] & 1) : c[i];
        const double wj = s.bondSides ? c[j] * ((s.bondSides[b] >> 1) & 1) : c[j];
        const double si = stretch - s.thermalStrain[i], sj = stretch - s.thermalStrain[j];
        wb = 0.125 * (wi * si * si + wj * sj * sj) * (kOverLength ? 1.0 : zeta);
      }
      if (s.influence) wb *= s.influence[b];
      if (s.bondDamage || s.bondBroken) wb *= intactFraction(s, b);
      w += wb * s.volume[j];
    }
    energyDensity[i] = w;
  }
}

}  // namespace peridot
