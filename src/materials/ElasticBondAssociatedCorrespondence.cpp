#include "materials/ElasticBondAssociatedCorrespondence.hpp"

namespace peridot {

PERIDOT_REGISTER_MATERIAL(
    "Elastic Bond Associated Correspondence", ElasticBondAssociatedCorrespondence,
    "Bond-associated correspondence solid (Chen; Behzadinasab and Foster): a deformation "
    "gradient and a hypoelastic stress per bond, no hourglass control; explicit dynamics",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Gradient Order Of Accuracy",
         "integer, default 1: order of the gradient weights; only 1 is supported (higher orders "
         "are refused)"},
        {"Hourglass Coefficient", "number >= 0: accepted and ignored (as Peridigm)"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported"},
        {"Finite Difference Probe Length", "positive number: accepted (explicit dynamics only)"}}))

}  // namespace peridot
