#pragma once
// A serial planar problem for kernel tests: points in z = 0 with volume = area x thickness, one
// block, a model evaluator marked planar (setPlanar before initialize) and an influence
// function; optionally periodic in x and y.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "evaluator/ModelEvaluator.hpp"

namespace peridot {
namespace testing {

struct PlanarProblem {
  PointCloud cloud;
  Topology topology;
  std::unique_ptr<FieldManager> fields;
  std::vector<Block> blocks;
  Timers timers;
  std::unique_ptr<ModelEvaluator> evaluator;

  // `points`: in-plane coordinates; each point has volume area x thickness.
  PlanarProblem(const std::vector<std::array<double, 2>>& points, double horizon,
                std::shared_ptr<MaterialModel> material, double thickness, double area = 1.0,
                std::shared_ptr<DamageModel> damage = nullptr,
                const PeriodicBox& periodic = PeriodicBox(),
                const std::string& influenceFunction = "One") {
    const double volume = area * thickness;
    for (std::size_t i = 0; i < points.size(); ++i) {
      cloud.x.insert(cloud.x.end(), {points[i][0], points[i][1], 0.0});
      cloud.volume.push_back(volume);
      cloud.blockId.push_back(1);
      cloud.globalId.push_back(static_cast<long long>(i));
    }
    cloud.dimension = 2;
    cloud.thickness = thickness;
    cloud.blockNames[1] = "block_1";
    std::vector<double> h(points.size(), horizon);
    TopologyOptions options;
    options.periodic = periodic;
    topology = buildTopology(cloud, h, options, MPI_COMM_SELF);
    fields = std::make_unique<FieldManager>(topology);
    double* x = fields->node("Model_Coordinates", 3);
    double* y = fields->node("Coordinates", 3);
    double* v = fields->node("Volume", 1);
    double* hz = fields->node("Horizon", 1);
    fields->markPosition("Coordinates");
    for (int k = 0; k < topology.numOverlap; ++k) {
      const std::size_t p = topology.overlapCloudIndex[k];
      const double* shift = topology.shiftOf(k);
      for (int d = 0; d < 3; ++d) x[3 * k + d] = y[3 * k + d] = cloud.x[3 * p + d] + shift[d];
      v[k] = volume;
      hz[k] = horizon;
    }
    Block b;
    b.name = "block_1";
    b.id = 1;
    b.material = std::move(material);
    b.damage = std::move(damage);
    for (int i = 0; i < topology.numOwned; ++i) b.points.push_back(i);
    blocks.push_back(b);
    evaluator =
        std::make_unique<ModelEvaluator>(topology, *fields, blocks, influenceFunction, timers);
    evaluator->setPlanar(thickness);
    evaluator->initialize();
  }
  int local(long long g) const {
    for (int k = 0; k < topology.numOwned; ++k)
      if (topology.overlapGlobalId[k] == g) return k;
    return -1;
  }
  void move(long long g, double dx, double dy) {
    double* y = fields->node("Coordinates", 3);
    const int k = local(g);
    y[3 * k] += dx;
    y[3 * k + 1] += dy;
  }
  const double* force(long long g) const {
    return fields->nodeField("Force_Density").data + 3 * local(g);
  }
};

}  // namespace testing
}  // namespace peridot
