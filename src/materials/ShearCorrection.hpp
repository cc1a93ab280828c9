#pragma once
// Peridigm's shear correction factor of an ordinary state-based point, shared by the LPS
// ("Elastic") and the hardening plasticity model ("Elastic Plastic Hardening").
#include "materials/MaterialModel.hpp"

namespace peridot {

// The ratio between the continuum and the discrete deviatoric energy of pure shear of point i's
// neighbourhood (m its weighted volume; theta = thetaFactor / m sum omega zeta e V; alpha =
// deviatoricFactor G / m), so that alpha times it reproduces the continuum shear energy.
double shearCorrectionFactor(const ModelState& s, int i, double m, double thetaFactor,
                             double deviatoricFactor);

}  // namespace peridot
