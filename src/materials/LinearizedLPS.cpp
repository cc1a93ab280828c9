#include "materials/LinearizedLPS.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "core/MulAdd.hpp"
#include "materials/LinearizedLpsRows.hpp"

namespace peridot {

LinearizedLPS::LinearizedLPS(ListReader& p) {
  density_ = p.positiveNumber("Density");
  mode_ = readPlaneMode(p);
  constants_ = readTwoElasticConstants(p);
  acceptCommonMaterialKeys(p);
  const double E = constants_.youngsModulus, nu = constants_.poissonsRatio;
  const double G = constants_.shearModulus;
  const double lambda = constants_.bulkModulus - 2.0 * G / 3.0;
  // Matching W = A/2 theta^2 + c2/2 sum omega |xi|^2 eps^2 V to the continuum energy of every
  // homogeneous strain (doc/theory/damage.md): m c2 = d (d + 2) G, A = (lambda_eff - G)(d/kappa)^2,
  // c1 = A kappa, with lambda_eff the in-plane Lame constant.
  switch (mode_) {
    case PlaneMode::ThreeD:
      kappa_ = 3.0;
      c2m_ = 15.0 * G;
      c1_ = 3.0 * (lambda - G);
      break;
    case PlaneMode::PlaneStrain:
      kappa_ = 2.0;
      c2m_ = 8.0 * G;
      c1_ = 2.0 * (lambda - G);
      break;
    case PlaneMode::PlaneStress:
      // theta is the 3D dilatation: the out-of-plane strain is -nu/(1 - nu) tr(eps_2D).
      kappa_ = 2.0 * (1.0 - 2.0 * nu) / (1.0 - nu);
      c2m_ = 8.0 * G;
      c1_ = E * (1.0 - 3.0 * nu) / ((1.0 + nu) * (2.0 * nu - 1.0));
      break;
  }
}

void LinearizedLPS::declareFields(FieldManager& fields) {
  weightedVolume_ = fields.node(kWeightedVolume, 1);
  dilatation_ = fields.node(kDilatation, 1);
  alpha_ = fields.node(kAlpha, 1);
  beta_ = fields.node(kBeta, 1);
}

void LinearizedLPS::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, "Linearized LPS");
  checkAssumedInfluenceFunction(s);
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    double m = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      if (!s.topology->ownSide(b)) continue;
      const double omega = s.influence ? s.influence[b] : 1.0;
      m += omega * s.bondLength[b] * s.bondLength[b] * s.volume[neighbors[b]];
    }
    weightedVolume_[i] = m;
    // A point without bonds has no weighted volume and exerts no force.
    alpha_[i] = m > 0 ? c2m_ / m : 0.0;
    beta_[i] = m > 0 ? c1_ / m : 0.0;
  }
}

void LinearizedLPS::precompute(const ModelState& s, const std::vector<int>& points) {
  // The block's damage, when the evaluator fuses it here (breaksInPrecompute): LSJ-T's update
  // (its first evaluation updates nothing: inactive) or DTT's broken fraction.
  if (s.fusedLsjt.active())
    dilatationLoop<Fused::Lsjt>(s, points);
  else if (s.breakableBondDamage && s.bondLaw.kind == BondLaw::Kind::Smooth)
    dilatationLoop<Fused::Dtt>(s, points);
  else
    dilatationLoop<Fused::None>(s, points);
}

// theta_i = (kappa / m_i) sum_j omega mu xi.eta V_j over the bonds in i's own horizon. With
// kFused the loop first updates the damage of every bond entry of i (one-sided ones too: the
// force reads them) with the very functions of the separate damage pass (LSJ-T's
// lsjtStrains / lsjtUpdateBonds, DTT's raiseBrokenFractions), so the same bits, and that pass's
// walk over the bond arrays is saved: the sum reads i's entries again from the cache. The update
// loops vectorize; the sum forms its terms four bonds at a time in vector lanes and adds them in
// order (materials/LinearizedLpsRows.hpp: the bits of the one-pass scalar loop).
template <LinearizedLPS::Fused kFused>
void LinearizedLPS::dilatationLoop(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* x = s.x;
  const double* y = s.y;
  const LsjtStep lsjt = s.fusedLsjt;
  float* breakable = s.breakableBondDamage;
  llps::DilatationInputs in;
  in.neighbors = neighbors;
  in.x = x;
  in.y = y;
  in.volume = s.volume;
  in.influence = s.influence;
  in.damage = kFused == Fused::None ? s.bondDamage : breakable;
  in.sides = s.bondSides;
  const llps::DilatationRow rowSum = llps::dilatationRow(in, kFused == Fused::Lsjt);
  double *dot = nullptr, *eps = nullptr, *integral = nullptr;
  if constexpr (kFused == Fused::Lsjt) {
    std::int64_t family = 0;
    for (int i : points) family = std::max(family, offsets[i + 1] - offsets[i]);
    scratch_.resize(3 * static_cast<std::size_t>(family));
    dot = scratch_.data();
    eps = dot + family;
    integral = eps + family;
  }
  for (int i : points) {
    const std::int64_t b0 = offsets[i], b1 = offsets[i + 1];
    if constexpr (kFused == Fused::Lsjt) {
      if (lsjtStrains(x, y, neighbors, s.bondLength, i, b0, b1, dot, eps, lsjt.criticalStretch))
        lsjtUpdateBonds(lsjt, b0, b1, eps, integral, breakable);
    } else if constexpr (kFused == Fused::Dtt) {
      raiseBrokenFractions(s.bondLaw, y, neighbors, s.bondLength, i, b0, b1, breakable);
    }
    const double m = weightedVolume_[i];
    const double sum = rowSum(in, i, b0, b1, dot);
    dilatation_[i] = m > 0 ? kappa_ * sum / m : 0.0;
  }
}

void LinearizedLPS::computeForce(const ModelState& s, const std::vector<int>& points) {
  llps::force(s, points, dilatation_, alpha_, beta_);
}

void LinearizedLPS::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                        double* energyDensity) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  // W = c1 / (2 kappa) theta^2 + c2 sum omega |xi|^2 p(eps) mu V, p' = F (p = eps^2/2 when
  // linear): the potential of the force with mu once on the dilatation term.
  const double a = c1_ / (2.0 * kappa_);
  // The multiply-adds written out as an optimised build contracts them, so that every build
  // gives the same bits (an unoptimised one contracts none).
  for (int i : points) {
    double bonds = 0;
    const double *xi = s.x + 3 * i, *yi = s.y + 3 * i;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      if (!s.topology->ownSide(b)) continue;
      const int j = neighbors[b];
      const double *xj = s.x + 3 * j, *yj = s.y + 3 * j;
      const double X0 = xj[0] - xi[0], X1 = xj[1] - xi[1], X2 = xj[2] - xi[2];
      double dot = mulAdd(X0, (yj[0] - yi[0]) - X0, 0.0);
      dot = mulAdd(X1, (yj[1] - yi[1]) - X1, dot);
      dot = mulAdd(X2, (yj[2] - yi[2]) - X2, dot);
      const double z2 = s.bondLength[b] * s.bondLength[b];
      const double eps = dot / z2;
      const double omega = s.influence ? s.influence[b] : 1.0;
      const double mu = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      bonds = mulAdd(omega * z2 * s.bondLaw.potential(eps) * mu, s.volume[j], bonds);
    }
    energyDensity[i] = mulAdd(a * dilatation_[i], dilatation_[i], alpha_[i] * bonds);
  }
}

PERIDOT_REGISTER_MATERIAL(
    "Linearized LPS", LinearizedLPS,
    "Linearized peridynamic solid (paper 001 eqs. 17-19): linearized bond strain and "
    "dilatation, forces along the reference bond; 3D, plane stress or plane strain; with "
    "\"LSJ-T\" damage it is paper 001's LSJ-T model",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Plane Stress",
         "bool, default false: 2D plane stress (E and nu are the 3D constants; the dilatation is "
         "the 3D one)"},
        {"Plane Strain", "bool, default false: 2D plane strain"},
        {"Apply Automatic Differentiation Jacobian",
         "bool: accepted; the implicit tangent is probed by finite differences"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported yet"},
        {"Compute Partial Stress", "bool, default false: true is not supported yet"},
        {"Finite Difference Probe Length",
         "positive number: accepted; the probe is Solver -> Finite Difference Probe Length"}}))

}  // namespace peridot
