#include "materials/ElasticPlasticCorrespondence.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "materials/CorrespondenceRate.hpp"

namespace peridot {

double ElasticPlasticCorrespondence::deviator(const double* S, double* dev) {
  const double mean = (S[0] + S[4] + S[8]) / 3.0;
  double ss = 0;
  for (int k = 0; k < 9; ++k) {
    dev[k] = S[k] - (k % 4 == 0 ? mean : 0.0);
    ss += dev[k] * dev[k];
  }
  return ss;
}

ElasticPlasticCorrespondence::ElasticPlasticCorrespondence(ListReader& p, const std::string& name,
                                                           bool hardening, bool flaw)
    : CorrespondenceMaterial(p, name) {
  yieldStress_ = p.positiveNumber("Yield Stress");
  if (hardening) {
    hardeningModulus_ = p.nonNegativeNumber("Hardening Modulus", -1.0);
    if (hardeningModulus_ < 0)
      throw InputError(p.pathOf("Hardening Modulus"), "required (a number >= 0)");
  }
  if (flaw) {
    flaw_ = p.boolean("Enable Flaw", false);
    if (flaw_) {
      flawLocation_[0] = p.number("Flaw Location X");
      flawLocation_[1] = p.number("Flaw Location Y");
      flawLocation_[2] = p.number("Flaw Location Z");
      flawSize_ = p.positiveNumber("Flaw Size");
      flawMagnitude_ = p.number("Flaw Magnitude");
      if (!(flawMagnitude_ >= 0 && flawMagnitude_ < 1))
        throw InputError(p.pathOf("Flaw Magnitude"),
                         "must be in [0, 1): the yield stress at the flaw's centre is "
                         "(1 - magnitude) sigma_Y");
    } else {
      for (const char* key :
           {"Flaw Location X", "Flaw Location Y", "Flaw Location Z", "Flaw Size", "Flaw Magnitude"})
        if (p.has(key)) p.number(key);  // Peridigm reads them only with Enable Flaw
    }
  }
}

double ElasticPlasticCorrespondence::yieldStressAt(const double* x) const {
  if (!flaw_) return yieldStress_;
  double r2 = 0;
  for (int d = 0; d < 3; ++d) r2 += (x[d] - flawLocation_[d]) * (x[d] - flawLocation_[d]);
  return yieldStress_ * (1.0 - flawMagnitude_ * std::exp(-r2 / (flawSize_ * flawSize_)));
}

void ElasticPlasticCorrespondence::declareFields(FieldManager& fields) {
  CorrespondenceMaterial::declareFields(fields);
  eqps_ = fields.node(kEquivalentPlasticStrain, 1);
  if (!rateForm()) plasticStrain_ = fields.node(kPlasticStrain, 9);
}

std::vector<std::string> ElasticPlasticCorrespondence::historyNodeFields() const {
  auto names = CorrespondenceMaterial::historyNodeFields();
  names.push_back(kEquivalentPlasticStrain);
  if (!rateForm()) names.push_back(kPlasticStrain);
  return names;
}

std::vector<std::string> ElasticPlasticCorrespondence::outputFields() const {
  auto names = CorrespondenceMaterial::outputFields();
  names.push_back(kEquivalentPlasticStrain);
  return names;
}

void ElasticPlasticCorrespondence::initialize(const ModelState& s, const std::vector<int>& points) {
  const std::size_t n = static_cast<std::size_t>(s.topology->numOverlap);
  if (eqpsNew_.size() < n) {
    eqpsNew_.resize(n, 0.0);
    if (!rateForm()) plasticStrainNew_.resize(9 * n, 0.0);
    yield_.resize(n, yieldStress_);
  }
  for (int i : points) {
    yield_[i] = yieldStressAt(s.x + 3 * i);
    eqpsNew_[i] = eqps_[i];
    if (!rateForm())
      std::copy(plasticStrain_ + 9 * i, plasticStrain_ + 9 * i + 9,
                plasticStrainNew_.begin() + 9 * i);
  }
  CorrespondenceMaterial::initialize(s, points);
}

void ElasticPlasticCorrespondence::secondPiolaKirchhoff(int i, const double* E, double* S) {
  const double* Ep = plasticStrain_ + 9 * i;
  double Ee[9];
  for (int k = 0; k < 9; ++k) Ee[k] = E[k] - Ep[k];
  elasticStress(Ee, S);  // trial
  double dev[9];
  const double ss = deviator(S, dev);
  const double q = std::sqrt(1.5 * ss);  // von Mises of the trial stress
  const double yieldNow = yield_[i] + hardeningModulus_ * eqps_[i];
  double* EpNew = plasticStrainNew_.data() + 9 * i;
  if (q <= yieldNow || !(ss > 0)) {
    eqpsNew_[i] = eqps_[i];
    std::copy(Ep, Ep + 9, EpNew);
    return;
  }
  const double G = constants_.shearModulus;
  const double dgamma = (q - yieldNow) / (3.0 * G + hardeningModulus_);
  const double norm = std::sqrt(ss);
  const double r = std::sqrt(1.5) * dgamma / norm;  // sqrt(3/2) dgamma n = r dev
  for (int k = 0; k < 9; ++k) {
    S[k] -= 2.0 * G * r * dev[k];
    EpNew[k] = Ep[k] + r * dev[k];
  }
  eqpsNew_[i] = eqps_[i] + dgamma;
}

void ElasticPlasticCorrespondence::unrotatedCauchyStress(int i, const double* d, double dt,
                                                         const double* sigmaN, double* sigma) {
  const double G = constants_.shearModulus;
  correspondence::hypoelasticIncrement(lame_, G, d, dt, sigmaN, sigma);  // trial
  const double yieldNow = yield_[i] + hardeningModulus_ * eqps_[i];
  eqpsNew_[i] = eqps_[i] + correspondence::radialReturn(G, hardeningModulus_, yieldNow, sigma);
}

void ElasticPlasticCorrespondence::commitHistory(const std::vector<int>& points) {
  for (int i : points) {
    eqps_[i] = eqpsNew_[i];
    if (rateForm()) continue;
    std::copy(plasticStrainNew_.begin() + 9 * i, plasticStrainNew_.begin() + 9 * i + 9,
              plasticStrain_ + 9 * i);
  }
}

double ElasticPlasticCorrespondence::energyDensity(int i, const double* E) const {
  double Ee[9];
  for (int k = 0; k < 9; ++k) Ee[k] = E[k] - plasticStrain_[9 * i + k];
  return CorrespondenceMaterial::energyDensity(i, Ee);
}

PERIDOT_REGISTER_MATERIAL(
    "Elastic Plastic Correspondence", ElasticPlasticCorrespondence,
    "Correspondence solid with J2 (von Mises) perfect plasticity, radial return on the "
    "unrotated Cauchy stress (rate form) or the Green strain; outputs "
    "Equivalent_Plastic_Strain, Von_Mises_Stress",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Yield Stress", "positive number, required: uniaxial yield stress sigma_Y"},
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
