// The shell-mesh bond filter's segment test, against hand-placed segments.
#include <gtest/gtest.h>

#include "discretization/FacetMesh.hpp"

namespace peridot {
namespace {

// The unit square in z = 0 as a quad split on its 1-3 diagonal.
FacetMesh unitSquare() {
  std::vector<double> corners;
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {1, 1, 0}, d[3] = {0, 1, 0};
  FacetMesh::splitQuad(a, b, c, d, corners);
  return FacetMesh::fromTriangles(corners);
}

TEST(FacetMesh, SegmentsThroughTheInteriorEdgesAndCornersAreCut) {
  const FacetMesh m = unitSquare();
  EXPECT_EQ(m.numTriangles(), 2u);
  auto cuts = [&](double x, double y, double z0, double z1) {
    const double p[3] = {x, y, z0}, q[3] = {x, y, z1};
    return m.cuts(p, q);
  };
  EXPECT_TRUE(cuts(0.3, 0.6, -0.5, 0.5));   // interior of the second triangle
  EXPECT_TRUE(cuts(0.7, 0.2, 0.5, -0.5));   // interior of the first, either direction
  EXPECT_TRUE(cuts(0.5, 0.5, -0.1, 0.1));   // on the shared diagonal: no gap between halves
  EXPECT_TRUE(cuts(1.0, 0.5, -0.1, 0.1));   // on the boundary edge (closed facets)
  EXPECT_TRUE(cuts(0.0, 0.0, -0.1, 0.1));   // corner
  EXPECT_TRUE(cuts(0.5, 0.5, 0.0, 1.0));    // an end on the facet (closed segment)
  EXPECT_FALSE(cuts(1.2, 0.5, -0.1, 0.1));  // beside the square
  EXPECT_FALSE(cuts(0.5, 0.5, 0.1, 0.9));   // above it
  const double p[3] = {-1, 0.5, 0}, q[3] = {2, 0.5, 0};
  EXPECT_FALSE(m.cuts(p, q));  // in the plane of the facets: not a crossing
  const double r[3] = {-1, 0.5, 0.2}, s[3] = {2, 0.5, -0.2};
  EXPECT_TRUE(m.cuts(r, s));  // an oblique crossing at (0.5, 0.5, 0)
}

TEST(FacetMesh, AWarpedQuadIsTwoFlatTrianglesOnItsFirstDiagonal) {
  // Corners (0,0,0), (1,0,0), (1,1,1), (0,1,0): the halves are z = y (triangle 1-2-3) and
  // z = x (1-3-4). Above (0.75, 0.25) the split surface is at z = 0.25 (the bilinear patch
  // z = x y would be at 0.1875).
  std::vector<double> corners;
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {1, 1, 1}, d[3] = {0, 1, 0};
  FacetMesh::splitQuad(a, b, c, d, corners);
  const FacetMesh m = FacetMesh::fromTriangles(corners);
  auto cuts = [&](double x, double y, double z0, double z1) {
    const double p[3] = {x, y, z0}, q[3] = {x, y, z1};
    return m.cuts(p, q);
  };
  EXPECT_TRUE(cuts(0.75, 0.25, 0.2, 0.3));
  EXPECT_FALSE(cuts(0.75, 0.25, 0.1, 0.2));  // would cross the bilinear patch, not the halves
  EXPECT_TRUE(cuts(0.25, 0.75, 0.2, 0.3));   // z = x = 0.25 on the other half
}

TEST(FacetMesh, ManyFacetsGridFindsTheRightOne) {
  // A 20 x 20 tiling of [0, 1]^2 at z = 0.5 with one tile left out (a hole at [0.5, 0.55]^2).
  std::vector<double> corners;
  const int n = 20;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (i == 10 && j == 10) continue;
      const double a[3] = {i / 20.0, j / 20.0, 0.5}, b[3] = {(i + 1) / 20.0, j / 20.0, 0.5},
                   c[3] = {(i + 1) / 20.0, (j + 1) / 20.0, 0.5},
                   d[3] = {i / 20.0, (j + 1) / 20.0, 0.5};
      FacetMesh::splitQuad(a, b, c, d, corners);
    }
  const FacetMesh m = FacetMesh::fromTriangles(corners);
  const double hole0[3] = {0.525, 0.525, 0.4}, hole1[3] = {0.525, 0.525, 0.6};
  EXPECT_FALSE(m.cuts(hole0, hole1));
  const double in0[3] = {0.925, 0.125, 0.4}, in1[3] = {0.925, 0.125, 0.6};
  EXPECT_TRUE(m.cuts(in0, in1));
  const double edge0[3] = {0.5, 0.525, 0.4}, edge1[3] = {0.5, 0.525, 0.6};
  EXPECT_TRUE(m.cuts(edge0, edge1));  // the hole's edge belongs to its neighbour tile
}

}  // namespace
}  // namespace peridot
