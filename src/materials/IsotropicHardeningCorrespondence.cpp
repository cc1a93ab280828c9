#include "materials/IsotropicHardeningCorrespondence.hpp"

namespace peridot {

PERIDOT_REGISTER_MATERIAL(
    "Isotropic Hardening Correspondence", IsotropicHardeningCorrespondence,
    "Correspondence solid with J2 plasticity and linear isotropic hardening (radial return on "
    "the unrotated Cauchy stress, or on the Green strain); optional Gaussian flaw lowering the "
    "yield stress",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Yield Stress", "positive number, required: initial uniaxial yield stress sigma_Y"},
        {"Hardening Modulus", "number >= 0, required: H, yield sigma_Y + H eps_p"},
        {"Enable Flaw", "bool, default false: lower the yield stress around a point"},
        {"Flaw Location X", "number: x of the flaw's centre (with Enable Flaw)"},
        {"Flaw Location Y", "number: y of the flaw's centre"},
        {"Flaw Location Z", "number: z of the flaw's centre"},
        {"Flaw Size", "positive number: s, the Gaussian's length scale"},
        {"Flaw Magnitude", "number in [0, 1): m, yield sigma_Y (1 - m exp(-|x - x_f|^2 / s^2))"},
        {"Hourglass Coefficient",
         "number >= 0, required: c_hg of the hourglass bond force, C = 18 c_hg K / (pi "
         "delta^4)"},
        {"Stress Integration",
         "\"Hypoelastic Rate\" (default, as Peridigm: unrotated Cauchy stress advanced by the "
         "Flanagan-Taylor rate of deformation) or \"Total Lagrangian Green Strain\" (Peridot "
         "extension: stress from the Green strain of F)"},
        {"Apply Shear Correction Factor", "not available (as in Peridigm)"},
        {"Apply Automatic Differentiation Jacobian",
         "bool: accepted; the implicit tangent is probed by finite differences"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported"},
        {"Finite Difference Probe Length",
         "positive number: accepted; the probe is Solver -> Finite Difference Probe Length"}}))

}  // namespace peridot
