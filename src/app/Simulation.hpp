#pragma once
// A run: builds the problem from a validated deck (discretization, blocks, decomposition,
// neighbourhoods, fields, models, conditions, outputs) and integrates it in time.
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/RunVariables.hpp"
#include "bc/Conditions.hpp"
#include "contact/ShortRangeContact.hpp"
#include "core/Timers.hpp"
#include "deck/Expression.hpp"
#include "deck/RunConfig.hpp"
#include "discretization/PointCloud.hpp"
#include "evaluator/ModelEvaluator.hpp"
#include "fields/FieldManager.hpp"
#include "output/OutputManager.hpp"
#include "parallel/Topology.hpp"
#include "restart/Checkpoint.hpp"
#include "restart/RunControl.hpp"
#include "solvers/DivergenceMonitor.hpp"
#include "solvers/VerletStep.hpp"

namespace peridot {

class QuasiStatic;
class NOXQuasiStatic;
class DynamicRelaxation;
class Implicit;

class Simulation {
 public:
  // Collective. Throws InputError for anything wrong with the deck or its mesh.
  Simulation(RunConfig config, MPI_Comm comm, std::ostream& log);
  ~Simulation();

  // Runs the Verlet solver to the final time, writing the outputs. Collective.
  void run();
  // True when run() left the time loop early (a stop signal or the Wall Clock Limit); with
  // Restart a checkpoint of the last completed step was written first.
  bool stopped() const { return stopped_; }
  int stopSignal() const { return stopSignal_; }
  // True when the stop came during QuasiStatic, NOXQuasiStatic, Implicit or Adaptive Dynamic
  // Relaxation, which write no checkpoint.
  bool stoppedInImplicitSolver() const { return stoppedInImplicitSolver_; }
  // The step and time the run reached (the checkpoint's, when stopped).
  // Collective: checks that the output files can be created (without creating them) and rank 0
  // prints points, bonds, the stable time step, the time step, the steps and the outputs.
  // run() calls it; `peridot --check` calls it alone.
  void reportSetup();
  long long lastStep() const { return lastStep_; }
  double time() const { return time_; }
  // Collective: rank 0 prints checkpoint and signal-check statistics (nothing without Restart).
  void reportCheckpoints(std::ostream& out);
  const Checkpoint* checkpoint() const { return checkpoint_.get(); }
  // Called after every completed step (and once for the initial state with step 0).
  void setStepObserver(std::function<void(long long step, double time)> observer) {
    observer_ = std::move(observer);
  }

  // The run's output variables (node and global, by Peridigm's names).
  RunVariables& variables() { return *variables_; }

  const Topology& topology() const { return topology_; }
  // Collective: field and bond-list memory and peak resident memory, summed over ranks.
  void reportMemory(std::ostream& out);
  FieldManager& fields() { return *fields_; }
  Timers& timers() { return timers_; }
  double timeStep() const { return dt_; }
  long long numSteps() const { return numSteps_; }
  double stableTimeStepEstimate() const { return stableDt_; }
  // The QuasiStatic solver of the last run() (null for Verlet), for its statistics.
  QuasiStatic* quasiStatic() { return quasiStatic_.get(); }
  // Whether a QuasiStatic solver's Adaptive Load-Stepping switched to Verlet.
  bool switchedToVerlet() const { return switchedToVerlet_; }
  // For tests: the model evaluator and the blocks.
  ModelEvaluator& evaluator() { return *evaluator_; }
  std::vector<Block>& blocks() { return blocks_; }
  NOXQuasiStatic* noxQuasiStatic() { return noxQuasiStatic_.get(); }
  // The Adaptive Dynamic Relaxation solver of the last run() (null for the others).
  DynamicRelaxation* dynamicRelaxation() { return relaxation_.get(); }
  // The Implicit (Newmark) solver of the last run() (null for the others).
  Implicit* implicit() { return implicit_.get(); }

 private:
  void openOutputs();
  // Throws (collectively) the cause of a zero stable time step, in words.
  [[noreturn]] void explainZeroTimeStep(const double* stiffness);
  // 2D: every block's material in plane stress or strain, no z condition; 3D: no plane material.
  void checkDimension();
  // A deforming periodic box with a model that reads node velocities (their images lack the
  // box's rate): an input error.
  void checkPeriodicBox();
  void checkVariables();
  void evaluateForces(long long step);
  // Throws (collectively) at a non-finite force or displacement, as VerletStep::accelerate
  // found (`finite`), or at a non-finite prescribed temperature.
  void checkFinite(long long step, double time, bool finite);
  // The accelerations of step `step` and, after step 0, the second half-kick; then the checks.
  void accelerate(long long step);
  // Stable time step (SimulationTimeStep.cpp): Peridigm's estimate, and with "Verlet Limit"
  // the Lanczos estimate of the linearized problem's true limit.
  void estimateStableTimeStep();
  // The time step, number of steps and solver objects of config_.solver (the first solver at
  // set-up, then each chained solver in turn).
  void prepareSolver();
  void runSolver();
  // Restart (SimulationRestart.cpp): continue from the checkpoint, write one, search contact.
  void resume();
  void writeCheckpoint(long long step);
  void searchContact();
  // Implicit solvers (SimulationImplicit.cpp): checks at set-up, and the QuasiStatic or
  // Implicit run.
  void checkImplicit();
  void runImplicit();
  // QuasiStatic's Adaptive Load-Stepping exhausted with Switch to Verlet: the explicit solver
  // continues from the last converged load step.
  void switchToVerlet();
  bool switchedToVerlet_ = false;
  bool switching_ = false;  // preparing that Verlet solver

  RunConfig config_;
  MPI_Comm comm_;
  int rank_ = 0;
  std::ostream& log_;
  Timers timers_;
  std::map<int, std::string> blockNames_;  // mesh block id -> name, every block of the mesh
  double thickness_ = 1.0;                 // of a 2D discretization
  Topology topology_;
  std::unique_ptr<FieldManager> fields_;
  std::vector<Block> blocks_;
  std::unique_ptr<ModelEvaluator> evaluator_;
  std::map<std::string, std::vector<long long>> nodeSetIds_;
  std::map<std::string, std::vector<int>> nodeSets_;  // owned local indices
  std::unique_ptr<BoundaryConditions> conditions_;
  std::unique_ptr<RunVariables> variables_;
  std::unique_ptr<OutputManager> outputs_;
  std::unique_ptr<ShortRangeContact> contact_;
  std::vector<double> density_;         // owned
  std::vector<int> blockIndexOfPoint_;  // owned -> index in blocks_
  bool planar_ = false;                 // a 2D discretization: points in z = 0, no z motion
  double dt_ = 0, stableDt_ = 0, time_ = 0;
  double peridigmDt_ = 0;          // Peridigm's estimate (stableDt_ unless "Verlet Limit")
  int verletLimitIterations_ = 0;  // Lanczos iterations of the "Verlet Limit" estimate
  long long numSteps_ = 0;
  // Displacement components the Verlet integration moves, over all ranks (not prescribed): with
  // none, no step can diverge.
  long long freeComponents_ = -1;
  // Over all ranks, the components of `prescribed` (3 per owned point, 1 = prescribed) that are
  // not (x and y only in a planar run).
  long long countFreeComponents(const std::vector<double>& prescribed) const;
  std::function<void(long long, double)> observer_;
  std::unique_ptr<Checkpoint> checkpoint_;  // with Restart
  std::unique_ptr<RunControl> control_;
  std::unique_ptr<DivergenceMonitor> divergence_;
  std::unique_ptr<VerletStep> verlet_;  // the explicit step's passes over the points
  std::unique_ptr<QuasiStatic> quasiStatic_;
  std::unique_ptr<NOXQuasiStatic> noxQuasiStatic_;
  std::unique_ptr<DynamicRelaxation> relaxation_;
  std::unique_ptr<Implicit> implicit_;
  double origin_ = 0;        // time of step 0: time at step n is origin_ + n * dt_
  long long firstStep_ = 1;  // the first step run() takes (after a checkpoint's step)
  long long lastStep_ = 0;   // the last step completed
  // The implicit solvers' nonlinear iterations of their last step (0 under Verlet).
  long long nonlinearIterations_ = 0;
  long long stepOffset_ = 0;  // chained solvers: the steps of the solvers before this one
  bool resumed_ = false, stopped_ = false;
  int stopSignal_ = 0;
  bool stoppedInImplicitSolver_ = false;
  // Temperature conditions: owned Temperature and Temperature_Change (null without them), and
  // the first non-finite prescribed temperature of the last step (reported with checkFinite).
  double *temperature_ = nullptr, *temperatureChange_ = nullptr;
  std::string temperatureProblem_;
  // "Time Dependent Short Range Force": the friction coefficient as an expression in t.
  std::unique_ptr<Expression> friction_;
  // A deformable periodic box: F(t), row-major (empty when the box is rigid).
  std::vector<Expression> boxDeformation_;
  void deformPeriodicBox();
  double *u_ = nullptr, *v_ = nullptr, *a_ = nullptr, *y_ = nullptr, *x_ = nullptr, *f_ = nullptr,
         *b_ = nullptr, *volume_ = nullptr, *fc_ = nullptr;
};

}  // namespace peridot
