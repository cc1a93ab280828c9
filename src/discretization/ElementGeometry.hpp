#pragma once
// Volumes and centres of the finite elements an Exodus mesh is made of, in Exodus node order.
//
// HEX8 (and the corner nodes 1-8 of HEX20/HEX27): nodes 1-4 are the face zeta = -1 and nodes 5-8
// the face zeta = +1, each counter-clockwise when seen from +zeta; node k+4 sits above node k. In
// reference coordinates (xi, eta, zeta) the corners are
//   1 (-1,-1,-1)  2 (+1,-1,-1)  3 (+1,+1,-1)  4 (-1,+1,-1)
//   5 (-1,-1,+1)  6 (+1,-1,+1)  7 (+1,+1,+1)  8 (-1,+1,+1)
// and the element is the trilinear image of the cube [-1,1]^3.
//
// TET4 (and the corner nodes 1-4 of TET10): any order; the volume is returned unsigned.

namespace peridot {

// Signed volume of the trilinear hexahedron: the integral of det(dx/dxi) over [-1,1]^3, computed
// with 2x2x2 Gauss points (exact: the Jacobian determinant is at most quadratic in each reference
// coordinate). Positive for the Exodus (right-handed) node order, negative for a mirrored element.
double hexVolume(const double nodes[8][3]);

// Arithmetic mean of the 8 corner nodes. This is what Peridigm uses as the point position of a hex
// element; it equals the true centroid for parallelepipeds but not for general (non-affine) hexes.
void hexNodeAverage(const double nodes[8][3], double average[3]);

// Volume-weighted centroid (integral of x dV / V, exact with 2x2x2 Gauss points) of the trilinear
// hexahedron; returns the signed volume as hexVolume does. The centroid is left at the node
// average when the volume is zero.
double hexCentroid(const double nodes[8][3], double centroid[3]);

// Volume of the tetrahedron, positive whatever the node orientation (0 for a degenerate one).
double tetVolume(const double nodes[4][3]);

// Centroid of the tetrahedron: the mean of its 4 nodes.
void tetCentroid(const double nodes[4][3], double centroid[3]);

}  // namespace peridot
