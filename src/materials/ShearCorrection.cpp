#include "materials/ShearCorrection.hpp"

#include <algorithm>
#include <cmath>

namespace peridot {

// Peridigm's shear correction: the ratio between the continuum and the discrete deviatoric
// energy of pure shear u = gamma (y, x, 0) (and the zx, yz modes; the largest discrete energy
// is used), so that alpha = 15 G / m reproduces the shear energy on the actual neighbourhood.
// In 2D (thetaFactor 2r, deviatoricFactor 8) the one in-plane mode, with the 2D dilatation.
double shearCorrectionFactor(const ModelState& s, int i, double m, double thetaFactor,
                             double deviatoricFactor) {
  const double gamma = 1.0e-6;
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const int modes = s.dimension == 2 ? 1 : 3;
  double largest = 0;
  for (int mode = 0; mode < modes; ++mode) {
    const int a = mode, b = (mode + 1) % 3;  // shear in the (a, b) plane
    auto deformedLength = [&](std::int64_t bond, double& zeta) {
      const int j = neighbors[bond];
      double X[3], Y[3];
      for (int d = 0; d < 3; ++d) X[d] = s.x[3 * j + d] - s.x[3 * i + d];
      for (int d = 0; d < 3; ++d) Y[d] = X[d];
      Y[a] += gamma * X[b];
      Y[b] += gamma * X[a];
      zeta = std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]);
      return std::sqrt(Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2]);
    };
    double theta = 0;
    for (std::int64_t bond = offsets[i]; bond < offsets[i + 1]; ++bond) {
      double zeta = 0;
      const double dY = deformedLength(bond, zeta);
      const double omega = s.influence ? s.influence[bond] : 1.0;
      theta += thetaFactor * omega * zeta * (dY - zeta) * s.volume[neighbors[bond]] / m;
    }
    double norm = 0;
    for (std::int64_t bond = offsets[i]; bond < offsets[i + 1]; ++bond) {
      double zeta = 0;
      const double dY = deformedLength(bond, zeta);
      const double ed = dY - zeta - theta * zeta / thetaFactor;
      const double omega = s.influence ? s.influence[bond] : 1.0;
      norm += ed * omega * ed * s.volume[neighbors[bond]];
    }
    largest = std::max(largest, norm);
  }
  return largest > 0 ? 4.0 * gamma * gamma * m / largest / deviatoricFactor : 1.0;
}

}  // namespace peridot
