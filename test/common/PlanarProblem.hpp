#pragma once
// A serial planar problem for kernel tests: points in z = 0 with volume = area x thickness, one
// block, a model evaluator marked planar (setPlanar before initialize) and an influence
// function; optionally periodic in x and y.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "SerialProblem.hpp"

namespace peridot {
namespace testing {

struct PlanarProblem : Problem {
  // `points`: in-plane coordinates; each point has volume area x thickness.
  PlanarProblem(const std::vector<std::array<double, 2>>& points, double horizon,
                std::shared_ptr<MaterialModel> material, double thickness, double area = 1.0,
                std::shared_ptr<DamageModel> damage = nullptr,
                const PeriodicBox& periodic = PeriodicBox(),
                const std::string& influenceFunction = "One")
      : Problem(inPlane(points), horizon, std::move(material), std::move(damage), periodic,
                area * thickness, influenceFunction, thickness) {}
  using Problem::move;
  void move(long long g, double dx, double dy) { Problem::move(g, dx, dy, 0.0); }

 private:
  static std::vector<std::array<double, 3>> inPlane(
      const std::vector<std::array<double, 2>>& points) {
    std::vector<std::array<double, 3>> p;
    for (const auto& q : points) p.push_back({q[0], q[1], 0.0});
    return p;
  }
};

}  // namespace testing
}  // namespace peridot
