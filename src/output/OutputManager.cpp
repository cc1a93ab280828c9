#include "output/OutputManager.hpp"

#include <algorithm>
#include <numeric>

#include "core/Error.hpp"

namespace peridot {

OutputManager::OutputManager(const RunConfig& config, const std::map<int, std::string>& blockNames,
                             int dimension,
                             const std::map<std::string, std::vector<long long>>& nodeSets,
                             const Topology& topology, VariableSource& source, Timers& timers)
    : topology_(topology), source_(source), timers_(timers) {
  // Group the streams into files.
  for (const auto& out : config.outputs) {
    if (out.frequency == -1 || out.variables.empty()) continue;
    bool onlyGlobal = true;
    for (const auto& v : out.variables) onlyGlobal = onlyGlobal && source.components(v) == 0;
    const std::string path = out.fileName + (onlyGlobal ? ".h" : ".e");
    auto it =
        std::find_if(files_.begin(), files_.end(), [&](const File& f) { return f.path == path; });
    if (it == files_.end()) {
      files_.push_back(File{path, {}, {}, nullptr});
      it = files_.end() - 1;
    }
    for (const auto& v : out.variables)
      if (std::find(it->variables.begin(), it->variables.end(), v) == it->variables.end())
        it->variables.push_back(v);
    it->triggers.push_back({out.frequency, out.initialStep, out.finalStep});
  }
  numPoints_ = topology.globalNumPoints;
  dimension_ = dimension == 2 ? 2 : 3;

  // TODO(bounded output): rank 0 gathers every point's id, block and position.
  int size = topology.numRanks;
  gatherCounts_.assign(size, 0);
  gatherDispls_.assign(size, 0);
  int numOwned = topology.numOwned;
  MPI_Gather(&numOwned, 1, MPI_INT, gatherCounts_.data(), 1, MPI_INT, 0, topology.comm);
  for (int r = 1; r < size; ++r) gatherDispls_[r] = gatherDispls_[r - 1] + gatherCounts_[r - 1];
  std::vector<long long> ownedIds(topology.overlapGlobalId.begin(),
                                  topology.overlapGlobalId.begin() + topology.numOwned);
  const bool root = topology.rank == 0;
  std::vector<long long> allIds(root ? static_cast<std::size_t>(numPoints_) : 0);
  MPI_Gatherv(ownedIds.data(), numOwned, MPI_LONG_LONG, allIds.data(), gatherCounts_.data(),
              gatherDispls_.data(), MPI_LONG_LONG, 0, topology.comm);
  std::vector<int> allBlocks(root ? static_cast<std::size_t>(numPoints_) : 0);
  MPI_Gatherv(topology.blockId.data(), numOwned, MPI_INT, allBlocks.data(), gatherCounts_.data(),
              gatherDispls_.data(), MPI_INT, 0, topology.comm);
  std::vector<double> allX(root ? static_cast<std::size_t>(3 * numPoints_) : 0);
  {
    std::vector<int> c3(gatherCounts_), d3(gatherDispls_);
    for (int r = 0; r < size; ++r) c3[r] *= 3, d3[r] *= 3;
    MPI_Gatherv(topology.referencePosition.data(), 3 * numOwned, MPI_DOUBLE, allX.data(), c3.data(),
                d3.data(), MPI_DOUBLE, 0, topology.comm);
  }
  std::map<std::string, std::vector<long long>> allSets;
  for (const auto& kv : nodeSets) {
    const int m = static_cast<int>(kv.second.size());
    std::vector<int> c(size), dsp(size, 0);
    MPI_Gather(&m, 1, MPI_INT, c.data(), 1, MPI_INT, 0, topology.comm);
    for (int r = 1; r < size; ++r) dsp[r] = dsp[r - 1] + c[r - 1];
    std::vector<long long> ids(root ? static_cast<std::size_t>(dsp[size - 1] + c[size - 1]) : 0);
    MPI_Gatherv(kv.second.data(), m, MPI_LONG_LONG, ids.data(), c.data(), dsp.data(), MPI_LONG_LONG,
                0, topology.comm);
    allSets[kv.first] = std::move(ids);
  }
  if (!root) return;

  // Output order: blocks by id, points by id within a block.
  std::vector<std::size_t> order(allIds.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return allBlocks[a] != allBlocks[b] ? allBlocks[a] < allBlocks[b] : allIds[a] < allIds[b];
  });
  std::map<long long, long long> positionOfId;
  for (std::size_t p = 0; p < order.size(); ++p) positionOfId[allIds[order[p]]] = p;
  positionOfReceived_.resize(allIds.size());
  for (std::size_t k = 0; k < allIds.size(); ++k)
    positionOfReceived_[k] = positionOfId.at(allIds[k]);

  ExodusLayout layout;
  layout.dimension = dimension_;
  for (std::size_t p : order) {
    layout.ids.push_back(allIds[p] + 1);
    layout.x.push_back(allX[3 * p]);
    layout.y.push_back(allX[3 * p + 1]);
    layout.z.push_back(allX[3 * p + 2]);
    if (layout.blockIds.empty() || layout.blockIds.back() != allBlocks[p]) {
      layout.blockIds.push_back(allBlocks[p]);
      layout.blockNames.push_back(blockNames.at(allBlocks[p]));
      layout.blockCounts.push_back(0);
    }
    ++layout.blockCounts.back();
  }
  for (const auto& kv : allSets) {
    ExodusLayout::Set s;
    s.name = kv.first;
    for (long long g : kv.second) s.positions.push_back(static_cast<int>(positionOfId.at(g)));
    std::sort(s.positions.begin(), s.positions.end());
    layout.nodeSets.push_back(s);
  }
  for (auto& f : files_) {
    std::vector<std::string> nodal, element, global;
    const char* axes[3] = {"X", "Y", "Z"};
    for (const auto& v : f.variables) {
      const int c = source.components(v);
      if (c == 3) {
        for (int d = 0; d < dimension_; ++d) nodal.push_back(v + axes[d]);
      } else if (c == 1) {
        element.push_back(v);
      } else {
        if (source.globalSize(v) == 3) {
          for (int d = 0; d < dimension_; ++d) global.push_back(v + axes[d]);
        } else {
          global.push_back(v);
        }
      }
    }
    f.writer = std::make_unique<ExodusWriter>(f.path, layout, nodal, element, global);
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

bool OutputManager::due(long long step) const {
  for (const auto& f : files_)
    if (fires(f, step)) return true;
  return false;
}

void OutputManager::gather(const std::vector<double>& owned, int components,
                           std::vector<double>& out) {
  std::vector<int> counts(gatherCounts_), displs(gatherDispls_);
  for (auto& c : counts) c *= components;
  for (auto& d : displs) d *= components;
  std::vector<double> received(
      topology_.rank == 0 ? static_cast<std::size_t>(numPoints_ * components) : 0);
  MPI_Gatherv(owned.data(), topology_.numOwned * components, MPI_DOUBLE, received.data(),
              counts.data(), displs.data(), MPI_DOUBLE, 0, topology_.comm);
  if (topology_.rank != 0) return;
  out.assign(static_cast<std::size_t>(numPoints_ * components), 0.0);
  for (std::size_t k = 0; k < positionOfReceived_.size(); ++k)
    for (int c = 0; c < components; ++c)
      out[positionOfReceived_[k] * components + c] = received[k * components + c];
}

void OutputManager::write(long long step, double time) {
  Timers::Scope timer(timers_, "Output");
  std::map<std::string, std::vector<double>> cache;  // gathered values by variable
  for (auto& f : files_) {
    if (!fires(f, step)) continue;
    std::vector<std::vector<double>> nodal, element;
    std::vector<double> globals;
    for (const auto& v : f.variables) {
      const int c = source_.components(v);
      if (c == 0) {
        std::vector<double> g;
        source_.globalVariable(v, g);
        // A vector's z component is not written in a planar run.
        if (g.size() == 3) g.resize(static_cast<std::size_t>(dimension_));
        globals.insert(globals.end(), g.begin(), g.end());
        continue;
      }
      auto it = cache.find(v);
      if (it == cache.end()) {
        std::vector<double> owned, all;
        source_.nodeVariable(v, owned);
        gather(owned, c, all);
        it = cache.emplace(v, std::move(all)).first;
      }
      if (topology_.rank != 0) continue;
      const std::vector<double>& all = it->second;
      if (c == 3) {
        for (int d = 0; d < dimension_; ++d) {
          std::vector<double> comp(static_cast<std::size_t>(numPoints_));
          for (long long p = 0; p < numPoints_; ++p) comp[p] = all[3 * p + d];
          nodal.push_back(std::move(comp));
        }
      } else {
        element.push_back(all);
      }
    }
    if (topology_.rank == 0) f.writer->writeRecord(time, nodal, element, globals);
  }
}

}  // namespace peridot
