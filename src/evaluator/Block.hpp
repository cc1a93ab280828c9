#pragma once
// A block: the points of one mesh block with their material, optional damage model and horizon.
#include <memory>
#include <string>
#include <vector>

#include "damage/DamageModel.hpp"
#include "materials/MaterialModel.hpp"

namespace peridot {

struct Block {
  std::string name;  // mesh block name, e.g. "block_1"
  int id = 0;        // mesh block id
  std::string materialName, damageName;
  std::shared_ptr<MaterialModel> material;
  std::shared_ptr<DamageModel> damage;  // null when the block has none
  std::vector<int> points;              // owned local indices
};

}  // namespace peridot
