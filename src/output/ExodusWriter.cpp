#include "output/ExodusWriter.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>

#include "core/Error.hpp"

namespace peridot {

namespace {

std::vector<char*> cstrings(std::vector<std::string>& names) {
  std::vector<char*> out;
  for (auto& n : names) out.push_back(n.data());
  return out;
}

const char* kVarType[3] = {"g", "n", "e"};

}  // namespace

std::string exodusReason() {
  // errno first: a failed open/create/write leaves the OS reason there, which says more than
  // the library's generic "failed to create file".
  const int osError = errno;
  const char* message = nullptr;
  const char* function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  std::string reason;
  if (osError != 0) reason = std::strerror(osError);
  if (message != nullptr && *message != '\0') {
    if (!reason.empty()) reason += "; ";
    reason += std::string("Exodus: ") + message;
  }
  return reason;
}

void ExodusWriter::check(int status, const std::string& what) const {
  if (status < 0) {
    const std::string reason = exodusReason();
    throw RunError("writing Exodus file \"" + fileName_ + "\" failed in " + what + " (code " +
                   std::to_string(status) + (reason.empty() ? "" : ": " + reason) + ")");
  }
}

ExodusWriter::ExodusWriter(const std::string& fileName, const ExodusHeader& h)
    : fileName_(fileName), dimension_(h.dimension == 2 ? 2 : 3), blockIds_(h.blockIds) {
  blockFirst_.assign(1, 0);
  for (long long c : h.blockCounts) blockFirst_.push_back(blockFirst_.back() + c);
  const long long n = h.numPoints;
  if (n > INT_MAX) throw RunError("more points than 32-bit Exodus ids can hold");
  int cpuWordSize = sizeof(double), ioWordSize = sizeof(double);
  errno = 0;
  exoid_ = ex_create(fileName.c_str(), EX_CLOBBER, &cpuWordSize, &ioWordSize);
  if (exoid_ < 0) {
    const std::string reason = exodusReason();
    throw RunError("cannot create Exodus file \"" + fileName + "\"" +
                   (reason.empty() ? "" : ": " + reason));
  }
  errno = 0;
  const bool planar = h.dimension == 2;
  check(ex_put_init(exoid_, "Peridot", planar ? 2 : 3, n, n,
                    static_cast<long long>(h.blockIds.size()),
                    static_cast<long long>(h.setNames.size()), 0),
        "ex_put_init");
  std::vector<std::string> coordNames = {"x", "y", "z"};
  if (planar) coordNames.pop_back();
  auto coordPtrs = cstrings(coordNames);
  check(ex_put_coord_names(exoid_, coordPtrs.data()), "ex_put_coord_names");
  for (std::size_t b = 0; b < h.blockIds.size(); ++b) {
    check(
        ex_put_block(exoid_, EX_ELEM_BLOCK, h.blockIds[b], "SPHERE", h.blockCounts[b], 1, 0, 0, 0),
        "ex_put_block");
  }
  std::vector<std::string> blockNames = h.blockNames;
  auto blockPtrs = cstrings(blockNames);
  if (!blockPtrs.empty())
    check(ex_put_names(exoid_, EX_ELEM_BLOCK, blockPtrs.data()), "ex_put_names");
  if (n > 0) {
    // Define the id maps here, where writing a whole map would: the file is then laid out as a
    // file written in one piece (byte for byte), and netCDF does not move bulk data to grow the
    // header later. The placeholder entry is overwritten by putMesh.
    const int placeholder = 0;
    check(ex_put_partial_id_map(exoid_, EX_NODE_MAP, 1, 1, &placeholder), "ex_put_partial_id_map");
    check(ex_put_partial_id_map(exoid_, EX_ELEM_MAP, 1, 1, &placeholder), "ex_put_partial_id_map");
  }
  std::vector<std::string> setNames;
  for (std::size_t s = 0; s < h.setNames.size(); ++s) {
    check(ex_put_set_param(exoid_, EX_NODE_SET, static_cast<int>(s + 1), h.setSizes[s], 0),
          "ex_put_set_param");
    setNames.push_back(h.setNames[s].substr(0, 32));
  }
  if (!setNames.empty()) {
    auto setPtrs = cstrings(setNames);
    check(ex_put_names(exoid_, EX_NODE_SET, setPtrs.data()), "ex_put_names(node sets)");
  }
  const std::vector<std::string>* names[3] = {&h.globalNames, &h.nodalNames, &h.elementNames};
  for (int k = 0; k < 3; ++k) {
    if (names[k]->empty()) continue;
    const int count = static_cast<int>(names[k]->size());
    check(ex_put_var_param(exoid_, kVarType[k], count), "ex_put_var_param");
    std::vector<std::string> copy = *names[k];
    auto ptrs = cstrings(copy);
    check(ex_put_var_names(exoid_, kVarType[k], count, ptrs.data()), "ex_put_var_names");
  }
  if (!h.elementNames.empty() && !blockIds_.empty()) {
    std::vector<int> truth(blockIds_.size() * h.elementNames.size(), 1);
    check(ex_put_elem_var_tab(exoid_, static_cast<int>(blockIds_.size()),
                              static_cast<int>(h.elementNames.size()), truth.data()),
          "ex_put_elem_var_tab");
  }
  check(ex_update(exoid_), "ex_update");
}

std::unique_ptr<ExodusWriter> ExodusWriter::resume(const std::string& fileName,
                                                   const ExodusHeader& h, double time,
                                                   std::string& whyNot) {
  int cpuWordSize = sizeof(double), ioWordSize = 0;
  float version = 0;
  errno = 0;
  const int exoid = ex_open(fileName.c_str(), EX_WRITE, &cpuWordSize, &ioWordSize, &version);
  if (exoid < 0) {
    whyNot = "cannot open it: " + exodusReason();
    return nullptr;
  }
  std::unique_ptr<ExodusWriter> w(new ExodusWriter());
  w->fileName_ = fileName;
  w->exoid_ = exoid;  // closed by the destructor if we give up
  w->dimension_ = h.dimension == 2 ? 2 : 3;
  w->blockIds_ = h.blockIds;
  w->blockFirst_.assign(1, 0);
  for (long long c : h.blockCounts) w->blockFirst_.push_back(w->blockFirst_.back() + c);

  // The file matches when a reader could not tell it from one this run would create.
  ex_init_params p{};
  if (ex_get_init_ext(exoid, &p) < 0) {
    whyNot = "cannot read its header: " + exodusReason();
    return nullptr;
  }
  auto differs = [&](const std::string& what, long long file, long long run) {
    if (file == run) return false;
    whyNot =
        what + " " + std::to_string(file) + " in the file, " + std::to_string(run) + " in this run";
    return true;
  };
  if (differs("dimension", p.num_dim, h.dimension) || differs("points", p.num_nodes, h.numPoints) ||
      differs("elements", p.num_elem, h.numPoints) ||
      differs("blocks", p.num_elem_blk, static_cast<long long>(h.blockIds.size())) ||
      differs("node sets", p.num_node_sets, static_cast<long long>(h.setNames.size())))
    return nullptr;
  std::vector<int> ids(h.blockIds.size());
  if (!ids.empty() && ex_get_ids(exoid, EX_ELEM_BLOCK, ids.data()) < 0) {
    whyNot = "cannot read its block ids: " + exodusReason();
    return nullptr;
  }
  if (ids != h.blockIds) {
    whyNot = "its block ids differ";
    return nullptr;
  }
  const std::vector<std::string>* names[3] = {&h.globalNames, &h.nodalNames, &h.elementNames};
  const char* kinds[3] = {"global", "nodal", "element"};
  const ex_entity_type types[3] = {EX_GLOBAL, EX_NODAL, EX_ELEM_BLOCK};
  for (int k = 0; k < 3; ++k) {
    int count = 0;
    if (ex_get_variable_param(exoid, types[k], &count) < 0) count = -1;
    std::vector<std::string> inFile;
    if (count > 0) {
      std::vector<std::vector<char>> buffers(count, std::vector<char>(MAX_STR_LENGTH + 1, '\0'));
      std::vector<char*> ptrs;
      for (auto& b : buffers) ptrs.push_back(b.data());
      if (ex_get_variable_names(exoid, types[k], count, ptrs.data()) < 0) count = -1;
      for (auto& b : buffers) inFile.emplace_back(b.data());
    }
    if (count < 0 || inFile != *names[k]) {
      whyNot = std::string("its ") + kinds[k] + " variables differ";
      return nullptr;
    }
  }
  // Keep the records up to `time` (records are in time order).
  const int numRecords = static_cast<int>(ex_inquire_int(exoid, EX_INQ_TIME));
  std::vector<double> times(static_cast<std::size_t>(std::max(numRecords, 0)));
  for (int s = 0; s < numRecords; ++s) {
    if (ex_get_time(exoid, s + 1, &times[s]) < 0) {
      whyNot = "cannot read its times: " + exodusReason();
      return nullptr;
    }
  }
  // The first record after `time` (a linear scan: records left over from an earlier resumed run
  // need not be in time order after that point).
  w->step_ = static_cast<int>(
      std::find_if(times.begin(), times.end(), [&](double t) { return t > time; }) - times.begin());
  return w;
}

ExodusWriter::~ExodusWriter() {
  if (exoid_ >= 0) ex_close(exoid_);
}

void ExodusWriter::putMesh(long long first, long long count, const long long* ids,
                           const double* xyz) {
  if (count <= 0) return;
  errno = 0;
  std::vector<int> ids32(ids, ids + count);
  check(ex_put_partial_id_map(exoid_, EX_NODE_MAP, first + 1, count, ids32.data()),
        "ex_put_partial_id_map(nodes)");
  check(ex_put_partial_id_map(exoid_, EX_ELEM_MAP, first + 1, count, ids32.data()),
        "ex_put_partial_id_map(elements)");
  std::vector<double> c[3];
  for (int d = 0; d < 3; ++d) {
    c[d].resize(static_cast<std::size_t>(count));
    for (long long k = 0; k < count; ++k) c[d][k] = xyz[3 * k + d];
  }
  check(ex_put_partial_coord(exoid_, first + 1, count, c[0].data(), c[1].data(),
                             dimension_ == 2 ? nullptr : c[2].data()),
        "ex_put_partial_coord");
  // Connectivity: element k of the file is node k (one-node SPHERE elements).
  for (std::size_t b = 0; b < blockIds_.size(); ++b) {
    const long long lo = std::max(first, blockFirst_[b]);
    const long long hi = std::min(first + count, blockFirst_[b + 1]);
    if (lo >= hi) continue;
    std::vector<int> conn(static_cast<std::size_t>(hi - lo));
    for (long long p = lo; p < hi; ++p) conn[p - lo] = static_cast<int>(p + 1);
    check(ex_put_partial_elem_conn(exoid_, blockIds_[b], lo - blockFirst_[b] + 1, hi - lo,
                                   conn.data()),
          "ex_put_partial_elem_conn");
  }
}

void ExodusWriter::putSet(int set, long long offset, long long count, const long long* positions) {
  if (count <= 0) return;
  errno = 0;
  std::vector<int> nodes(static_cast<std::size_t>(count));
  for (long long k = 0; k < count; ++k) nodes[k] = static_cast<int>(positions[k] + 1);
  check(ex_put_partial_set(exoid_, EX_NODE_SET, set + 1, offset + 1, count, nodes.data(), nullptr),
        "ex_put_partial_set");
}

void ExodusWriter::beginRecord(double time, const std::vector<double>& globals) {
  errno = 0;
  ++step_;
  check(ex_put_time(exoid_, step_, &time), "ex_put_time");
  if (!globals.empty()) {
    check(ex_put_glob_vars(exoid_, step_, static_cast<int>(globals.size()), globals.data()),
          "ex_put_glob_vars");
  }
}

void ExodusWriter::putNodal(int variable, long long first, long long count, const double* values) {
  if (count <= 0) return;
  errno = 0;  // so that a failure reports its own OS reason, not an older one
  check(ex_put_partial_nodal_var(exoid_, step_, variable + 1, first + 1, count, values),
        "ex_put_partial_nodal_var");
}

void ExodusWriter::putElement(int variable, long long first, long long count,
                              const double* values) {
  // A piece of positions may span blocks: one call per block part.
  errno = 0;
  for (std::size_t b = 0; b < blockIds_.size(); ++b) {
    const long long lo = std::max(first, blockFirst_[b]);
    const long long hi = std::min(first + count, blockFirst_[b + 1]);
    if (lo >= hi) continue;
    check(ex_put_partial_var(exoid_, step_, EX_ELEM_BLOCK, variable + 1, blockIds_[b],
                             lo - blockFirst_[b] + 1, hi - lo, values + (lo - first)),
          "ex_put_partial_var");
  }
}

void ExodusWriter::endRecord() {
  // Flush every record, so a run that stops early leaves a readable file.
  errno = 0;
  check(ex_update(exoid_), "ex_update");
}

}  // namespace peridot
