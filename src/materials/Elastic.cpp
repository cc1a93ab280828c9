#include "materials/Elastic.hpp"

#include <cmath>

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
  constants_ = readTwoElasticConstants(p);
  acceptCommonMaterialKeys(p);
}

void Elastic::declareFields(FieldManager& fields) {
  weightedVolume_ = fields.node(kWeightedVolume, 1);
  dilatation_ = fields.node(kDilatation, 1);
  bulk_ = fields.node(kBulkModulus, 1);
  shear_ = fields.node(kShearModulus, 1);
}

void Elastic::initialize(const ModelState& s, const std::vector<int>& points) {
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
      m += omega * zetaSquared * s.volume[j];
    }
    weightedVolume_[i] = m;
    bulk_[i] = constants_.bulkModulus;
    shear_[i] = constants_.shearModulus;
  }
}

// The kernels below keep Peridigm's order of floating-point operations per bond entry, so that
// small cases reproduce its gold results to the last bits.
void Elastic::precompute(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    double theta = 0;
    const double m = weightedVolume_[i];
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const Bond g = bondGeometry(s.x, s.y, i, j);
      const double omega = s.influence ? s.influence[b] : 1.0;
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      theta += 3.0 * omega * intact * g.zeta * (g.dY - g.zeta) * s.volume[j] / m;
    }
    // A point without bonds has no weighted volume and no dilatation.
    dilatation_[i] = m > 0 ? theta : 0.0;
  }
}

void Elastic::computeForce(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* m = weightedVolume_;
  const double* theta = dilatation_;
  for (int i : points) {
    double f[3] = {0, 0, 0};
    const double alphaI = m[i] > 0 ? 15.0 * shear_[i] / m[i] : 0.0;
    const double betaI = m[i] > 0 ? 3.0 * bulk_[i] / m[i] - alphaI / 3.0 : 0.0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const Bond g = bondGeometry(s.x, s.y, i, j);
      if (!(g.dY > 0)) continue;  // coincident ends: no direction, no force
      const double alphaJ = m[j] > 0 ? 15.0 * shear_[j] / m[j] : 0.0;
      const double betaJ = m[j] > 0 ? 3.0 * bulk_[j] / m[j] - alphaJ / 3.0 : 0.0;
      const double omega = s.influence ? s.influence[b] : 1.0;
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double e = g.dY - g.zeta;
      // Force state of i on the bond, then that of j on the reversed bond (pull form: each
      // point sums only its own list, in global-id order, whatever the rank count).
      const double ti = intact * (omega * theta[i] * betaI * g.zeta + intact * omega * alphaI * e);
      const double tj = intact * (omega * theta[j] * betaJ * g.zeta + intact * omega * alphaJ * e);
      const double vj = s.volume[j];
      for (int d = 0; d < 3; ++d) f[d] += ti * g.Y[d] / g.dY * vj;
      for (int d = 0; d < 3; ++d) f[d] += tj * g.Y[d] / g.dY * vj;
    }
    for (int d = 0; d < 3; ++d) s.forceDensity[3 * i + d] = f[d];
  }
}

void Elastic::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                  double* energyDensity) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    const double mi = weightedVolume_[i];
    double deviatoric = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const Bond g = bondGeometry(s.x, s.y, i, j);
      const double ed = g.dY - g.zeta - dilatation_[i] * g.zeta / 3.0;
      double w = ed * ed * s.volume[j];
      if (s.influence) w *= s.influence[b];
      if (s.bondDamage) w *= 1.0 - s.bondDamage[b];
      deviatoric += w;
    }
    energyDensity[i] = 0.5 * bulk_[i] * dilatation_[i] * dilatation_[i] +
                       (mi > 0 ? 0.5 * 15.0 * shear_[i] / mi * deviatoric : 0.0);
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
        {"Apply Shear Correction Factor", "bool, default false: true is not supported yet"},
        {"Apply Automatic Differentiation Jacobian", "bool: accepted, unused (explicit only)"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported yet"},
        {"Compute Partial Stress", "bool, default false: true is not supported yet"},
        {"Finite Difference Probe Length", "positive number: accepted, unused"}}))

}  // namespace peridot
