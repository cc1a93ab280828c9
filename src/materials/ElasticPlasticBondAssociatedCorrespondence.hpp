#pragma once
// "Elastic Plastic Bond Associated Correspondence": the bond-associated correspondence model
// (materials/BondAssociatedCorrespondence.hpp) with J2 perfect plasticity per bond: the radial
// return of materials/J2Return.hpp on each bond's unrotated Cauchy stress, yield "Yield Stress".
#include "materials/BondAssociatedCorrespondence.hpp"

namespace peridot {

class ElasticPlasticBondAssociatedCorrespondence : public BondAssociatedCorrespondence {
 public:
  explicit ElasticPlasticBondAssociatedCorrespondence(ListReader& params);
};

}  // namespace peridot
