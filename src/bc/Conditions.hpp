#pragma once
// Initial conditions, prescribed displacements and body forces on node sets, with values given
// as expressions in x, y, z, t. Each condition evaluates its expression at most once per point
// per step (prescribed displacements keep the previous step's values to form the increment).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "deck/Expression.hpp"
#include "deck/RunConfig.hpp"

namespace peridot {

class BoundaryConditions {
 public:
  // `sets`: owned local indices per node-set name; `x`: reference coordinates of owned points;
  // `pointIds`: their global (0-based) ids, for messages.
  BoundaryConditions(const std::vector<ConditionConfig>& conditions,
                     const std::map<std::string, std::vector<int>>& sets, const double* x,
                     const long long* pointIds);

  // Initial displacement and velocity, and prescribed displacements at t0. Returns a message
  // naming the condition and point where a value is not finite (empty if all are).
  std::string applyInitial(double t0, double* u, double* v);
  // Velocity of prescribed components over the step [tPrev, tNext]: (u(tNext) - u(tPrev)) / dt.
  void applyPrescribedVelocity(double tNext, double dt, double* v);
  // Sets the body force density at time t (zero elsewhere) in `externalForceDensity` (owned).
  void applyBodyForce(double t, double* externalForceDensity, int numOwned);

  bool hasBodyForce() const { return hasBodyForce_; }
  // Points with a prescribed component, for reaction output and checks.
  std::size_t numExpressionEvaluations() const { return evaluations_; }

 private:
  struct Condition {
    ConditionConfig config;
    std::unique_ptr<Expression> value;
    std::vector<int> points;
    std::vector<double> previous;  // prescribed displacement: u at the previous step
  };
  double evaluate(Condition& c, int point, double t);
  const double* x_;
  const long long* pointIds_ = nullptr;
  std::vector<Condition> conditions_;
  bool hasBodyForce_ = false;
  std::size_t evaluations_ = 0;
};

}  // namespace peridot
