#include "materials/ElasticPlasticBondAssociatedCorrespondence.hpp"

namespace peridot {

ElasticPlasticBondAssociatedCorrespondence::ElasticPlasticBondAssociatedCorrespondence(
    ListReader& p)
    : BondAssociatedCorrespondence(p, "Elastic Plastic Bond Associated Correspondence") {
  correspondence::Hardening perfect;  // linear with H = 0
  perfect.yield = p.positiveNumber("Yield Stress");
  setPlasticity(perfect);
}

PERIDOT_REGISTER_MATERIAL(
    "Elastic Plastic Bond Associated Correspondence", ElasticPlasticBondAssociatedCorrespondence,
    "Bond-associated correspondence solid with J2 perfect plasticity per bond (radial return on "
    "each bond's unrotated Cauchy stress); outputs Equivalent_Plastic_Strain, Von_Mises_Stress, "
    "Stress_Triaxiality",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Yield Stress", "positive number, required: uniaxial yield stress sigma_Y"},
        {"Gradient Order Of Accuracy",
         "integer, default 1: order of the gradient weights; only 1 is supported (higher orders "
         "are refused)"},
        {"Hourglass Coefficient", "number >= 0: accepted and ignored (as Peridigm)"},
        {"Thermal Expansion Coefficient", "number: only 0 is supported"},
        {"Finite Difference Probe Length", "positive number: accepted (explicit dynamics only)"}}))

}  // namespace peridot
