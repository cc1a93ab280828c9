#pragma once
// Output streams (`Output*` lists): which variables, how often, into which file. Streams with
// the same file name share one file; a stream with only global variables goes to <name>.h as
// in Peridigm. Data is gathered on rank 0, which writes one file whatever the rank count.
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/Timers.hpp"
#include "deck/RunConfig.hpp"
#include "output/ExodusWriter.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

// Computes a named variable on the owned points (components interleaved) or a global value.
class VariableSource {
 public:
  virtual ~VariableSource() = default;
  virtual void nodeVariable(const std::string& name, std::vector<double>& ownedValues) = 0;
  virtual void globalVariable(const std::string& name, std::vector<double>& values) = 0;
  virtual int components(const std::string& name) const = 0;  // 0 = global
  // Values of a global variable (1, or 3 for a vector); not collective.
  virtual int globalSize(const std::string& name) const = 0;
};

class OutputManager {
 public:
  // Collective. `nodeSets`: every set name, with the global ids of its owned points (sorted);
  // the mesh (positions, blocks) comes from the topology's owned points.
  OutputManager(const RunConfig& config, const std::map<int, std::string>& blockNames,
                int dimension, const std::map<std::string, std::vector<long long>>& nodeSets,
                const Topology& topology, VariableSource& source, Timers& timers);
  ~OutputManager();
  // Writes the records due at `step` (step 0 is always written).
  void write(long long step, double time);
  bool due(long long step) const;
  std::vector<std::string> fileNames() const;

 private:
  struct Trigger {
    long long frequency, initialStep, finalStep;
  };
  struct File {
    std::string path;
    std::vector<std::string> variables;
    std::vector<Trigger> triggers;
    std::unique_ptr<ExodusWriter> writer;  // rank 0
  };
  bool fires(const File& f, long long step) const;
  void gather(const std::vector<double>& owned, int components, std::vector<double>& out);

  const Topology& topology_;
  VariableSource& source_;
  Timers& timers_;
  std::vector<File> files_;
  std::vector<int> gatherCounts_, gatherDispls_;
  std::vector<long long> positionOfReceived_;  // rank 0: output position of each gathered point
  long long numPoints_ = 0;
  int dimension_ = 3;  // components written per vector: 2 in a planar run (no z)
};

}  // namespace peridot
