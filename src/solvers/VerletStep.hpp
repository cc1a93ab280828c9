#pragma once
// The velocity Verlet step's passes over the owned points' arrays, fused so that each half of
// the step reads and writes the point arrays once:
//
//   kickAndDrift:  v += dt/2 a;  y = x + u + dt v;  u += dt v
//   (boundary conditions set the prescribed components' velocities; the force is evaluated)
//   accelerate:    a = (f + f_contact + b) / rho;  v += dt/2 a;  the divergence monitor's sums
//
// instead of six passes (two half-kicks, the drift, the acceleration, the finiteness check and
// the divergence check each read the arrays again). Each value written is computed by the same
// expression as in the separate passes, element by element, so u, v, y and a keep their bits.
//
// Components whose motion a boundary condition prescribes get their velocity between the kick
// and the drift: kickAndDrift leaves their u and y, and driftPrescribed() moves them once the
// conditions have set the velocity (a short list, usually empty).
#include <vector>

#include "solvers/DivergenceMonitor.hpp"

namespace peridot {

// The owned points' arrays: 3 per point, density 1 per point.
struct VerletArrays {
  int numOwned = 0;
  const double* x = nullptr;  // reference positions
  double* u = nullptr;
  double* v = nullptr;
  double* y = nullptr;  // current positions, x + u
  double* a = nullptr;
  const double* force = nullptr;         // the models' force density
  const double* contactForce = nullptr;  // null without contact
  const double* bodyForce = nullptr;     // null without a body force
  const double* density = nullptr;
  bool planar = false;  // no acceleration along z
};

class VerletStep {
 public:
  // `prescribed`: 3 per owned point, non-zero where a boundary condition prescribes the
  // component's motion (null: none is).
  VerletStep(const VerletArrays& arrays, double dt, const double* prescribed);

  // The first half of a step: the half-kick of every velocity, and the drift of the free
  // components. Also notes whether every displacement it wrote is finite.
  void kickAndDrift();
  // After the conditions have set the prescribed components' velocities: their drift.
  void driftPrescribed();

  // The second half, after the force evaluation: the accelerations, the half-kick (`kick`
  // false: accelerations only, the step the run starts from), and the monitor's sums of its
  // check (monitor.conclude() finishes it). The previous accelerations, which it overwrites,
  // are the monitor's previous check: call it at every check. Returns whether every force
  // density component and every displacement is finite (those of the last drift, or all of
  // them when no drift came before: the step the run starts or resumes from).
  bool accelerate(bool kick, const DivergenceMonitor& monitor, DivergenceMonitor::LocalSums& sums);

 private:
  VerletArrays p_;
  double dt_, half_;
  std::vector<int> prescribed_;  // flat component indices 3 i + d, increasing
  bool displacementFinite_ = true;
  bool drifted_ = false;  // kickAndDrift ran since the last accelerate (and checked u)
};

}  // namespace peridot
