#pragma once
// Reads an Exodus II mesh into a PointCloud: one point per element, Peridigm's way.
#include <string>

#include "discretization/PointCloud.hpp"

namespace peridot {

// The whole mesh on the calling rank: readExodusMeshShare (DistributedExodusReader.hpp) on
// MPI_COMM_SELF, so MPI must be initialized; no communication with other ranks.
//
// - Element types: HEX8/HEX/HEX20/HEX27 (the 8 corner nodes are used), TET4/TET/TETRA/TET10 (the
//   4 corner nodes), SPHERE (one node; the volume is the element's second attribute). Other types
//   (WEDGE, PYRAMID, BEAM, ...) are rejected as not supported yet.
// - Planar meshes: QUAD/QUAD4/QUAD8/QUAD9/SHELL4 (the 4 corner nodes) and TRI/TRI3/TRI6/TRI7 (the
//   3 corner nodes), in a num_dim = 2 file, or in a num_dim = 3 file whose nodes all have z = 0.
//   The cloud is then 2D (dimension 2, z = 0): position = area centroid of the element, volume =
//   exact element area x `thickness`. A mesh mixing planar and solid blocks, a planar mesh off z =
//   0, a solid block in a 2D file, and a self-intersecting or non-convex quad are errors.
// - Each element becomes one point: for a hex, Peridigm's point and volume (hexTetCentroid: 24
//   tetrahedra around the face and body centres; the volume-weighted centroid, not the corner
//   mean); for a tet its centroid (the corner mean) and exact volume.
// - Points are in file element order; globalId = Exodus element id (element number map, 1..n when
//   the file has none) - 1; blockId = the Exodus element block id.
// - blockNames holds every element block of the file, named as in the file or "block_<id>" when
//   unnamed. Every node set becomes a PointSet of the global ids of all elements with at least one
//   node (corner or not) in the set, sorted and unique, named as in the file or "nodelist_<id>".
//
// Every problem (missing, truncated or corrupt file, unsupported element type, no elements,
// degenerate element, duplicate ids or names, ...) throws InputError(deckPath, message) with a
// message naming the file, e.g. `cannot open Exodus mesh "foo.g": No such file or directory`.
PointCloud readExodusMesh(const std::string& fileName, const std::string& deckPath,
                          double thickness = 1.0);

// An Exodus file opened for reading: doubles in memory, 64-bit integers through the whole API,
// names up to the longest one the file stores; closed on destruction. The constructor throws
// InputError(deckPath, "cannot open Exodus <kind> \"<file>\": <reason>") when the file is missing
// or unreadable, is not netCDF/Exodus, or is shorter than its header says (a truncated copy, which
// the netCDF library would otherwise read as zeros). kind is e.g. "mesh" or "file".
class ExodusInputFile {
 public:
  ExodusInputFile(const std::string& fileName, const std::string& kind,
                  const std::string& deckPath);
  ~ExodusInputFile();
  ExodusInputFile(const ExodusInputFile&) = delete;
  ExodusInputFile& operator=(const ExodusInputFile&) = delete;

  int id() const { return id_; }

 private:
  int id_ = -1;
};

// The Exodus library's last error message ("(no details)" when it has none).
std::string exodusLastError();

}  // namespace peridot
