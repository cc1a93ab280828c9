#pragma once
// "Elastic Correspondence": Silling's non-ordinary correspondence model with a linear isotropic
// law and Peridigm's hourglass control ("Hourglass Coefficient"). By default (as Peridigm) the
// law is hypoelastic, integrated in the frame unrotated by Flanagan and Taylor's rotation:
// sigma_u += dt (lambda tr(d) I + 2 mu d) (CorrespondenceMaterial::unrotatedCauchyStress);
// with "Stress Integration: Total Lagrangian Green Strain" it is St Venant-Kirchhoff,
// S = lambda tr(E) I + 2 mu E. For small strains and any rigid rotation both give the same stress
// to first order in the strain (the difference is O(|E|^2), see doc/theory/correspondence.md).
// The shared kinematics, force state and diagnostics are in materials/Correspondence.hpp.
#include "materials/Correspondence.hpp"

namespace peridot {

class ElasticCorrespondence : public CorrespondenceMaterial {
 public:
  explicit ElasticCorrespondence(ListReader& params);

 protected:
  void secondPiolaKirchhoff(int i, const double* E, double* S) override;
};

}  // namespace peridot
