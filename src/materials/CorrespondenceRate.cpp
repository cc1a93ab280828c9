#include "materials/CorrespondenceRate.hpp"

#include <algorithm>
#include <cmath>

#include "materials/Correspondence.hpp"
#include "materials/J2Return.hpp"

namespace peridot {
namespace correspondence {

bool flanaganTaylorStep(const double* L, const double* Vn, const double* Rn, double dt,
                        double* Vnew, double* Rnew, double* d) {
  double D[9], W[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      D[3 * r + c] = 0.5 * (L[3 * r + c] + L[3 * c + r]);
      W[3 * r + c] = 0.5 * (L[3 * r + c] - L[3 * c + r]);
    }
  // z_i = e_ikj (D V)_jk: z_x = (DV)_zy - (DV)_yz, and cyclically.
  double DV[9];
  multiply(D, Vn, DV);
  const double z[3] = {DV[7] - DV[5], DV[2] - DV[6], DV[3] - DV[1]};
  // The vorticity vector w_i = -e_ijk W_jk / 2: (W_zy, W_xz, W_yx).
  const double w[3] = {W[7], W[2], W[3]};
  const double traceV = Vn[0] + Vn[4] + Vn[8];
  double M[9], Minv[9];
  for (int k = 0; k < 9; ++k) M[k] = (k % 4 == 0 ? traceV : 0.0) - Vn[k];
  const bool regular = invert(M, Minv);
  double omega[3];
  for (int a = 0; a < 3; ++a)
    omega[a] = w[a] + Minv[3 * a] * z[0] + Minv[3 * a + 1] * z[1] + Minv[3 * a + 2] * z[2];
  // Omega_ij = e_ikj omega_k, so that Omega y = omega x y.
  const double Omega[9] = {0, -omega[2], omega[1], omega[2], 0, -omega[0], -omega[1], omega[0], 0};
  // R_{n+1} = exp(dt Omega) R_n by Rodrigues' formula.
  const double rate2 = omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2];
  double Q[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  if (rate2 > 0) {
    const double rate = std::sqrt(rate2);
    const double a = std::sin(dt * rate) / rate;
    const double half = std::sin(0.5 * dt * rate);
    const double b = 2.0 * half * half / rate2;  // (1 - cos(dt rate)) / rate^2, without cancelling
    double Omega2[9];
    multiply(Omega, Omega, Omega2);
    for (int k = 0; k < 9; ++k) Q[k] += a * Omega[k] + b * Omega2[k];
  }
  multiply(Q, Rn, Rnew);
  // V_{n+1} = V_n + dt (L V_n - V_n Omega)
  double LV[9], VO[9];
  multiply(L, Vn, LV);
  multiply(Vn, Omega, VO);
  for (int k = 0; k < 9; ++k) Vnew[k] = Vn[k] + dt * (LV[k] - VO[k]);
  // d = R^T D R, symmetric to the last bit (so is then the stress it drives)
  double DR[9], RtDR[9];
  multiply(D, Rnew, DR);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      RtDR[3 * r + c] = Rnew[r] * DR[c] + Rnew[3 + r] * DR[3 + c] + Rnew[6 + r] * DR[6 + c];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) d[3 * r + c] = 0.5 * (RtDR[3 * r + c] + RtDR[3 * c + r]);
  return regular;
}

void velocityGradient(const double* M, const double* Kinv, const double* Finv, double* L) {
  double Fdot[9];
  multiply(M, Kinv, Fdot);
  multiply(Fdot, Finv, L);
}

void hypoelasticIncrement(double lambda, double mu, const double* d, double dt,
                          const double* sigmaN, double* sigma) {
  const double trace = d[0] + d[4] + d[8];
  for (int k = 0; k < 9; ++k)
    sigma[k] = sigmaN[k] + dt * (2.0 * mu * d[k] + (k % 4 == 0 ? lambda * trace : 0.0));
}

double complementaryEnergyDensity(double K, double mu, const double* sigma) {
  const double mean = (sigma[0] + sigma[4] + sigma[8]) / 3.0;
  double ss = 0;
  for (int k = 0; k < 9; ++k) {
    const double dev = sigma[k] - (k % 4 == 0 ? mean : 0.0);
    ss += dev * dev;
  }
  return 0.5 * mean * mean / K + 0.25 * ss / mu;
}

double radialReturn(double mu, double H, double yieldNow, double* sigma) {
  // J2Return's linear case from plastic strain 0: sigma_y(0) = yieldNow + H 0 = yieldNow and the
  // slope H, the same arithmetic.
  Hardening hardening;
  hardening.yield = yieldNow;
  hardening.modulus = H;
  return radialReturn(mu, hardening, 0.0, sigma);
}

}  // namespace correspondence
}  // namespace peridot
