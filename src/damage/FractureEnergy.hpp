#pragma once
// Critical stretch from a fracture energy G0 for each material model, dimension and influence
// function (derivations in doc/theory/planar-and-fracture-energy.md). Shared by the damage models
// that accept `Fracture Energy` (Critical Stretch, DTT).
#include <ostream>
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

// A damage model's critical stretch as the deck gives it: `Critical Stretch` directly, or
// `Fracture Energy`, from which bind() derives it per block (and prints it). Exactly one of
// the two keys; shared by every damage model that has a critical stretch.
class CriticalStretchInput {
 public:
  explicit CriticalStretchInput(ListReader& params);
  double value() const { return criticalStretch_; }
  bool fromFractureEnergy() const { return fractureEnergy_ > 0; }
  // With `Fracture Energy`: s_c from the block's material (and the influence function it
  // assumes) and constant horizon; a no-op otherwise.
  void bind(const MaterialModel& material, double horizon, const std::string& blockName,
            std::ostream& log);

 private:
  double criticalStretch_ = 0;
  double fractureEnergy_ = 0;  // G0, when given instead of the critical stretch
  std::string path_;
};

}  // namespace peridot
