#pragma once
// Adaptive dynamic relaxation (Kilic & Madenci 2010), a Peridot extension: each load step's
// static equilibrium is found as the steady state of a fictitiously damped dynamic problem
// Λ ü + c Λ u̇ = f(u) + b integrated with unit steps. Λ is a fictitious density chosen from the
// largest eigenvalue of the stiffness (so that the unit step is stable), c the damping that is
// critical for the lowest mode the iteration currently excites (a Rayleigh quotient of the local
// stiffness, updated every iteration). It needs no tangent and follows softening and fracture:
// the state is relaxed with the bonds frozen, bonds then break at the relaxed state, and the
// state is relaxed again until no bond breaks, so a load step ends in equilibrium with its
// damage. Global sums are exact, so the iterations (and results) are the same at any rank count.
#include <vector>

#include "solvers/DynamicRelaxationConfig.hpp"
#include "solvers/SolverContext.hpp"

namespace peridot {

class DynamicRelaxation {
 public:
  // Estimates the fictitious density at the current configuration (collective; the state's
  // coordinates and forces are restored). Throws InputError for a material with history.
  DynamicRelaxation(const DynamicRelaxationConfig& config, SolverContext context);
  // Runs every load step, writing outputs after each. Throws RunError when a step does not
  // relax within Maximum Iterations (the outputs of the completed steps stay in the files).
  void run();
  void setRunHooks(OutputManager* outputs, std::function<void(long long, double)> observer) {
    c_.outputs = outputs;
    c_.observer = std::move(observer);
  }

  struct Statistics {
    long long iterations = 0;  // all load steps
    std::vector<long long> iterationsPerStep;
    std::vector<int> relaxationsPerStep;  // 1 + the times bonds broke and the step relaxed again
    double lambdaMax = 0;                 // largest eigenvalue of rho^-1 K (Lanczos)
    double fictitiousDensityScale = 0;    // Lambda_i = this x rho_i
  };
  const Statistics& statistics() const { return stats_; }

 private:
  // Forces at y = x + u (bonds frozen unless `updateDamage`); fills force_ = f + b on the free
  // components (0 on the held ones) and returns the load: the norm of the reactions at the held
  // components and of the applied body force (Peridigm's QuasiStatic measure). Collective.
  // A trial evaluation of the load step (history models keep the step's start) unless `commit`.
  double evaluate(double time, bool updateDamage, bool commit = false);
  double stepDt_ = 0.0;   // the load step's duration (dt of history models' evaluations)
  double residualNorm();  // || V (f + b) || over the free components, exact
  double damageSum();     // sum of bond damage over the owned bond entries, exact
  // Relaxes the current load step from rest; returns the iterations taken, or -1 when the
  // criterion was not met within `budget` iterations (residual in lastNorm_).
  long long relax(double time, long long budget);
  double sum(const std::vector<double>& perPoint);  // exact, over all ranks

  DynamicRelaxationConfig config_;
  SolverContext c_;
  std::vector<double> held_;      // owned, 3 per point: 1 where the displacement is prescribed
  std::vector<double> lambda_;    // owned: fictitious density per point
  std::vector<double> force_;     // owned, 3 per point: f + b on the free components
  std::vector<double> velocity_;  // owned, 3 per point: the relaxation's u̇ at the half step
  std::vector<double> terms_, terms2_;  // owned, per point: scratch for exact sums
  std::vector<double> terms3_;          // owned, 3 per point: the force before an iteration
  double largestLoad_ = 0;              // the largest load of a relaxed state so far
  double lastNorm_ = 0, lastCriterion_ = 0;
  Statistics stats_;
};

}  // namespace peridot
