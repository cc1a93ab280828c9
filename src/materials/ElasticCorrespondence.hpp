#pragma once
// "Elastic Correspondence": Silling's non-ordinary correspondence model with a linear isotropic
// law on the Green strain (St Venant-Kirchhoff), S = lambda tr(E) I + 2 mu E, and Peridigm's
// hourglass control ("Hourglass Coefficient"). The shared kinematics, force state and
// diagnostics are in materials/Correspondence.hpp; the theory in doc/theory/correspondence.md.
//
// Peridigm integrates the same linear law in rate form in the frame unrotated by Flanagan and
// Taylor's polar decomposition; for small strains and any rigid rotation both give the same
// stress to first order in the strain (the difference is O(|E|^2), see the theory page).
#include "materials/Correspondence.hpp"

namespace peridot {

class ElasticCorrespondence : public CorrespondenceMaterial {
 public:
  explicit ElasticCorrespondence(ListReader& params);

 protected:
  void secondPiolaKirchhoff(int i, const double* E, double* S) override;
};

}  // namespace peridot
