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
//
// QUAD4 (and the corner nodes 1-4 of QUAD8/QUAD9, SHELL4): corners in order around the element,
// the bilinear image of the square [-1,1]^2 with corners (-1,-1), (+1,-1), (+1,+1), (-1,+1).
// TRI3 (and the corner nodes 1-3 of TRI6/TRI7): any order. Planar elements are in the x-y plane.

#include <string>

namespace peridot {

// The element types the Exodus reader turns into points.
enum class ElementKind { Hex, Tet, Sphere, Quad, Tri, Unsupported };

inline bool isPlanar(ElementKind kind) {
  return kind == ElementKind::Quad || kind == ElementKind::Tri;
}

// The kind of an Exodus element block from its upper-case topology name and nodes per element.
ElementKind classify(const std::string& topology, long long nodesPerElement);

// Signed volume of the trilinear hexahedron: the integral of det(dx/dxi) over [-1,1]^3, computed
// with 2x2x2 Gauss points (exact: the Jacobian determinant is at most quadratic in each reference
// coordinate). Positive for the Exodus (right-handed) node order, negative for a mirrored element.
double hexVolume(const double nodes[8][3]);

// Arithmetic mean of the 8 corner nodes; it equals the centroid for parallelepipeds but not for
// general (non-affine) hexes, where Peridigm's point is hexTetCentroid's.
void hexNodeAverage(const double nodes[8][3], double average[3]);

// Volume-weighted centroid (integral of x dV / V, exact with 2x2x2 Gauss points) of the trilinear
// hexahedron; returns the signed volume as hexVolume does. The centroid is left at the node
// average when the volume is zero.
double hexCentroid(const double nodes[8][3], double centroid[3]);

// Peridigm's point and volume of a hex element: the hex split into 24 tetrahedra, each made of
// one edge of a face, that face's centre (the mean of its 4 corners) and the body centre (the
// mean of the bottom and top face centres); the volume is their sum and the position their
// volume-weighted centroid. Exact for hexes with planar faces (any shape, not only
// parallelepipeds); the volume of a trilinear hex with warped faces too. Same operands in the
// same order as Peridigm, so its points and volumes come out to the bit. Returns the signed
// volume (negative for a mirrored node order; the centroid is right either way). The centroid
// is not finite when the volume is zero.
double hexTetCentroid(const double nodes[8][3], double centroid[3]);

// Volume of the tetrahedron, positive whatever the node orientation (0 for a degenerate one).
double tetVolume(const double nodes[4][3]);

// Centroid of the tetrahedron: the mean of its 4 nodes.
void tetCentroid(const double nodes[4][3], double centroid[3]);

// Signed area of the bilinear quadrilateral, positive for counter-clockwise corners. Its Jacobian
// determinant is affine in the reference coordinates, so the area is exact from the corners (the
// shoelace formula).
double quadArea(const double nodes[4][2]);

// True when the bilinear map is one-to-one: the Jacobian determinant, affine in each reference
// coordinate, keeps the sign of the area at all four corners (the cross product of the two edges
// meeting there), i.e. the quad is convex and not self-intersecting (a bow tie). A corner with
// collinear edges (a quad collapsed towards a triangle) is accepted.
bool quadIsValid(const double nodes[4][2]);

// Arithmetic mean of the 4 corner nodes.
void quadNodeAverage(const double nodes[4][2], double average[2]);

// Area-weighted centroid of the quadrilateral (the 2D analogue of hexTetCentroid: four
// triangles around the corner mean, exact for any convex quad); returns the signed area (the
// same as quadArea up to rounding). The corner mean is returned for a zero area.
double quadCentroid(const double nodes[4][2], double centroid[2]);

// Signed area of the triangle, positive for counter-clockwise corners.
double triArea(const double nodes[3][2]);

// Centroid of the triangle: the mean of its 3 nodes.
void triCentroid(const double nodes[3][2], double centroid[2]);

}  // namespace peridot
