// The variables an output file writes: each Exodus name once, whatever the deck asks for. A
// tensor requested with some of its components writes the nine components once (the tensor's),
// and repeated names (two streams into one file) are written once, in the order first asked.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "deck/OutputVariables.hpp"

namespace peridot {
namespace {

// The Exodus names a list of variables expands to (a tensor: <name>XX ... ZZ; a vector: X, Y,
// Z; a scalar: its name), written out here from the layout, not from the output code.
std::vector<std::string> exodusNames(const std::vector<std::string>& variables) {
  std::vector<std::string> names;
  for (const auto& v : variables) {
    const VariableInfo* info = findOutputVariable(v);
    if (info && info->components == 9) {
      for (const char* r : {"X", "Y", "Z"})
        for (const char* c : {"X", "Y", "Z"}) names.push_back(v + r + c);
    } else if (info && info->components == 3) {
      for (const char* d : {"X", "Y", "Z"}) names.push_back(v + d);
    } else {
      names.push_back(v);
    }
  }
  return names;
}

TEST(OutputVariables, ATensorAndItsComponentGiveEachComponentOnce) {
  const std::vector<std::string> requested = {"Cauchy_StressXX", "Displacement", "Cauchy_Stress",
                                              "Cauchy_StressYZ", "Damage",       "Displacement"};
  const auto written = distinctOutputVariables(requested);
  EXPECT_EQ(written, (std::vector<std::string>{"Displacement", "Cauchy_Stress", "Damage"}));
  const auto names = exodusNames(written);
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
  EXPECT_EQ(names.size(), 3u + 9u + 1u);
}

TEST(OutputVariables, ComponentsWithoutTheirTensorAreKept) {
  // Components of a tensor that is not requested are the file's own variables; a component of
  // another tensor is not covered by this one.
  const std::vector<std::string> requested = {"Cauchy_StressXX", "Left_Stretch_Tensor",
                                              "Cauchy_StressYY", "Cauchy_StressXX",
                                              "Rotation_TensorXY"};
  EXPECT_EQ(distinctOutputVariables(requested),
            (std::vector<std::string>{"Cauchy_StressXX", "Left_Stretch_Tensor", "Cauchy_StressYY",
                                      "Rotation_TensorXY"}));
}

TEST(OutputVariables, ComputeLabelsAndUnknownNamesPassThroughOnce) {
  // A compute's label is not in the table; it is written once like any other name.
  const std::vector<std::string> requested = {"Max_Sxx", "Max_Sxx", "Volume"};
  EXPECT_EQ(distinctOutputVariables(requested), (std::vector<std::string>{"Max_Sxx", "Volume"}));
}

}  // namespace
}  // namespace peridot
