#pragma once
// The output variables of a run, by Peridigm's names: node variables (displacement, damage,
// energies, ...) and global ones (the compute classes' reductions), computed on request from the
// run's fields and models for the Exodus writer and the computes. Reads the run; changes nothing.
#include <map>
#include <string>
#include <vector>

#include "deck/RunConfig.hpp"
#include "evaluator/Block.hpp"
#include "evaluator/ModelEvaluator.hpp"
#include "fields/FieldManager.hpp"
#include "output/OutputManager.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

class RunVariables : public VariableSource {
 public:
  // What the variables are computed from; all owned by the run, which outlives this object.
  struct Sources {
    const RunConfig* config = nullptr;
    MPI_Comm comm = MPI_COMM_WORLD;
    int rank = 0;
    const Topology* topology = nullptr;
    FieldManager* fields = nullptr;
    const std::vector<Block>* blocks = nullptr;
    const ModelEvaluator* evaluator = nullptr;
    const std::map<std::string, std::vector<int>>* nodeSets = nullptr;  // owned local indices
    const std::vector<double>* density = nullptr;                       // owned
    const std::vector<int>* blockIndexOfPoint = nullptr;                // owned -> blocks index
    // Optional fields: null when the run has no body force / no contact.
    const double* externalForceDensity = nullptr;
    const double* contactForceDensity = nullptr;
    // The implicit solvers' nonlinear iterations of their last step (null: 0).
    const long long* nonlinearIterations = nullptr;
  };
  explicit RunVariables(const Sources& sources);

  void nodeVariable(const std::string& name, std::vector<double>& ownedValues) override;
  void globalVariable(const std::string& name, std::vector<double>& values) override;
  int components(const std::string& name) const override;
  int globalSize(const std::string& name) const override;
  std::string globalComponentName(const std::string& name, int d) const override;

 private:
  // Collective: the calculation ("Sum", "Minimum", "Maximum") of one component of a node
  // variable over `points` (all owned points when null), over all ranks.
  double reduce(const std::vector<int>* points, const std::string& variable, int component,
                const std::string& calculation);

  // Nearest_Point_Data: the owned index of the tracked point on its owner, -1 elsewhere; found
  // on first use (collective) and kept, as the reference positions never change.
  int nearestPoint(const ComputeConfig& c);
  std::map<std::string, int> nearest_;

  Sources s_;
  const double *x_, *y_, *u_, *v_, *a_, *f_, *volume_;
};

}  // namespace peridot
