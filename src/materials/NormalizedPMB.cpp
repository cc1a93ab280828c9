#include "materials/NormalizedPMB.hpp"

#include <cmath>

#include "core/Error.hpp"

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
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* y = s.y;
  const double* c = micromodulus_;
  const double* zeta = s.bondLength;
  for (int i : points) {
    double f0 = 0, f1 = 0, f2 = 0;
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      const double dY = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
      const double stretch = (dY - zeta[b]) / zeta[b];
      double t = 0.5 * (c[i] + c[j]) * stretch / zeta[b];
      if (s.influence) t *= s.influence[b];
      if (s.bondDamage) t *= 1.0 - s.bondDamage[b];
      const double scale = dY > 0 ? t * s.volume[j] / dY : 0.0;
      f0 += scale * Y0;
      f1 += scale * Y1;
      f2 += scale * Y2;
    }
    s.forceDensity[3 * i] = f0;
    s.forceDensity[3 * i + 1] = f1;
    s.forceDensity[3 * i + 2] = f2;
  }
}

void NormalizedPMB::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                        double* energyDensity) const {
  for (int i : points) {
    double w = 0;
    for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
      const int j = s.topology->neighbors[b];
      double Y2 = 0;
      for (int d = 0; d < 3; ++d)
        Y2 += (s.y[3 * j + d] - s.y[3 * i + d]) * (s.y[3 * j + d] - s.y[3 * i + d]);
      const double stretch = (std::sqrt(Y2) - s.bondLength[b]) / s.bondLength[b];
      double wb = 0.25 * 0.5 * (micromodulus_[i] + micromodulus_[j]) * stretch * stretch;
      if (s.influence) wb *= s.influence[b];
      if (s.bondDamage) wb *= 1.0 - s.bondDamage[b];
      w += wb * s.volume[j];
    }
    energyDensity[i] = w;
  }
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
