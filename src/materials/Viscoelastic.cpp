#include "materials/Viscoelastic.hpp"

#include <cmath>
#include <type_traits>

#include "core/Error.hpp"

namespace peridot {

Viscoelastic::Viscoelastic(ListReader& p) {
  density_ = p.positiveNumber("Density");
  constants_ = readTwoElasticConstants(p);
  lambdaI_ = p.number("lambda_i");
  if (!(lambdaI_ >= 0.0 && lambdaI_ <= 1.0))
    throw InputError(p.pathOf("lambda_i"), "expected a number in [0, 1]");
  tauB_ = p.positiveNumber("tau b");
  // Peridigm refuses both for this model.
  for (const char* k :
       {"Apply Shear Correction Factor", "Apply Automatic Differentiation Jacobian"})
    if (p.has(k)) throw InputError(p.pathOf(k), "not supported for the Viscoelastic material");
  acceptCommonMaterialKeys(p, false);
}

void Viscoelastic::declareFields(FieldManager& fields) {
  weightedVolume_ = fields.node(kWeightedVolume, 1);
  dilatation_ = fields.node(kDilatation, 1);
  fields.bond(kBackExtension);
  fields.bond(kDeviatoricExtension);
  fields.bond(kNeighborBackExtension);
  fields.bond(kNeighborDeviatoricExtension);
}

void Viscoelastic::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, "Viscoelastic");
  if (s.influence) {
    throw InputError("Discretization",
                     "the Viscoelastic model uses omega = 1 (as Peridigm's kernel does): "
                     "influence functions other than \"One\" and partial volumes are not "
                     "supported with it");
  }
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  for (int i : points) {
    double m = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b)
      if (s.topology->ownSide(b))
        m += s.bondLength[b] * s.bondLength[b] * s.volume[s.topology->neighbors[b]];
    weightedVolume_[i] = m;
  }
}

void Viscoelastic::precompute(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    const double m = weightedVolume_[i];
    double theta = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      if (!s.topology->ownSide(b)) continue;
      const int j = neighbors[b];
      double Y[3];
      for (int d = 0; d < 3; ++d) Y[d] = s.y[3 * j + d] - s.y[3 * i + d];
      const double dY = std::sqrt(Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2]);
      const double zeta = s.bondLength[b];
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      theta += 3.0 * intact * zeta * (dY - zeta) * s.volume[j] / m;
    }
    dilatation_[i] = m > 0 ? theta : 0.0;
  }
}

void Viscoelastic::computeForce(const ModelState& s, const std::vector<int>& points) {
  if (!s.commitHistory) {
    withDamageAndSides<false>(s, points);
    return;
  }
  withDamageAndSides<true>(s, points);
}

template <bool kCommit>
void Viscoelastic::withDamageAndSides(const ModelState& s, const std::vector<int>& points) {
  if (s.bondDamage) {
    if (s.bondSides)
      forceLoop<true, true, kCommit>(s, points);
    else
      forceLoop<true, false, kCommit>(s, points);
  } else {
    if (s.bondSides)
      forceLoop<false, true, kCommit>(s, points);
    else
      forceLoop<false, false, kCommit>(s, points);
  }
}

template <bool kDamage, bool kSides, bool kCommit>
void Viscoelastic::forceLoop(const ModelState& s, const std::vector<int>& points) {
  // Exact integration of tau de^b/dt = e^d - e^b over a step with e^d linear in time. For
  // dt -> 0 (no step yet) beta -> dt / (2 tau) -> 0 and D -> 1: the back state does not move.
  const double r = s.dt > 0 ? s.dt / tauB_ : 0.0;
  const double decay = std::exp(-r);
  const double beta = r > 1e-8 ? 1.0 - (1.0 - decay) / r : 0.5 * r;
  const double G = constants_.shearModulus, K = constants_.bulkModulus, li = lambdaI_;
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  double* ebI = s.fields->bond(kBackExtension).data();
  double* edI = s.fields->bond(kDeviatoricExtension).data();
  double* ebJ = s.fields->bond(kNeighborBackExtension).data();
  double* edJ = s.fields->bond(kNeighborDeviatoricExtension).data();
  const double* m = weightedVolume_;
  const double* theta = dilatation_;
  for (int i : points) {
    double f0 = 0, f1 = 0, f2 = 0;
    const double yi0 = s.y[3 * i], yi1 = s.y[3 * i + 1], yi2 = s.y[3 * i + 2];
    const double alphaI = m[i] > 0 ? 15.0 * G / m[i] : 0.0;
    const double isoI = m[i] > 0 ? 3.0 * K * theta[i] / m[i] : 0.0;
#pragma omp simd reduction(+ : f0, f1, f2)
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = s.y[3 * j] - yi0, Y1 = s.y[3 * j + 1] - yi1, Y2 = s.y[3 * j + 2] - yi2;
      const double length = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
      const double dY = length > 0 ? length : 1.0;
      const double zeta = s.bondLength[b];
      const double intact = kDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double alphaJ = m[j] > 0 ? 15.0 * G / m[j] : 0.0;
      const double isoJ = m[j] > 0 ? 3.0 * K * theta[j] / m[j] : 0.0;
      // Damage enters the deviatoric extension (and through it the back extension), as in
      // Peridigm; the same bond damage is taken for both ends of the step.
      const double edNewI = intact * (length - zeta) - theta[i] * zeta / 3.0;
      const double edNewJ = intact * (length - zeta) - theta[j] * zeta / 3.0;
      const double ebNewI = edI[b] * (1.0 - decay) + ebI[b] * decay + beta * (edNewI - edI[b]);
      const double ebNewJ = edJ[b] * (1.0 - decay) + ebJ[b] * decay + beta * (edNewJ - edJ[b]);
      const double tdI = alphaI * ((1.0 - li) * edNewI + li * (edNewI - ebNewI));
      const double tdJ = alphaJ * ((1.0 - li) * edNewJ + li * (edNewJ - ebNewJ));
      double ti = intact * (isoI * zeta + tdI);
      double tj = intact * (isoJ * zeta + tdJ);
      if constexpr (kSides) {
        ti *= s.bondSides[b] & 1;
        tj *= (s.bondSides[b] >> 1) & 1;
      }
      if constexpr (kCommit) {
        edI[b] = edNewI;
        ebI[b] = ebNewI;
        edJ[b] = edNewJ;
        ebJ[b] = ebNewJ;
      }
      const double vj = s.volume[j];
      f0 += (ti + tj) * Y0 / dY * vj;
      f1 += (ti + tj) * Y1 / dY * vj;
      f2 += (ti + tj) * Y2 / dY * vj;
    }
    s.forceDensity[3 * i] = f0;
    s.forceDensity[3 * i + 1] = f1;
    s.forceDensity[3 * i + 2] = f2;
  }
}

void Viscoelastic::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                       double* energyDensity) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* eb = s.fields->bond(kBackExtension).data();
  for (int i : points) {
    const double m = weightedVolume_[i];
    double deviatoric = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      if (!s.topology->ownSide(b)) continue;
      const int j = neighbors[b];
      double Y[3];
      for (int d = 0; d < 3; ++d) Y[d] = s.y[3 * j + d] - s.y[3 * i + d];
      const double dY = std::sqrt(Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2]);
      const double zeta = s.bondLength[b];
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double ed = intact * (dY - zeta) - dilatation_[i] * zeta / 3.0;
      deviatoric += intact * ((1.0 - lambdaI_) * ed * ed + lambdaI_ * (ed - eb[b]) * (ed - eb[b])) *
                    s.volume[j];
    }
    energyDensity[i] = 0.5 * constants_.bulkModulus * dilatation_[i] * dilatation_[i] +
                       (m > 0 ? 0.5 * 15.0 * constants_.shearModulus / m * deviatoric : 0.0);
  }
}

PERIDOT_REGISTER_MATERIAL(
    "Viscoelastic", Viscoelastic,
    "Ordinary state-based standard linear solid (Mitchell): LPS with one relaxing deviatoric "
    "branch",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G (the instantaneous deviatoric modulus)"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"lambda_i",
         "number in [0, 1], required: fraction of the deviatoric modulus carried by the relaxing "
         "(Maxwell) branch; the long-time shear modulus is (1 - lambda_i) G"},
        {"tau b", "positive number, required: relaxation time of the branch"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported"},
        {"Finite Difference Probe Length",
         "positive number: accepted; the probe is Solver -> Finite Difference Probe Length"}}))

}  // namespace peridot
