#pragma once
// The discretization's product on one rank: this rank's share of the points (one per element,
// generator cell or text line), each with its reference position, volume, block and global id,
// plus the named point sets restricted to those points. The shares of all ranks together hold
// every point exactly once; which rank reads which point is the reader's business (the
// decomposition moves points to their owners afterwards). blockNames, the set names, dimension,
// thickness and globalNumPoints are the same on every rank.
#include <map>
#include <string>
#include <vector>

namespace peridot {

struct PointSet {
  std::string name;
  // 0-based ids (element id - 1) of the points of this share in the set, sorted, unique. Every
  // rank lists every set name (an empty list where none of its points is in the set).
  std::vector<long long> globalIds;
};

struct PointCloud {
  std::vector<double> x;                  // 3 per point, reference coordinates
  std::vector<double> volume;             // per point
  std::vector<int> blockId;               // per point, the mesh block id
  std::vector<long long> globalId;        // per point, 0-based (Exodus element id - 1)
  std::map<int, std::string> blockNames;  // block id -> name ("block_<id>" when unnamed)
  std::vector<PointSet> pointSets;        // mesh node sets as point sets
  // 2 for planar discretizations (points in z = 0, volume = area x thickness), else 3.
  int dimension = 3;
  double thickness = 1.0;         // out-of-plane thickness of a 2D discretization
  long long globalNumPoints = 0;  // the points of all shares

  std::size_t size() const { return volume.size(); }  // this share's points
};

}  // namespace peridot
