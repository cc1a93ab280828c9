#pragma once
// Linearized LPS's bond loops over the full bond lists (materials/LinearizedLPS.hpp), with four
// bonds at a time in vector lanes (AVX2 and FMA; the plain scalar loop otherwise and for a row's
// last bonds): each lane does the scalar loop's operations on its bond, no lane reading another's
// result, so every bond's term has the bits the scalar loop gives it, and the terms are then
// added one by one in the bond list's order. The dilatation and the force are thus the same, to
// the bit, as the one-pass scalar loops they replace (a vector reduction would reassociate the
// sums and change every dilatation and force).
//
// The arithmetic is written out as the earlier scalar loops rounded it (that file is compiled
// with contraction, and GCC fused exactly the multiply-adds written here as such); this file is
// compiled without contraction (CMakeLists.txt), so that nothing else is fused.
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
// from xiEta[b - b0] when xiEta is given (LSJ-T's lsjtStrains formed it already).
using DilatationRow = double (*)(const DilatationInputs& in, int i, std::int64_t b0,
                                 std::int64_t b1, const double* xiEta);

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
