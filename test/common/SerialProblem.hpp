#pragma once
// A serial problem for kernel tests: points (unit volume unless given), one block, a model
// evaluator; optionally periodic, with an influence function, planar (thickness > 0: the
// points must lie in z = 0 and their volumes include the thickness), or with partial volumes.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "evaluator/ModelEvaluator.hpp"

namespace peridot {
namespace testing {

// A serial problem: points, one block, a model evaluator.
struct Problem {
  PointCloud cloud;
  Topology topology;
  std::unique_ptr<FieldManager> fields;
  std::vector<Block> blocks;
  Timers timers;
  std::unique_ptr<ModelEvaluator> evaluator;

  Problem(const std::vector<std::array<double, 3>>& points, double horizon,
          std::shared_ptr<MaterialModel> material, std::shared_ptr<DamageModel> damage = nullptr,
          const PeriodicBox& periodic = PeriodicBox(), double volume = 1.0,
          const std::string& influenceFunction = "One", double planarThickness = 0.0,
          bool partialVolumes = false) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      cloud.x.insert(cloud.x.end(), points[i].begin(), points[i].end());
      cloud.volume.push_back(volume);
      cloud.blockId.push_back(1);
      cloud.globalId.push_back(static_cast<long long>(i));
    }
    cloud.blockNames[1] = "block_1";
    if (planarThickness > 0) {
      cloud.dimension = 2;
      cloud.thickness = planarThickness;
    }
    std::vector<double> h(points.size(), horizon);
    TopologyOptions options;
    options.periodic = periodic;
    if (partialVolumes) options.rule.kind = NeighborhoodRule::Kind::CellOverlap;
    topology = buildTopology(cloud, h, options, MPI_COMM_SELF);
    fields = std::make_unique<FieldManager>(topology);
    double* x = fields->node("Model_Coordinates", 3);
    double* y = fields->node("Coordinates", 3);
    double* v = fields->node("Volume", 1);
    double* hz = fields->node("Horizon", 1);
    fields->markPosition("Coordinates");
    for (int k = 0; k < topology.numOverlap; ++k) {
      for (int d = 0; d < 3; ++d)
        x[3 * k + d] = y[3 * k + d] = topology.referencePosition[3 * k + d];
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
    if (planarThickness > 0) evaluator->setPlanar(planarThickness);
    evaluator->setPartialVolumes(partialVolumes);
    evaluator->initialize();
  }
  // Local index of the point with global id g.
  int local(long long g) const {
    for (int k = 0; k < topology.numOwned; ++k)
      if (topology.overlapGlobalId[k] == g) return k;
    return -1;
  }
  void move(long long g, double dx, double dy, double dz) {
    double* y = fields->node("Coordinates", 3);
    const int k = local(g);
    y[3 * k] += dx;
    y[3 * k + 1] += dy;
    y[3 * k + 2] += dz;
  }
  const double* force(long long g) const {
    return fields->nodeField("Force_Density").data + 3 * local(g);
  }
  // Every point (owned and ghost) at y = F x moving with v = Fdot x (3x3 row-major), then one
  // evaluation of step size dt: a homogeneous motion for the rate form of the correspondence
  // models, whose F and velocity gradient are then exact at every point.
  void evaluateAffine(const double F[9], const double Fdot[9], double dt) {
    double* y = fields->node("Coordinates", 3);
    double* v = fields->node("Velocity", 3);
    const double* x = fields->node("Model_Coordinates", 3);
    for (int p = 0; p < topology.numOverlap; ++p)
      for (int a = 0; a < 3; ++a) {
        const double* X = x + 3 * p;
        y[3 * p + a] = F[3 * a] * X[0] + F[3 * a + 1] * X[1] + F[3 * a + 2] * X[2];
        v[3 * p + a] = Fdot[3 * a] * X[0] + Fdot[3 * a + 1] * X[1] + Fdot[3 * a + 2] * X[2];
      }
    evaluator->evaluate(dt);
  }
  // Deforms every point (owned, ghosts, images) to y = x + H x, runs the models' precompute and
  // returns the stored energy density at local point k. The precompute is called directly: a
  // ghost refresh would give periodic images the undeformed period.
  double energyDensityUnder(const double H[3][3], int k = 0) {
    double* y = fields->node("Coordinates", 3);
    const double* x = fields->node("Model_Coordinates", 3);
    for (int p = 0; p < topology.numOverlap; ++p)
      for (int a = 0; a < 3; ++a) {
        y[3 * p + a] = x[3 * p + a];
        for (int b = 0; b < 3; ++b) y[3 * p + a] += H[a][b] * x[3 * p + b];
      }
    for (auto& b : blocks) b.material->precompute(evaluator->state(), b.points);
    std::vector<double> w(topology.numOverlap);
    evaluator->storedEnergyDensity(w.data());
    return w[k];
  }
};

}  // namespace testing
}  // namespace peridot
