#include "materials/ElasticBondBased.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "materials/BondBasedKernels.hpp"
#include "materials/BondBasedTangent.hpp"
#include "materials/HalfPairForce.hpp"

namespace peridot {

namespace {
const double kPi = 3.14159265358979323846;
}

ElasticBondBased::ElasticBondBased(ListReader& p) {
  density_ = p.positiveNumber("Density");
  mode_ = readPlaneMode(p);
  bulkModulus_ = readBondBasedBulkModulus(p, mode_);
  if (p.has("Height")) height_ = p.positiveNumber("Height");
  thermalExpansion_ = p.number("Thermal Expansion Coefficient", 0.0);
  acceptCommonMaterialKeys(p, false, true);
}

void ElasticBondBased::declareFields(FieldManager& fields) {
  micromodulus_ = fields.node(kMicromodulus, 1);
}

void ElasticBondBased::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, "Elastic Bond Based");
  checkAssumedInfluenceFunction(s);
  if (s.dimension == 2 && height_ > 0 && std::fabs(height_ - s.thickness) > 1e-12 * s.thickness) {
    throw InputError("Materials -> Height",
                     "differs from the discretization's thickness " + std::to_string(s.thickness));
  }
  const bool one = s.influenceFunction == "One";
  const double kappa = inPlaneBulkModulus(youngsModulus(), poissonsRatio(), mode_);
  if (s.dimension == 3 && mode_ != PlaneMode::ThreeD) {
    // Peridigm's 2D form: a 3D cloud (one layer of solid elements, volumes = area x height),
    // the 3D neighbourhood, and the plane micromodulus 12 K / (pi h delta^3) with K the bulk
    // modulus of the deck (from E with nu = 1/3 or 1/4). Not the plane-stress continuum
    // constant of a planar discretization (which uses kappa): Peridigm's own choice.
    if (!(height_ > 0)) {
      throw InputError("Materials -> Height",
                       "required with \"Plane Stress\" or \"Plane Strain\" on a 3D "
                       "discretization (Peridigm's 2D form: the thickness of the one layer of "
                       "elements)");
    }
    if (!one) {
      throw InputError("Discretization -> Influence Function",
                       "\"Elastic Bond Based\" in Peridigm's 2D form (plane mode on a 3D "
                       "discretization) is defined for the influence function One only");
    }
    for (int i : points) {
      const double d = s.horizon[i];
      micromodulus_[i] = 12.0 * bulkModulus_ / (kPi * height_ * d * d * d);
    }
    return;
  }
  for (int i : points) {
    const double d = s.horizon[i];
    if (s.dimension == 3 && one) {
      micromodulus_[i] = 18.0 * bulkModulus_ / (kPi * d * d * d * d);
      continue;
    }
    // W = 1/4 c s^2 integral omega zeta dV must be the continuum dilatation energy:
    // 3D 9 K s^2 / 2 = pi c s^2 J3; 2D 2 kappa s^2 = pi c s^2 t J2 / 2.
    double Jk = 0;
    if (!influenceIntegral(s.influenceFunction, s.dimension == 3 ? 3 : 2, d, Jk)) {
      throw InputError(
          "Discretization -> Influence Function",
          "\"Elastic Bond Based\" has no micromodulus for \"" + s.influenceFunction + "\"");
    }
    micromodulus_[i] = s.dimension == 3 ? 9.0 * bulkModulus_ / (2.0 * kPi * Jk)
                                        : 4.0 * kappa / (kPi * s.thickness * Jk);
  }
}

void ElasticBondBased::computeForce(const ModelState& s, const std::vector<int>& points) {
  if (s.halfBonds)
    halfPairForce(s, micromodulus_, false);
  else
    pairForce<false>(s, points, micromodulus_);
}

void ElasticBondBased::addStiffness(const ModelState& s, const std::vector<int>& points,
                                    TangentBlocks& K) const {
  pairStiffness<false>(s, points, micromodulus_, K);
}

void ElasticBondBased::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                           double* energyDensity) const {
  pairEnergyDensity<false>(s, points, micromodulus_, energyDensity);
}

void ElasticBondBased::stiffnessSum(const ModelState& s, const std::vector<int>& points,
                                    double* sum) const {
  // 3D with omega = 1: Peridigm's estimate (the same constant, the same bits).
  if (s.dimension == 3 && !s.influence) {
    MaterialModel::stiffnessSum(s, points, sum);
    return;
  }
  // Force c_ij omega s V_j = c_ij omega (relative displacement) V_j / |xi|.
  for (int i : points) {
    double total = 0;
    for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
      if (!s.topology->ownSide(b)) continue;
      const int j = s.topology->neighbors[b];
      const double omega = s.influence ? s.influence[b] : 1.0;
      total +=
          0.5 * (micromodulus_[i] + micromodulus_[j]) * omega * s.volume[j] / bondLengthOf(s, i, b);
    }
    sum[i] = total;
  }
}

PERIDOT_REGISTER_MATERIAL(
    "Elastic Bond Based", ElasticBondBased,
    "Prototype micro-elastic brittle (PMB) bond-based model; micromodulus from the dilatation "
    "energy (3D, omega = 1: 18K/(pi delta^4)); 3D, plane stress or plane strain",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus",
         "positive number: the (3D) bulk modulus K (give this or Young's Modulus); E = 3K(1-2nu) "
         "with the fixed nu"},
        {"Young's Modulus",
         "positive number: E; Poisson's ratio is fixed: 1/4 in 3D and plane strain (K = 2E/3), "
         "1/3 in plane stress (K = E)"},
        {"Plane Stress",
         "bool, default false: 2D plane stress (nu = 1/3). On a planar discretization c = 4 "
         "kappa/(pi t J2), kappa = E/(2(1-nu)); on a 3D one (Peridigm's form, one layer of "
         "elements) c = 12 K/(pi h delta^3) with h = Height"},
        {"Plane Strain",
         "bool, default false: 2D plane strain (nu = 1/4), kappa = E/(2(1+nu)(1-2nu)); on a 3D "
         "discretization as Plane Stress (Peridigm's form)"},
        {"Height",
         "positive number: thickness h of a 2D model; required with a plane mode on a 3D "
         "discretization (Peridigm's form); on a planar one it must equal the discretization's "
         "thickness"},
        {"Thermal Expansion Coefficient",
         "number, default 0: alpha; each end's half of the pair force uses its stretch less "
         "alpha Delta T (a Peridot extension: Peridigm's bond-based model ignores the key)"},
        {"Finite Difference Probe Length",
         "positive number: accepted for Peridigm decks, unused"}}))

}  // namespace peridot
