#include "materials/ElasticPlasticHypoelasticCorrespondence.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace peridot {

namespace {
// The trial increment and the return of one bond or point; eps_p by slot.
struct PlasticLaw {
  double lambda, mu, yield, eps0, exponent;
  const double *bondEqps, *pointEqps;
  double *bondEqpsNew, *pointEqpsNew;
  void operator()(std::size_t slot, const double* d, double dt, const double* sigmaN, double* sigma,
                  bool bond) const {
    correspondence::hypoelasticIncrement(lambda, mu, d, dt, sigmaN, sigma);  // trial
    const double eqps = bond ? bondEqps[slot] : pointEqps[slot];
    const double dgamma = exponent == 0.0 ? correspondence::radialReturn(mu, 0.0, yield, sigma)
                                          : ElasticPlasticHypoelasticCorrespondence::powerLawReturn(
                                                mu, yield, eps0, exponent, eqps, sigma);
    (bond ? bondEqpsNew : pointEqpsNew)[slot] = eqps + dgamma;
  }
};
}  // namespace

ElasticPlasticHypoelasticCorrespondence::ElasticPlasticHypoelasticCorrespondence(
    ListReader& p, const std::string& name, bool hardening)
    : HypoelasticCorrespondence(p, name) {
  yieldStress_ = p.positiveNumber("Yield Stress");
  if (hardening) {
    for (const char* key : {"Hardening Characteristic Strain", "Hardening Exponent"})
      if (!p.has(key)) throw InputError(p.pathOf(key), "required (as Peridigm)");
    eps0_ = p.positiveNumber("Hardening Characteristic Strain");
    exponent_ = p.number("Hardening Exponent");
    if (!(exponent_ >= 0 && exponent_ <= 1))
      throw InputError(p.pathOf("Hardening Exponent"),
                       "must be in [0, 1] (0: perfect plasticity; yield sigma_Y (1 + eps_p / "
                       "eps_0)^n)");
  }
}

double ElasticPlasticHypoelasticCorrespondence::powerLawReturn(double mu, double yieldStress,
                                                               double eps0, double exponent,
                                                               double eqps, double* sigma) {
  const auto yieldAt = [&](double e) { return yieldStress * std::pow(1.0 + e / eps0, exponent); };
  // (1 + 0 / eps_0)^n = 1: a bond that never yielded needs no pow (most bonds, most steps).
  const double yieldNow = eqps == 0.0 ? yieldStress : yieldAt(eqps);
  if (exponent == 0.0) return correspondence::radialReturn(mu, 0.0, yieldNow, sigma);
  const double mean = (sigma[0] + sigma[4] + sigma[8]) / 3.0;
  double dev[9], ss = 0;
  for (int k = 0; k < 9; ++k) {
    dev[k] = sigma[k] - (k % 4 == 0 ? mean : 0.0);
    ss += dev[k] * dev[k];
  }
  const double q = std::sqrt(1.5 * ss);
  if (q <= yieldNow || !(ss > 0)) return 0.0;
  // r(dgamma) = q - 3 mu dgamma - sigma_y(eps_p + dgamma) = 0: r is decreasing and concave in
  // dgamma (sigma_y concave for n <= 1), so Newton from 0 climbs monotonically to the root.
  double dgamma = 0;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double base = 1.0 + (eqps + dgamma) / eps0;
    const double yieldNew = yieldStress * std::pow(base, exponent);  // one pow per iteration
    const double slope = yieldNew * exponent / (eps0 * base);
    const double r = q - 3.0 * mu * dgamma - yieldNew;
    const double step = r / (3.0 * mu + slope);
    dgamma += step;
    // Newton climbs to the root from below: a step that is no longer positive beyond rounding
    // means it has arrived (a tolerance test on |step| alone can cycle at the last bit).
    if (!(step > 1e-15 * dgamma)) break;
  }
  const double shrink = 1.0 - 3.0 * mu * dgamma / q;
  for (int k = 0; k < 9; ++k) sigma[k] = (k % 4 == 0 ? mean : 0.0) + shrink * dev[k];
  return dgamma;
}

void ElasticPlasticHypoelasticCorrespondence::declareFields(FieldManager& fields) {
  HypoelasticCorrespondence::declareFields(fields);
  eqps_ = fields.node(kEquivalentPlasticStrain, 1);
  triaxiality_ = fields.node(kStressTriaxiality, 1);
  bondEqps_ = &fields.bond(kBondEquivalentPlasticStrain, 0.0);
}

void ElasticPlasticHypoelasticCorrespondence::initialize(const ModelState& s,
                                                         const std::vector<int>& points) {
  HypoelasticCorrespondence::initialize(s, points);
  eqpsNew_.resize(static_cast<std::size_t>(s.topology->numOverlap), 0.0);
  bondEqpsNew_.resize(bondEqps_->size(), 0.0);
  for (int i : points) eqpsNew_[i] = eqps_[i], triaxiality_[i] = 0.0;
}

std::vector<std::string> ElasticPlasticHypoelasticCorrespondence::outputFields() const {
  auto names = HypoelasticCorrespondence::outputFields();
  names.push_back(kEquivalentPlasticStrain);
  names.push_back(kStressTriaxiality);
  return names;
}

std::vector<std::string> ElasticPlasticHypoelasticCorrespondence::historyNodeFields() const {
  auto names = HypoelasticCorrespondence::historyNodeFields();
  names.push_back(kEquivalentPlasticStrain);
  return names;
}

void ElasticPlasticHypoelasticCorrespondence::bondStresses(const ModelState& s) {
  bondStressesWith(s, PlasticLaw{lame_, constants_.shearModulus, yieldStress_, eps0_, exponent_,
                                 bondEqps_->data(), eqps_, bondEqpsNew_.data(), eqpsNew_.data()});
}

void ElasticPlasticHypoelasticCorrespondence::pointStresses(const ModelState& s,
                                                            const std::vector<int>& points) {
  pointStressesWith(s, points,
                    PlasticLaw{lame_, constants_.shearModulus, yieldStress_, eps0_, exponent_,
                               bondEqps_->data(), eqps_, bondEqpsNew_.data(), eqpsNew_.data()});
  for (int i : points) {
    const double* sigma = unrotatedNew_.data() + 9 * i;
    const double q = correspondence::vonMises(sigma);
    triaxiality_[i] = (sigma[0] + sigma[4] + sigma[8]) / (3.0 * std::max(1e-20, q));
  }
}

void ElasticPlasticHypoelasticCorrespondence::commitLaw(const ModelState&,
                                                        const std::vector<int>& points) {
  for (int i : points) eqps_[i] = eqpsNew_[i];
  std::copy(bondEqpsNew_.begin(), bondEqpsNew_.end(), bondEqps_->begin());
}

PERIDOT_REGISTER_MATERIAL(
    "Elastic Plastic Hypoelastic Correspondence", ElasticPlasticHypoelasticCorrespondence,
    "Hypoelastic correspondence solid (bond-level stress, higher-order gradient) with J2 perfect "
    "plasticity per bond; outputs Equivalent_Plastic_Strain, Stress_Triaxiality",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Yield Stress", "positive number, required: uniaxial yield stress sigma_Y"},
        {"Actual Horizon", "positive number, required: delta of the gradient's monomials"},
        {"Gradient Order Of Accuracy", "integer 1-4, default 1"},
        {"Hourglass Coefficient", "number >= 0: accepted and ignored (no hourglass force)"},
        {"Apply Automatic Differentiation Jacobian", "refused (as Peridigm)"},
        {"Apply Shear Correction Factor", "refused (as Peridigm)"},
        {"Thermal Expansion Coefficient", "refused (as Peridigm)"}}))

}  // namespace peridot
