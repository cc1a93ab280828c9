#include "damage/TimeDependentCriticalStretch.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "core/Format.hpp"
#include "damage/CriticalStretch.hpp"

namespace peridot {

TimeDependentCriticalStretch::TimeDependentCriticalStretch(ListReader& p) {
  path_ = p.pathOf("Time Dependent Critical Stretch");
  criticalStretch_ =
      std::make_unique<Expression>(p.numberOrExpression("Time Dependent Critical Stretch"),
                                   std::vector<std::string>{"t"}, path_);
  alpha_ = p.number("Thermal Expansion Coefficient", 0.0);
  p.boolean("Verbose", false);
}

void TimeDependentCriticalStretch::computeDamage(const ModelState& s,
                                                 const std::vector<int>& points,
                                                 float* bondDamage) {
  const double sc = criticalStretchAt(s.time);
  if (std::isnan(sc)) {
    // The same on every rank (the time is), so every rank stops with the same message.
    RunError error(path_ + ": the expression gives NaN at t = " + formatNumber(s.time));
    error.markCollective();
    throw error;
  }
  breakStretchedBonds(s, points, sc, alpha_, bondDamage);
}

PERIDOT_REGISTER_DAMAGE(
    "Time Dependent Critical Stretch", TimeDependentCriticalStretch,
    "Critical stretch given as an expression in the time t, evaluated at each model evaluation",
    (std::vector<ParameterDoc>{
        {"Time Dependent Critical Stretch",
         "number or expression in t, required: s_c(t), e.g. \"if(t <= 7.0e-5){ value = 50.0; } "
         "else{ value = 0.015; }\""},
        {"Thermal Expansion Coefficient", "number, default 0: as for Critical Stretch"},
        {"Verbose", "bool, default false"}}))

}  // namespace peridot
