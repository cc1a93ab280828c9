#pragma once
// "Isotropic Hardening Bond Associated Correspondence": the bond-associated correspondence model
// (materials/BondAssociatedCorrespondence.hpp) with J2 plasticity and isotropic hardening per
// bond, Peridigm's "Hardening Rule" and "Hardening Parameters":
//   "Power-law":                   sigma_y = sigma_Y (1 + eps_p / eps_0)^n
//     (Yield Stress, Hardening Characteristic Strain eps_0, Hardening Exponent n)
//   "Saturation type exponential": sigma_y = sigma_0 + (sigma_s - sigma_0)(1 - exp(-delta eps_p))
//                                            + H eps_p
//     (Initial Yield Stress sigma_0, Saturated Yield Stress sigma_s, Exponential Constant delta,
//      Linear Constant H)
// The return solves the backward-Euler condition by Newton's iteration (materials/J2Return.hpp).
#include "materials/BondAssociatedCorrespondence.hpp"

namespace peridot {

class IsotropicHardeningBondAssociatedCorrespondence : public BondAssociatedCorrespondence {
 public:
  explicit IsotropicHardeningBondAssociatedCorrespondence(ListReader& params);
};

}  // namespace peridot
