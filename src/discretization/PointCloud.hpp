#pragma once
// The discretization's product: one point per element (or generator cell / text line),
// with its reference position, volume, block and global id, plus named point sets.
#include <map>
#include <string>
#include <vector>

namespace peridot {

struct PointSet {
  std::string name;
  std::vector<long long> globalIds;  // 0-based point ids (element id - 1), sorted, unique
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
  double thickness = 1.0;  // out-of-plane thickness of a 2D discretization

  std::size_t size() const { return volume.size(); }
};

}  // namespace peridot
