#include "materials/IsotropicHardeningHypoelasticCorrespondence.hpp"

namespace peridot {

PERIDOT_REGISTER_MATERIAL(
    "Isotropic Hardening Hypoelastic Correspondence", IsotropicHardeningHypoelasticCorrespondence,
    "Hypoelastic correspondence solid (bond-level stress, higher-order gradient) with J2 "
    "plasticity and power-law isotropic hardening sigma_Y (1 + eps_p / eps_0)^n per bond",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Yield Stress", "positive number, required: initial uniaxial yield stress sigma_Y"},
        {"Hardening Characteristic Strain", "positive number, required: eps_0"},
        {"Hardening Exponent", "number in [0, 1], required: n"},
        {"Actual Horizon", "positive number, required: delta of the gradient's monomials"},
        {"Gradient Order Of Accuracy", "integer 1-4, default 1"},
        {"Hourglass Coefficient", "number >= 0: accepted and ignored (no hourglass force)"},
        {"Apply Automatic Differentiation Jacobian", "refused (as Peridigm)"},
        {"Apply Shear Correction Factor", "refused (as Peridigm)"},
        {"Thermal Expansion Coefficient", "refused (as Peridigm)"}}))

}  // namespace peridot
