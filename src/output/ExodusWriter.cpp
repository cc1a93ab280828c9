#include "output/ExodusWriter.hpp"

#include <exodusII.h>

#include <climits>

#include "core/Error.hpp"

namespace peridot {

namespace {

std::vector<char*> cstrings(std::vector<std::string>& names) {
  std::vector<char*> out;
  for (auto& n : names) out.push_back(n.data());
  return out;
}

}  // namespace

void ExodusWriter::check(int status, const std::string& what) const {
  if (status < 0) {
    throw RunError("writing Exodus file \"" + fileName_ + "\" failed in " + what + " (code " +
                   std::to_string(status) + ")");
  }
}

ExodusWriter::ExodusWriter(const std::string& fileName, const ExodusLayout& layout,
                           const std::vector<std::string>& nodalNames,
                           const std::vector<std::string>& elementNames,
                           const std::vector<std::string>& globalNames)
    : fileName_(fileName), blockIds_(layout.blockIds), blockCounts_(layout.blockCounts) {
  int cpuWordSize = sizeof(double), ioWordSize = sizeof(double);
  exoid_ = ex_create(fileName.c_str(), EX_CLOBBER, &cpuWordSize, &ioWordSize);
  if (exoid_ < 0) throw RunError("cannot create Exodus file \"" + fileName + "\"");
  const long long n = static_cast<long long>(layout.ids.size());
  if (n > INT_MAX) throw RunError("more points than 32-bit Exodus ids can hold");
  const bool planar = layout.dimension == 2;
  check(ex_put_init(exoid_, "Peridot", planar ? 2 : 3, n, n,
                    static_cast<long long>(layout.blockIds.size()),
                    static_cast<long long>(layout.nodeSets.size()), 0),
        "ex_put_init");
  check(ex_put_coord(exoid_, layout.x.data(), layout.y.data(), planar ? nullptr : layout.z.data()),
        "ex_put_coord");
  std::vector<std::string> coordNames = {"x", "y", "z"};
  if (planar) coordNames.pop_back();
  auto coordPtrs = cstrings(coordNames);
  check(ex_put_coord_names(exoid_, coordPtrs.data()), "ex_put_coord_names");

  std::vector<int> ids(layout.ids.begin(), layout.ids.end());
  long long position = 0;
  for (std::size_t b = 0; b < layout.blockIds.size(); ++b) {
    const long long count = layout.blockCounts[b];
    check(ex_put_block(exoid_, EX_ELEM_BLOCK, layout.blockIds[b], "SPHERE", count, 1, 0, 0, 0),
          "ex_put_block");
    std::vector<int> conn(static_cast<std::size_t>(count));
    for (long long k = 0; k < count; ++k) conn[k] = static_cast<int>(position + k + 1);
    if (count > 0)
      check(ex_put_conn(exoid_, EX_ELEM_BLOCK, layout.blockIds[b], conn.data(), nullptr, nullptr),
            "ex_put_conn");
    position += count;
  }
  std::vector<std::string> blockNames = layout.blockNames;
  auto blockPtrs = cstrings(blockNames);
  if (!blockPtrs.empty())
    check(ex_put_names(exoid_, EX_ELEM_BLOCK, blockPtrs.data()), "ex_put_names");
  check(ex_put_id_map(exoid_, EX_NODE_MAP, ids.data()), "ex_put_id_map(nodes)");
  check(ex_put_id_map(exoid_, EX_ELEM_MAP, ids.data()), "ex_put_id_map(elements)");

  std::vector<std::string> setNames;
  for (std::size_t s = 0; s < layout.nodeSets.size(); ++s) {
    const auto& set = layout.nodeSets[s];
    const int setId = static_cast<int>(s + 1);
    check(ex_put_set_param(exoid_, EX_NODE_SET, setId, static_cast<long long>(set.positions.size()),
                           0),
          "ex_put_set_param");
    std::vector<int> nodes;
    for (int p : set.positions) nodes.push_back(p + 1);
    if (!nodes.empty())
      check(ex_put_set(exoid_, EX_NODE_SET, setId, nodes.data(), nullptr), "ex_put_set");
    setNames.push_back(set.name.substr(0, 32));
  }
  if (!setNames.empty()) {
    auto setPtrs = cstrings(setNames);
    check(ex_put_names(exoid_, EX_NODE_SET, setPtrs.data()), "ex_put_names(node sets)");
  }

  auto putNames = [&](const char* type, ex_entity_type entity, std::vector<std::string> names) {
    if (names.empty()) return;
    check(ex_put_var_param(exoid_, type, static_cast<int>(names.size())), "ex_put_var_param");
    auto ptrs = cstrings(names);
    check(ex_put_var_names(exoid_, type, static_cast<int>(names.size()), ptrs.data()),
          "ex_put_var_names");
    (void)entity;
  };
  putNames("g", EX_GLOBAL, globalNames);
  putNames("n", EX_NODAL, nodalNames);
  putNames("e", EX_ELEM_BLOCK, elementNames);
  if (!elementNames.empty() && !blockIds_.empty()) {
    std::vector<int> truth(blockIds_.size() * elementNames.size(), 1);
    check(ex_put_elem_var_tab(exoid_, static_cast<int>(blockIds_.size()),
                              static_cast<int>(elementNames.size()), truth.data()),
          "ex_put_elem_var_tab");
  }
  check(ex_update(exoid_), "ex_update");
}

ExodusWriter::~ExodusWriter() {
  if (exoid_ >= 0) ex_close(exoid_);
}

void ExodusWriter::writeRecord(double time, const std::vector<std::vector<double>>& nodal,
                               const std::vector<std::vector<double>>& element,
                               const std::vector<double>& globals) {
  ++step_;
  check(ex_put_time(exoid_, step_, &time), "ex_put_time");
  if (!globals.empty()) {
    check(ex_put_glob_vars(exoid_, step_, static_cast<int>(globals.size()), globals.data()),
          "ex_put_glob_vars");
  }
  for (std::size_t k = 0; k < nodal.size(); ++k) {
    check(ex_put_nodal_var(exoid_, step_, static_cast<int>(k + 1),
                           static_cast<int>(nodal[k].size()), nodal[k].data()),
          "ex_put_nodal_var");
  }
  for (std::size_t k = 0; k < element.size(); ++k) {
    long long offset = 0;
    for (std::size_t b = 0; b < blockIds_.size(); ++b) {
      if (blockCounts_[b] > 0) {
        check(ex_put_elem_var(exoid_, step_, static_cast<int>(k + 1), blockIds_[b],
                              static_cast<int>(blockCounts_[b]), element[k].data() + offset),
              "ex_put_elem_var");
      }
      offset += blockCounts_[b];
    }
  }
  // Flush every record, so a run that stops early leaves a readable file.
  check(ex_update(exoid_), "ex_update");
}

}  // namespace peridot
