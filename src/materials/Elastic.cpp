#include "materials/Elastic.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "materials/BondOptions.hpp"
#include "materials/HalfLps.hpp"
#include "materials/ShearCorrection.hpp"
#include "solvers/TangentBlocks.hpp"

namespace peridot {

namespace {

struct Bond {
  double zeta, dY, Y[3];
};

inline Bond bondGeometry(const double* x, const double* y, int i, int j) {
  Bond b;
  double X[3];
  for (int d = 0; d < 3; ++d) {
    X[d] = x[3 * j + d] - x[3 * i + d];
    b.Y[d] = y[3 * j + d] - y[3 * i + d];
  }
  b.zeta = std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]);
  b.dY = std::sqrt(b.Y[0] * b.Y[0] + b.Y[1] * b.Y[1] + b.Y[2] * b.Y[2]);
  return b;
}

}  // namespace

Elastic::Elastic(ListReader& p) {
  density_ = p.positiveNumber("Density");
  mode_ = readPlaneMode(p);
  constants_ = readTwoElasticConstants(p);
  shearCorrection_ = p.boolean("Apply Shear Correction Factor", false);
  // Peridigm reads the hourglass coefficient only in its correspondence models; decks that
  // share one material block between model kinds carry it on LPS too.
  if (p.has("Hourglass Coefficient")) p.nonNegativeNumber("Hourglass Coefficient", 0.0);
  thermalExpansion_ = p.number("Thermal Expansion Coefficient", 0.0);
  if (mode_ != PlaneMode::ThreeD) {
    // The dilatation is the 3D volumetric strain (Le, Chan and Schwartz 2014): in plane stress
    // eps_zz = -nu/(1-nu) tr eps_2D, so theta = r tr eps_2D with r = (1-2nu)/(1-nu); in plane
    // strain r = 1. The in-plane energy 1/2 kappa (tr eps_2D)^2 becomes 1/2 (kappa/r^2) theta^2.
    const double nu = constants_.poissonsRatio;
    const double r = mode_ == PlaneMode::PlaneStress ? (1.0 - 2.0 * nu) / (1.0 - nu) : 1.0;
    thetaFactor_ = 2.0 * r;
    const double kappa = inPlaneBulkModulus(constants_.youngsModulus, nu, mode_);
    dilatationModulus_ = kappa / (r * r);
    deviatoricFactor_ = 8.0;
  } else {
    dilatationModulus_ = constants_.bulkModulus;
  }
  partialStress_ = p.boolean("Compute Partial Stress", false);
  // Peridigm's Elastic takes its Jacobian from Sacado unless this is false, and then by finite
  // differences: ours is analytic (the same values) unless this is false.
  analyticTangent_ = p.boolean("Apply Automatic Differentiation Jacobian", true);
  acceptCommonMaterialKeys(p, true, true, true);
}

void Elastic::declareFields(FieldManager& fields) {
  weightedVolume_ = fields.node(kWeightedVolume, 1);
  dilatation_ = fields.node(kDilatation, 1);
  bulk_ = fields.node(kBulkModulus, 1);
  alpha_ = fields.node(kAlpha, 1);
  beta_ = fields.node(kBeta, 1);
  if (partialStress_) partialStressField_ = fields.node(kPartialStress, 9);
}

void Elastic::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, "Elastic");
  checkAssumedInfluenceFunction(s);
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    double m = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      double zetaSquared = 0;
      for (int d = 0; d < 3; ++d) {
        const double X = s.x[3 * j + d] - s.x[3 * i + d];
        zetaSquared += X * X;
      }
      const double omega = s.influence ? s.influence[b] : 1.0;
      if (s.topology->ownSide(b)) m += omega * zetaSquared * s.volume[j];
    }
    weightedVolume_[i] = m;
    bulk_[i] = dilatationModulus_;
    // A point without bonds has no weighted volume and exerts no force.
    alpha_[i] = m > 0 ? deviatoricFactor_ * constants_.shearModulus / m : 0.0;
    if (shearCorrection_ && m > 0)
      alpha_[i] *= shearCorrectionFactor(s, i, m, thetaFactor_, deviatoricFactor_);
    // beta = B c / m - alpha / c (3D: 3 K / m - alpha / 3).
    beta_[i] = m > 0 ? thetaFactor_ * dilatationModulus_ / m - alpha_[i] / thetaFactor_ : 0.0;
  }
}

// The kernels below keep Peridigm's order of floating-point operations per bond entry, so that
// small cases reproduce its gold results to the last bits.
void Elastic::precompute(const ModelState& s, const std::vector<int>& points) {
  if (s.halfBonds) {  // every owned point's, whatever `points` (blocks sharing this material)
    halfLpsDilatation(s, weightedVolume_, thetaFactor_, dilatation_);
    return;
  }
  // The block's critical stretch, when the evaluator fuses it here (breaksInPrecompute).
  const bool breaks = s.breakableBondDamage != nullptr;
  withBondOptions(s, [&](auto o) {
    using O = decltype(o);
    if (s.thermalStrain) {
      if (O::damage && breaks)
        dilatationLoop<O::influence, O::damage, O::sides, true, true>(s, points);
      else
        dilatationLoop<O::influence, O::damage, O::sides, true, false>(s, points);
    } else if (O::damage && breaks) {
      dilatationLoop<O::influence, O::damage, O::sides, false, true>(s, points);
    } else {
      dilatationLoop<O::influence, O::damage, O::sides, false, false>(s, points);
    }
  });
}

// kBreak: the fused critical stretch. A bond whose stretch (|Y| - |xi|) / |xi| exceeds it gets
// bond damage 1 before it enters the dilatation, the stretch computed as the separate damage
// pass computes it (damage/CriticalStretch.cpp; the material's thermal strain does not enter
// it), so that the same bonds break, and the damage pass's walk over the bonds is saved.
template <bool kInfluence, bool kDamage, bool kSides, bool kThermal, bool kBreak>
void Elastic::dilatationLoop(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double criticalStretch = s.fusedCriticalStretch;
  float* breakable = s.breakableBondDamage;
  // A row's terms, then their sum in order: the vectorizer may split a reduction into partial
  // sums in different ways for the fused and the unfused loop (AVX-512 builds do), and the two
  // must give the same bits.
  thread_local std::vector<double> terms;
  for (int i : points) {
    const double m = weightedVolume_[i];
    const double yi0 = s.y[3 * i], yi1 = s.y[3 * i + 1], yi2 = s.y[3 * i + 2];
    const double strainI = kThermal ? s.thermalStrain[i] : 0.0;
    const std::int64_t b0 = offsets[i];
    if (terms.size() < static_cast<std::size_t>(offsets[i + 1] - b0))
      terms.resize(static_cast<std::size_t>(offsets[i + 1] - b0));
    double* term = terms.data();
#pragma omp simd
    for (std::int64_t b = b0; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = s.y[3 * j] - yi0, Y1 = s.y[3 * j + 1] - yi1, Y2 = s.y[3 * j + 2] - yi2;
      const double dY = std::sqrt(sumOfSquares(Y0, Y1, Y2));
      const double zeta = s.bondLength[b];
      const double omega = kInfluence ? s.influence[b] : 1.0;
      double intact = 1.0;
      if constexpr (kBreak) {
        const bool broken = (dY - zeta) / zeta > criticalStretch;
        const float d = broken ? 1.0f : breakable[b];
        if (broken) breakable[b] = 1.0f;  // a masked store: intact bonds' lines stay clean
        intact = 1.0 - d;
      } else if constexpr (kDamage) {
        intact = 1.0 - s.bondDamage[b];
      }
      const double own = kSides ? (s.bondSides[b] & 1) : 1.0;  // adds +0 where not own
      double e = dY - zeta;
      if (kThermal) e -= strainI * zeta;
      term[b - b0] = own * (thetaFactor_ * omega * intact * zeta * e * s.volume[j] / m);
    }
    double theta = 0;
    for (std::int64_t b = b0; b < offsets[i + 1]; ++b) theta += term[b - b0];
    // A point without bonds has no weighted volume and no dilatation.
    dilatation_[i] = m > 0 ? theta : 0.0;
  }
}

void Elastic::computeForce(const ModelState& s, const std::vector<int>& points) {
  const bool smooth = s.bondLaw.kind == BondLaw::Kind::Smooth;
  const bool thermal = s.thermalStrain != nullptr;
  // theta beta of every point a bond can reach (own and ghost), once per point instead of once
  // per bond entry: one gathered load a bond less, the same product.
  thetaBeta_.resize(static_cast<std::size_t>(s.topology->numOverlap));
  for (int p = 0; p < s.topology->numOverlap; ++p) thetaBeta_[p] = dilatation_[p] * beta_[p];
  if (s.halfBonds) {
    halfLpsForce(s, thetaBeta_.data(), alpha_);
    return;
  }
  withBondOptions(s, [&](auto o) {
    using O = decltype(o);
    if (smooth)  // thermal strains with a smooth law are refused at set-up
      forceLoop<true, O::influence, O::damage, O::sides, false>(s, points);
    else if (thermal)
      forceLoop<false, O::influence, O::damage, O::sides, true>(s, points);
    else
      forceLoop<false, O::influence, O::damage, O::sides, false>(s, points);
  });
  if (partialStress_) partialStressLoop(s, points);
}

// Peridigm's partial stress: sum over the point's own bonds of its own force state's pair force
// t_i Y/|Y| times the reference bond xi and the neighbour's volume (row: force component, column:
// xi component). Only the point's own half of each bond force enters, as in Peridigm. A separate
// pass, off the force loop: a run pays for it only when it asks.
void Elastic::partialStressLoop(const ModelState& s, const std::vector<int>& points) const {
  const bool smooth = s.bondLaw.kind == BondLaw::Kind::Smooth;
  for (int i : points) {
    double P[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    const double thetaBetaI = dilatation_[i] * beta_[i], alphaI = alpha_[i];
    const double strainI = s.thermalStrain ? s.thermalStrain[i] : 0.0;
    for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
      if (s.bondSides && !(s.bondSides[b] & 1)) continue;
      const int j = s.topology->neighbors[b];
      const Bond g = bondGeometry(s.x, s.y, i, j);
      if (!(g.dY > 0)) continue;
      const double omega = s.influence ? s.influence[b] : 1.0;
      const double intact = intactFraction(s, b);
      double t;
      if (smooth) {
        t = intact * omega * g.zeta *
            (thetaBetaI + alphaI * s.bondLaw.forceScalar((g.dY - g.zeta) / g.zeta));
      } else {
        const double e = g.dY - g.zeta - strainI * g.zeta;
        t = intact * (omega * thetaBetaI * g.zeta + intact * omega * alphaI * e);
      }
      const double scale = t / g.dY * s.volume[j];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          P[3 * r + c] += scale * g.Y[r] * (s.x[3 * j + c] - s.x[3 * i + c]);
    }
    std::copy(P, P + 9, partialStressField_ + 9 * static_cast<std::size_t>(i));
  }
}

// kSmooth: LPS-T (paper 001 eq. 15), t = (1 - d) omega zeta (beta theta + alpha F(s)), with the
// dilatation of the surviving bond parts (precompute). Otherwise Peridigm's LPS, as it was.
template <bool kSmooth, bool kInfluence, bool kDamage, bool kSides, bool kThermal>
void Elastic::forceLoop(const ModelState& s, const std::vector<int>& points) const {
  const BondLaw law = s.bondLaw;
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* thetaBeta = thetaBeta_.data();
  const double* alpha = alpha_;
  const double* y = s.y;
  const double* volume = s.volume;
  const double* zeta = s.bondLength;
  const double* omegaOf = s.influence;
  const float* damage = s.bondDamage;
  for (int i : points) {
    double f0 = 0, f1 = 0, f2 = 0;
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    const double thetaBetaI = thetaBeta[i], alphaI = alpha[i];
    const double* strain = s.thermalStrain;
    const double strainI = kThermal ? strain[i] : 0.0;
#pragma omp simd reduction(+ : f0, f1, f2)
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      // Coincident ends have no direction and, with Y = 0, add +0 (divided by 1): no branch.
      const double length = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
      const double dY = length > 0 ? length : 1.0;
      const double omega = kInfluence ? omegaOf[b] : 1.0;
      const double intact = kDamage ? 1.0 - damage[b] : 1.0;
      const double e = length - zeta[b];
      // Force state of i on the bond and of j on the reversed bond (pull form: each point sums
      // only its own list, in global-id order, whatever the rank count), each term as Peridigm
      // forms it so that two-point cases reproduce its gold results to the last bits.
      double ti, tj;
      if constexpr (kSmooth) {
        const double F = law.forceScalar(e / zeta[b]);
        ti = intact * omega * zeta[b] * (thetaBetaI + alphaI * F);
        tj = intact * omega * zeta[b] * (thetaBeta[j] + alpha[j] * F);
      } else if constexpr (kThermal) {
        // Each end's extension less its own thermal part (Peridigm: e -= alpha Delta T zeta).
        double ei = e, ej = e;
        ei -= strainI * zeta[b];
        ej -= strain[j] * zeta[b];
        ti = intact * (omega * thetaBetaI * zeta[b] + intact * omega * alphaI * ei);
        tj = intact * (omega * thetaBeta[j] * zeta[b] + intact * omega * alpha[j] * ej);
      } else {
        ti = intact * (omega * thetaBetaI * zeta[b] + intact * omega * alphaI * e);
        tj = intact * (omega * thetaBeta[j] * zeta[b] + intact * omega * alpha[j] * e);
      }
      if constexpr (kSides) {  // an end whose horizon does not hold the bond exerts no force
        ti *= s.bondSides[b] & 1;
        tj *= (s.bondSides[b] >> 1) & 1;
      }
      const double vj = volume[j];
      f0 += ti * Y0 / dY * vj;
      f1 += ti * Y1 / dY * vj;
      f2 += ti * Y2 / dY * vj;
      f0 += tj * Y0 / dY * vj;
      f1 += tj * Y1 / dY * vj;
      f2 += tj * Y2 / dY * vj;
    }
    s.forceDensity[3 * i] = f0;
    s.forceDensity[3 * i + 1] = f1;
    s.forceDensity[3 * i + 2] = f2;
  }
}

// Tangent of the linear LPS force, family by family. Family i exerts on i the sum over its bonds
// of p_b = t_b V_j n_b, and on each neighbour j the reaction -(V_i / V_j) p_b, with
//   t_b = own (1-d) omega (beta_i theta_i zeta + (1-d) alpha_i e_b),  e_b = |Y_b| - zeta,
//   theta_i = c/m sum_b own omega (1-d) zeta e_b V_j   (own: the bond is in i's horizon).
// With n_b = Y_b/|Y_b|, g_b = c/m own omega (1-d) zeta V_j (d theta/d y_j = g_b n_b^T) and
// h_b = own (1-d) omega beta_i zeta (d t_b/d theta):
//   d p_b / d y_j(c) = delta_bc D_b + V_j(b) h_b g_c n_b n_c^T,
//   D_b = V_j [own (1-d)^2 omega alpha_i n n^T + t_b (I - n n^T)/|Y_b|],
// and d/d y_i is minus the sum over c (translation invariance). Stiffness K = -V_row d f/d y;
// every family's contribution is symmetric.
void Elastic::addStiffness(const ModelState& s, const std::vector<int>& points,
                           TangentBlocks& K) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  std::vector<double> n, D, g, h;  // per bond of the family, reused
  for (int i : points) {
    const std::int64_t first = offsets[i], count = offsets[i + 1] - first;
    const double m = weightedVolume_[i];
    if (!(m > 0) || count == 0) continue;
    n.assign(3 * count, 0.0);
    D.assign(9 * count, 0.0);
    g.assign(count, 0.0);
    h.assign(count, 0.0);
    const double vi = s.volume[i];
    double G[3] = {0, 0, 0}, S[3] = {0, 0, 0};  // sum g_c n_c; sum V_j h_b n_b
    for (std::int64_t k = 0; k < count; ++k) {
      const std::int64_t b = first + k;
      const int j = neighbors[b];
      double Y[3];
      for (int d = 0; d < 3; ++d) Y[d] = s.y[3 * j + d] - s.y[3 * i + d];
      const double length = std::sqrt(Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2]);
      if (!(length > 0)) continue;  // no direction: no force, no stiffness (as the force loop)
      const double own = s.bondSides ? (s.bondSides[b] & 1) : 1.0;
      const double omega = s.influence ? s.influence[b] : 1.0;
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double zeta = bondLengthOf(s, i, b);  // not stored with the half list
      const double vj = s.volume[j];
      const double t =
          own * intact *
          (omega * dilatation_[i] * beta_[i] * zeta + intact * omega * alpha_[i] * (length - zeta));
      const double a = own * intact * intact * omega * alpha_[i];
      for (int d = 0; d < 3; ++d) n[3 * k + d] = Y[d] / length;
      const double* nb = &n[3 * k];
      for (int r = 0; r < 3; ++r)
        for (int e = 0; e < 3; ++e)
          D[9 * k + 3 * r + e] =
              vj * (a * nb[r] * nb[e] + t * ((r == e ? 1.0 : 0.0) - nb[r] * nb[e]) / length);
      g[k] = thetaFactor_ / m * own * omega * intact * zeta * vj;
      h[k] = own * intact * omega * beta_[i] * zeta;
      for (int d = 0; d < 3; ++d) {
        G[d] += g[k] * nb[d];
        S[d] += vj * h[k] * nb[d];
      }
    }
    // Row i: K_i,j(c) = -V_i (D_c + g_c S n_c^T), K_ii = -sum_c K_i,j(c).
    double Dsum[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (std::int64_t k = 0; k < count; ++k) {
      const int j = neighbors[first + k];
      K.add(i, j, -vi, &D[9 * k]);
      K.addOuter(i, j, -vi * g[k], S, &n[3 * k]);
      for (int r = 0; r < 9; ++r) Dsum[r] += D[9 * k + r];
    }
    K.add(i, i, vi, Dsum);
    K.addOuter(i, i, vi, S, G);
    // Rows j(b): K_jj += V_i D_b, K_ji -= V_i D_b, K_j,j(c) += V_i V_j h_b g_c n_b n_c^T,
    // K_ji -= V_i V_j h_b n_b G^T.
    for (std::int64_t k = 0; k < count; ++k) {
      const int j = neighbors[first + k];
      const double vj = s.volume[j];
      K.add(j, j, vi, &D[9 * k]);
      K.add(j, i, -vi, &D[9 * k]);
      const double coupling = vi * vj * h[k];
      if (coupling == 0.0) continue;
      for (std::int64_t l = 0; l < count; ++l) {
        if (g[l] == 0.0) continue;
        K.addOuter(j, neighbors[first + l], coupling * g[l], &n[3 * k], &n[3 * l]);
      }
      K.addOuter(j, i, -coupling, &n[3 * k], G);
    }
  }
}

void Elastic::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                  double* energyDensity) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  if (s.bondLaw.kind == BondLaw::Kind::Smooth) {
    smoothEnergyDensity(s, points, energyDensity);
    return;
  }
  for (int i : points) {
    const double mi = weightedVolume_[i];
    double deviatoric = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const Bond g = bondGeometry(s.x, s.y, i, j);
      if (!s.topology->ownSide(b)) continue;
      const double thermal = s.thermalStrain ? s.thermalStrain[i] * g.zeta : 0.0;
      const double ed = g.dY - g.zeta - thermal - dilatation_[i] * g.zeta / thetaFactor_;
      double w = ed * ed * s.volume[j];
      if (s.influence) w *= s.influence[b];
      if (s.bondDamage) w *= 1.0 - s.bondDamage[b];
      deviatoric += w;
    }
    energyDensity[i] = 0.5 * bulk_[i] * dilatation_[i] * dilatation_[i] +
                       (mi > 0 ? 0.5 * alpha_[i] * deviatoric : 0.0);
  }
}

// LPS-T energy: W = 1/2 (beta m / c) theta^2 + alpha sum_j omega (1 - d) zeta^2 p(s) V_j, whose
// derivative with respect to the extension of a bond (d held fixed) is the LPS-T force state
// (1 - d) omega zeta (beta theta + alpha F(s)) (theta = c/m sum omega (1-d) zeta e V). Undamaged
// and with p = s^2/2 it is the LPS energy above.
void Elastic::smoothEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                  double* energyDensity) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    const double mi = weightedVolume_[i];
    if (!(mi > 0)) {
      energyDensity[i] = 0.0;
      continue;
    }
    double bonds = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      if (!s.topology->ownSide(b)) continue;
      const int j = neighbors[b];
      const Bond g = bondGeometry(s.x, s.y, i, j);
      double w = g.zeta * g.zeta * s.bondLaw.potential((g.dY - g.zeta) / g.zeta) * s.volume[j];
      if (s.influence) w *= s.influence[b];
      if (s.bondDamage) w *= 1.0 - s.bondDamage[b];
      bonds += w;
    }
    energyDensity[i] =
        0.5 * beta_[i] * mi / thetaFactor_ * dilatation_[i] * dilatation_[i] + alpha_[i] * bonds;
  }
}

PERIDOT_REGISTER_MATERIAL(
    "Elastic", Elastic,
    "Linear peridynamic solid (LPS), ordinary state-based; free Poisson's ratio",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Plane Stress",
         "bool, default false: 2D LPS in plane stress (Le et al. 2014): theta = 2(1-2nu)/(1-nu) "
         "/ m sum omega zeta e V, alpha = 8 G / m; needs a planar discretization"},
        {"Plane Strain",
         "bool, default false: 2D LPS in plane strain: theta = 2 / m sum omega zeta e V, "
         "alpha = 8 G / m"},
        {"Apply Shear Correction Factor",
         "bool, default false: scale the deviatoric modulus of each point so that pure shear of "
         "its discrete neighbourhood stores the continuum energy (Peridigm's option; in 2D the "
         "one in-plane shear mode)"},
        {"Apply Automatic Differentiation Jacobian",
         "bool, default true: the implicit solvers' tangent is analytic; false: probed by finite "
         "differences (as Peridigm without Sacado)"},
        {"Thermal Expansion Coefficient",
         "number, default 0: alpha; with a Prescribed Temperature every bond's extension is taken "
         "less alpha Delta T |xi| (Delta T of the end whose force state it is), in the "
         "dilatation and the force, as Peridigm"},
        {"Compute Partial Stress",
         "bool, default false: true maintains Peridigm's partial stress, sum over the point's "
         "bonds of its own pair force t Y/|Y| (x) xi V_j, as the output Partial_Stress"},
        {"Finite Difference Probe Length",
         "positive number: accepted; the probe is Solver -> Finite Difference Probe Length"},
        {"Hourglass Coefficient",
         "number >= 0: accepted and ignored (Peridigm reads it only in correspondence models)"}}))

}  // namespace peridot
