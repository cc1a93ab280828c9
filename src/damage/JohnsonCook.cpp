#include "damage/JohnsonCook.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "materials/Correspondence.hpp"
#include "materials/ElasticPlasticCorrespondence.hpp"

namespace peridot {

JohnsonCook::JohnsonCook(ListReader& p) : path_(p.path()) {
  d1_ = p.number("Damage Parameter 1");
  d2_ = p.number("Damage Parameter 2");
  d3_ = p.number("Damage Parameter 3");
  ramp_.critical = p.positiveNumber("Critical Damage");
  if (ramp_.critical > 1.0)
    throw InputError(p.pathOf("Critical Damage"),
                     "must be at most 1 (the damage parameter stops at 1)");
  ramp_.threshold = p.number("Threshold Damage");
  if (ramp_.threshold < 0.0 || ramp_.threshold >= ramp_.critical)
    throw InputError(p.pathOf("Threshold Damage"),
                     "must be at least 0 and less than Critical Damage (as Peridigm)");
  ramp_.neglect = p.number("Critical Damage To Neglect Material Point", 0.95);
  p.boolean("Verbose", false);
}

void JohnsonCook::bind(const MaterialModel& material, double, const std::string& blockName,
                       std::ostream&) {
  requireMaterialFields(
      material,
      {ElasticPlasticCorrespondence::kEquivalentPlasticStrain,
       CorrespondenceMaterial::kCauchyStress},
      path_, "Johnson Cook", blockName,
      "use a plastic correspondence material (\"Elastic Plastic Correspondence\", \"Isotropic "
      "Hardening Correspondence\", \"Viscoplastic Needleman Correspondence\")");
}

void JohnsonCook::computeDamage(const ModelState& s, const std::vector<int>& points,
                                float* bondDamage) {
  FieldManager& f = *s.fields;
  const double* eqps = f.node(ElasticPlasticCorrespondence::kEquivalentPlasticStrain, 1);
  const double* sigma = f.node(CorrespondenceMaterial::kCauchyStress, 9);
  double* damage = f.node(kDamageParameter, 1);
  double* committed = f.node(kCommittedDamageParameter, 1);
  double* integrated = f.node(kIntegratedPlasticStrain, 1);
  for (int i : points) {
    const double increment = eqps[i] - integrated[i];
    double D = committed[i];
    if (increment > 0.0) {
      const double* t = sigma + 9 * i;
      const double mean = (t[0] + t[4] + t[8]) / 3.0;
      const double equivalent = correspondence::vonMises(t);
      const double triaxiality = equivalent > 0.0 ? mean / equivalent : 0.0;
      const double epsF = failureStrain(triaxiality);
      // A failure strain of zero or less: the first plastic increment fails the point.
      D = epsF > 0.0 ? std::min(1.0, D + increment / epsF) : 1.0;
    }
    damage[i] = D;
    if (s.commitHistory) {
      committed[i] = D;
      integrated[i] = eqps[i];
    }
  }
  // Collective: every rank runs the damage pass of every block (ModelEvaluator::evaluate).
  f.refreshGhosts(kDamageParameter);
  ramp_.apply(s, points, damage, bondDamage);
}

PERIDOT_REGISTER_DAMAGE(
    "Johnson Cook", JohnsonCook,
    "Johnson-Cook ductile damage: each point accumulates D += d eps_p / eps_f(sigma*) from its "
    "plastic correspondence material; bonds break from the larger D of their ends",
    (std::vector<ParameterDoc>{
        {"Damage Parameter 1", "number, required: D1 of eps_f = D1 + D2 exp(-D3 sigma*)"},
        {"Damage Parameter 2", "number, required: D2"},
        {"Damage Parameter 3",
         "number, required: D3 (Peridigm's sign: positive D3 lowers eps_f in tension)"},
        {"Critical Damage",
         "number in (0, 1], required: a bond whose larger end D reaches it is broken "
         "(Peridigm reads it but breaks bonds fully only at D = 1)"},
        {"Threshold Damage",
         "number in [0, Critical Damage), required: bond damage rises linearly from 0 at this "
         "D to 1 at Critical Damage"},
        {"Critical Damage To Neglect Material Point",
         "number, default 0.95: a point whose Damage (mean bond damage) exceeds it has all its "
         "bonds broken"},
        {"Verbose", "bool, default false"}}))

}  // namespace peridot
