#pragma once
// Output streams (`Output*` lists): which variables, how often, into which file. Streams with
// the same file name share one file; a stream with only global variables goes to <name>.h as
// in Peridigm. One file whatever the rank count, written by rank 0 one rank's range of output
// positions at a time (OutputDistribution): no rank holds more than O(N/P) of a field.
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/Timers.hpp"
#include "deck/RunConfig.hpp"
#include "output/ExodusWriter.hpp"
#include "output/OutputDistribution.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

// Longest output path handed to the Exodus library (it copies names into fixed buffers).
constexpr std::size_t kMaxOutputPath = 200;
// "" if an output file can be created at `path` (checked without creating it: the directory
// exists and is writable, the name is not a directory, FIFO or too long); else why not, with
// the operating system's reason.
std::string whyCannotCreate(const std::string& path);

// Computes a named variable on the owned points (components interleaved) or a global value.
class VariableSource {
 public:
  virtual ~VariableSource() = default;
  virtual void nodeVariable(const std::string& name, std::vector<double>& ownedValues) = 0;
  virtual void globalVariable(const std::string& name, std::vector<double>& values) = 0;
  virtual int components(const std::string& name) const = 0;  // 0 = global
  // Values of a global variable (1, or 3 for a vector); not collective.
  virtual int globalSize(const std::string& name) const = 0;
  // The file's name of component d of a vector global variable.
  virtual std::string globalComponentName(const std::string& name, int d) const {
    return name + std::string(1, "XYZ"[d]);
  }
};

class OutputManager {
 public:
  // Collective. `nodeSets`: every set name, with the global ids of its owned points (sorted);
  // the mesh (positions, blocks) comes from the topology's owned points. Works out where each
  // owned point goes in the files; the files themselves are created (or continued, see
  // resume()) by the first write().
  OutputManager(const RunConfig& config, const std::map<int, std::string>& blockNames,
                int dimension, const std::map<std::string, std::vector<long long>>& nodeSets,
                const Topology& topology, VariableSource& source, Timers& timers);
  ~OutputManager();

  // Collective; for a run restarted from a checkpoint taken at `step` / `time`, called instead
  // of the first write(step, time) (that record is already in the files). Each file that
  // exists and matches this run (dimension, number of points, blocks, node sets, variable
  // names) is continued: its records with time <= `time` are kept and the next write() goes
  // right after them (later records of the earlier run are overwritten as the run proceeds;
  // see doc/architecture.md section 8). A file that is missing or does not match is created
  // anew. Returns one message per file saying which happened, and why; the same on every rank.
  std::vector<std::string> resume(long long step, double time);
  // Collective. Writes the records due at `step` (step 0 is always written).
  void write(long long step, double time);
  bool due(long long step) const;
  // Every stream's Output Frequency multiplied by `factor` (Adaptive output frequency: a halved
  // load step doubles it) or set to `frequency` (Switch to Verlet's Output Frequency), as
  // Peridigm changes its output managers' frequency; a record is due when its step number is a
  // multiple of the frequency in force.
  void multiplyFrequency(long long factor);
  void setFrequency(long long frequency);
  std::vector<std::string> fileNames() const;

 private:
  struct Trigger {
    long long frequency, initialStep, finalStep;
  };
  struct File {
    std::string path;
    std::string deckPath;  // "Output -> Output Filename" of the first stream writing it
    std::vector<std::string> variables;
    std::vector<Trigger> triggers;
    ExodusHeader header;
    std::unique_ptr<ExodusWriter> writer;  // rank 0
    // Global variables only (a `.h` file): Peridigm's placeholder mesh of one node and one
    // element instead of the points.
    bool onlyGlobal = false;
  };
  bool fires(const File& f, long long step) const;
  // Collective: creates the files (or continues them: `resumeTime` set, `messages` filled).
  void open(const double* resumeTime, std::vector<std::string>* messages);
  void writeMesh(File& f);
  // Rank 0 runs `action` unless an earlier one failed; the first failure is kept, and
  // raiseErrors() (collective) throws it on every rank, so that no rank is left waiting.
  template <class Action>
  void onRoot(Action&& action);
  void raiseErrors();

  const Topology& topology_;
  VariableSource& source_;
  Timers& timers_;
  std::vector<File> files_;
  std::unique_ptr<OutputDistribution> distribution_;
  std::map<std::string, std::vector<long long>> nodeSets_;  // owned members: O(N/P)
  int dimension_ = 3;  // components written per vector: 2 in a planar run (no z)
  bool opened_ = false;
  std::string error_;  // rank 0: the first failure since the last raiseErrors()
};

}  // namespace peridot
