#pragma once
// What the comparison with a gold file reads of an Exodus result file (output/ExodusCompare.hpp).
#include <string>
#include <vector>

namespace peridot {

// Everything in an Exodus result file that the comparison looks at.
struct ExodusResults {
  std::string fileName;
  int dimension = 3;
  std::vector<double> times;            // one per time step (record)
  std::vector<long long> nodeIds;       // node number map (1..n when absent)
  std::vector<double> nodeCoordinates;  // 3 per node (0 beyond the file's dimension)
  std::vector<long long> elementIds;    // element number map, file order (blocks concatenated)
  std::vector<long long> elementBlock;  // block id of each element, file order
  std::vector<std::string> nodalNames, elementNames, globalNames;
  // values[variable][step][entry]; entries in node / element file order, one entry for globals.
  // An element variable a block does not carry (truth table) is NaN on that block's elements.
  std::vector<std::vector<std::vector<double>>> nodal, element, global;
};

// Reads the whole file. Throws InputError (naming the file) when it cannot be opened, is
// truncated or corrupt.
ExodusResults readExodusResults(const std::string& fileName);

}  // namespace peridot
