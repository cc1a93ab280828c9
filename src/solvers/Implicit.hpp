#pragma once
// Peridigm's Implicit solver on Tpetra: implicit dynamics by Newmark's method. Each time step
// solves  M a_{n+1} = f(u_{n+1}) + b(t_{n+1})  with
//   u_{n+1} = u_n + dt v_n + dt^2 ((1/2 - beta) a_n + beta a_{n+1}),
//   v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}),
// for u_{n+1} by Newton's method: the Jacobian is M / (beta dt^2) + K with K the tangent
// stiffness (solvers/Tangent.hpp) and M = rho V, solved by Belos. Prescribed displacements take
// their value at t_{n+1}; their velocity and acceleration follow Newmark's relations.
#include <memory>
#include <vector>

#include "solvers/ImplicitConfig.hpp"
#include "solvers/SolverContext.hpp"
#include "solvers/Tangent.hpp"

namespace peridot {

class Implicit {
 public:
  // Steps of `config.dt` from `initialTime`, `numSteps` of them. Builds the tangent (throws
  // InputError when a material has none). `context.density` must be set.
  Implicit(const ImplicitConfig& config, double initialTime, long long numSteps,
           SolverContext context);
  // Runs every step, writing outputs. The initial acceleration is M^-1 (f + b) at the initial
  // time (Newmark's start; Peridigm starts from a = 0, which is the same for a body at rest in
  // its reference configuration without body force). Collective.
  void run();
  void setRunHooks(OutputManager* outputs, std::function<void(long long, double)> observer) {
    c_.outputs = outputs;
    c_.observer = std::move(observer);
  }

  struct Statistics {
    long long newtonIterations = 0, linearIterations = 0;
    std::vector<int> newtonIterationsPerStep;
  };
  const Statistics& statistics() const { return stats_; }

 private:
  // Evaluates the forces at y = x + u and the residual R = V (f + b - rho a) on the free
  // components; returns Peridigm's norm beta dt^2 |f + b - rho a| (per unit volume).
  // A trial evaluation of the step (history models keep its start) unless `commit`.
  double evaluateResidual(double time, bool commit = false);
  // a and v of every free component from u and the predictors (Newmark's relations).
  void updateRates();

  ImplicitConfig config_;
  SolverContext c_;
  double initialTime_ = 0;
  long long numSteps_ = 0;
  std::unique_ptr<Tangent> tangent_;
  double* held_ = nullptr;               // overlap, 3 per point: prescribed (and planar z)
  std::vector<double> mass_;             // owned, 3 per point: rho V / (beta dt^2)
  std::vector<double> uTilde_, vTilde_;  // owned: Newmark's predictors
  std::vector<double> residual_, increment_;
  double heldDiagonal_ = 1.0;
  Statistics stats_;
};

}  // namespace peridot
