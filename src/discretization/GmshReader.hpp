#pragma once
// The Gmsh discretization (`Type: "Gmsh"`): a .msh file (format 4.1 or 2.2, ASCII or binary)
// becomes points as an Exodus mesh does. The cells of the mesh's highest dimension (tetrahedra
// and hexahedra in 3D, triangles and quadrangles in 2D, any order, corners only) are the points;
// their physical groups are the blocks (named by the physical name, else "block_<tag>"); the
// physical groups of lower dimension are node sets (a point is in the set when its cell has a
// node in the group), optionally grown into the layer of points within a depth of the group.
//
// Distribution: every rank streams through the whole file (three passes, nothing buffered but
// its share) and keeps the contiguous slice of the cells (in file order) that Slicing assigns
// it, the nodes of those cells and their set memberships: O(N/P) memory per rank, O(N) reading.
// The facets of the groups grown into layers (a surface, O(N^(2/3))) are kept on every rank.
#include <mpi.h>

#include <string>
#include <vector>

#include "discretization/PointCloud.hpp"

namespace peridot {

struct GmshOptions {
  double thickness = 1.0;           // 2D meshes: volume = area x thickness
  std::vector<std::string> layers;  // node sets grown into layers
  double layerDepth = 0.0;          // > 0 when layers is not empty
  std::string layersPath = "Discretization -> Node Set Layers";  // for messages
};

// Collective over comm. Point ids are the cells' order in the file (0-based, over all cell
// blocks). Throws InputError on every rank, with the same message at any rank count.
PointCloud readGmshMeshShare(const std::string& fileName, const std::string& deckPath,
                             const GmshOptions& options, MPI_Comm comm);

}  // namespace peridot
