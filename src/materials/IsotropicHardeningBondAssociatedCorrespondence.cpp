#include "materials/IsotropicHardeningBondAssociatedCorrespondence.hpp"

#include "core/Error.hpp"

namespace peridot {

IsotropicHardeningBondAssociatedCorrespondence::IsotropicHardeningBondAssociatedCorrespondence(
    ListReader& p)
    : BondAssociatedCorrespondence(p, "Isotropic Hardening Bond Associated Correspondence") {
  using Kind = correspondence::Hardening::Kind;
  const std::string rule =
      p.choice("Hardening Rule", {"Power-law", "Saturation type exponential"}, "");
  ListReader h = p.sublist("Hardening Parameters");
  correspondence::Hardening hardening;
  if (rule == "Power-law") {
    hardening.kind = Kind::PowerLaw;
    hardening.yield = h.positiveNumber("Yield Stress");
    hardening.strain0 = h.positiveNumber("Hardening Characteristic Strain");
    hardening.exponent = h.number("Hardening Exponent");
    if (!(hardening.exponent >= 0 && hardening.exponent <= 1))
      throw InputError(h.pathOf("Hardening Exponent"),
                       "must be in [0, 1] (a hardening curve whose slope does not grow)");
  } else {
    hardening.kind = Kind::SaturationExponential;
    hardening.yield = h.positiveNumber("Initial Yield Stress");
    hardening.saturated = h.positiveNumber("Saturated Yield Stress");
    hardening.rate = h.nonNegativeNumber("Exponential Constant", -1.0);
    hardening.modulus = h.nonNegativeNumber("Linear Constant", -1.0);
    if (hardening.rate < 0) throw InputError(h.pathOf("Exponential Constant"), "required (>= 0)");
    if (hardening.modulus < 0) throw InputError(h.pathOf("Linear Constant"), "required (>= 0)");
    if (hardening.saturated < hardening.yield)
      throw InputError(h.pathOf("Saturated Yield Stress"),
                       "must be at least the Initial Yield Stress (a softening curve is not "
                       "supported)");
  }
  h.finish();
  setPlasticity(hardening);
}

PERIDOT_REGISTER_MATERIAL(
    "Isotropic Hardening Bond Associated Correspondence",
    IsotropicHardeningBondAssociatedCorrespondence,
    "Bond-associated correspondence solid with J2 plasticity and isotropic hardening per bond "
    "(Peridigm's Power-law or Saturation type exponential rule); outputs "
    "Equivalent_Plastic_Strain, Von_Mises_Stress, Stress_Triaxiality",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Hardening Rule", "\"Power-law\" or \"Saturation type exponential\", required"},
        {"Hardening Parameters",
         "parameter list, required: Power-law: Yield Stress, Hardening Characteristic Strain, "
         "Hardening Exponent (in [0, 1]); Saturation type exponential: Initial Yield Stress, "
         "Saturated Yield Stress, Exponential Constant, Linear Constant"},
        {"Gradient Order Of Accuracy",
         "integer, default 1: order of the gradient weights; only 1 is supported (higher orders "
         "are refused)"},
        {"Hourglass Coefficient", "number >= 0: accepted and ignored (as Peridigm)"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported"},
        {"Finite Difference Probe Length", "positive number: accepted (explicit dynamics only)"}}))

}  // namespace peridot
