#pragma once
// The kinematics of the bond-associated correspondence models (Chen 2018; Chen and Spencer 2019;
// Behzadinasab and Foster 2020, as Peridigm implements them; theory in
// doc/theory/bond-associated-correspondence.md):
//
//   point level   F_i = [sum_j w_ij Y (x) xi V_j] K_i^-1, Fdot_i likewise with v_j - v_i
//                 (first-order gradient weights w K^-1 xi; materials/Correspondence.hpp), and the
//                 weighted volume m_i = sum_j w_ij V_j
//   bond level    Fbar = (F_i + F_j) / 2,  F_b = Fbar + (Y - Fbar xi) (x) xi / |xi|^2
//                 and Fdot_b alike from the velocity difference: the average of the two ends'
//                 gradients with its component along the bond replaced by the bond's own
//                 stretch, so F_b xi = Y exactly. F_b is the same for the bond seen from i and
//                 from j (xi and Y change sign together), to the last bit.
//
// All tensors 3x3 row-major. Point tensors are kept as three ghosted rows of three components
// (the ghost refreshes move 1- or 3-component fields): G_p[3 r + c] = rows[r][3 p + c].
#include "materials/MaterialModel.hpp"

namespace peridot {
namespace bondassociated {

// Fbar + (Y - Fbar xi) (x) xi / |xi|^2 with Fbar the mean of the row-stored tensors of points i
// and j; `invXi2` is 1 / |xi|^2.
inline void bondTensor(const double* const rows[3], int i, int j, const double* xi, const double* Y,
                       double invXi2, double* out) {
  for (int r = 0; r < 3; ++r) {
    const double a0 = 0.5 * (rows[r][3 * i] + rows[r][3 * j]);
    const double a1 = 0.5 * (rows[r][3 * i + 1] + rows[r][3 * j + 1]);
    const double a2 = 0.5 * (rows[r][3 * i + 2] + rows[r][3 * j + 2]);
    const double miss = (Y[r] - (a0 * xi[0] + a1 * xi[1] + a2 * xi[2])) * invXi2;
    out[3 * r] = a0 + miss * xi[0];
    out[3 * r + 1] = a1 + miss * xi[1];
    out[3 * r + 2] = a2 + miss * xi[2];
  }
}

// The weighted volume m_i = sum_j w_ij V_j of owned point i, w = omega (1 - d) on its own side
// (the weights of its shape tensor).
double weightedVolume(const ModelState& s, int i);

}  // namespace bondassociated
}  // namespace peridot
