#pragma once
// The output variables Peridot knows, by Peridigm's names: how many components each has (1, 3,
// 9 for a full tensor, 0 for a global), the nine component names of a tensor, and the variables
// an output file writes for what its streams ask. Which model maintains a variable is checked
// with the run's blocks (Simulation::checkVariables); how it is computed is app/RunVariables.
#include <string>
#include <vector>

namespace peridot {

// Output variables Peridot knows, with the number of components: 3 written per node (vectors),
// 1 per element (scalars), 9 as nine element variables (full tensors), 0 global; Peridigm's
// layout.
struct VariableInfo {
  std::string name;
  int components;
  std::string description;
};
// The suffixes of a full tensor's nine components, row-major (Peridigm's names).
inline constexpr const char* kTensorComponentSuffixes[9] = {"XX", "XY", "XZ", "YX", "YY",
                                                            "YZ", "ZX", "ZY", "ZZ"};
const std::vector<VariableInfo>& knownOutputVariables();
const VariableInfo* findOutputVariable(const std::string& name);
// True when `name` is component <row><column> of a full-tensor output variable (e.g.
// Cauchy_StressXY): `tensor` is then the tensor's name and `component` 3 row + column.
bool tensorComponent(const std::string& name, std::string& tensor, int& component);
// The variables one output file writes for `requested` (its streams' lists, in deck order):
// each name once, and a tensor component (Cauchy_StressXX) left out when its tensor
// (Cauchy_Stress) is requested too, since the tensor writes all nine components under the
// same names (two variables of one name in a file: a reader by name gets either).
std::vector<std::string> distinctOutputVariables(const std::vector<std::string>& requested);

}  // namespace peridot
