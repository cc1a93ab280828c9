#include "output/ExodusResults.hpp"

#include <exodusII.h>

#include <cctype>
#include <limits>

#include "core/Error.hpp"
#include "discretization/ExodusMeshReader.hpp"

namespace peridot {

// ----------------------------------------------------------------------------------------------
// Reading a result file

namespace {

class ResultReader {
 public:
  explicit ResultReader(const std::string& fileName)
      : fileName_(fileName), file_(fileName, "file", "") {}

  ExodusResults read();

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError("Exodus file \"" + fileName_ + "\": " + message);
  }
  void check(int status, const char* call) const {
    if (status < 0) {
      fail(std::string(call) + " failed (" + exodusLastError() +
           "); the file may be truncated or corrupt");
    }
  }
  std::vector<std::string> variableNames(ex_entity_type type) const;

  std::string fileName_;
  ExodusInputFile file_;
};

std::vector<std::string> ResultReader::variableNames(ex_entity_type type) const {
  int count = 0;
  check(ex_get_variable_param(file_.id(), type, &count), "ex_get_variable_param");
  std::vector<std::string> names(static_cast<std::size_t>(std::max(count, 0)));
  if (count <= 0) return names;
  constexpr std::size_t kBufferSize = 257;  // the longest netCDF name plus the terminator
  std::vector<std::vector<char>> buffers(names.size(), std::vector<char>(kBufferSize, '\0'));
  std::vector<char*> pointers(names.size());
  for (std::size_t i = 0; i < names.size(); ++i) pointers[i] = buffers[i].data();
  check(ex_get_variable_names(file_.id(), type, count, pointers.data()), "ex_get_variable_names");
  for (std::size_t i = 0; i < names.size(); ++i) {
    buffers[i].back() = '\0';
    std::string name = buffers[i].data();
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
    names[i] = name;
  }
  return names;
}

ExodusResults ResultReader::read() {
  const int exoid = file_.id();
  ExodusResults r;
  r.fileName = fileName_;
  ex_init_params init{};
  check(ex_get_init_ext(exoid, &init), "ex_get_init_ext");
  if (init.num_dim < 1 || init.num_dim > 3 || init.num_nodes < 0 || init.num_elem < 0 ||
      init.num_elem_blk < 0) {
    fail("implausible sizes in the header; the file may be corrupt");
  }
  r.dimension = static_cast<int>(init.num_dim);
  const auto numNodes = static_cast<std::size_t>(init.num_nodes);
  const auto numElements = static_cast<std::size_t>(init.num_elem);

  const int64_t numSteps = ex_inquire_int(exoid, EX_INQ_TIME);
  if (numSteps < 0) fail("cannot read the number of time steps (" + exodusLastError() + ")");
  r.times.resize(static_cast<std::size_t>(numSteps));
  if (numSteps > 0) check(ex_get_all_times(exoid, r.times.data()), "ex_get_all_times");

  std::vector<int64_t> ids(numNodes);
  if (numNodes > 0) {
    check(ex_get_id_map(exoid, EX_NODE_MAP, ids.data()), "ex_get_id_map");
    std::vector<double> c[3];
    for (int d = 0; d < 3; ++d) c[d].assign(numNodes, 0.0);
    check(ex_get_coord(exoid, c[0].data(), r.dimension > 1 ? c[1].data() : nullptr,
                       r.dimension > 2 ? c[2].data() : nullptr),
          "ex_get_coord");
    r.nodeCoordinates.resize(3 * numNodes);
    for (std::size_t n = 0; n < numNodes; ++n) {
      for (int d = 0; d < 3; ++d) r.nodeCoordinates[3 * n + static_cast<std::size_t>(d)] = c[d][n];
    }
  }
  r.nodeIds.assign(ids.begin(), ids.end());

  ids.assign(numElements, 0);
  if (numElements > 0) check(ex_get_id_map(exoid, EX_ELEM_MAP, ids.data()), "ex_get_id_map");
  r.elementIds.assign(ids.begin(), ids.end());

  const auto numBlocks = static_cast<std::size_t>(init.num_elem_blk);
  std::vector<int64_t> blockIds(numBlocks);
  std::vector<std::size_t> blockStart(numBlocks + 1, 0);
  if (numBlocks > 0) check(ex_get_ids(exoid, EX_ELEM_BLOCK, blockIds.data()), "ex_get_ids");
  for (std::size_t b = 0; b < numBlocks; ++b) {
    ex_block param{};
    param.id = blockIds[b];
    param.type = EX_ELEM_BLOCK;
    check(ex_get_block_param(exoid, &param), "ex_get_block_param");
    if (param.num_entry < 0 ||
        blockStart[b] + static_cast<std::size_t>(param.num_entry) > numElements) {
      fail("element block " + std::to_string(blockIds[b]) + " has an inconsistent size");
    }
    blockStart[b + 1] = blockStart[b] + static_cast<std::size_t>(param.num_entry);
    r.elementBlock.insert(r.elementBlock.end(), static_cast<std::size_t>(param.num_entry),
                          static_cast<long long>(blockIds[b]));
  }
  if (blockStart[numBlocks] != numElements) {
    fail("the element blocks hold " + std::to_string(blockStart[numBlocks]) +
         " elements but the header declares " + std::to_string(numElements));
  }

  r.nodalNames = variableNames(EX_NODAL);
  r.elementNames = variableNames(EX_ELEM_BLOCK);
  r.globalNames = variableNames(EX_GLOBAL);
  const auto steps = static_cast<std::size_t>(numSteps);

  r.nodal.assign(r.nodalNames.size(), std::vector<std::vector<double>>(steps));
  for (std::size_t v = 0; v < r.nodalNames.size(); ++v) {
    for (std::size_t s = 0; s < steps; ++s) {
      auto& values = r.nodal[v][s];
      values.assign(numNodes, 0.0);
      if (numNodes == 0) continue;
      check(ex_get_var(exoid, static_cast<int>(s + 1), EX_NODAL, static_cast<int>(v + 1), 1,
                       static_cast<int64_t>(numNodes), values.data()),
            "ex_get_var (nodal)");
    }
  }

  const std::size_t numElementVars = r.elementNames.size();
  std::vector<int> truth(numBlocks * numElementVars, 1);
  if (numElementVars > 0 && numBlocks > 0) {
    check(ex_get_truth_table(exoid, EX_ELEM_BLOCK, static_cast<int>(numBlocks),
                             static_cast<int>(numElementVars), truth.data()),
          "ex_get_truth_table");
  }
  r.element.assign(numElementVars, std::vector<std::vector<double>>(steps));
  for (std::size_t v = 0; v < numElementVars; ++v) {
    for (std::size_t s = 0; s < steps; ++s) {
      auto& values = r.element[v][s];
      values.assign(numElements, std::numeric_limits<double>::quiet_NaN());
      for (std::size_t b = 0; b < numBlocks; ++b) {
        const std::size_t count = blockStart[b + 1] - blockStart[b];
        if (count == 0 || truth[b * numElementVars + v] == 0) continue;
        check(ex_get_var(exoid, static_cast<int>(s + 1), EX_ELEM_BLOCK, static_cast<int>(v + 1),
                         blockIds[b], static_cast<int64_t>(count), values.data() + blockStart[b]),
              "ex_get_var (element)");
      }
    }
  }

  const std::size_t numGlobals = r.globalNames.size();
  r.global.assign(numGlobals, std::vector<std::vector<double>>(steps, std::vector<double>(1)));
  std::vector<double> row(numGlobals);
  for (std::size_t s = 0; s < steps && numGlobals > 0; ++s) {
    check(
        ex_get_glob_vars(exoid, static_cast<int>(s + 1), static_cast<int>(numGlobals), row.data()),
        "ex_get_glob_vars");
    for (std::size_t v = 0; v < numGlobals; ++v) r.global[v][s][0] = row[v];
  }
  return r;
}

}  // namespace

ExodusResults readExodusResults(const std::string& fileName) {
  ResultReader reader(fileName);
  return reader.read();
}

}  // namespace peridot
