#pragma once
// "Viscoplastic Needleman Correspondence": the correspondence kinematics and hypoelastic rate form
// (materials/Correspondence.hpp) with Peridigm's rate-dependent J2 law after Needleman (1988).
// The von Mises stress q of a point that flows lies on the rate-dependent flow stress
//
//   Y(eps_p, epsdot_p) = g(eps_p) (epsdot_p / epsdot_0)^m,
//   g(eps_p) = sigma_Y(x) (1 + eps_p / eps_0)^N / (1 + (eps_p / eps_1)^2),
//
// N "Strain Hardening Exponent", m "Rate Hardening Exponent", epsdot_0 "Reference Strain Rate",
// eps_0 and eps_1 "Reference Strain 0/1", sigma_Y(x) "Yield Stress" lowered by Peridigm's
// optional flaw. As in Peridigm, a point whose trial von Mises stress is below sigma_Y(x) is
// elastic; otherwise it flows (any stress above sigma_Y flows at some rate when m > 0), by a
// backward-Euler radial return on the unrotated Cauchy stress: with the trial q*,
//
//   q* - 3 mu Deps = g(eps_p,n + Deps) (Deps / (epsdot_0 dt))^m,
//
// solved for the plastic increment Deps >= 0 by a bracketed Newton iteration to rounding; the
// deviator is scaled by 1 - 3 mu Deps / q*, eps_p += Deps. With m = 0 the law is rate-independent
// J2 plasticity with the hardening curve g (theory: doc/theory/correspondence.md).
//
// The stress integration is the rate form only, as in Peridigm ("Total Lagrangian Green Strain"
// is refused). History per point: eps_p and the rate form's sigma_u, R, V, committed once per
// step by computeForce (the convention of the other plastic correspondence models).
#include "materials/ElasticPlasticCorrespondence.hpp"

namespace peridot {

class ViscoplasticNeedlemanCorrespondence : public ElasticPlasticCorrespondence {
 public:
  explicit ViscoplasticNeedlemanCorrespondence(ListReader& params);

  // The plastic increment Deps >= 0 of a step of size dt > 0 from the trial von Mises stress
  // qTrial >= 0, the committed eps_p and the point's sigma_Y(x): the root of the consistency
  // condition above (0 when m = 0 and qTrial <= g(eps_p)). Also reports the iterations it took.
  double plasticIncrement(double qTrial, double eqps, double yieldStress, double dt,
                          int* iterations = nullptr) const;

 protected:
  void unrotatedCauchyStress(int i, const double* d, double dt, const double* sigmaN,
                             double* sigma) override;

 private:
  // g(eps_p) of a point with yield stress sigmaY, and dg/deps_p.
  void hardening(double yieldStress, double eqps, double& g, double& slope) const;
  double strainHardeningExponent_ = 0.0, rateHardeningExponent_ = 0.0;
  double referenceStrainRate_ = 1.0, referenceStrain0_ = 1.0, referenceStrain1_ = 1.0;
};

}  // namespace peridot
