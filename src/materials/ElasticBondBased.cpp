#include "materials/ElasticBondBased.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace peridot {

namespace {
const double kPi = 3.14159265358979323846;
}

ElasticBondBased::ElasticBondBased(ListReader& p) {
  density_ = p.positiveNumber("Density");
  bulkModulus_ = readBondBasedBulkModulus(p);
  for (const char* k : {"Plane Strain", "Plane Stress"}) {
    if (p.has(k) && p.boolean(k, false)) {
      throw InputError(p.pathOf(k), "2D bond-based models are not supported by Peridot yet");
    }
  }
  if (p.has("Height")) p.positiveNumber("Height");
  acceptCommonMaterialKeys(p);
}

void ElasticBondBased::declareFields(FieldManager& fields) {
  micromodulus_ = fields.node(kMicromodulus, 1);
}

void ElasticBondBased::initialize(const ModelState& s, const std::vector<int>& points) {
  for (int i : points) {
    const double d = s.horizon[i];
    micromodulus_[i] = 18.0 * bulkModulus_ / (kPi * d * d * d * d);
  }
}

namespace {

// The PMB bond loop, instantiated for the scene's options so that the loop body has no
// branches on them (and one division per bond).
template <bool kDamage, bool kSides>
void pmbForce(const ModelState& s, const std::vector<int>& points, const double* c) {
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
      // Half the pair force from each end, each with its own micromodulus; an end whose
      // horizon does not hold the bond contributes nothing.
      double c2 = kSides ? ci * (sides[b] & 1) + c[j] * ((sides[b] >> 1) & 1) : ci + c[j];
      if (kDamage) c2 *= 1.0 - damage[b];
      // t V_j / |Y| with t = c s / 2 and s = (|Y| - |xi|) / |xi|, in one division. A bond whose
      // ends coincide has no direction and, by symmetry, no force.
      const double denominator = 2.0 * zeta[b] * dY;
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

}  // namespace

void ElasticBondBased::computeForce(const ModelState& s, const std::vector<int>& points) {
  // Influence functions are refused for this model (its micromodulus assumes omega = 1).
  if (s.bondDamage) {
    s.bondSides ? pmbForce<true, true>(s, points, micromodulus_)
                : pmbForce<true, false>(s, points, micromodulus_);
  } else {
    s.bondSides ? pmbForce<false, true>(s, points, micromodulus_)
                : pmbForce<false, false>(s, points, micromodulus_);
  }
}

void ElasticBondBased::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                           double* energyDensity) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    double w = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      double X[3], Y[3];
      for (int d = 0; d < 3; ++d) {
        X[d] = s.x[3 * j + d] - s.x[3 * i + d];
        Y[d] = s.y[3 * j + d] - s.y[3 * i + d];
      }
      const double zeta = std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]);
      const double dY = std::sqrt(Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2]);
      const double stretch = (dY - zeta) / zeta;
      double wb = 0.25 * 0.5 * (micromodulus_[i] + micromodulus_[j]) * stretch * stretch * zeta;
      if (s.influence) wb *= s.influence[b];
      if (s.bondDamage) wb *= 1.0 - s.bondDamage[b];
      w += wb * s.volume[j];
    }
    energyDensity[i] = w;
  }
}

PERIDOT_REGISTER_MATERIAL(
    "Elastic Bond Based", ElasticBondBased,
    "Prototype micro-elastic brittle (PMB) bond-based model; micromodulus 18K/(pi delta^4)",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: bulk modulus K (give this or Young's Modulus)"},
        {"Young's Modulus", "positive number: E; K = 2E/3 since Poisson's ratio is 1/4"},
        {"Plane Strain", "bool, default false: true is not supported yet"},
        {"Plane Stress", "bool, default false: true is not supported yet"},
        {"Height", "positive number: thickness of 2D models (accepted, unused in 3D)"},
        {"Finite Difference Probe Length",
         "positive number: accepted for Peridigm decks, unused"}}))

}  // namespace peridot
