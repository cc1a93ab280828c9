#include "materials/ElasticHypoelasticCorrespondence.hpp"

namespace peridot {

namespace {
struct LinearLaw {
  double lambda, mu;
  void operator()(std::size_t, const double* d, double dt, const double* sigmaN, double* sigma,
                  bool) const {
    correspondence::hypoelasticIncrement(lambda, mu, d, dt, sigmaN, sigma);
  }
};
}  // namespace

void ElasticHypoelasticCorrespondence::bondStresses(const ModelState& s) {
  bondStressesWith(s, LinearLaw{lame_, constants_.shearModulus});
}

void ElasticHypoelasticCorrespondence::pointStresses(const ModelState& s,
                                                     const std::vector<int>& points) {
  pointStressesWith(s, points, LinearLaw{lame_, constants_.shearModulus});
}

PERIDOT_REGISTER_MATERIAL(
    "Elastic Hypoelastic Correspondence", ElasticHypoelasticCorrespondence,
    "Peridigm's hypoelastic correspondence solid: higher-order peridynamic velocity gradient in "
    "the current configuration, a Flanagan-Taylor hypoelastic stress per bond, no hourglass "
    "force; explicit dynamics, 3D",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Actual Horizon",
         "positive number, required: delta of the gradient's monomials (the block's Horizon, "
         "which sets the neighbour lists, may be larger, as in Peridigm)"},
        {"Gradient Order Of Accuracy",
         "integer 1-4, default 1: n, the gradient is exact for polynomials of degree <= n"},
        {"Hourglass Coefficient", "number >= 0: accepted and ignored (no hourglass force)"},
        {"Apply Automatic Differentiation Jacobian", "refused (as Peridigm)"},
        {"Apply Shear Correction Factor", "refused (as Peridigm)"},
        {"Thermal Expansion Coefficient", "refused (as Peridigm)"}}))

}  // namespace peridot
