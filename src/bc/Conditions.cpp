#include "bc/Conditions.hpp"

#include <cmath>
#include <vector>

#include "core/Error.hpp"
#include "parallel/ExactSum.hpp"

namespace peridot {

BoundaryConditions::BoundaryConditions(const std::vector<ConditionConfig>& conditions,
                                       const std::map<std::string, std::vector<int>>& sets,
                                       const double* x, const long long* pointIds,
                                       const double* volume, MPI_Comm comm)
    : x_(x), pointIds_(pointIds) {
  for (const auto& cc : conditions) {
    auto it = sets.find(cc.nodeSet);
    if (it == sets.end()) {
      throw InputError(cc.path + " -> Node Set",
                       "unknown node set \"" + cc.nodeSet +
                           "\"; define it in Boundary Conditions or in the mesh");
    }
    Condition c;
    c.config = cc;
    c.value = std::make_unique<Expression>(cc.value, std::vector<std::string>{"x", "y", "z", "t"},
                                           cc.path + " -> Value");
    c.points = it->second;
    if (cc.kind == ConditionConfig::Kind::BodyForce) hasBodyForce_ = true;
    if (cc.isTemperature()) hasTemperature_ = true;
    if (cc.kind == ConditionConfig::Kind::PrescribedTemperature) {
      // The reference of the temperature change: the value at t = 0 (Peridigm's choice, whatever
      // the Initial Time).
      for (int p : c.points) c.previous.push_back(evaluate(c, p, 0.0));
    }
    if (cc.kind == ConditionConfig::Kind::Traction) {
      hasBodyForce_ = true;
      // The layer's volume, summed exactly (ExactSum): a plain MPI sum of doubles rounds by
      // the partition, and every loaded point's force would then differ in its last bits
      // between rank counts.
      std::vector<double> volumes;
      for (int p : c.points) volumes.push_back(volume[p]);
      long long count = static_cast<long long>(volumes.size());
      MPI_Allreduce(MPI_IN_PLACE, &count, 1, MPI_LONG_LONG, MPI_SUM, comm);
      const double layer = exactSum(volumes, count, comm);
      c.scale = cc.surfaceArea / layer;  // the node set is not empty (checked with the deck)
    }
    conditions_.push_back(std::move(c));
  }
}

double BoundaryConditions::evaluate(Condition& c, int p, double t) {
  ++evaluations_;
  const double vars[4] = {x_[3 * p], x_[3 * p + 1], x_[3 * p + 2], t};
  return c.value->evaluate(vars);
}

std::string BoundaryConditions::applyInitial(double t0, double* u, double* v) {
  using Kind = ConditionConfig::Kind;
  std::string message;
  auto check = [&](const Condition& c, int p, double value) {
    if (std::isfinite(value) || !message.empty()) return;
    message = c.config.path + " -> Value: the expression gives " + std::to_string(value) +
              " at point " + std::to_string(pointIds_[p] + 1) +
              " (x = " + std::to_string(x_[3 * p]) + ", y = " + std::to_string(x_[3 * p + 1]) +
              ", z = " + std::to_string(x_[3 * p + 2]) + ")";
  };
  for (auto& c : conditions_) {
    const int d = c.config.coordinate;
    if (c.config.kind == Kind::InitialDisplacement ||
        c.config.kind == Kind::PrescribedDisplacement) {
      if (c.config.kind == Kind::PrescribedDisplacement) c.previous.resize(c.points.size());
      for (std::size_t k = 0; k < c.points.size(); ++k) {
        const double value = evaluate(c, c.points[k], t0);
        check(c, c.points[k], value);
        u[3 * c.points[k] + d] = value;
        if (c.config.kind == Kind::PrescribedDisplacement) c.previous[k] = value;
      }
    } else if (c.config.kind == Kind::InitialVelocity) {
      for (int p : c.points) {
        v[3 * p + d] = evaluate(c, p, t0);
        check(c, p, v[3 * p + d]);
      }
    }
  }
  return message;
}

void BoundaryConditions::resume(double t) {
  for (auto& c : conditions_) {
    if (c.config.kind != ConditionConfig::Kind::PrescribedDisplacement) continue;
    c.previous.resize(c.points.size());
    for (std::size_t k = 0; k < c.points.size(); ++k) c.previous[k] = evaluate(c, c.points[k], t);
  }
}

void BoundaryConditions::applyPrescribedVelocity(double tNext, double dt, double* v) {
  for (auto& c : conditions_) {
    if (c.config.kind != ConditionConfig::Kind::PrescribedDisplacement) continue;
    const int d = c.config.coordinate;
    if (!c.value->usesVariable("t")) {
      // A time-independent prescribed displacement holds the component still.
      for (int p : c.points) v[3 * p + d] = 0.0;
      continue;
    }
    for (std::size_t k = 0; k < c.points.size(); ++k) {
      const double next = evaluate(c, c.points[k], tNext);
      v[3 * c.points[k] + d] = (next - c.previous[k]) / dt;
      c.previous[k] = next;
    }
  }
}

std::string BoundaryConditions::nonFinite(const Condition& c, int p, double value) const {
  return c.config.path + " -> Value: the expression gives " + std::to_string(value) + " at point " +
         std::to_string(pointIds_[p] + 1) + " (x = " + std::to_string(x_[3 * p]) +
         ", y = " + std::to_string(x_[3 * p + 1]) + ", z = " + std::to_string(x_[3 * p + 2]) + ")";
}

std::string BoundaryConditions::applyInitialTemperature(double t0, double* temperature) {
  std::string message;
  for (auto& c : conditions_) {
    if (c.config.kind != ConditionConfig::Kind::InitialTemperature) continue;
    for (int p : c.points) {
      temperature[p] = evaluate(c, p, t0);
      if (!std::isfinite(temperature[p]) && message.empty())
        message = nonFinite(c, p, temperature[p]);
    }
  }
  return message;
}

std::string BoundaryConditions::applyPrescribedTemperature(double t, double* temperature,
                                                           double* change) {
  std::string message;
  for (auto& c : conditions_) {
    if (c.config.kind != ConditionConfig::Kind::PrescribedTemperature) continue;
    const bool constant = !c.value->usesVariable("t");
    for (std::size_t k = 0; k < c.points.size(); ++k) {
      const int p = c.points[k];
      // Constant in time: f(t) = f(0) and no change, without evaluating again.
      const double value = constant ? c.previous[k] : evaluate(c, p, t);
      temperature[p] = value;
      change[p] = value - c.previous[k];
      if (!std::isfinite(value) && message.empty()) message = nonFinite(c, p, value);
    }
  }
  return message;
}

void BoundaryConditions::applyBodyForce(double t, double* b, int numOwned) {
  for (int k = 0; k < 3 * numOwned; ++k) b[k] = 0.0;
  for (auto& c : conditions_) {
    if (c.config.kind != ConditionConfig::Kind::BodyForce &&
        c.config.kind != ConditionConfig::Kind::Traction)
      continue;
    const int d = c.config.coordinate;
    if (c.value->isConstant()) {
      const double value = c.value->evaluate(nullptr) * c.scale;
      for (int p : c.points) b[3 * p + d] += value;
    } else {
      for (int p : c.points) b[3 * p + d] += evaluate(c, p, t) * c.scale;
    }
  }
}

void BoundaryConditions::applyPrescribedDisplacement(double t, double* u) {
  for (auto& c : conditions_) {
    if (c.config.kind != ConditionConfig::Kind::PrescribedDisplacement) continue;
    const int d = c.config.coordinate;
    for (int p : c.points) u[3 * p + d] = evaluate(c, p, t);
  }
}

void BoundaryConditions::markPrescribed(double* held) const {
  for (const auto& c : conditions_) {
    if (c.config.kind != ConditionConfig::Kind::PrescribedDisplacement) continue;
    for (int p : c.points) held[3 * p + c.config.coordinate] = 1.0;
  }
}

}  // namespace peridot
