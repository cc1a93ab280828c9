#pragma once
// Initial conditions, prescribed displacements and body forces on node sets, with values given
// as expressions in x, y, z, t. Each condition evaluates its expression at most once per point
// per step (prescribed displacements keep the previous step's values to form the increment).
#include <mpi.h>

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
                     const long long* pointIds, const double* volume, MPI_Comm comm);

  // Initial displacement and velocity, and prescribed displacements at t0. Returns a message
  // naming the condition and point where a value is not finite (empty if all are).
  std::string applyInitial(double t0, double* u, double* v);
  // Velocity of prescribed components over the step [tPrev, tNext]: (u(tNext) - u(tPrev)) / dt.
  void applyPrescribedVelocity(double tNext, double dt, double* v);
  // A run continued from a checkpoint at time t: prescribed displacements restart from u(t),
  // the same values the uninterrupted run holds after the step that ended at t.
  void resume(double t);
  // Sets the body force density at time t (zero elsewhere) in `externalForceDensity` (owned).
  // A traction sigma on a surface of area A becomes the body force density sigma A / V over
  // the points of its node set (total volume V), so that the total force is sigma A exactly
  // (paper 002's nonlocal Neumann condition, b = sigma dx / (m V) on a lattice).
  void applyBodyForce(double t, double* externalForceDensity, int numOwned);

  bool hasBodyForce() const { return hasBodyForce_; }
  bool hasTemperature() const { return hasTemperature_; }
  // Temperature conditions (Peridigm's): Initial Temperature sets the temperature at t0 and
  // leaves the temperature change 0; Prescribed Temperature sets, at each time t, the
  // temperature f(t) and the change f(t) - f(0) (measured from t = 0, as Peridigm). Both return
  // a message naming the condition and point where a value is not finite (empty if none).
  std::string applyInitialTemperature(double t0, double* temperature);
  std::string applyPrescribedTemperature(double t, double* temperature, double* change);
  // Implicit solvers: sets u = the prescribed value at time t on every prescribed component, and
  // marks those components (held[3 p + d] = 1) in `held` (owned, not cleared first).
  void applyPrescribedDisplacement(double t, double* u);
  void markPrescribed(double* held) const;
  // Points with a prescribed component, for reaction output and checks.
  std::size_t numExpressionEvaluations() const { return evaluations_; }

 private:
  struct Condition {
    ConditionConfig config;
    std::unique_ptr<Expression> value;
    std::vector<int> points;
    std::vector<double> previous;  // prescribed displacement: u at the previous step;
                                   // prescribed temperature: f(0) of each point
    double scale = 1.0;            // traction: surface area / layer volume
  };
  double evaluate(Condition& c, int point, double t);
  const double* x_;
  const long long* pointIds_ = nullptr;
  std::vector<Condition> conditions_;
  std::string nonFinite(const Condition& c, int point, double value) const;
  bool hasBodyForce_ = false, hasTemperature_ = false;
  std::size_t evaluations_ = 0;
};

}  // namespace peridot
