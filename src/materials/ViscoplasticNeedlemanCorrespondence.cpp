#include "materials/ViscoplasticNeedlemanCorrespondence.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "materials/CorrespondenceRate.hpp"

namespace peridot {

namespace {

// A required number >= 0 (Peridigm reads these keys without a default).
double requiredNonNegative(ListReader& p, const char* key) {
  const double value = p.number(key);  // throws "required parameter is missing"
  if (value < 0) throw InputError(p.pathOf(key), "expected a non-negative number");
  return value;
}

}  // namespace

ViscoplasticNeedlemanCorrespondence::ViscoplasticNeedlemanCorrespondence(ListReader& p)
    : ElasticPlasticCorrespondence(p, "Viscoplastic Needleman Correspondence", false, true) {
  strainHardeningExponent_ = requiredNonNegative(p, "Strain Hardening Exponent");
  rateHardeningExponent_ = requiredNonNegative(p, "Rate Hardening Exponent");
  referenceStrainRate_ = p.positiveNumber("Reference Strain Rate");
  referenceStrain0_ = p.positiveNumber("Reference Strain 0");
  referenceStrain1_ = p.positiveNumber("Reference Strain 1");
  if (!rateForm())
    throw InputError(p.pathOf("Stress Integration"),
                     "only \"Hypoelastic Rate\" is available for Viscoplastic Needleman "
                     "Correspondence (its flow rule integrates a strain rate, as in Peridigm)");
}

void ViscoplasticNeedlemanCorrespondence::hardening(double yieldStress, double eqps, double& g,
                                                    double& slope) const {
  const double ratio = eqps / referenceStrain1_;
  g = yieldStress * std::pow(1.0 + eqps / referenceStrain0_, strainHardeningExponent_) /
      (1.0 + ratio * ratio);
  // d ln g / d eps_p = N / (eps_0 + eps_p) - 2 eps_p / (eps_1^2 + eps_p^2)
  slope = g * (strainHardeningExponent_ / (referenceStrain0_ + eqps) -
               2.0 * eqps / (referenceStrain1_ * referenceStrain1_ + eqps * eqps));
}

double ViscoplasticNeedlemanCorrespondence::plasticIncrement(double qTrial, double eqps,
                                                             double yieldStress, double dt,
                                                             int* iterations) const {
  if (iterations) *iterations = 0;
  const double m = rateHardeningExponent_;
  const double threeMu = 3.0 * constants_.shearModulus;
  const double base = referenceStrainRate_ * dt;  // the increment at the reference rate
  // r(x) = qTrial - 3 mu x - Y(x): positive at 0+ (or the step is elastic), -Y < 0 at
  // qTrial / 3 mu, and decreasing in between for any hardening slope above -3 mu: one root.
  auto residual = [&](double x, double& slope) {
    double g, dg;
    hardening(yieldStress, eqps + x, g, dg);
    const double rate = m > 0 ? std::pow(x / base, m) : 1.0;
    const double Y = g * rate;
    slope = -threeMu - dg * rate - (m > 0 ? m * Y / x : 0.0);
    return qTrial - threeMu * x - Y;
  };
  double g0, dg0;
  hardening(yieldStress, eqps, g0, dg0);
  if (m == 0 && qTrial <= g0) return 0.0;  // rate-independent: inside the yield surface
  double lo = 0.0, hi = qTrial / threeMu;
  // First guess: with m > 0 the explicit flow increment at the trial stress, epsdot_0 dt (q* /
  // g)^(1/m) (Newton then walks up to the root from the left); with m = 0 the linearised return.
  double x = m > 0 ? base * std::pow(qTrial / g0, 1.0 / m)
                   : (qTrial - g0) / (threeMu + std::max(dg0, 0.0));
  if (!(x > 0)) return 0.0;  // a flow below the smallest double: none
  x = std::min(x, 0.5 * hi);
  for (int iteration = 1; iteration <= 200; ++iteration) {
    if (iterations) *iterations = iteration;
    double slope;
    const double r = residual(x, slope);
    if (r > 0)
      lo = x;
    else if (r < 0)
      hi = x;
    else
      return x;
    const double step = r / slope;
    // Converged: Newton's next step would be below rounding (a relative 1e-12 step is followed
    // by a ~1e-24 one), or below 1e-16 of the largest increment (the stress's own rounding).
    // Tested before the bracket, which rounding can make the converged Newton point leave.
    if (std::abs(step) <= 1e-12 * x || std::abs(step) <= 1e-16 * hi) return x - step;
    double next = x - step;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (hi - lo <= 1e-15 * hi) return next;
    x = next;
  }
  return x;
}

void ViscoplasticNeedlemanCorrespondence::unrotatedCauchyStress(int i, const double* d, double dt,
                                                                const double* sigmaN,
                                                                double* sigma) {
  const double G = constants_.shearModulus;
  correspondence::hypoelasticIncrement(lame_, G, d, dt, sigmaN, sigma);  // trial
  eqpsNew_[i] = eqps_[i];
  const double mean = (sigma[0] + sigma[4] + sigma[8]) / 3.0;  // kept by the radial return
  double dev[9];
  const double ss = deviator(sigma, dev);
  const double q = std::sqrt(1.5 * ss);  // von Mises of the trial stress
  // Peridigm's gate: below the (flaw-lowered) initial yield stress the step is elastic. A step
  // of size 0 (the initial evaluation) has no rate and no flow.
  if (!(dt > 0) || q < yield_[i] || !(ss > 0)) return;
  const double dgamma = plasticIncrement(q, eqps_[i], yield_[i], dt);
  if (!(dgamma > 0)) return;
  const double shrink = 1.0 - 3.0 * G * dgamma / q;
  for (int k = 0; k < 9; ++k) sigma[k] = (k % 4 == 0 ? mean : 0.0) + shrink * dev[k];
  eqpsNew_[i] = eqps_[i] + dgamma;
}

PERIDOT_REGISTER_MATERIAL(
    "Viscoplastic Needleman Correspondence", ViscoplasticNeedlemanCorrespondence,
    "Correspondence solid with Needleman's rate-dependent J2 flow stress sigma_Y (1 + eps_p / "
    "eps_0)^N / (1 + (eps_p / eps_1)^2) (epsdot_p / epsdot_0)^m, backward-Euler radial return on "
    "the unrotated Cauchy stress (rate form); optional Gaussian flaw lowering the yield stress; "
    "outputs Equivalent_Plastic_Strain, Von_Mises_Stress",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Yield Stress",
         "positive number, required: sigma_Y, the stress below which a point is elastic and the "
         "scale of the flow stress"},
        {"Strain Hardening Exponent", "number >= 0, required: N"},
        {"Rate Hardening Exponent",
         "number >= 0, required: m, the rate sensitivity (0: rate-independent)"},
        {"Reference Strain Rate", "positive number, required: epsdot_0 (1/time)"},
        {"Reference Strain 0",
         "positive number, required: eps_0 of the hardening (1 + eps_p/eps_0)^N"},
        {"Reference Strain 1",
         "positive number, required: eps_1 of the softening 1 / (1 + (eps_p/eps_1)^2)"},
        {"Enable Flaw", "bool, default false: lower the yield stress around a point"},
        {"Flaw Location X", "number: x of the flaw's centre (with Enable Flaw)"},
        {"Flaw Location Y", "number: y of the flaw's centre"},
        {"Flaw Location Z", "number: z of the flaw's centre"},
        {"Flaw Size", "positive number: s, the Gaussian's length scale"},
        {"Flaw Magnitude",
         "number in [0, 1): m_f, yield sigma_Y (1 - m_f exp(-|x - x_f|^2 / s^2))"},
        {"Hourglass Coefficient",
         "number >= 0, required: c_hg of the hourglass bond force, C = 18 c_hg K / (pi "
         "delta^4)"},
        {"Stress Integration",
         "\"Hypoelastic Rate\" only (the default, as Peridigm: unrotated Cauchy stress advanced "
         "by the Flanagan-Taylor rate of deformation)"},
        {"Apply Shear Correction Factor", "not available (as in Peridigm)"},
        {"Apply Automatic Differentiation Jacobian",
         "bool: accepted; the implicit tangent is probed by finite differences"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported"},
        {"Finite Difference Probe Length",
         "positive number: accepted; the probe is Solver -> Finite Difference Probe Length"}}))

}  // namespace peridot
