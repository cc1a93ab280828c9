#pragma once
// Partial-volume quadrature of the horizon integral. A point stands for a cell (a cube of edge
// h in 3D, a square of side h in 2D, h from its volume) centred on it; a neighbour contributes
// the fraction of its cell that lies inside the horizon ball instead of all or nothing. On a
// lattice this removes most of the quadrature error of the "centre inside" rule, whose shear
// energy oscillates with delta/h (doc/theory/partial-volumes.md). A cell the sphere crosses is
// split into 4^d sub-cells, and each is cut by the sphere's tangent plane normal to its centre's
// direction: the cut of a cube by a plane has a closed form, and the curvature error left is
// O((h/4)^2/delta) per sub-cell.

#include <cstddef>
#include <unordered_map>

namespace peridot {

// Edge of the cell of a point of this volume: V^(1/3) in 3D, sqrt(V / thickness) in 2D.
double cellEdge(double volume, int dimension, double thickness);

// Fraction in [0, 1] of the cell of edge h centred at xi (relative to the horizon's centre,
// |xi| = zeta > 0) that lies inside the ball of radius `horizon`. In 2D the cell is a square
// and xi's z component must be 0.
double cellFractionInHorizon(const double xi[3], double zeta, double h, double horizon,
                             int dimension);

// Whether the cell of edge h centred at xi overlaps the open ball of radius `horizon`: the
// neighbour rule of partial volumes (exact, and cheap: the cell's nearest point to the centre).
bool cellOverlapsHorizon(const double xi[3], double h, double horizon, int dimension);

// cellFractionInHorizon for a scene's many bonds: on a lattice the same offsets recur at every
// point, so fractions are kept per offset. The offset is rounded to h / 2^20 before the
// fraction is computed from it, so that the result does not depend on which bond came first
// (nodal results stay the same at any rank count). Only cells the sphere crosses are cached,
// at most 2^20 of them (beyond that, fractions are computed each time: the same values).
class CellFractionCache {
 public:
  double fraction(const double xi[3], double h, double horizon, int dimension);

 private:
  struct Key {
    long long q[3];
    double h, horizon;
    bool operator==(const Key& o) const {
      return q[0] == o.q[0] && q[1] == o.q[1] && q[2] == o.q[2] && h == o.h && horizon == o.horizon;
    }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const;
  };
  std::unordered_map<Key, double, Hash> cache_;
};

// Largest distance beyond the horizon at which a cell of edge h can still overlap it: half
// the cell's diagonal.
double cellOverlapReach(double h, int dimension);

}  // namespace peridot
