#pragma once
// What a solver other than the explicit Verlet loop needs of a set-up run (Simulation builds it):
// the problem's topology, fields, models, conditions and outputs, and the run's fields as raw
// owned/overlap arrays.
#include <mpi.h>

#include <functional>
#include <iosfwd>
#include <vector>

#include "bc/Conditions.hpp"
#include "core/Timers.hpp"
#include "evaluator/ModelEvaluator.hpp"
#include "fields/FieldManager.hpp"
#include "output/OutputManager.hpp"
#include "parallel/Topology.hpp"
#include "solvers/FiniteDifferenceTangent.hpp"

namespace peridot {

struct SolverContext {
  MPI_Comm comm = MPI_COMM_WORLD;
  int rank = 0;
  std::ostream* log = nullptr;
  Timers* timers = nullptr;
  const Topology* topology = nullptr;
  FieldManager* fields = nullptr;
  std::vector<Block>* blocks = nullptr;
  const std::vector<int>* blockIndexOfPoint = nullptr;
  ModelEvaluator* evaluator = nullptr;
  BoundaryConditions* conditions = nullptr;
  OutputManager* outputs = nullptr;
  bool planar = false;
  // Overlap arrays, 3 per point: reference and current coordinates, displacement, velocity,
  // acceleration, internal force density; body force density (null without a body force).
  double *x = nullptr, *y = nullptr, *u = nullptr, *v = nullptr, *a = nullptr, *f = nullptr,
         *b = nullptr;
  const double* volume = nullptr;
  const double* density = nullptr;  // owned, per point
  // Owned temperature and temperature change (null without temperature conditions).
  double *temperature = nullptr, *temperatureChange = nullptr;
  std::function<void(long long, double)> observer;
  // Chained solvers: the steps taken by the solvers before (outputs and the observer see step
  // numbers stepOffset + n); a chained solver does not write its initial state again (the
  // previous solver's last record). The previous solver's velocity is the first load step's
  // predictor when predictorFromPrevious is set (QuasiStatic).
  long long stepOffset = 0;
  bool predictorFromPrevious = false;
  // Solver -> Finite Difference Probe Length (0: Peridigm's default, 1e-6 x the smallest
  // element radius), for the tangents of materials without an analytic one.
  double probeLength = 0.0;
  // Where the solver records the nonlinear iterations of its last step before writing outputs
  // (Peridigm's Nonlinear_Solver_Iterations); may be null.
  long long* nonlinearIterations = nullptr;

  // What a Tangent needs to probe materials without an analytic tangent.
  ProbeSettings probe() const {
    ProbeSettings p;
    p.evaluator = evaluator;
    p.y = y;
    p.v = v;
    p.f = f;
    p.volume = volume;
    p.probeLength = probeLength;
    return p;
  }
};

}  // namespace peridot
