#pragma once
// The scene the bench programs measure on: an n^3 cubic lattice of unit spacing and unit
// volumes (one block, one rank), with delta = 3.015 dx as in run_bench.py's cube. One definition,
// so that the programs' figures are of the same scene.
#include <mpi.h>

#include <Teuchos_ParameterList.hpp>
#include <memory>
#include <string>
#include <vector>

#include "damage/DamageModel.hpp"
#include "evaluator/ModelEvaluator.hpp"
#include "parallel/Topology.hpp"

namespace peridot::bench {

constexpr double kLatticeHorizon = 3.015;

// n x n x n points at integer coordinates, x fastest, global ids in that order, all in block 1.
inline PointCloud unitLattice(int n) {
  PointCloud cloud;
  const auto points = static_cast<std::size_t>(n) * n * n;
  cloud.x.reserve(3 * points);
  cloud.volume.assign(points, 1.0);
  cloud.blockId.assign(points, 1);
  cloud.globalId.reserve(points);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        cloud.x.insert(cloud.x.end(), {double(i), double(j), double(k)});
        cloud.globalId.push_back(static_cast<long long>(cloud.globalId.size()));
      }
  cloud.blockNames[1] = "block_1";
  return cloud;
}

// The lattice's topology and the fields every model reads: Model_Coordinates and Coordinates
// (both the reference positions until the program moves them), Volume, Horizon. A program then
// sets its block (setBlock) and initializes the evaluator, after any switch of its own.
struct LatticeScene {
  Topology topology;
  std::unique_ptr<FieldManager> fields;
  std::vector<Block> blocks;
  Timers timers;
  std::unique_ptr<ModelEvaluator> evaluator;
  double* x = nullptr;  // 3 per overlap point
  double* y = nullptr;

  explicit LatticeScene(int n) {
    PointCloud cloud = unitLattice(n);
    std::vector<double> horizon(cloud.size(), kLatticeHorizon);
    topology =
        buildTopology(std::move(cloud), std::move(horizon), TopologyOptions{}, MPI_COMM_SELF);
    fields = std::make_unique<FieldManager>(topology);
    x = fields->node("Model_Coordinates", 3);
    y = fields->node("Coordinates", 3);
    double* volume = fields->node("Volume", 1);
    double* hz = fields->node("Horizon", 1);
    for (int p = 0; p < topology.numOverlap; ++p) {
      for (int d = 0; d < 3; ++d)
        x[3 * p + d] = y[3 * p + d] = topology.referencePosition[3 * p + d];
      volume[p] = 1.0;
      hz[p] = kLatticeHorizon;
    }
  }

  // The one block over every owned point, its material and (if given) damage model made from
  // these lists, and the evaluator over it (not yet initialized).
  void setBlock(const Teuchos::ParameterList& material, const Teuchos::ParameterList* damage,
                const std::string& influence) {
    Teuchos::ParameterList m = material;
    ListReader mr(m, "Materials -> M");
    Block b;
    b.name = "block_1";
    b.id = 1;
    b.material = createMaterial(mr);
    if (damage) {
      Teuchos::ParameterList d = *damage;
      ListReader dr(d, "Damage Models -> D");
      b.damage = createDamageModel(dr);
    }
    for (int p = 0; p < topology.numOwned; ++p) b.points.push_back(p);
    blocks.assign(1, b);
    evaluator = std::make_unique<ModelEvaluator>(topology, *fields, blocks, influence, timers);
  }
};

}  // namespace peridot::bench
