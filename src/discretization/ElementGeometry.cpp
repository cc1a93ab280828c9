#include "discretization/ElementGeometry.hpp"

#include <cmath>

namespace peridot {

namespace {

// Reference coordinates of the hex corners in Exodus order.
constexpr double kCorner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

double det3(const double a[3], const double b[3], const double c[3]) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// Position and Jacobian determinant of the trilinear map at reference point r.
double hexMapAt(const double nodes[8][3], const double r[3], double x[3]) {
  // d[i][k]: derivative of physical coordinate k with respect to reference coordinate i.
  double d[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  x[0] = x[1] = x[2] = 0.0;
  for (int a = 0; a < 8; ++a) {
    const double f[3] = {1.0 + kCorner[a][0] * r[0], 1.0 + kCorner[a][1] * r[1],
                         1.0 + kCorner[a][2] * r[2]};
    const double shape = f[0] * f[1] * f[2] / 8.0;
    const double dShape[3] = {kCorner[a][0] * f[1] * f[2] / 8.0, f[0] * kCorner[a][1] * f[2] / 8.0,
                              f[0] * f[1] * kCorner[a][2] / 8.0};
    for (int k = 0; k < 3; ++k) {
      x[k] += shape * nodes[a][k];
      for (int i = 0; i < 3; ++i) d[i][k] += dShape[i] * nodes[a][k];
    }
  }
  return det3(d[0], d[1], d[2]);
}

// Integrates detJ and x*detJ with the 2x2x2 Gauss rule (unit weights).
double hexIntegrate(const double nodes[8][3], double moment[3]) {
  const double g = 1.0 / std::sqrt(3.0);
  double volume = 0.0;
  moment[0] = moment[1] = moment[2] = 0.0;
  for (int q = 0; q < 8; ++q) {
    const double r[3] = {kCorner[q][0] * g, kCorner[q][1] * g, kCorner[q][2] * g};
    double x[3];
    const double detJ = hexMapAt(nodes, r, x);
    volume += detJ;
    for (int k = 0; k < 3; ++k) moment[k] += x[k] * detJ;
  }
  return volume;
}

}  // namespace

double hexVolume(const double nodes[8][3]) {
  double moment[3];
  return hexIntegrate(nodes, moment);
}

void hexNodeAverage(const double nodes[8][3], double average[3]) {
  for (int k = 0; k < 3; ++k) {
    double sum = 0.0;
    for (int a = 0; a < 8; ++a) sum += nodes[a][k];
    average[k] = sum / 8.0;
  }
}

double hexCentroid(const double nodes[8][3], double centroid[3]) {
  double moment[3];
  const double volume = hexIntegrate(nodes, moment);
  if (volume == 0.0) {
    hexNodeAverage(nodes, centroid);
  } else {
    for (int k = 0; k < 3; ++k) centroid[k] = moment[k] / volume;
  }
  return volume;
}

namespace {

// The 24 tetrahedra of a hex in Peridigm's order: for each face, its centre (the mean of the
// corners listed, summed in that order) and four edges (a, b), each giving the tetrahedron
// (a, b, face centre, body centre). The body centre is the mean of the centres of faces 4 and 5.
struct HexFace {
  int corners[4];
  int edges[4][2];
};
constexpr HexFace kHexFaces[6] = {{{0, 1, 4, 5}, {{1, 0}, {5, 1}, {4, 5}, {0, 4}}},
                                  {{1, 2, 5, 6}, {{2, 1}, {6, 2}, {5, 6}, {1, 5}}},
                                  {{2, 3, 6, 7}, {{3, 2}, {7, 3}, {6, 7}, {2, 6}}},
                                  {{0, 3, 4, 7}, {{0, 3}, {3, 7}, {7, 4}, {4, 0}}},
                                  {{0, 1, 2, 3}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}},
                                  {{4, 5, 6, 7}, {{5, 4}, {4, 7}, {7, 6}, {6, 5}}}};

// Signed volume of the tetrahedron (p0, p1, p2, p3): (p1-p0) . ((p2-p0) x (p3-p0)) / 6, the
// terms grouped as Peridigm groups them so that its volumes and centroids come out to the bit.
double signedTetVolume(const double* p0, const double* p1, const double* p2, const double* p3) {
  double a[3], b[3], c[3];
  for (int k = 0; k < 3; ++k) {
    a[k] = p1[k] - p0[k];
    b[k] = p2[k] - p0[k];
    c[k] = p3[k] - p0[k];
  }
  return (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
          a[2] * (b[0] * c[1] - b[1] * c[0])) /
         6.0;
}

}  // namespace

double hexTetCentroid(const double nodes[8][3], double centroid[3]) {
  double faceCentre[6][3];
  for (int f = 0; f < 6; ++f) {
    const int* n = kHexFaces[f].corners;
    for (int k = 0; k < 3; ++k) {
      faceCentre[f][k] = 0.25 * (nodes[n[0]][k] + nodes[n[1]][k] + nodes[n[2]][k] + nodes[n[3]][k]);
    }
  }
  double body[3];
  for (int k = 0; k < 3; ++k) body[k] = 0.5 * (faceCentre[4][k] + faceCentre[5][k]);
  double volume = 0.0;
  double moment[3] = {0.0, 0.0, 0.0};
  for (int f = 0; f < 6; ++f) {
    for (const auto& edge : kHexFaces[f].edges) {
      const double* p0 = nodes[edge[0]];
      const double* p1 = nodes[edge[1]];
      const double* p2 = faceCentre[f];
      const double v = signedTetVolume(p0, p1, p2, body);
      volume += v;
      for (int k = 0; k < 3; ++k) moment[k] += (p0[k] + p1[k] + p2[k] + body[k]) * 0.25 * v;
    }
  }
  for (int k = 0; k < 3; ++k) centroid[k] = moment[k] / volume;
  return volume;
}

double tetVolume(const double nodes[4][3]) {
  double e[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) e[i][k] = nodes[i + 1][k] - nodes[0][k];
  }
  return std::fabs(det3(e[0], e[1], e[2])) / 6.0;
}

void tetCentroid(const double nodes[4][3], double centroid[3]) {
  for (int k = 0; k < 3; ++k) {
    centroid[k] = (nodes[0][k] + nodes[1][k] + nodes[2][k] + nodes[3][k]) / 4.0;
  }
}

double quadArea(const double nodes[4][2]) {
  double twice = 0.0;
  for (int a = 0; a < 4; ++a) {
    const double* p = nodes[a];
    const double* q = nodes[(a + 1) % 4];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * twice;
}

bool quadIsValid(const double nodes[4][2]) {
  const double area = quadArea(nodes);
  if (area == 0.0) return false;
  for (int a = 0; a < 4; ++a) {
    const double* previous = nodes[(a + 3) % 4];
    const double* here = nodes[a];
    const double* next = nodes[(a + 1) % 4];
    const double cross = (next[0] - here[0]) * (previous[1] - here[1]) -
                         (next[1] - here[1]) * (previous[0] - here[0]);
    if (cross * area < 0.0) return false;
  }
  return true;
}

void quadNodeAverage(const double nodes[4][2], double average[2]) {
  for (int k = 0; k < 2; ++k) {
    average[k] = (nodes[0][k] + nodes[1][k] + nodes[2][k] + nodes[3][k]) / 4.0;
  }
}

double quadCentroid(const double nodes[4][2], double centroid[2]) {
  double centre[2];
  quadNodeAverage(nodes, centre);
  double area = 0.0;
  double moment[2] = {0.0, 0.0};
  for (int a = 0; a < 4; ++a) {
    const double* p = nodes[a];
    const double* q = nodes[(a + 1) % 4];
    const double twice =
        (p[0] - centre[0]) * (q[1] - centre[1]) - (p[1] - centre[1]) * (q[0] - centre[0]);
    area += 0.5 * twice;
    for (int k = 0; k < 2; ++k) moment[k] += (p[k] + q[k] + centre[k]) / 3.0 * (0.5 * twice);
  }
  for (int k = 0; k < 2; ++k) centroid[k] = area == 0.0 ? centre[k] : moment[k] / area;
  return area;
}

double triArea(const double nodes[3][2]) {
  return 0.5 * ((nodes[1][0] - nodes[0][0]) * (nodes[2][1] - nodes[0][1]) -
                (nodes[1][1] - nodes[0][1]) * (nodes[2][0] - nodes[0][0]));
}

void triCentroid(const double nodes[3][2], double centroid[2]) {
  for (int k = 0; k < 2; ++k) centroid[k] = (nodes[0][k] + nodes[1][k] + nodes[2][k]) / 3.0;
}

ElementKind classify(const std::string& topology, long long nodesPerElement) {
  // Exodus names planar quads QUAD/QUAD4/QUAD8/QUAD9 (SHELL4 etc. when written by a 3D mesher)
  // and triangles TRI/TRI3/TRI6/TRI7/TRIANGLE (TRISHELL for shells); higher-order elements are
  // read through their corner nodes, which come first.
  if (topology.rfind("QUAD", 0) == 0 || topology.rfind("SHELL", 0) == 0) {
    if (nodesPerElement == 4 || nodesPerElement == 8 || nodesPerElement == 9) {
      return ElementKind::Quad;
    }
  } else if (topology.rfind("TRI", 0) == 0) {
    if (nodesPerElement == 3 || nodesPerElement == 6 || nodesPerElement == 7) {
      return ElementKind::Tri;
    }
  } else if (topology.rfind("HEX", 0) == 0) {
    if (nodesPerElement == 8 || nodesPerElement == 20 || nodesPerElement == 27) {
      return ElementKind::Hex;
    }
  } else if (topology.rfind("TET", 0) == 0) {
    if (nodesPerElement == 4 || nodesPerElement == 10) return ElementKind::Tet;
  } else if (topology == "SPHERE") {
    if (nodesPerElement == 1) return ElementKind::Sphere;
  }
  return ElementKind::Unsupported;
}

}  // namespace peridot
