#pragma once
// Deck -> PointCloud: the `Discretization` section (Exodus mesh, text file, or Peridigm's
// PdQuickGrid tensor-product generators) plus the neighbourhood rule that goes with it.
#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "deck/Deck.hpp"
#include "discretization/FacetMesh.hpp"
#include "discretization/PointCloud.hpp"

namespace peridot {

// Bond filters cut bonds whose segment crosses a surface (pre-cracks): a finite rectangle, a
// disk, or a shell mesh of triangles and quads read from an Exodus file (`Exodus Mesh`).
struct BondFilter {
  enum class Kind { RectangularPlane, Disk, ExodusMesh };
  Kind kind = Kind::RectangularPlane;
  std::string name;
  double normal[3] = {0, 0, 1};
  double lowerLeftCorner[3] = {0, 0, 0};
  double bottomUnitVector[3] = {1, 0, 0};
  double bottomLength = 0.0, sideLength = 0.0;
  double center[3] = {0, 0, 0};
  double radius = 0.0;
  std::shared_ptr<const FacetMesh> facets;  // ExodusMesh: shared by the copies of the config
  // True if the segment p -> q crosses the filter surface.
  bool cuts(const double* p, const double* q) const;
};

// Periodic boundaries: along a periodic axis a point near one face is bonded to the images of
// the points near the opposite face, shifted by the box length.
struct PeriodicBox {
  bool periodic[3] = {false, false, false};
  double lower[3] = {0, 0, 0}, upper[3] = {0, 0, 0};
  bool any() const { return periodic[0] || periodic[1] || periodic[2]; }
  // A deformable box (Peridot extension, `Periodic Box Deformation Gradient XX` ... `ZZ`):
  // expressions in t of the box's deformation gradient F(t), row-major; empty when the box is
  // rigid. An image of a point sits at F(t) s from it, s its reference shift (a multiple of the
  // box lengths), so a homogeneous deformation y = F x is carried across the boundary.
  std::vector<std::string> deformation;
  std::string deformationPath;  // deck path of the first key, for messages
};

// How neighbours are selected. Exodus and text meshes use the sphere |xi| <= delta (inclusive);
// PdQuickGrid's default takes every point within +-n cells per axis (a box); with
// `NeighborhoodType: Spherical` it keeps |xi| < delta (strict). In 2D the sphere is a disk (all
// points have z = 0) and the box a rectangle.
struct NeighborhoodRule {
  // CellOverlap (`Partial Volumes`): j is a neighbour when its cell overlaps the horizon ball
  // (src/neighbor/PartialVolume.hpp); its bonds then carry the overlapping fraction.
  enum class Kind { SphereInclusive, SphereStrict, CellBox, CellOverlap };
  Kind kind = Kind::SphereInclusive;
  double cellSize[3] = {0, 0, 0};  // CellBox: generator spacing per axis
  int cellCount[3] = {0, 0, 0};    // CellBox: number of cells per axis (caps n); 0: no such axis
  double overlapReach = 0;         // CellOverlap: the largest half cell diagonal of the cloud
  int dimension = 3;               // CellOverlap: cells are squares in 2D
};

struct DiscretizationConfig {
  std::string type;  // "Exodus", "Gmsh", "Text File", "PdQuickGrid"
  std::string meshFile;
  std::string meshFilePath;  // deck path of the mesh file key, for messages
  enum class Generator {
    None,
    TensorProduct3D,
    TensorProduct2D,
    Cylinder
  } generator = Generator::None;
  // 2 or 3: the `Dimension` key for a text file, the generator's; 0 for Exodus (the mesh's).
  int dimension = 3;
  // `Thickness` of a 2D discretization: volume = area x thickness.
  double thickness = 1.0;
  bool thicknessGiven = false;
  std::string thicknessPath = "Discretization -> Thickness";
  double origin[3] = {0, 0, 0}, length[3] = {0, 0, 0};
  long long numPoints[3] = {0, 0, 0};
  double innerRadius = 0, outerRadius = 0, cylinderLength = 0, ringCenter[2] = {0, 0}, zOrigin = 0;
  long long numRadius = 0;
  bool spherical = false;
  bool omitBondsBetweenBlocks = false;
  std::vector<BondFilter> bondFilters;
  std::string influenceFunction = "One";
  // `Partial Volumes`: neighbours weighted by the part of their cell inside the horizon.
  bool partialVolumes = false;
  // `Bond Storage: "Compact"` (Peridot extension): models that can compute |xi| in their loop do,
  // and a fused critical stretch keeps 1-byte broken flags; "Fast" (default) stores both.
  bool compactBonds = false;
  // `Half Bond List` (Peridot extension; default true, false with Compact storage): bond-based
  // models walk each bond once where the scene allows it (ModelEvaluator::setHalfBondListAllowed).
  bool halfBondList = true;
  std::string generatorPath;
  PeriodicBox periodic;  // bonds across periodic faces reach the images of the points
  // Gmsh: node sets grown into the layer of points within layerDepth of their group
  // (`Node Set Layers`, `Node Set Layer Depth`; 0 until readRunConfig sets the horizon).
  std::vector<std::string> layerSets;
  double layerDepth = 0.0;
  std::string layerSetsPath = "Discretization -> Node Set Layers";
};

// One filter of a `Bond Filters` list (also read by the `Initial Damage` damage model): Type
// `Rectangular_Plane`, `Disk` or `Exodus Mesh` (`File Name`, read here, whole, on every rank).
BondFilter readBondFilter(ListReader filter, const std::string& name);

// Validates the `Discretization` list (reads every key; unknown keys are errors).
DiscretizationConfig readDiscretizationConfig(ListReader discretization);

// Collective: builds this rank's share of the point cloud (see PointCloud). No rank reads or
// holds more than its share plus O(number of ranks): Exodus meshes through partial reads, text
// files by byte ranges, generators only their slice.
PointCloud buildPointCloud(const DiscretizationConfig& config, MPI_Comm comm);

// Not collective: the whole cloud on the calling rank (tests and tools on small meshes); it is
// buildPointCloud on MPI_COMM_SELF, so MPI must be initialized.
PointCloud buildWholePointCloud(const DiscretizationConfig& config);

NeighborhoodRule neighborhoodRule(const DiscretizationConfig& config);

// The whole text mesh on the calling rank (readTextMeshShare on MPI_COMM_SELF).
// Reads `x y z block_id volume` lines ('#', '/', '*' start comments). With dimension 2 the cloud
// is planar: every z must be 0 and the fifth column is the point's area, multiplied by thickness.
PointCloud readTextMesh(const std::string& fileName, const std::string& deckPath, int dimension = 3,
                        double thickness = 1.0);

}  // namespace peridot
