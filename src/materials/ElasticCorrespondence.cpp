#include "materials/ElasticCorrespondence.hpp"

namespace peridot {

ElasticCorrespondence::ElasticCorrespondence(ListReader& p)
    : CorrespondenceMaterial(p, "Elastic Correspondence") {}

void ElasticCorrespondence::secondPiolaKirchhoff(int, const double* E, double* S) {
  elasticStress(E, S);
}

PERIDOT_REGISTER_MATERIAL(
    "Elastic Correspondence", ElasticCorrespondence,
    "Non-ordinary correspondence solid (Silling): shape tensor, deformation gradient, linear "
    "isotropic hypoelastic law in Flanagan-Taylor's unrotated frame (or on the Green strain), "
    "Peridigm's hourglass control",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Hourglass Coefficient",
         "number >= 0, required: c_hg of the hourglass bond force, C = 18 c_hg K / (pi "
         "delta^4); Peridigm's decks use 0.0-0.05"},
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
