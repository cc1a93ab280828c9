#pragma once
// Who owns which point, which points each rank sees as ghosts, the bonds of every owned point
// as CSR lists in local overlap indices, and the reference data of the points a rank sees.
// Built once from the ranks' shares of the point cloud: every rank holds O(owned + ghosts).
#include <mpi.h>

#include <Teuchos_RCP.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "discretization/Discretization.hpp"
#include "discretization/PointCloud.hpp"

namespace peridot {

using LocalOrdinal = int;
using GlobalOrdinal = long long;
using Map = Tpetra::Map<LocalOrdinal, GlobalOrdinal>;
using Import = Tpetra::Import<LocalOrdinal, GlobalOrdinal>;

struct Topology {
  MPI_Comm comm = MPI_COMM_WORLD;
  int rank = 0, numRanks = 1;
  int numOwned = 0;  // local indices [0, numOwned) are owned, in space-filling-curve order
  // The box of that curve (every point's bounding box, the same on every rank): ordering points
  // by (mortonKey(x, curveLo, curveHi), global id) is one order whatever the partition, and the
  // owned points' local order is it. hasCurveBox is false for a topology made by hand.
  bool hasCurveBox = false;
  double curveLo[3] = {0, 0, 0}, curveHi[3] = {0, 0, 0};
  int numOverlap = 0;  // owned followed by ghosts (ghosts sorted by global id)
  long long globalNumPoints = 0;
  long long globalNumBonds = 0;                // one-sided bond entries, all ranks
  std::vector<GlobalOrdinal> overlapGlobalId;  // per overlap index
  // Reference data per overlap point (owned, ghosts, images; an image's position includes its
  // shift): what the discretization said of the point, moved to where it is used.
  std::vector<double> referencePosition;  // 3 per overlap point
  std::vector<double> volume;             // per overlap point
  std::vector<double> horizon;            // per overlap point
  std::vector<int> blockId;               // per overlap point, the mesh block id
  // The cloud's point sets (same order and names as PointCloud::pointSets), as the owned local
  // indices of their points, sorted.
  std::vector<std::string> pointSetNames;
  std::vector<std::vector<int>> ownedPointSets;
  // Periodic images: overlap indices [numOwned + numGhosts, numOverlap) are copies of a real
  // point (owned or ghost) shifted by a multiple of the periodic box; refreshed after ghosts.
  int numGhosts = 0;
  std::vector<int> imageSource;    // per image: overlap index of the real point
  std::vector<double> imageShift;  // per image: 3 components
  const double* shiftOf(int k) const {
    static const double zero[3] = {0, 0, 0};
    const int image = k - numOwned - numGhosts;
    return image >= 0 ? &imageShift[3 * static_cast<std::size_t>(image)] : zero;
  }
  std::vector<std::int64_t> bondOffsets;  // numOwned + 1
  std::vector<int> neighbors;             // overlap indices, each list sorted by global id
  // Where horizons differ a bond may lie within one end's horizon only: lists then hold the
  // union, and bondSides tells per bond whether it is within the owner's horizon (bit 0) and
  // within the neighbour's (bit 1). Empty when every bond is within both.
  std::vector<unsigned char> bondSides;
  bool ownSide(std::int64_t b) const { return bondSides.empty() || (bondSides[b] & 1); }

  // Tpetra maps of the points (one entry each) and the Import that refreshes the ghosts. Node
  // fields of any width move by these (fields/PointValues.hpp).
  Teuchos::RCP<const Map> ownedMap, ghostMap;
  Teuchos::RCP<const Import> ghostImport;
  // The owned degrees of freedom, 3 a point (3*gid + d), for the solvers' vectors and matrices.
  // Built on the first call, which is collective (every rank calls it, as the solvers' set-ups
  // do): a non-contiguous Map keeps every id and a hash of them (200 MB at 128^3 on one rank),
  // which an explicit run does not need.
  const Teuchos::RCP<const Map>& ownedMap3() const;

  int numNeighbors(int i) const { return static_cast<int>(bondOffsets[i + 1] - bondOffsets[i]); }
  std::int64_t numBonds() const { return bondOffsets.empty() ? 0 : bondOffsets.back(); }

 private:
  mutable Teuchos::RCP<const Map> ownedMap3_;
};

struct TopologyOptions {
  NeighborhoodRule rule;
  PeriodicBox periodic;
  const std::vector<BondFilter>* bondFilters = nullptr;
  std::vector<long long>* bondFilterCuts = nullptr;  // per filter, this rank's cuts (added to)
  bool omitBondsBetweenBlocks = false;
  bool weightByBondCount = true;  // second Zoltan pass weighted by bonds per point
  int searchThreads = 1;          // threads the neighbour search may use (NeighborSearchInput)
};

// Collective. `cloud` is this rank's share of the points (see PointCloud; any distribution in
// which every point is on exactly one rank) and `horizon` has one value per point of the share.
// The points move to their owners (Zoltan RCB, weighted by bonds), and each rank finds the
// neighbours of its owned points among the points within reach of its box (a halo exchange).
Topology buildTopology(const PointCloud& cloud, const std::vector<double>& horizon,
                       const TopologyOptions& options, MPI_Comm comm);
// The same, taking the share's arrays instead of copying them (the cloud keeps its sets).
Topology buildTopology(PointCloud&& cloud, std::vector<double>&& horizon,
                       const TopologyOptions& options, MPI_Comm comm);

}  // namespace peridot
