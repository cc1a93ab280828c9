#pragma once
// A shell mesh of triangles (the `Exodus Mesh` bond filter): a bond is cut when its segment meets
// any facet. TRI3 facets are taken as they are; QUAD4 / SHELL4 facets are split along their
// 1-3 diagonal into two triangles (Peridigm's own split for planar quads; for a warped quad the
// two flat halves still meet their neighbours along the shared straight edges, so the surface
// has no gaps, which a single plane per quad would not guarantee).
//
// Every rank reads the whole facet file: its size is that of the crack surface, not of the
// problem. A uniform grid of cells over the facets' bounding box keeps a segment test to the
// facets of the few cells its bounding box touches.
#include <array>
#include <string>
#include <vector>

namespace peridot {

class FacetMesh {
 public:
  // Reads the element blocks of an Exodus file (3D coordinates). Types: TRI/TRI3/TRIANGLE/
  // TRISHELL/TRISHELL3/SHELL3 (3 nodes), QUAD/QUAD4/SHELL/SHELL4 (4 corner nodes). Anything else
  // is an InputError naming the deck path, the file and the block.
  static FacetMesh read(const std::string& fileName, const std::string& deckPath);
  // From triangles given directly (tests): 9 numbers per triangle.
  static FacetMesh fromTriangles(const std::vector<double>& corners);
  // Appends the two triangles (a, b, c) and (a, c, d) of a quad a-b-c-d.
  static void splitQuad(const double* a, const double* b, const double* c, const double* d,
                        std::vector<double>& corners);

  // True if the closed segment p-q meets a facet (edges and corners included, within a relative
  // tolerance of 1e-12, so that a bond through a shared edge is cut). Exactly symmetric in p and
  // q (the ends are put in lexicographic order first).
  bool cuts(const double* p, const double* q) const;
  std::size_t numTriangles() const { return corners_.size() / 9; }

 private:
  void buildGrid();
  bool cutsTriangle(std::size_t t, const double* p, const double* q) const;
  std::vector<double> corners_;  // 9 per triangle
  double lo_[3] = {0, 0, 0}, cell_[3] = {1, 1, 1};
  int dims_[3] = {1, 1, 1};
  std::vector<std::size_t> cellStart_, cellTriangles_;  // CSR: the triangles of each cell
};

}  // namespace peridot
