#include "damage/LSJT.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "damage/FractureEnergy.hpp"

namespace peridot {

double lsjtDamageFactor(double integral, double xc) {
  if (!(integral > 0.0)) return 1.0;
  if (!(integral < xc)) return 0.0;
  return std::exp(1.0 - 1.0 / (1.0 - std::pow(integral / xc, 2.01)));
}

LSJT::LSJT(ListReader& p) : criticalStretch_(p) { p.boolean("Verbose", false); }

void LSJT::bind(const MaterialModel& material, double horizon, const std::string& blockName,
                std::ostream& log) {
  criticalStretch_.bind(material, horizon, blockName, log);
}

LsjtStep LSJT::beginLsjtStep(const ModelState& s) {
  LsjtStep k;
  // The history field exists from the first evaluation on (a checkpoint saves it).
  double* history = s.fields->bond(kHistoryIntegral).data();
  // The first evaluation is the initial state at t0: the integral over [t0, t0] is zero. Each
  // later one closes a step [t_{n-1}, t_n] with the rate at its end (the current stretch).
  // A trial evaluation (ModelState::commitHistory false) takes the integral to its state
  // without storing it: every trial of a step starts from the integral at the step's start.
  const double dt = started_ ? s.dt : 0.0;
  if (s.commitHistory) started_ = true;
  if (dt == 0.0) return k;  // inactive: nothing accumulates
  k.historyIntegral = history;
  k.dt = dt;
  k.criticalStretch = criticalStretch_.value();
  k.xc = lsjtOverstretchRate(1.05 * k.criticalStretch, k.criticalStretch) * s.dt;
  k.commit = s.commitHistory;
  return k;
}

void LSJT::computeDamage(const ModelState& s, const std::vector<int>& points, float* bondDamage) {
  const LsjtStep k = beginLsjtStep(s);
  if (!k.active()) return;
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  std::int64_t family = 0;
  for (int i : points) family = std::max(family, offsets[i + 1] - offsets[i]);
  scratch_.resize(3 * static_cast<std::size_t>(family));
  double* dot = scratch_.data();
  double* eps = dot + family;
  double* integral = eps + family;
  for (int i : points) {
    if (lsjtStrains(s.x, s.y, s.topology->neighbors.data(), s.bondLength, i, offsets[i],
                    offsets[i + 1], dot, eps, k.criticalStretch))
      lsjtUpdateBonds(k, offsets[i], offsets[i + 1], eps, integral, bondDamage);
  }
}

PERIDOT_REGISTER_DAMAGE(
    "LSJ-T", LSJT,
    "Aguiar-Patriota LSJ-T damage (paper 001): damage factor h of the time integral of the "
    "overstretch rate j_s(eps) of each bond; with \"Linearized LPS\" it is their LSJ-T model",
    (std::vector<ParameterDoc>{
        {"Critical Stretch", "positive number: S_c (or give Fracture Energy)"},
        {"Fracture Energy",
         "positive number: G0, from which S_c is derived per block from its material, dimension "
         "and influence function (doc/theory/planar-and-fracture-energy.md)"},
        {"Verbose", "bool, default false"}}))

}  // namespace peridot
