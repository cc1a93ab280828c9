#pragma once
// The J2 (von Mises) radial return on an unrotated Cauchy stress, with an isotropic hardening
// curve sigma_y(eps_p), shared by the rate-form correspondence models (point level:
// "Elastic Plastic Correspondence", "Isotropic Hardening Correspondence"; bond level: the
// bond-associated family). Theory in doc/theory/correspondence.md and
// doc/theory/bond-associated-correspondence.md.
//
// Backward Euler on the yield condition: with q* the von Mises stress of the elastic trial
// sigma* and eps_p^n the start-of-step plastic strain, a step is plastic when q* > sigma_y(eps_p^n)
// and then dgamma solves
//   q* - 3 mu dgamma = sigma_y(eps_p^n + dgamma),
// the deviator of sigma* shrinks by 1 - 3 mu dgamma / q* along its own direction and the mean
// stress is kept. The returned stress is on the yield surface of the new eps_p (exactly, in one
// step, for linear hardening; by Newton's iteration to rounding for the others).
namespace peridot {
namespace correspondence {

// An isotropic hardening curve, evaluated without a virtual call (it runs once per bond).
struct Hardening {
  enum class Kind {
    Linear,                // sigma_Y + H eps_p (H = 0: perfect plasticity)
    PowerLaw,              // sigma_Y (1 + eps_p / eps_0)^n  (Peridigm's "Power-law")
    SaturationExponential  // sigma_0 + (sigma_s - sigma_0)(1 - exp(-delta eps_p)) + H eps_p
  };
  Kind kind = Kind::Linear;
  double yield = 0.0;      // sigma_Y, or sigma_0 of the saturation law
  double modulus = 0.0;    // H of the linear law and the saturation law's linear term
  double strain0 = 1.0;    // eps_0 of the power law
  double exponent = 0.0;   // n of the power law
  double saturated = 0.0;  // sigma_s of the saturation law
  double rate = 0.0;       // delta of the saturation law

  double stress(double eqps) const;  // sigma_y(eps_p)
  double slope(double eqps) const;   // d sigma_y / d eps_p
};

// The return of the trial stress `sigma` (3x3 row-major, overwritten by the returned stress)
// from plastic strain `eqps`; returns dgamma (0 for an elastic step).
double radialReturn(double mu, const Hardening& hardening, double eqps, double* sigma);

}  // namespace correspondence
}  // namespace peridot
