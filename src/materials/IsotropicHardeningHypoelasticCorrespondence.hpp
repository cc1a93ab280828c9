#pragma once
// "Isotropic Hardening Hypoelastic Correspondence": "Elastic Plastic Hypoelastic Correspondence"
// with Peridigm's power-law isotropic hardening, yield sigma_Y (1 + eps_p / eps_0)^n
// ("Hardening Characteristic Strain" eps_0, "Hardening Exponent" n), returned by backward Euler
// (ElasticPlasticHypoelasticCorrespondence::powerLawReturn).
#include "materials/ElasticPlasticHypoelasticCorrespondence.hpp"

namespace peridot {

class IsotropicHardeningHypoelasticCorrespondence : public ElasticPlasticHypoelasticCorrespondence {
 public:
  explicit IsotropicHardeningHypoelasticCorrespondence(ListReader& params)
      : ElasticPlasticHypoelasticCorrespondence(
            params, "Isotropic Hardening Hypoelastic Correspondence", true) {}
};

}  // namespace peridot
