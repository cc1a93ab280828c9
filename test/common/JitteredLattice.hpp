#pragma once
// A serial jittered lattice for bit-for-bit kernel tests (a fused bond loop against its separate
// pass): n^3 points (n^2 in z = 0 when planar) of spacing 1, each coordinate and volume moved by
// up to 0.05, horizons `horizon` (2.1) or (varyingHorizon) drawn from 1.9..2.3 so that some
// bonds are one-sided; the fields set from the topology. The test adds its block and then the
// evaluator.
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "evaluator/ModelEvaluator.hpp"

namespace peridot {
namespace testing {

struct JitteredLattice {
  PointCloud cloud;
  Topology topology;
  std::unique_ptr<FieldManager> fields;
  std::vector<Block> blocks;
  Timers timers;
  std::unique_ptr<ModelEvaluator> evaluator;

  JitteredLattice(int n, bool planar, bool varyingHorizon, unsigned seed, double horizon = 2.1) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05), drawn(1.9, 2.3);
    long long id = 0;
    std::vector<double> h;
    for (int k = 0; k < (planar ? 1 : n); ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          cloud.x.insert(cloud.x.end(),
                         {i + jitter(rng), j + jitter(rng), planar ? 0.0 : k + jitter(rng)});
          cloud.volume.push_back(1.0 + jitter(rng));
          cloud.blockId.push_back(1);
          cloud.globalId.push_back(id++);
          h.push_back(varyingHorizon ? drawn(rng) : horizon);
        }
    cloud.blockNames[1] = "block_1";
    if (planar) cloud.dimension = 2;
    topology = buildTopology(cloud, h, TopologyOptions(), MPI_COMM_SELF);
    fields = std::make_unique<FieldManager>(topology);
    double* x = fields->node("Model_Coordinates", 3);
    double* y = fields->node("Coordinates", 3);
    double* v = fields->node("Volume", 1);
    double* hz = fields->node("Horizon", 1);
    for (int p = 0; p < topology.numOverlap; ++p) {
      for (int d = 0; d < 3; ++d)
        x[3 * p + d] = y[3 * p + d] = topology.referencePosition[3 * p + d];
      v[p] = topology.volume[p];
      hz[p] = topology.horizon[p];
    }
  }

  // One block over the owned points, then the evaluator (planar: thickness 1), initialized.
  // halfList: whether a bond-based block may walk the half bond list (a run's default).
  void addBlock(std::shared_ptr<MaterialModel> material, std::shared_ptr<DamageModel> damage,
                const std::string& influence, bool fuse, bool halfList = true,
                bool allowCompact = false) {
    Block b;
    b.name = "block_1";
    b.id = 1;
    b.material = std::move(material);
    b.damage = std::move(damage);
    for (int i = 0; i < topology.numOwned; ++i) b.points.push_back(i);
    blocks.push_back(b);
    evaluator = std::make_unique<ModelEvaluator>(topology, *fields, blocks, influence, timers);
    if (cloud.dimension == 2) evaluator->setPlanar(1.0);
    evaluator->setFuseCriticalStretch(fuse);
    evaluator->setHalfBondListAllowed(halfList);
    evaluator->setCompactDamageAllowed(allowCompact);
    evaluator->initialize();
  }

  // The owned points' force density and node damage after an evaluation.
  std::vector<double> force() const {
    const double* f = fields->nodeField("Force_Density").data;
    return std::vector<double>(f, f + 3 * topology.numOwned);
  }
  std::vector<double> nodeDamage() const {
    std::vector<double> d(topology.numOwned);
    evaluator->nodeDamage(d.data());
    return d;
  }
};

}  // namespace testing
}  // namespace peridot
