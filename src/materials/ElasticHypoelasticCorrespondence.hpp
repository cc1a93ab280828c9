#pragma once
// "Elastic Hypoelastic Correspondence": the hypoelastic correspondence family
// (materials/HypoelasticCorrespondence.hpp) with the linear hypoelastic law on the unrotated
// stress of each bond (and of each point, for output): sigma_u += dt (lambda tr(d) I + 2 mu d).
#include "materials/HypoelasticCorrespondence.hpp"

namespace peridot {

class ElasticHypoelasticCorrespondence : public HypoelasticCorrespondence {
 public:
  explicit ElasticHypoelasticCorrespondence(ListReader& params)
      : HypoelasticCorrespondence(params, "Elastic Hypoelastic Correspondence") {}

 protected:
  void bondStresses(const ModelState& s) override;
  void pointStresses(const ModelState& s, const std::vector<int>& points) override;
};

}  // namespace peridot
