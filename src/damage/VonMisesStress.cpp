#include "damage/VonMisesStress.hpp"

#include "core/Error.hpp"
#include "materials/Correspondence.hpp"

namespace peridot {

VonMisesStress::VonMisesStress(ListReader& p) : path_(p.path()) {
  criticalStress_ = p.positiveNumber("Critical Von Mises Stress");
  ramp_.critical = p.positiveNumber("Critical Damage", 1.0);
  ramp_.threshold = p.nonNegativeNumber("Threshold Damage", 0.99);
  if (ramp_.threshold > ramp_.critical)
    throw InputError(p.pathOf("Threshold Damage"),
                     "cannot be greater than Critical Damage (as Peridigm)");
  ramp_.neglect = p.number("Critical Damage To Neglect Material Point", 0.95);
  p.boolean("Verbose", false);
}

void VonMisesStress::bind(const MaterialModel& material, double, const std::string& blockName,
                          std::ostream&) {
  requireMaterialFields(material, {CorrespondenceMaterial::kVonMisesStress}, path_,
                        "Von Mises Stress", blockName,
                        "use a correspondence material (e.g. \"Elastic Correspondence\")");
}

void VonMisesStress::computeDamage(const ModelState& s, const std::vector<int>& points,
                                   float* bondDamage) {
  FieldManager& f = *s.fields;
  const double* vonMises = f.node(CorrespondenceMaterial::kVonMisesStress, 1);
  double* ratio = f.node(kStressRatio, 1);
  for (int i : points) ratio[i] = vonMises[i] / criticalStress_;
  // Collective: every rank runs the damage pass of every block (ModelEvaluator::evaluate).
  f.refreshGhosts(kStressRatio);
  ramp_.apply(s, points, ratio, bondDamage);
}

PERIDOT_REGISTER_DAMAGE(
    "Von Mises Stress", VonMisesStress,
    "Bonds break when the von Mises stress of an end point (a correspondence material's) "
    "reaches a critical value",
    (std::vector<ParameterDoc>{
        {"Critical Von Mises Stress", "positive number, required: sigma_c"},
        {"Critical Damage",
         "positive number, default 1: a bond whose larger end sigma_vm / sigma_c reaches it is "
         "broken"},
        {"Threshold Damage",
         "number in [0, Critical Damage], default 0.99: bond damage rises linearly from 0 at "
         "this sigma_vm / sigma_c to 1 at Critical Damage"},
        {"Critical Damage To Neglect Material Point",
         "number, default 0.95: a point whose Damage (mean bond damage) exceeds it has all its "
         "bonds broken"},
        {"Verbose", "bool, default false"}}))

}  // namespace peridot
