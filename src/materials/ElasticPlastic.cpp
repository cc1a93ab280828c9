#include "materials/ElasticPlastic.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

#include "core/Error.hpp"
#include "materials/ShearCorrection.hpp"

namespace peridot {

namespace {

const double kPi = 3.14159265358979323846;

// Calls loop.template operator()<kDamage, kSides>() for the state's options.
template <typename Loop>
void withDamageAndSides(const ModelState& s, Loop&& loop) {
  if (s.bondDamage) {
    if (s.bondSides)
      loop(std::true_type{}, std::true_type{});
    else
      loop(std::true_type{}, std::false_type{});
  } else {
    if (s.bondSides)
      loop(std::false_type{}, std::true_type{});
    else
      loop(std::false_type{}, std::false_type{});
  }
}

}  // namespace

double plasticMultiplierIncrement(double norm, double psi, double alpha, double H) {
  const double perfect = (norm / std::sqrt(2.0 * psi) - 1.0) / alpha;
  if (!(H > 0)) return perfect;
  // g(x) = 2 (1 + alpha x)^2 (psi + H x) - norm^2 is increasing and convex for x >= 0, g(0) < 0
  // and g(perfect) >= 0 (hardening only raises the yield value): Newton from `perfect` descends
  // monotonically onto the root.
  const double target = norm * norm;
  double x = perfect;
  for (int k = 0; k < 60; ++k) {
    const double a = 1.0 + alpha * x, y = psi + H * x;
    const double g = 2.0 * a * a * y - target;
    const double dg = 4.0 * alpha * a * y + 2.0 * a * a * H;
    const double next = x - g / dg;
    if (!(next < x)) break;  // converged: rounding stops the descent
    x = next;
  }
  return x > 0 ? x : 0.0;
}

ElasticPlastic::ElasticPlastic(ListReader& p, bool hardening)
    : name_(hardening ? "Elastic Plastic Hardening" : "Elastic Plastic") {
  density_ = p.positiveNumber("Density");
  constants_ = readTwoElasticConstants(p);
  yieldStress_ = p.positiveNumber("Yield Stress");
  plasticityDisabled_ = p.boolean("Disable Plasticity", false);
  if (hardening) {
    hardeningModulus_ = p.nonNegativeNumber("Hardening Modulus", -1.0);
    if (hardeningModulus_ < 0)
      throw InputError(p.pathOf("Hardening Modulus"), "required (a number >= 0)");
    shearCorrection_ = p.boolean("Apply Shear Correction Factor", false);
  }
  if (p.has("Planar Problem") && p.boolean("Planar Problem", false)) {
    throw InputError(p.pathOf("Planar Problem"),
                     "Peridigm's planar variant of the elastic-plastic model (3D kernel with a 2D "
                     "yield value) is not supported by Peridot");
  }
  if (p.has("Thickness")) {
    throw InputError(p.pathOf("Thickness"),
                     "only used with \"Planar Problem\", which is not supported");
  }
  acceptCommonMaterialKeys(p, hardening);
}

void ElasticPlastic::declareFields(FieldManager& fields) {
  weightedVolume_ = fields.node(kWeightedVolume, 1);
  dilatation_ = fields.node(kDilatation, 1);
  lambda_ = fields.node(kLambda, 1);
  moduli_ = fields.node(kModuli, 3);
  return_ = fields.node(kReturn, 3);
  fields.bond(kPlasticExtension);
  fields.bond(kNeighborPlasticExtension);
}

void ElasticPlastic::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, name_);
  if (s.influence) {
    throw InputError("Discretization",
                     "the elastic-plastic models use omega = 1 (as Peridigm's kernel does): "
                     "influence functions other than \"One\" and partial volumes are not "
                     "supported with them");
  }
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    double m = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b)
      if (s.topology->ownSide(b)) m += s.bondLength[b] * s.bondLength[b] * s.volume[neighbors[b]];
    weightedVolume_[i] = m;
    double alpha = m > 0 ? 15.0 * constants_.shearModulus / m : 0.0;
    // Peridigm's hardening model scales alpha by the shear correction factor and the yield value
    // by its square (the same yield stress on the corrected neighbourhood).
    const double scf = shearCorrection_ && m > 0 ? shearCorrectionFactor(s, i, m, 3.0, 15.0) : 1.0;
    alpha *= scf;
    const double delta = s.horizon[i];
    const double psi0 = plasticityDisabled_ ? std::numeric_limits<double>::infinity()
                                            : scf * scf * 25.0 * yieldStress_ * yieldStress_ /
                                                  (8.0 * kPi * std::pow(delta, 5));
    moduli_[3 * i] = alpha;
    moduli_[3 * i + 1] = m > 0 ? 3.0 * constants_.bulkModulus / m : 0.0;
    moduli_[3 * i + 2] = psi0;
    return_[3 * i + 1] = 1.0;
  }
}

void ElasticPlastic::precompute(const ModelState& s, const std::vector<int>& points) {
  withDamageAndSides(s, [&](auto damage, auto sides) {
    precomputeLoop<decltype(damage)::value, decltype(sides)::value>(s, points);
  });
}

// Dilatation, then the trial deviatoric force state's norm from the history of the last step,
// then the return mapping of the point: scale 1 / (1 + alpha dLambda) and dLambda. Nothing is
// written to the history here (precompute may be repeated); computeForce commits it.
template <bool kDamage, bool kSides>
void ElasticPlastic::precomputeLoop(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* edp = s.fields->bond(kPlasticExtension).data();
  const double* y = s.y;
  for (int i : points) {
    const double m = weightedVolume_[i];
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    double theta = 0;
#pragma omp simd reduction(+ : theta)
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      const double dY = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
      const double zeta = s.bondLength[b];
      const double intact = kDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double own = kSides ? (s.bondSides[b] & 1) : 1.0;
      theta += own * (3.0 * intact * zeta * (dY - zeta) * s.volume[j] / m);
    }
    theta = m > 0 ? theta : 0.0;
    const double alpha = moduli_[3 * i];
    double normSquared = 0;
#pragma omp simd reduction(+ : normSquared)
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      const double dY = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
      const double zeta = s.bondLength[b];
      const double intact = kDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double own = kSides ? (s.bondSides[b] & 1) : 1.0;
      const double td = intact * alpha * (dY - zeta - theta * zeta / 3.0 - edp[b]);
      normSquared += own * td * td * s.volume[j];
    }
    const double psi = moduli_[3 * i + 2] + hardeningModulus_ * lambda_[i];
    double scale = 1.0, increment = 0.0;
    if (m > 0 && normSquared / 2.0 - psi > 0) {
      increment = plasticMultiplierIncrement(std::sqrt(normSquared), psi, alpha, hardeningModulus_);
      scale = 1.0 / (1.0 + alpha * increment);
    }
    dilatation_[i] = theta;
    return_[3 * i] = theta;
    return_[3 * i + 1] = scale;
    return_[3 * i + 2] = increment;
  }
}

void ElasticPlastic::computeForce(const ModelState& s, const std::vector<int>& points) {
  withDamageAndSides(s, [&](auto damage, auto sides) {
    if (s.commitHistory)
      forceLoop<decltype(damage)::value, decltype(sides)::value, true>(s, points);
    else
      forceLoop<decltype(damage)::value, decltype(sides)::value, false>(s, points);
  });
  // A trial leaves e^dp and Lambda at the step's start (the force is the same either way).
  if (s.commitHistory)
    for (int i : points) lambda_[i] += return_[3 * i + 2];
}

// Both ends' force states on each bond of i (pull form): t = (1 - d)(3 K theta / m zeta +
// (1 - d) t_d), t_d = scale alpha (e^d - e^dp); each end's e^dp then advances by dLambda t_d.
template <bool kDamage, bool kSides, bool kCommit>
void ElasticPlastic::forceLoop(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  double* edp = s.fields->bond(kPlasticExtension).data();
  double* edpOfNeighbor = s.fields->bond(kNeighborPlasticExtension).data();
  const double* y = s.y;
  const double* mod = moduli_;
  const double* ret = return_;
  for (int i : points) {
    double f0 = 0, f1 = 0, f2 = 0;
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    const double thetaI = ret[3 * i], scaleI = ret[3 * i + 1], dLambdaI = ret[3 * i + 2];
    const double alphaI = mod[3 * i], isoI = mod[3 * i + 1] * thetaI;
#pragma omp simd reduction(+ : f0, f1, f2)
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      const double length = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
      const double dY = length > 0 ? length : 1.0;  // coincident ends: Y = 0 adds nothing
      const double zeta = s.bondLength[b];
      const double intact = kDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double thetaJ = ret[3 * j];
      // i's deviatoric force state on (i, j) and j's on (j, i) (same |Y| and zeta).
      const double tdI = scaleI * (alphaI * (length - zeta - thetaI * zeta / 3.0 - edp[b]));
      const double tdJ =
          ret[3 * j + 1] * (mod[3 * j] * (length - zeta - thetaJ * zeta / 3.0 - edpOfNeighbor[b]));
      double ti = intact * (isoI * zeta + intact * tdI);
      double tj = intact * (mod[3 * j + 1] * thetaJ * zeta + intact * tdJ);
      const double ownI = kSides ? (s.bondSides[b] & 1) : 1.0;
      const double ownJ = kSides ? ((s.bondSides[b] >> 1) & 1) : 1.0;
      ti *= ownI;
      tj *= ownJ;
      if constexpr (kCommit) {
        edp[b] += ownI * (tdI * dLambdaI);
        edpOfNeighbor[b] += ownJ * (tdJ * ret[3 * j + 2]);
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

void ElasticPlastic::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                         double* energyDensity) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* edp = s.fields->bond(kPlasticExtension).data();
  for (int i : points) {
    const double theta = dilatation_[i];
    double deviatoric = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      if (!s.topology->ownSide(b)) continue;
      const int j = neighbors[b];
      double Y[3];
      for (int d = 0; d < 3; ++d) Y[d] = s.y[3 * j + d] - s.y[3 * i + d];
      const double dY = std::sqrt(Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2]);
      const double zeta = s.bondLength[b];
      const double ee = dY - zeta - theta * zeta / 3.0 - edp[b];
      double w = ee * ee * s.volume[j];
      if (s.bondDamage) w *= 1.0 - s.bondDamage[b];
      deviatoric += w;
    }
    energyDensity[i] = 0.5 * constants_.bulkModulus * theta * theta +
                       (weightedVolume_[i] > 0 ? 0.5 * moduli_[3 * i] * deviatoric : 0.0);
  }
}

PERIDOT_REGISTER_MATERIAL(
    "Elastic Plastic", ElasticPlastic,
    "Ordinary state-based elastic-perfectly plastic solid (Mitchell): LPS with a deviatoric "
    "return mapping; output Lambda",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Yield Stress",
         "positive number, required: uniaxial yield stress sigma_Y; yield value psi_0 = 25 "
         "sigma_Y^2 / (8 pi delta^5) on the deviatoric force state"},
        {"Disable Plasticity", "bool, default false: never yield (the LPS with omega = 1)"},
        {"Planar Problem", "bool: only false (Peridigm's planar variant is not supported)"},
        {"Thickness", "not supported (belongs to \"Planar Problem\")"},
        {"Apply Automatic Differentiation Jacobian",
         "bool: accepted; the implicit tangent is probed by finite differences"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported"},
        {"Finite Difference Probe Length",
         "positive number: accepted; the probe is Solver -> Finite Difference Probe Length"}}))

}  // namespace peridot
