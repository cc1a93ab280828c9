#pragma once
// Golds for "Viscoplastic Needleman Correspondence" under uniaxial stretch, written from the law
// (doc/theory/correspondence.md), not from the model's code: its hardening curve g, and one step
// of its time-discrete scheme as a scalar recursion, whose return is solved for the new stress by
// bisection (the model solves for the plastic increment by Newton).
#include <cmath>

namespace peridot {
namespace testing {

// The law's constants (the deck's keys).
struct NeedlemanLaw {
  double sigmaY = 1e-3;  // Yield Stress (at the point: the flaw's value)
  double N = 0.1;        // Strain Hardening Exponent
  double m = 0.05;       // Rate Hardening Exponent
  double rate0 = 1e-3;   // Reference Strain Rate
  double eps0 = 1e-3;    // Reference Strain 0
  double eps1 = 5e-3;    // Reference Strain 1
};

// g(eps_p) = sigma_Y (1 + eps_p / eps_0)^N / (1 + (eps_p / eps_1)^2)
inline double needlemanHardening(const NeedlemanLaw& l, double e) {
  return l.sigmaY * std::pow(1.0 + e / l.eps0, l.N) / (1.0 + (e / l.eps1) * (e / l.eps1));
}

// The scalar state of uniaxial stretch: sigma = p I + q diag(2/3, -1/3, -1/3) along the stretch.
struct Uniaxial {
  double p = 0, q = 0, eqps = 0;
  double axial() const { return p + 2.0 * q / 3.0; }
  double lateral() const { return p - q / 3.0; }
};

// One step: the elastic trial with delta = d dt (the unrotated rate of deformation along the
// stretch times the step), p += K delta, q* = q + 2 mu delta; if dt > 0 and |q*| >= sigma_Y, the
// new von Mises stress s in [0, |q*|] with s = g(eps_p + Deps) (Deps / (epsdot_0 dt))^m,
// Deps = (|q*| - s) / (3 mu), by bisection. Returns whether the step flowed.
inline bool needlemanStep(const NeedlemanLaw& l, double K, double mu, Uniaxial& u, double delta,
                          double dt) {
  u.p += K * delta;
  const double qt = u.q + 2 * mu * delta, qa = std::abs(qt);
  u.q = qt;
  if (!(dt > 0) || qa < l.sigmaY) return false;
  auto excess = [&](double s) {  // increasing in s; its root is the new stress
    const double de = (qa - s) / (3 * mu);
    const double rate = l.m > 0 ? std::pow(de / (l.rate0 * dt), l.m) : 1.0;
    return s - needlemanHardening(l, u.eqps + de) * rate;
  };
  if (excess(qa) <= 0) return false;  // (m = 0 only) inside the hardened surface
  double lo = 0, hi = qa;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (excess(mid) > 0 ? hi : lo) = mid;
  }
  const double s = 0.5 * (lo + hi);
  u.eqps += (qa - s) / (3 * mu);
  u.q = qt > 0 ? s : -s;
  return true;
}

}  // namespace testing
}  // namespace peridot
