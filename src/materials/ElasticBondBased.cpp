#include "materials/ElasticBondBased.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "materials/BondBasedKernels.hpp"

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

void ElasticBondBased::computeForce(const ModelState& s, const std::vector<int>& points) {
  pairForce<false>(s, points, micromodulus_);
}

void ElasticBondBased::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                           double* energyDensity) const {
  pairEnergyDensity<false>(s, points, micromodulus_, energyDensity);
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
