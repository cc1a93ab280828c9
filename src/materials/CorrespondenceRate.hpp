#pragma once
// The kinematics of the hypoelastic rate form of the correspondence models ("Stress Integration:
// Hypoelastic Rate", the default; theory in doc/theory/correspondence.md), as Peridigm's
// correspondence models integrate their stress:
//
//   velocity gradient   L = Fdot F^-1,  Fdot = [sum_j w_ij (v_j - v_i) (x) xi V_j] K^-1
//   rate of deformation D = (L + L^T) / 2, spin W = (L - L^T) / 2
//   Flanagan and Taylor (1987): the left stretch V and rotation R of F = V R advanced over one
//   step from the rates, without a polar decomposition of F; the unrotated rate of deformation
//   d = R^T D R (R at the end of the step) is what the constitutive law integrates.
//
// All tensors 3x3 row-major, as in materials/Correspondence.hpp.
#include "materials/MaterialModel.hpp"

namespace peridot {
namespace correspondence {

// One Flanagan-Taylor step of size dt from the velocity gradient L and the step-start stretch
// Vn and rotation Rn: the step-end Vnew, Rnew and the unrotated rate of deformation
// d = Rnew^T D Rnew. The rotation is advanced by the exact exponential of the angular velocity
// omega = w + (tr(V) I - V)^-1 z (w the vorticity vector of W, z_i = e_ikj D_jm V_mk), so Rnew
// stays orthogonal to rounding and a constant spin is integrated exactly; V by forward Euler,
// Vdot = L V - V Omega. False when tr(V) I - V is singular (omega is then w alone).
bool flanaganTaylorStep(const double* L, const double* Vn, const double* Rn, double dt,
                        double* Vnew, double* Rnew, double* d);

// Velocity gradient L = Fdot F^-1, Fdot = M K^-1, from the velocity sums M = sum_j w (v_j - v_i)
// (x) xi V_j of a point (with the weights of its shape tensor; shapeTensorAndDeformationGradient
// sums them in its pass), its K^-1 and F^-1.
void velocityGradient(const double* M, const double* Kinv, const double* Finv, double* L);

// The linear hypoelastic increment in the unrotated frame: sigma = sigmaN + dt (lambda tr(d) I +
// 2 mu d).
void hypoelasticIncrement(double lambda, double mu, const double* d, double dt,
                          const double* sigmaN, double* sigma);

// The rate form's stored energy density: the complementary energy of the unrotated stress,
// p^2 / (2K) + s:s / (4 mu) (p the mean stress, s the deviator), the linear-elastic energy of
// that stress (the plain, hypoelastic and bond-associated correspondence models).
double complementaryEnergyDensity(double K, double mu, const double* sigma);

// J2 radial return of a trial unrotated stress `sigma` (in place) onto the von Mises surface
// sqrt(3/2) |dev sigma| = yieldNow + H dgamma (linear hardening modulus H, shear modulus mu):
// returns dgamma, the increment of the equivalent plastic strain (0 for an elastic step, sigma
// unchanged). The mean stress is kept; the deviator shrinks along itself by 3 mu dgamma.
double radialReturn(double mu, double H, double yieldNow, double* sigma);

}  // namespace correspondence
}  // namespace peridot
