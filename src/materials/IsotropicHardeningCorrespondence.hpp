#pragma once
// "Isotropic Hardening Correspondence": "Elastic Plastic Correspondence" with linear isotropic
// hardening, yield sigma_Y + H eps_p, and Peridigm's optional flaw: with "Enable Flaw", the
// yield stress of a point at x is sigma_Y (1 - m exp(-|x - x_f|^2 / s^2)) (m "Flaw
// Magnitude", s "Flaw Size", x_f "Flaw Location X/Y/Z"), to seed localisation.
#include "materials/ElasticPlasticCorrespondence.hpp"

namespace peridot {

class IsotropicHardeningCorrespondence : public ElasticPlasticCorrespondence {
 public:
  explicit IsotropicHardeningCorrespondence(ListReader& params)
      : ElasticPlasticCorrespondence(params, "Isotropic Hardening Correspondence", true, true) {}
};

}  // namespace peridot
