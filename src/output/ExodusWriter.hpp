#pragma once
// Writes an Exodus II results file in Peridigm's layout: every point is a one-node SPHERE
// element in its block; node and element ids are the point ids + 1; vectors are written as
// NameX/NameY/NameZ nodal variables (NameX/NameY in a 2D file), scalars as element variables,
// globals as global variables.
// Serial: the output manager gathers the data on rank 0, which owns the writer.
#include <string>
#include <vector>

namespace peridot {

struct ExodusLayout {
  int dimension = 3;            // num_dim: 2 writes x and y only (a planar run)
  std::vector<long long> ids;   // per output position: point id + 1
  std::vector<double> x, y, z;  // reference coordinates per output position (z unused in 2D)
  std::vector<int> blockIds;    // per block, in output order
  std::vector<std::string> blockNames;
  std::vector<long long> blockCounts;  // points of each block (positions are grouped by block)
  struct Set {
    std::string name;
    std::vector<int> positions;  // 0-based output positions
  };
  std::vector<Set> nodeSets;
};

class ExodusWriter {
 public:
  ExodusWriter(const std::string& fileName, const ExodusLayout& layout,
               const std::vector<std::string>& nodalNames,
               const std::vector<std::string>& elementNames,
               const std::vector<std::string>& globalNames);
  ~ExodusWriter();
  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;

  // nodal[k] / element[k]: one value per output position; globals: one per name.
  void writeRecord(double time, const std::vector<std::vector<double>>& nodal,
                   const std::vector<std::vector<double>>& element,
                   const std::vector<double>& globals);
  const std::string& fileName() const { return fileName_; }

 private:
  void check(int status, const std::string& what) const;
  std::string fileName_;
  int exoid_ = -1;
  int step_ = 0;
  std::vector<int> blockIds_;
  std::vector<long long> blockCounts_;
};

}  // namespace peridot
