#pragma once
// Critical stretch from a fracture energy G0 for each material model, dimension and influence
// function (derivations in doc/theory/planar-and-fracture-energy.md). Shared by the damage models
// that accept `Fracture Energy` (Critical Stretch, DTT).
#include <string>

#include "materials/MaterialModel.hpp"

namespace peridot {

// The critical stretch s_c at which the bonds crossing a unit crack area store G0, for a
// material in its bulk (constant horizon `horizon`, full neighbourhood, continuum integrals):
//   bond-based (PMB):   pair energy 1/2 c omega s^2 zeta, c from the dilatation energy;
//   normalized PMB:     pair energy 1/2 c omega s^2, c = its bulk value;
//   LPS (LPS-T):        the bond (deviatoric) term 2 alpha omega zeta^2 p(s) only, as in paper
//                       001 eq. (23)-(24) (the dilatational term is neglected).
// `influenceFunction`: "One", "Conical" or "Conical Over Zeta". Throws InputError(path, ...) for
// a model, dimension or influence function without a formula. `formulaUsed` receives a short
// description of the formula (for the log).
double criticalStretchFromFractureEnergy(const MaterialModel& material, double horizon, double G0,
                                         const std::string& influenceFunction,
                                         std::string& formulaUsed,
                                         const std::string& path = "Fracture Energy");

}  // namespace peridot
