#include "materials/ElasticPlasticHardening.hpp"

namespace peridot {

PERIDOT_REGISTER_MATERIAL(
    "Elastic Plastic Hardening", ElasticPlasticHardening,
    "Ordinary state-based elastic-plastic solid with linear isotropic hardening (Mitchell); "
    "output Lambda",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Yield Stress",
         "positive number, required: initial uniaxial yield stress; psi_0 = 25 sigma_Y^2 / "
         "(8 pi delta^5)"},
        {"Hardening Modulus",
         "number >= 0, required: H in the yield value psi = psi_0 + H Lambda (Peridigm's units: "
         "psi per unit of the plastic multiplier Lambda)"},
        {"Apply Shear Correction Factor",
         "bool, default false: scale alpha = 15 G / m by the point's shear correction factor "
         "and psi_0 by its square (as Peridigm)"},
        {"Disable Plasticity", "bool, default false: never yield"},
        {"Planar Problem", "bool: only false (Peridigm's planar variant is not supported)"},
        {"Thickness", "not supported (belongs to \"Planar Problem\")"},
        {"Apply Automatic Differentiation Jacobian",
         "bool: accepted; the implicit tangent is probed by finite differences"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported"},
        {"Finite Difference Probe Length",
         "positive number: accepted; the probe is Solver -> Finite Difference Probe Length"}}))

}  // namespace peridot
