#pragma once
// Tangent stiffness of the pairwise bond force of BondBasedKernels.hpp (linear bond law).
// The force on i from bond b is g(Y) = k (|Y| - zeta) Y / |Y| with Y = y_j - y_i and
//   k = (c2 / 2) omega (1 - d) V_j / zeta      (PMB;  / zeta^2 with kOverLength),
// whose derivative is dg/dY = k [(1 - zeta/|Y|) I + (zeta/|Y|) n n^T], n = Y / |Y|. In stiffness
// form K = -V_i df_i/dy: K_ij -= V_i dg/dY, K_ii += V_i dg/dY. Bond damage is held fixed (the
// tangent of the current bonds). Coincident ends carry no force and are skipped.
#include <cmath>
#include <vector>

#include "materials/MaterialModel.hpp"
#include "solvers/TangentBlocks.hpp"

namespace peridot {

template <bool kOverLength>
void pairStiffness(const ModelState& s, const std::vector<int>& points, const double* c,
                   TangentBlocks& K) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* y = s.y;
  for (int i : points) {
    double diagonal[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      double n[3] = {y[3 * j] - y[3 * i], y[3 * j + 1] - y[3 * i + 1], y[3 * j + 2] - y[3 * i + 2]};
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (!(length > 0)) continue;
      for (double& component : n) component /= length;
      double c2 = s.bondSides ? c[i] * (s.bondSides[b] & 1) + c[j] * ((s.bondSides[b] >> 1) & 1)
                              : c[i] + c[j];
      if (s.bondDamage || s.bondBroken) c2 *= intactFraction(s, b);
      if (s.influence) c2 *= s.influence[b];
      const double zeta = bondLengthOf(s, i, b);
      const double k = c2 * s.volume[j] / (kOverLength ? 2.0 * zeta * zeta : 2.0 * zeta);
      const double ratio = zeta / length;
      double D[9];
      for (int r = 0; r < 3; ++r)
        for (int e = 0; e < 3; ++e)
          D[3 * r + e] = s.volume[i] * k * ((r == e ? 1.0 - ratio : 0.0) + ratio * n[r] * n[e]);
      K.add(i, j, -1.0, D);
      for (int r = 0; r < 9; ++r) diagonal[r] += D[r];
    }
    K.add(i, i, 1.0, diagonal);
  }
}

}  // namespace peridot
