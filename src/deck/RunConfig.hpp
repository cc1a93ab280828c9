#pragma once
// The whole deck, validated and typed, before any work is done: every key is read here (or by
// the model it belongs to), so a misspelt or unsupported key stops the run at once.
#include <Teuchos_ParameterList.hpp>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "contact/ContactConfig.hpp"
#include "damage/DamageModel.hpp"
#include "discretization/Discretization.hpp"
#include "materials/MaterialModel.hpp"
#include "solvers/DynamicRelaxationConfig.hpp"
#include "solvers/ImplicitConfig.hpp"
#include "solvers/NOXQuasiStaticConfig.hpp"
#include "solvers/QuasiStaticConfig.hpp"

namespace peridot {

struct BlockGroupConfig {
  std::string name, path;
  std::vector<std::string> blockNames;  // "Default" matches every block not named elsewhere
  std::string material, damageModel;    // damageModel empty when none
  std::string horizon;                  // number or expression in x, y, z
};

struct NodeSetSpec {
  std::string name, path;
  std::string value;  // whitespace-separated 1-based ids, or a file name holding them
};

struct ConditionConfig {
  enum class Kind {
    InitialDisplacement,
    InitialVelocity,
    PrescribedDisplacement,
    BodyForce,
    Traction,  // a traction on a surface, applied as a body force over the node set's layer
    PrescribedTemperature,  // Temperature = f(t), Temperature_Change = f(t) - f(0) (Peridigm)
    InitialTemperature      // Temperature = f(t0); the temperature change stays 0
  };
  bool isTemperature() const {
    return kind == Kind::PrescribedTemperature || kind == Kind::InitialTemperature;
  }
  Kind kind = Kind::InitialVelocity;
  std::string name, path, nodeSet;
  int coordinate = 0;      // 0, 1, 2 (0 for the scalar temperature conditions)
  std::string value;       // expression in x, y, z, t
  double surfaceArea = 0;  // Traction: area of the loaded surface
};

struct SolverConfig {
  std::string path;
  double initialTime = 0.0, finalTime = 1.0;
  bool fixedDtGiven = false;
  double fixedDt = 0.0, safetyFactor = 1.0;
  // Verlet -> Stable Time Step Estimate: Peridigm's row-sum bound (default) or the Lanczos
  // estimate of the true Verlet limit (solvers/VerletLimit.hpp).
  bool verletLimitEstimate = false;
  bool quasiStatic = false;  // a QuasiStatic list instead of Verlet
  QuasiStaticConfig quasiStaticConfig;
  bool noxQuasiStatic = false;  // a NOXQuasiStatic list (NOX's solvers) instead of Verlet
  NOXQuasiStaticConfig noxQuasiStaticConfig;
  bool implicit = false;  // an Implicit (Newmark) list instead of Verlet
  ImplicitConfig implicitConfig;
  // An Adaptive Dynamic Relaxation list instead of Verlet (a Peridot extension).
  bool dynamicRelaxation = false;
  DynamicRelaxationConfig dynamicRelaxationConfig;
  // Solvers that step through load steps rather than time steps of a fixed size.
  bool loadStepped() const { return quasiStatic || noxQuasiStatic || dynamicRelaxation; }
  bool explicitVerlet() const {
    return !quasiStatic && !noxQuasiStatic && !implicit && !dynamicRelaxation;
  }
  // Initialize Predictor From Previous Solver: a chained QuasiStatic solver's first load step
  // starts from the velocity the previous solver left (times the step's duration).
  bool predictorFromPrevious = false;
  // Finite Difference Probe Length: eps of the finite-difference tangents (0: Peridigm's
  // default, 1e-6 x the smallest element radius).
  double probeLength = 0.0;
};

struct OutputConfig {
  std::string name, path, fileName;  // fileName without extension
  long long frequency = 1, initialStep = 0, finalStep = -1;
  std::vector<std::string> variables;  // requested names, deck order
};

// Top-level `Restart` (Peridigm's bool or list) with Peridot's checkpoint cadence keys.
struct RestartConfig {
  bool enabled = false;
  std::string path = "Restart";
  long long checkpointFrequency = 0;  // steps between checkpoints, 0 = only at the end
  double checkpointInterval = 0;      // wall-clock minutes between checkpoints, 0 = none
  double wallClockLimit = 0;          // minutes: checkpoint and stop before it, 0 = none
  std::string directory = ".";
  std::string name = "peridot.checkpoint";
  // Hash of the deck without what a continuation may change (Initial/Final Time, outputs,
  // Restart): a checkpoint written under another model, mesh or condition is refused.
  std::uint64_t deckHash = 0;
};

struct ComputeConfig {
  std::string name, path, computeClass, calculation, region, variable, label;
  double point[3] = {0, 0, 0};  // Nearest_Point_Data: the location (X, Y, Z)
};

struct RunConfig {
  bool verbose = false;
  DiscretizationConfig discretization;
  std::map<std::string, std::shared_ptr<MaterialModel>> materials;
  std::map<std::string, std::shared_ptr<DamageModel>> damageModels;
  std::map<std::string, Teuchos::ParameterList> damageParameters;  // to make per-block copies
  std::vector<BlockGroupConfig> blocks;
  std::vector<NodeSetSpec> nodeSets;
  std::vector<ConditionConfig> conditions;
  SolverConfig solver;  // the first solver list
  // Peridigm's chained solvers: the solver lists after the first, in deck order, each starting
  // where the previous one ended (its Initial Time is the previous Final Time).
  std::vector<SolverConfig> chainedSolvers;
  std::vector<OutputConfig> outputs;
  std::vector<ComputeConfig> computes;
  ContactConfig contact;
  RestartConfig restart;
};

RunConfig readRunConfig(const Teuchos::ParameterList& deck);

}  // namespace peridot
