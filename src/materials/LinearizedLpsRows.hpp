#pragma once
// Linearized LPS's bond loops over the full bond lists (materials/LinearizedLPS.hpp), each row
// (one point's bond entries) in two passes: a vector pass computes every bond's scalar (its
// linearized strain, F, the force state's pair sum, the dilatation term) in lanes into a row
// buffer, no lane reading another's result, so each value has the bits a scalar loop gives it;
// then a short scalar pass adds the buffer up in the bond list's order. The sums are thus the
// same, to the bit, as the one-pass scalar loops they replace: a vector reduction would
// reassociate them and change every dilatation and force.
//
// The arithmetic is written out as the earlier scalar loops rounded it (that file is compiled
// with contraction, and GCC fused exactly the multiply-adds written here with mulAdd); this
// file is compiled without contraction (CMakeLists.txt), so the roundings do not depend on how
// the compiler arranges the two passes.
#include <cstdint>
#include <vector>

#include "materials/MaterialModel.hpp"

namespace peridot::llps {

// What the dilatation sum of a point reads (full-list arrays; null pointers: omega = 1, no
// damage, all bonds two-sided).
struct DilatationInputs {
  const int* neighbors = nullptr;
  const double* x = nullptr;
  const double* y = nullptr;
  const double* volume = nullptr;
  const double* influence = nullptr;
  const float* damage = nullptr;
  const unsigned char* sides = nullptr;
};

// sum_j omega mu xi.eta V_j over the bond entries b0 .. b1 of point i that lie in i's own
// horizon: the dilatation theta_i times m_i / kappa. xi.eta is formed from x and y, or taken
// from xiEta[b - b0] when xiEta is given (LSJ-T's lsjtStrains formed it already). `buffer` holds
// at least b1 - b0 doubles.
using DilatationRow = double (*)(const DilatationInputs& in, int i, std::int64_t b0,
                                 std::int64_t b1, const double* xiEta, double* buffer);

// The row sum instantiated for the inputs' options (influence, damage, bond sides) and for
// whether xi.eta is given: chosen once per loop, so the bond loop has no branch on them.
DilatationRow dilatationRow(const DilatationInputs& in, bool xiEtaGiven);

// The force density of `points` (paper 001 eq. 18, along the reference bond):
//   f_i = sum_j mu omega (t_i + t_j) V_j xi,  t_i = mu beta_i theta_i + alpha_i F(eps)
// with the block's bond law F (s.bondLaw), bond damage s.bondDamage, influence s.influence and
// one-sided bonds s.bondSides (an end whose horizon does not hold the bond exerts no t).
void force(const ModelState& s, const std::vector<int>& points, const double* theta,
           const double* alpha, const double* beta);

}  // namespace peridot::llps
