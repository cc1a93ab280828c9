#pragma once
// "Elastic Bond Associated Correspondence": the bond-associated correspondence kinematics and
// force state (materials/BondAssociatedCorrespondence.hpp) with the linear isotropic hypoelastic
// law, sigma_u += dt (lambda tr(d) I + 2 mu d), per bond. No hourglass control.
#include "materials/BondAssociatedCorrespondence.hpp"

namespace peridot {

class ElasticBondAssociatedCorrespondence : public BondAssociatedCorrespondence {
 public:
  explicit ElasticBondAssociatedCorrespondence(ListReader& params)
      : BondAssociatedCorrespondence(params, "Elastic Bond Associated Correspondence") {}
};

}  // namespace peridot
