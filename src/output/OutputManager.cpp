#include "output/OutputManager.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <numeric>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "deck/OutputVariables.hpp"

namespace peridot {

namespace {

std::string formatTime(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", t);
  return text;
}

}  // namespace

constexpr std::size_t kMaxExodusName = 32;  // libexodus's default name length

std::string whyCannotCreate(const std::string& path) {
  if (path.size() > kMaxOutputPath) {
    return "the name is " + std::to_string(path.size()) +
           " characters long; Peridot takes at most " + std::to_string(kMaxOutputPath) +
           " (the Exodus library copies names into fixed buffers)";
  }
  const auto slash = path.find_last_of('/');
  const std::string dir =
      slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  if (base.empty() || base[0] == '.') {
    return "\"Output Filename\" names a directory, not a file (give a base name, e.g. "
           "\"results/run\")";
  }
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) return "a directory of that name exists";
    if (!S_ISREG(st.st_mode)) return "it exists and is not a regular file (a FIFO or device)";
    if (::access(path.c_str(), W_OK) != 0) return std::strerror(errno);
    return "";
  }
  if (::stat(dir.c_str(), &st) != 0) {
    return "directory \"" + dir + "\": " + std::strerror(errno) +
           (errno == ENOENT ? " (Peridot does not create directories)" : "");
  }
  if (!S_ISDIR(st.st_mode)) return "\"" + dir + "\" is not a directory";
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    return "directory \"" + dir + "\": " + std::strerror(errno);
  }
  return "";
}

OutputManager::OutputManager(const RunConfig& config, const std::map<int, std::string>& blockNames,
                             int dimension,
                             const std::map<std::string, std::vector<long long>>& nodeSets,
                             const Topology& topology, VariableSource& source, Timers& timers)
    : topology_(topology), source_(source), timers_(timers) {
  // Group the streams into files.
  for (const auto& out : config.outputs) {
    if (out.frequency == -1 && topology.rank == 0) {
      // Peridigm's default when the key is missing: the stream writes nothing, not even the
      // initial state. Said, since a forgotten key otherwise looks like a run without output.
      std::cerr << "peridot: warning: " << out.path
                << " -> Output Frequency: -1 (the default when the key is missing, as in "
                   "Peridigm): this stream writes no file; set it to the number of steps "
                   "between records"
                << std::endl;
    }
    if (out.frequency == -1 || out.variables.empty()) continue;
    bool onlyGlobal = true;
    for (const auto& v : out.variables) onlyGlobal = onlyGlobal && source.components(v) == 0;
    const std::string path = out.fileName + (onlyGlobal ? ".h" : ".e");
    auto it =
        std::find_if(files_.begin(), files_.end(), [&](const File& f) { return f.path == path; });
    if (it == files_.end()) {
      files_.push_back(
          File{path, out.path + " -> Output Filename", {}, {}, {}, nullptr, onlyGlobal});
      it = files_.end() - 1;
    }
    it->variables.insert(it->variables.end(), out.variables.begin(), out.variables.end());
    it->triggers.push_back({out.frequency, out.initialStep, out.finalStep});
  }
  // Each variable name once per file (streams sharing a file, a tensor and its components).
  for (auto& f : files_) f.variables = distinctOutputVariables(f.variables);
  {
    // Checked here, before any file is made and before the names reach the Exodus library
    // (which copies a long name into a fixed buffer): every file of the run can be created.
    std::string problem;
    if (topology.rank == 0)
      for (const auto& f : files_) {
        const std::string why = whyCannotCreate(f.path);
        if (!why.empty()) {
          problem = f.deckPath + ": cannot create \"" + f.path + "\": " + why;
          break;
        }
      }
    throwIfAnyRank(problem, topology.comm);
  }
  dimension_ = dimension == 2 ? 2 : 3;
  distribution_ = std::make_unique<OutputDistribution>(topology);
  nodeSets_ = nodeSets;

  // What every file holds besides the per-point data (the same on every rank).
  ExodusHeader header;
  header.dimension = dimension_;
  header.numPoints = distribution_->numPoints();
  header.blockIds = distribution_->blockIds();
  header.blockCounts = distribution_->blockCounts();
  for (int id : header.blockIds) header.blockNames.push_back(blockNames.at(id));
  for (const auto& kv : nodeSets_) {
    long long mine = static_cast<long long>(kv.second.size()), total = 0;
    MPI_Allreduce(&mine, &total, 1, MPI_LONG_LONG, MPI_SUM, topology.comm);
    header.setNames.push_back(kv.first);
    header.setSizes.push_back(total);
  }
  for (auto& f : files_) {
    f.header = header;
    if (f.onlyGlobal) {
      // As Peridigm: one node at the origin, one unnamed SPHERE element in block 1, no sets.
      f.header.numPoints = 1;
      f.header.blockIds = {1};
      f.header.blockNames.clear();
      f.header.blockCounts = {1};
      f.header.setNames.clear();
      f.header.setSizes.clear();
    }
    const char* axes[3] = {"X", "Y", "Z"};
    for (const auto& v : f.variables) {
      const int c = source.components(v);
      const bool vector = c == 3 || (c == 0 && source.globalSize(v) == 3);
      if (v.size() + (vector ? 1 : 0) + (c == 9 ? 2 : 0) > kMaxExodusName) {
        // libexodus would cut the name to 32 characters (two labels could become one).
        const std::string stream = f.deckPath.substr(0, f.deckPath.rfind(" -> "));
        throw InputError(stream + " -> Output Variables -> " + v,
                         "the name is " + std::to_string(v.size()) +
                             " characters long; an Exodus variable name holds at most " +
                             std::to_string(kMaxExodusName) +
                             (vector   ? " (with X, Y or Z appended)"
                              : c == 9 ? " (with XX ... ZZ appended)"
                                       : ""));
      }
      if (c == 9) {
        // A full tensor: nine element variables, Peridigm's <name>XX, XY, ..., ZZ.
        for (int r = 0; r < 3; ++r)
          for (int k = 0; k < 3; ++k) f.header.elementNames.push_back(v + axes[r] + axes[k]);
      } else if (c == 3) {
        for (int d = 0; d < dimension_; ++d) f.header.nodalNames.push_back(v + axes[d]);
      } else if (c == 1) {
        f.header.elementNames.push_back(v);
      } else if (source.globalSize(v) == 3) {
        for (int d = 0; d < dimension_; ++d)
          f.header.globalNames.push_back(source.globalComponentName(v, d));
      } else {
        f.header.globalNames.push_back(v);
      }
    }
  }
}

OutputManager::~OutputManager() = default;

std::vector<std::string> OutputManager::fileNames() const {
  std::vector<std::string> names;
  for (const auto& f : files_) names.push_back(f.path);
  return names;
}

bool OutputManager::fires(const File& f, long long step) const {
  if (step == 0) return true;
  for (const auto& t : f.triggers) {
    if (step < t.initialStep) continue;
    if (t.finalStep >= 0 && step > t.finalStep) continue;
    if (step % t.frequency == 0) return true;
  }
  return false;
}

void OutputManager::multiplyFrequency(long long factor) {
  for (auto& f : files_)
    for (auto& t : f.triggers)
      if (t.frequency < (1LL << 40)) t.frequency *= factor;
}

void OutputManager::setFrequency(long long frequency) {
  for (auto& f : files_)
    for (auto& t : f.triggers) t.frequency = frequency;
}

bool OutputManager::due(long long step) const {
  for (const auto& f : files_)
    if (fires(f, step)) return true;
  return false;
}

template <class Action>
void OutputManager::onRoot(Action&& action) {
  if (topology_.rank != 0 || !error_.empty()) return;
  try {
    action();
  } catch (const std::exception& e) {
    error_ = e.what();
    if (error_.empty()) error_ = "output failed";
  }
}

void OutputManager::raiseErrors() {
  std::string message;
  message.swap(error_);
  throwIfAnyRank(message, topology_.comm, /*duringRun=*/true);
}

void OutputManager::open(const double* resumeTime, std::vector<std::string>* messages) {
  opened_ = true;
  // Every file is created (or continued) before any mesh or record is written: a file that
  // cannot be made stops the run before the others hold anything, and those made by this call
  // are removed again (no file of 0 records is left behind).
  std::vector<int> created(files_.size(), 1);
  std::vector<std::string> said(files_.size());
  for (std::size_t k = 0; k < files_.size(); ++k) {
    File& f = files_[k];
    onRoot([&] {
      if (resumeTime != nullptr) {
        std::string whyNot;
        f.writer = ExodusWriter::resume(f.path, f.header, *resumeTime, whyNot);
        if (f.writer) {
          created[k] = 0;
          said[k] = "Output: continuing \"" + f.path + "\" after its record " +
                    std::to_string(f.writer->recordsWritten()) +
                    " (the last at time <= " + formatTime(*resumeTime) + ")";
          return;
        }
        said[k] = "Output: \"" + f.path + "\" not continued (" + whyNot + "); created anew";
      }
      f.writer = std::make_unique<ExodusWriter>(f.path, f.header);
    });
  }
  if (topology_.rank == 0 && !error_.empty()) {
    for (std::size_t k = 0; k < files_.size(); ++k)
      if (files_[k].writer && created[k]) {
        files_[k].writer.reset();
        std::remove(files_[k].path.c_str());
      }
  }
  raiseErrors();
  MPI_Bcast(created.data(), static_cast<int>(created.size()), MPI_INT, 0, topology_.comm);
  for (std::size_t k = 0; k < files_.size(); ++k) {
    if (created[k]) writeMesh(files_[k]);
    if (messages == nullptr) continue;
    std::string& message = said[k];
    int length = static_cast<int>(message.size());
    MPI_Bcast(&length, 1, MPI_INT, 0, topology_.comm);
    message.resize(static_cast<std::size_t>(length));
    MPI_Bcast(message.data(), length, MPI_CHAR, 0, topology_.comm);
    messages->push_back(message);
  }
}

void OutputManager::writeMesh(File& f) {
  if (f.onlyGlobal) {
    const long long id = 1;
    const double origin[3] = {0.0, 0.0, 0.0};
    onRoot([&] { f.writer->putMesh(0, 1, &id, origin); });
    raiseErrors();
    return;
  }
  const OutputDistribution& d = *distribution_;
  const int n = topology_.numOwned;
  {
    // Ids (exact in a double: below 2^31) and reference positions, 4 values per point.
    std::vector<double> owned(4 * static_cast<std::size_t>(n)), range;
    for (int i = 0; i < n; ++i) {
      owned[4 * i] = static_cast<double>(topology_.overlapGlobalId[i] + 1);
      for (int k = 0; k < 3; ++k) owned[4 * i + 1 + k] = topology_.referencePosition[3 * i + k];
    }
    d.toRange(owned.data(), 4, range);
    owned = {};
    std::vector<long long> ids;
    std::vector<double> xyz;
    streamRangesToRoot(d, topology_.comm, range, 4, MPI_DOUBLE,
                       [&](long long first, long long count, const double* v) {
                         onRoot([&] {
                           ids.resize(static_cast<std::size_t>(count));
                           xyz.resize(static_cast<std::size_t>(3 * count));
                           for (long long k = 0; k < count; ++k) {
                             ids[k] = static_cast<long long>(v[4 * k]);
                             for (int c = 0; c < 3; ++c) xyz[3 * k + c] = v[4 * k + 1 + c];
                           }
                           f.writer->putMesh(first, count, ids.data(), xyz.data());
                         });
                       });
  }
  // Node sets: each rank's members within its range are consecutive entries of the set.
  std::vector<const std::vector<long long>*> sets;
  for (const auto& kv : nodeSets_) sets.push_back(&kv.second);
  const std::vector<std::vector<long long>> inRange = d.setsInRange(sets);
  for (std::size_t set = 0; set < inRange.size(); ++set) {
    const std::vector<long long>& positions = inRange[set];
    long long mine = static_cast<long long>(positions.size());
    std::vector<long long> counts(topology_.rank == 0 ? topology_.numRanks : 0);
    MPI_Gather(&mine, 1, MPI_LONG_LONG, counts.data(), 1, MPI_LONG_LONG, 0, topology_.comm);
    if (topology_.rank != 0) {
      MPI_Send(positions.data(), static_cast<int>(mine), MPI_LONG_LONG, 0, 1, topology_.comm);
    } else {
      onRoot([&] { f.writer->putSet(static_cast<int>(set), 0, mine, positions.data()); });
      long long offset = mine;
      std::vector<long long> buffer;
      for (int r = 1; r < topology_.numRanks; ++r) {
        buffer.resize(static_cast<std::size_t>(counts[r]));
        MPI_Recv(buffer.data(), static_cast<int>(counts[r]), MPI_LONG_LONG, r, 1, topology_.comm,
                 MPI_STATUS_IGNORE);
        onRoot([&] { f.writer->putSet(static_cast<int>(set), offset, counts[r], buffer.data()); });
        offset += counts[r];
      }
    }
  }
  onRoot([&] { f.writer->endRecord(); });  // flush the mesh
  raiseErrors();
}

std::vector<std::string> OutputManager::resume(long long step, double time) {
  if (opened_) throw RunError("OutputManager::resume must come before the first write");
  Timers::Scope timer(timers_, "Output");
  std::vector<std::string> messages;
  // The records are told apart by their times (a file has no step numbers); the step goes
  // into the messages, for the log.
  open(&time, &messages);
  for (auto& m : messages) m += " [restart at step " + std::to_string(step) + "]";
  return messages;
}

void OutputManager::write(long long step, double time) {
  Timers::Scope timer(timers_, "Output");
  if (!opened_) open(nullptr, nullptr);
  const OutputDistribution& d = *distribution_;
  // Each variable's values on this rank's range, computed once for all the files.
  std::map<std::string, std::vector<double>> cache;
  for (auto& f : files_) {
    if (!fires(f, step)) continue;
    std::vector<double> globals;
    for (const auto& v : f.variables) {
      if (source_.components(v) != 0) continue;
      std::vector<double> g;
      source_.globalVariable(v, g);
      // A vector's z component is not written in a planar run.
      if (g.size() == 3) g.resize(static_cast<std::size_t>(dimension_));
      globals.insert(globals.end(), g.begin(), g.end());
    }
    onRoot([&] { f.writer->beginRecord(time, globals); });
    int nodal = 0, element = 0;  // variable indices in the file
    std::vector<double> component;
    for (const auto& v : f.variables) {
      const int c = source_.components(v);
      if (c == 0) continue;
      auto it = cache.find(v);
      if (it == cache.end()) {
        std::vector<double> owned, range;
        source_.nodeVariable(v, owned);
        d.toRange(owned.data(), c, range);
        it = cache.emplace(v, std::move(range)).first;
      }
      streamRangesToRoot(d, topology_.comm, it->second, c, MPI_DOUBLE,
                         [&](long long first, long long count, const double* values) {
                           onRoot([&] {
                             if (c == 1) {
                               f.writer->putElement(element, first, count, values);
                               return;
                             }
                             component.resize(static_cast<std::size_t>(count));
                             if (c == 9) {
                               for (int k = 0; k < 9; ++k) {
                                 for (long long p = 0; p < count; ++p)
                                   component[p] = values[9 * p + k];
                                 f.writer->putElement(element + k, first, count, component.data());
                               }
                               return;
                             }
                             for (int dd = 0; dd < dimension_; ++dd) {
                               for (long long k = 0; k < count; ++k)
                                 component[k] = values[c * k + dd];
                               f.writer->putNodal(nodal + dd, first, count, component.data());
                             }
                           });
                         });
      if (c == 1)
        ++element;
      else if (c == 9)
        element += 9;
      else
        nodal += dimension_;
    }
    onRoot([&] { f.writer->endRecord(); });
    raiseErrors();
  }
}

}  // namespace peridot
