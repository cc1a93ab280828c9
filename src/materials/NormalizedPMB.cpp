#include "materials/NormalizedPMB.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "materials/BondBasedKernels.hpp"
#include "materials/BondBasedTangent.hpp"
#include "materials/HalfPairForce.hpp"

namespace peridot {

NormalizedPMB::NormalizedPMB(ListReader& p) {
  density_ = p.positiveNumber("Density");
  mode_ = readPlaneMode(p);
  bulkModulus_ = readBondBasedBulkModulus(p, mode_);
  acceptCommonMaterialKeys(p);
}

void NormalizedPMB::declareFields(FieldManager& fields) {
  micromodulus_ = fields.node(kMicromodulus, 1);
}

void NormalizedPMB::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, "Normalized PMB");
  checkAssumedInfluenceFunction(s);
  // 4 x the dilatation energy per s^2: 3D 4 (9 K / 2) = 18 K; 2D 4 (2 kappa) = 8 kappa.
  const double numerator = s.dimension == 3
                               ? 18.0 * bulkModulus_
                               : 8.0 * inPlaneBulkModulus(youngsModulus(), poissonsRatio(), mode_);
  for (int i : points) {
    double neighbourhoodVolume = 0;
    for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b)
      if (s.topology->ownSide(b))
        neighbourhoodVolume += s.influence ? s.influence[b] * s.volume[s.topology->neighbors[b]]
                                           : s.volume[s.topology->neighbors[b]];
    // A point without neighbours has no bonds to carry a constant.
    micromodulus_[i] = neighbourhoodVolume > 0 ? numerator / neighbourhoodVolume : 0.0;
  }
}

void NormalizedPMB::computeForce(const ModelState& s, const std::vector<int>& points) {
  if (s.halfBonds)
    halfPairForce(s, micromodulus_, true);
  else
    pairForce<true>(s, points, micromodulus_);
}

void NormalizedPMB::addStiffness(const ModelState& s, const std::vector<int>& points,
                                 TangentBlocks& K) const {
  pairStiffness<true>(s, points, micromodulus_, K);
}

void NormalizedPMB::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                        double* energyDensity) const {
  pairEnergyDensity<true>(s, points, micromodulus_, energyDensity);
}

void NormalizedPMB::stiffnessSum(const ModelState& s, const std::vector<int>& points,
                                 double* sum) const {
  // Force c_ij omega s / |xi| V_j = c_ij omega (relative displacement) V_j / |xi|^2.
  for (int i : points) {
    double total = 0;
    for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
      const int j = s.topology->neighbors[b];
      const double k = 0.5 * (micromodulus_[i] + micromodulus_[j]) * s.volume[j] /
                       (bondLengthOf(s, i, b) * bondLengthOf(s, i, b));
      total += s.influence ? k * s.influence[b] : k;
    }
    sum[i] = total;
  }
}

PERIDOT_REGISTER_MATERIAL(
    "Normalized PMB", NormalizedPMB,
    "PMB with the micromodulus normalized by each point's discrete neighbourhood volume "
    "(Ganzenmueller et al.): exact total energy of a homogeneous dilatation (pointwise only "
    "where neighbourhood volumes are equal)",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus",
         "positive number: the (3D) bulk modulus K (give this or Young's Modulus); E = "
         "3K(1-2nu) with the fixed nu"},
        {"Young's Modulus",
         "positive number: E; Poisson's ratio is fixed: 1/4 in 3D and plane strain (K = 2E/3), "
         "1/3 in plane stress (K = E)"},
        {"Plane Stress",
         "bool, default false: 2D plane stress (nu = 1/3), c_i = 8 kappa / sum_j omega V_j, "
         "kappa = E/(2(1-nu)); needs a planar discretization"},
        {"Plane Strain",
         "bool, default false: 2D plane strain (nu = 1/4), kappa = E/(2(1+nu)(1-2nu))"}}))

}  // namespace peridot
