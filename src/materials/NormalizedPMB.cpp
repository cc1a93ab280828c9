#include "materials/NormalizedPMB.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "materials/BondBasedKernels.hpp"

namespace peridot {

NormalizedPMB::NormalizedPMB(ListReader& p) {
  density_ = p.positiveNumber("Density");
  bulkModulus_ = readBondBasedBulkModulus(p);
  acceptCommonMaterialKeys(p);
}

void NormalizedPMB::declareFields(FieldManager& fields) {
  micromodulus_ = fields.node(kMicromodulus, 1);
}

void NormalizedPMB::initialize(const ModelState& s, const std::vector<int>& points) {
  for (int i : points) {
    double neighbourhoodVolume = 0;
    for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b)
      if (s.topology->ownSide(b)) neighbourhoodVolume += s.volume[s.topology->neighbors[b]];
    // A point without neighbours has no bonds to carry a constant.
    micromodulus_[i] = neighbourhoodVolume > 0 ? 18.0 * bulkModulus_ / neighbourhoodVolume : 0.0;
  }
}

void NormalizedPMB::computeForce(const ModelState& s, const std::vector<int>& points) {
  pairForce<true>(s, points, micromodulus_);
}

void NormalizedPMB::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                        double* energyDensity) const {
  pairEnergyDensity<true>(s, points, micromodulus_, energyDensity);
}

void NormalizedPMB::stiffnessSum(const ModelState& s, const std::vector<int>& points,
                                 double* sum) const {
  // Force c_ij s / |xi| V_j = c_ij (relative displacement) V_j / |xi|^2.
  for (int i : points) {
    double total = 0;
    for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
      const int j = s.topology->neighbors[b];
      total += 0.5 * (micromodulus_[i] + micromodulus_[j]) * s.volume[j] /
               (s.bondLength[b] * s.bondLength[b]);
    }
    sum[i] = total;
  }
}

PERIDOT_REGISTER_MATERIAL(
    "Normalized PMB", NormalizedPMB,
    "PMB with the micromodulus normalized by each point's discrete neighbourhood volume "
    "(Ganzenmueller et al.): exact energy of homogeneous dilatation at every point",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (give this or Young's Modulus; Poisson's ratio 1/4)"},
        {"Young's Modulus", "positive number: E; K = 2E/3"}}))

}  // namespace peridot
