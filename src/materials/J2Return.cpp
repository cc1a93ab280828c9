#include "materials/J2Return.hpp"

#include <algorithm>
#include <cmath>

namespace peridot {
namespace correspondence {

double Hardening::stress(double eqps) const {
  switch (kind) {
    case Kind::Linear:
      return yield + modulus * eqps;
    case Kind::PowerLaw:
      return yield * std::pow(1.0 + eqps / strain0, exponent);
    case Kind::SaturationExponential:
      return yield + (saturated - yield) * (1.0 - std::exp(-rate * eqps)) + modulus * eqps;
  }
  return yield;
}

double Hardening::slope(double eqps) const {
  switch (kind) {
    case Kind::Linear:
      return modulus;
    case Kind::PowerLaw:
      return yield * exponent / strain0 * std::pow(1.0 + eqps / strain0, exponent - 1.0);
    case Kind::SaturationExponential:
      return (saturated - yield) * rate * std::exp(-rate * eqps) + modulus;
  }
  return modulus;
}

double radialReturn(double mu, const Hardening& h, double eqps, double* sigma) {
  const double mean = (sigma[0] + sigma[4] + sigma[8]) / 3.0;  // kept by the radial return
  double dev[9], ss = 0;
  for (int k = 0; k < 9; ++k) {
    dev[k] = sigma[k] - (k % 4 == 0 ? mean : 0.0);
    ss += dev[k] * dev[k];
  }
  const double q = std::sqrt(1.5 * ss);  // von Mises of the trial stress
  const double yieldNow = h.stress(eqps);
  if (q <= yieldNow || !(ss > 0)) return 0.0;
  // Linear hardening: the condition is linear in dgamma, one step is exact.
  double dgamma = (q - yieldNow) / (3.0 * mu + h.slope(eqps));
  if (h.kind != Hardening::Kind::Linear) {
    // Newton on g(dgamma) = q - 3 mu dgamma - sigma_y(eps_p + dgamma), decreasing in dgamma for a
    // hardening curve (3 mu + slope > 0); clamped to [0, q / (3 mu)], where g changes sign.
    const double upper = q / (3.0 * mu);
    for (int iteration = 0; iteration < 50; ++iteration) {
      const double g = q - 3.0 * mu * dgamma - h.stress(eqps + dgamma);
      const double next =
          std::min(upper, std::max(0.0, dgamma + g / (3.0 * mu + h.slope(eqps + dgamma))));
      const bool converged = std::abs(next - dgamma) <= 1e-15 * std::max(next, 1e-300);
      dgamma = next;
      if (converged) break;
    }
  }
  // Radial return: the deviator shrinks by 3 mu dgamma along its own direction.
  const double shrink = 1.0 - 3.0 * mu * dgamma / q;
  for (int k = 0; k < 9; ++k) sigma[k] = (k % 4 == 0 ? mean : 0.0) + shrink * dev[k];
  return dgamma;
}

}  // namespace correspondence
}  // namespace peridot
