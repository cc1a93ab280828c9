#pragma once
// The linear peridynamic solid's two bond loops (materials/Elastic.hpp, linear law, no thermal
// strain) over the half bond list: each bond's extension, square root and division once instead
// of twice, summed in the order that keeps results identical at any rank count
// (neighbor/HalfBondList.hpp). The same dilatation and force as Elastic's full-list loops, in
// another summation order.
#include "materials/MaterialModel.hpp"

namespace peridot {

// theta_i = c / m_i sum omega (1 - d) |xi| e V_j for every owned point (0 where m_i = 0), each
// bond's term added to both ends; with the fused critical stretch (s.breakableBondDamage or
// s.breakableBondBroken) a bond past it breaks first, in the pairs and the full lists.
void halfLpsDilatation(const ModelState& s, const double* weightedVolume, double thetaFactor,
                       double* dilatation);

// The force density of every owned point: each bond's pair force (t_i + t_j) Y/|Y|, with
//   t = (1 - d) omega (theta beta |xi| + (1 - d) alpha e)
// of each end, added to one end (times the other's volume) and subtracted from the other.
// thetaBeta and alpha per overlap point.
void halfLpsForce(const ModelState& s, const double* thetaBeta, const double* alpha);

}  // namespace peridot
