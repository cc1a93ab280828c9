#include "discretization/ExodusMeshReader.hpp"

#include <exodusII.h>
#include <netcdf.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <vector>

#include "core/Error.hpp"
#include "discretization/ElementGeometry.hpp"

namespace peridot {

namespace {

// Room for the longest name netCDF allows (NC_MAX_NAME) plus the terminator.
constexpr std::size_t kNameBufferSize = NC_MAX_NAME + 1;

// The number of bytes a classic-format netCDF file (CDF-1, CDF-2 or CDF-5, which is what Exodus
// writes) must have to hold all the data its header declares, or -1 for other formats (netCDF-4's
// HDF5 layer detects truncation itself) and headers this cannot follow. Needed because the netCDF
// library reads the missing tail of a truncated classic file as zeros, without an error.
class ClassicHeader {
 public:
  explicit ClassicHeader(const std::string& fileName) : in_(fileName, std::ios::binary) {}

  long long dataEnd() {
    char magic[4] = {0, 0, 0, 0};
    if (!in_.read(magic, 4) || magic[0] != 'C' || magic[1] != 'D' || magic[2] != 'F') return -1;
    const int version = magic[3];
    if (version != 1 && version != 2 && version != 5) return -1;
    sizeBytes_ = version == 5 ? 8 : 4;
    const int offsetBytes = version == 1 ? 4 : 8;
    const unsigned long long numRecords = read(sizeBytes_);
    const bool streaming = sizeBytes_ == 4 && numRecords == 0xFFFFFFFFull;

    std::vector<unsigned long long> dimLength;
    unsigned long long count = listLength(kDimensionTag);
    for (unsigned long long d = 0; d < count && ok_; ++d) {
      skipName();
      dimLength.push_back(read(sizeBytes_));
    }
    skipAttributes();
    count = listLength(kVariableTag);
    long long end = 0;
    unsigned long long recordSize = 0;
    std::vector<std::pair<unsigned long long, unsigned long long>> records;  // begin, size
    for (unsigned long long v = 0; v < count && ok_; ++v) {
      skipName();
      const unsigned long long numDims = read(sizeBytes_);
      if (numDims > 1024) return -1;
      bool isRecord = false;
      unsigned long long size = 1;
      for (unsigned long long d = 0; d < numDims && ok_; ++d) {
        const unsigned long long dim = read(sizeBytes_);
        if (dim >= dimLength.size()) return -1;
        if (d == 0 && dimLength[dim] == 0) {
          isRecord = true;
        } else {
          size *= dimLength[dim];
        }
      }
      skipAttributes();
      size *= typeSize(static_cast<int>(read(4)));
      read(sizeBytes_);  // vsize: recomputed above, the stored one saturates for huge variables
      const unsigned long long begin = read(offsetBytes);
      if (isRecord) {
        records.emplace_back(begin, size);
        recordSize += (size + 3) / 4 * 4;
      } else {
        end = std::max(end, static_cast<long long>(begin + size));
      }
    }
    if (!ok_) return -1;
    if (records.size() == 1) recordSize = records[0].second;  // a lone record variable: no padding
    if (!streaming && numRecords > 0) {
      for (const auto& [begin, size] : records) {
        end = std::max(end, static_cast<long long>(begin + (numRecords - 1) * recordSize + size));
      }
    }
    return end;
  }

 private:
  static constexpr unsigned long long kDimensionTag = 0x0A;
  static constexpr unsigned long long kVariableTag = 0x0B;
  static constexpr unsigned long long kAttributeTag = 0x0C;

  static unsigned long long typeSize(int type) {
    switch (type) {
      case NC_BYTE:
      case NC_CHAR:
      case NC_UBYTE:
        return 1;
      case NC_SHORT:
      case NC_USHORT:
        return 2;
      case NC_INT:
      case NC_FLOAT:
      case NC_UINT:
        return 4;
      default:
        return 8;
    }
  }

  // Big-endian unsigned integer of the given width; clears ok_ at the end of the file.
  unsigned long long read(int bytes) {
    unsigned char buffer[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    if (!ok_ || !in_.read(reinterpret_cast<char*>(buffer), bytes)) {
      ok_ = false;
      return 0;
    }
    unsigned long long value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | buffer[i];
    return value;
  }
  void skip(unsigned long long bytes) {
    if (ok_ && !in_.seekg(static_cast<std::streamoff>((bytes + 3) / 4 * 4), std::ios::cur)) {
      ok_ = false;
    }
  }
  void skipName() { skip(read(sizeBytes_)); }
  // Element count of a tagged list (0 for an absent one); clears ok_ on an unexpected tag.
  unsigned long long listLength(unsigned long long tag) {
    const unsigned long long found = read(4);
    const unsigned long long count = read(sizeBytes_);
    if (found != tag && !(found == 0 && count == 0)) ok_ = false;
    return ok_ ? count : 0;
  }
  void skipAttributes() {
    const unsigned long long count = listLength(kAttributeTag);
    for (unsigned long long a = 0; a < count && ok_; ++a) {
      skipName();
      const int type = static_cast<int>(read(4));
      skip(read(sizeBytes_) * typeSize(type));
    }
  }

  std::ifstream in_;
  int sizeBytes_ = 4;
  bool ok_ = true;
};

// Why fileName cannot be read as an Exodus file, or "" when it looks fine.
std::string openProblem(const std::string& fileName) {
  std::error_code ec;
  if (std::filesystem::is_directory(fileName, ec)) return "it is a directory";
  std::FILE* f = std::fopen(fileName.c_str(), "rb");
  if (f == nullptr) return std::strerror(errno);
  std::fclose(f);
  int ncid = -1;
  const int status = nc_open(fileName.c_str(), NC_NOWRITE, &ncid);
  if (status != NC_NOERR) {
    return std::string("not a readable Exodus (netCDF) file, or a truncated or corrupt one (") +
           nc_strerror(status) + ")";
  }
  nc_close(ncid);
  const long long needed = ClassicHeader(fileName).dataEnd();
  const auto size = std::filesystem::file_size(fileName, ec);
  if (!ec && needed > 0 && static_cast<long long>(size) < needed) {
    return "the file is truncated (" + std::to_string(size) + " bytes where its header needs " +
           std::to_string(needed) + ")";
  }
  return "";
}

std::string trimmed(const char* text) {
  std::string s(text);
  const auto notSpace = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), notSpace));
  s.erase(std::find_if(s.rbegin(), s.rend(), notSpace).base(), s.end());
  return s;
}

std::string upperTrimmed(const char* text) {
  std::string s = trimmed(text);
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

enum class ElementKind { Hex, Tet, Sphere, Quad, Tri, Unsupported };

bool isPlanar(ElementKind kind) { return kind == ElementKind::Quad || kind == ElementKind::Tri; }

ElementKind classify(const std::string& topology, long long nodesPerElement) {
  // Exodus names planar quads QUAD/QUAD4/QUAD8/QUAD9 (SHELL4 etc. when written by a 3D mesher)
  // and triangles TRI/TRI3/TRI6/TRI7/TRIANGLE (TRISHELL for shells); higher-order elements are
  // read through their corner nodes, which come first.
  if (topology.rfind("QUAD", 0) == 0 || topology.rfind("SHELL", 0) == 0) {
    if (nodesPerElement == 4 || nodesPerElement == 8 || nodesPerElement == 9) {
      return ElementKind::Quad;
    }
  } else if (topology.rfind("TRI", 0) == 0) {
    if (nodesPerElement == 3 || nodesPerElement == 6 || nodesPerElement == 7) {
      return ElementKind::Tri;
    }
  } else if (topology.rfind("HEX", 0) == 0) {
    if (nodesPerElement == 8 || nodesPerElement == 20 || nodesPerElement == 27) {
      return ElementKind::Hex;
    }
  } else if (topology.rfind("TET", 0) == 0) {
    if (nodesPerElement == 4 || nodesPerElement == 10) return ElementKind::Tet;
  } else if (topology == "SPHERE") {
    if (nodesPerElement == 1) return ElementKind::Sphere;
  }
  return ElementKind::Unsupported;
}

class MeshReader {
 public:
  MeshReader(const std::string& fileName, const std::string& deckPath, double thickness)
      : fileName_(fileName),
        deckPath_(deckPath),
        thickness_(thickness),
        file_(fileName, "mesh", deckPath) {}

  PointCloud read();

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(deckPath_, "Exodus mesh \"" + fileName_ + "\": " + message);
  }
  void check(int status, const char* call) const {
    if (status < 0) {
      fail(std::string(call) + " failed (" + exodusLastError() +
           "); the file may be truncated or corrupt");
    }
  }
  std::vector<std::string> names(ex_entity_type type, std::size_t count) const;

  struct Block {
    long long id = 0;
    long long numElements = 0;
    long long nodesPerElement = 0;
    std::vector<int64_t> connectivity;  // 1-based node indices
  };

  std::string fileName_;
  std::string deckPath_;
  double thickness_ = 1.0;
  ExodusInputFile file_;
};

std::vector<std::string> MeshReader::names(ex_entity_type type, std::size_t count) const {
  std::vector<std::string> result(count);
  if (count == 0) return result;
  std::vector<std::vector<char>> buffers(count, std::vector<char>(kNameBufferSize, '\0'));
  std::vector<char*> pointers(count);
  for (std::size_t i = 0; i < count; ++i) pointers[i] = buffers[i].data();
  check(ex_get_names(file_.id(), type, pointers.data()), "ex_get_names");
  for (std::size_t i = 0; i < count; ++i) {
    buffers[i].back() = '\0';
    result[i] = trimmed(buffers[i].data());
  }
  return result;
}

PointCloud MeshReader::read() {
  const int exoid = file_.id();
  ex_init_params init{};
  check(ex_get_init_ext(exoid, &init), "ex_get_init_ext");
  if (init.num_dim != 2 && init.num_dim != 3) {
    fail("the mesh is " + std::to_string(init.num_dim) +
         "-dimensional; only 2D and 3D meshes are supported");
  }
  if (init.num_elem <= 0) fail("the mesh has no elements");
  if (init.num_nodes <= 0) fail("the mesh has no nodes");
  if (init.num_elem_blk <= 0) fail("the mesh has no element blocks");
  const auto numNodes = static_cast<std::size_t>(init.num_nodes);
  const auto numElements = static_cast<std::size_t>(init.num_elem);

  std::vector<double> coord[3];
  for (auto& c : coord) c.assign(numNodes, 0.0);
  // A 2D file has no z coordinates: they stay 0.
  check(ex_get_coord(exoid, coord[0].data(), coord[1].data(),
                     init.num_dim == 3 ? coord[2].data() : nullptr),
        "ex_get_coord");
  for (const auto& c : coord) {
    for (double v : c) {
      if (!std::isfinite(v)) fail("the node coordinates contain a non-finite value");
    }
  }

  std::vector<int64_t> elementIds(numElements);
  check(ex_get_id_map(exoid, EX_ELEM_MAP, elementIds.data()), "ex_get_id_map");
  {
    std::vector<int64_t> sorted(elementIds);
    std::sort(sorted.begin(), sorted.end());
    if (sorted.front() < 1) {
      fail("the element number map contains the id " + std::to_string(sorted.front()) +
           "; element ids must be positive");
    }
    const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
    if (dup != sorted.end()) {
      fail("the element number map contains the id " + std::to_string(*dup) + " twice");
    }
  }

  PointCloud cloud;
  cloud.dimension = init.num_dim == 2 ? 2 : 3;
  cloud.thickness = thickness_;
  // The first non-empty block of each kind, to name both when a mesh mixes planar and solid ones.
  std::string firstPlanar, firstSolid;
  cloud.x.reserve(3 * numElements);
  cloud.volume.reserve(numElements);
  cloud.blockId.reserve(numElements);
  cloud.globalId.reserve(numElements);

  const auto numBlocks = static_cast<std::size_t>(init.num_elem_blk);
  std::vector<int64_t> blockIds(numBlocks);
  check(ex_get_ids(exoid, EX_ELEM_BLOCK, blockIds.data()), "ex_get_ids");
  const std::vector<std::string> blockNames = names(EX_ELEM_BLOCK, numBlocks);
  std::map<std::string, long long> blockOfName;

  std::vector<Block> blocks(numBlocks);
  std::size_t element = 0;  // index of the element in file order
  for (std::size_t b = 0; b < numBlocks; ++b) {
    Block& block = blocks[b];
    block.id = blockIds[b];
    const std::string blockLabel = "element block " + std::to_string(block.id);
    if (block.id < std::numeric_limits<int>::min() || block.id > std::numeric_limits<int>::max()) {
      fail(blockLabel + ": the block id does not fit in an int");
    }
    if (cloud.blockNames.count(static_cast<int>(block.id)) != 0) {
      fail("two element blocks have the id " + std::to_string(block.id));
    }
    const std::string name =
        blockNames[b].empty() ? "block_" + std::to_string(block.id) : blockNames[b];
    const auto [it, inserted] = blockOfName.emplace(name, block.id);
    if (!inserted) {
      fail("element blocks " + std::to_string(it->second) + " and " + std::to_string(block.id) +
           " are both named \"" + name + "\"");
    }
    cloud.blockNames[static_cast<int>(block.id)] = name;

    ex_block param{};
    param.id = block.id;
    param.type = EX_ELEM_BLOCK;
    check(ex_get_block_param(exoid, &param), "ex_get_block_param");
    block.numElements = param.num_entry;
    block.nodesPerElement = param.num_nodes_per_entry;
    if (block.numElements < 0 || block.nodesPerElement < 0 || param.num_attribute < 0 ||
        element + static_cast<std::size_t>(block.numElements) > numElements) {
      fail(blockLabel + ": inconsistent element counts; the file may be corrupt");
    }
    if (block.numElements == 0) continue;  // an empty block: nothing to read, any topology

    const std::string topology = upperTrimmed(param.topology);
    const ElementKind kind = classify(topology, block.nodesPerElement);
    if (kind == ElementKind::Unsupported) {
      fail(blockLabel + " (\"" + name + "\") has element type \"" + topology + "\" with " +
           std::to_string(block.nodesPerElement) +
           " nodes per element, which is not supported yet (supported: HEX8, HEX20, HEX27, "
           "TET4, TET10, SPHERE in 3D; QUAD4, QUAD8, QUAD9, SHELL4, TRI3, TRI6 in 2D)");
    }
    const std::string described = blockLabel + " (\"" + name + "\", " + topology + ")";
    if (isPlanar(kind)) {
      if (firstPlanar.empty()) firstPlanar = described;
      if (firstPlanar == described && init.num_dim == 3) {
        // A planar mesh written with three coordinates: it must lie in z = 0.
        for (std::size_t n = 0; n < numNodes; ++n) {
          if (coord[2][n] != 0.0) {
            fail(described + " is a planar element block, but node " + std::to_string(n + 1) +
                 " has z = " + std::to_string(coord[2][n]) +
                 "; a 2D mesh must lie in the plane z = 0 (or be written with num_dim = 2)");
          }
        }
      }
      cloud.dimension = 2;
    } else {
      if (firstSolid.empty()) firstSolid = described;
      if (init.num_dim == 2) {
        fail(described +
             " is a 3D element block in a 2D mesh (num_dim = 2); 2D meshes take "
             "QUAD and TRI elements");
      }
    }
    if (!firstPlanar.empty() && !firstSolid.empty()) {
      fail("the mesh mixes 2D and 3D element blocks: " + firstPlanar + " and " + firstSolid +
           "; a run is either planar or 3D");
    }

    block.connectivity.resize(static_cast<std::size_t>(block.numElements * block.nodesPerElement));
    check(ex_get_conn(exoid, EX_ELEM_BLOCK, block.id, block.connectivity.data(), nullptr, nullptr),
          "ex_get_conn");
    for (int64_t node : block.connectivity) {
      if (node < 1 || node > init.num_nodes) {
        fail(blockLabel + ": the connectivity refers to node " + std::to_string(node) +
             ", outside 1.." + std::to_string(init.num_nodes) +
             "; the file may be truncated or corrupt");
      }
    }

    std::vector<double> attributes;
    if (kind == ElementKind::Sphere) {
      if (param.num_attribute < 2) {
        fail(blockLabel + " (\"" + name + "\") is a SPHERE block with " +
             std::to_string(param.num_attribute) +
             " attribute(s); the sphere volume is read from the second attribute");
      }
      attributes.resize(static_cast<std::size_t>(block.numElements * param.num_attribute));
      check(ex_get_attr(exoid, EX_ELEM_BLOCK, block.id, attributes.data()), "ex_get_attr");
    }

    const auto npe = static_cast<std::size_t>(block.nodesPerElement);
    for (long long e = 0; e < block.numElements; ++e, ++element) {
      const int64_t* conn = block.connectivity.data() + static_cast<std::size_t>(e) * npe;
      double position[3] = {0.0, 0.0, 0.0};
      double volume = 0.0;
      if (kind == ElementKind::Hex) {
        double nodes[8][3];
        for (int a = 0; a < 8; ++a) {
          for (int k = 0; k < 3; ++k) nodes[a][k] = coord[k][static_cast<std::size_t>(conn[a] - 1)];
        }
        // Peridigm places the point at the plain average of the corner nodes, not at the
        // volume-weighted centroid (they differ for non-affine hexes); the golds need that. The
        // volume is the exact trilinear one, taken unsigned so a mirrored node order is accepted.
        hexNodeAverage(nodes, position);
        volume = std::fabs(hexVolume(nodes));
      } else if (kind == ElementKind::Tet) {
        double nodes[4][3];
        for (int a = 0; a < 4; ++a) {
          for (int k = 0; k < 3; ++k) nodes[a][k] = coord[k][static_cast<std::size_t>(conn[a] - 1)];
        }
        tetCentroid(nodes, position);
        volume = tetVolume(nodes);
      } else if (kind == ElementKind::Quad) {
        double nodes[4][2];
        for (int a = 0; a < 4; ++a) {
          for (int k = 0; k < 2; ++k) nodes[a][k] = coord[k][static_cast<std::size_t>(conn[a] - 1)];
        }
        // As for hexes: the corner mean, the exact area, either orientation; but a bow tie or a
        // re-entrant quad has no meaningful area (its bilinear map folds over).
        if (!quadIsValid(nodes) && quadArea(nodes) != 0.0) {
          fail(blockLabel + ", element " + std::to_string(elementIds[element]) +
               ": the quadrilateral is self-intersecting or not convex (inverted element)");
        }
        quadNodeAverage(nodes, position);
        volume = std::fabs(quadArea(nodes)) * thickness_;
      } else if (kind == ElementKind::Tri) {
        double nodes[3][2];
        for (int a = 0; a < 3; ++a) {
          for (int k = 0; k < 2; ++k) nodes[a][k] = coord[k][static_cast<std::size_t>(conn[a] - 1)];
        }
        triCentroid(nodes, position);
        volume = std::fabs(triArea(nodes)) * thickness_;
      } else {
        for (int k = 0; k < 3; ++k) position[k] = coord[k][static_cast<std::size_t>(conn[0] - 1)];
        volume = attributes[static_cast<std::size_t>(e * param.num_attribute + 1)];
      }
      const int64_t id = elementIds[element];
      if (!(volume > 0.0) || !std::isfinite(volume)) {
        fail(blockLabel + ", element " + std::to_string(id) + ": the element " +
             (isPlanar(kind) ? "area x thickness" : "volume") + " is " + std::to_string(volume) +
             (kind == ElementKind::Sphere ? " (second attribute)" : "") +
             "; it must be positive (degenerate element?)");
      }
      cloud.x.insert(cloud.x.end(), position, position + 3);
      cloud.volume.push_back(volume);
      cloud.blockId.push_back(static_cast<int>(block.id));
      cloud.globalId.push_back(static_cast<long long>(id) - 1);
    }
  }
  if (element != numElements) {
    fail("the element blocks hold " + std::to_string(element) + " elements but the file declares " +
         std::to_string(numElements));
  }

  if (init.num_node_sets > 0) {
    // Node -> elements incidence (all nodes of each element, corner or not), compressed.
    std::vector<std::size_t> start(numNodes + 1, 0);
    for (const Block& block : blocks) {
      for (int64_t node : block.connectivity) ++start[static_cast<std::size_t>(node)];
    }
    for (std::size_t n = 0; n < numNodes; ++n) start[n + 1] += start[n];
    std::vector<long long> incident(start[numNodes]);
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    std::size_t first = 0;  // file index of the block's first element
    for (const Block& block : blocks) {
      const auto npe = static_cast<std::size_t>(block.nodesPerElement);
      for (std::size_t i = 0; i < block.connectivity.size(); ++i) {
        const auto node = static_cast<std::size_t>(block.connectivity[i] - 1);
        incident[fill[node]++] = static_cast<long long>(elementIds[first + i / npe]) - 1;
      }
      first += static_cast<std::size_t>(block.numElements);
    }

    const auto numSets = static_cast<std::size_t>(init.num_node_sets);
    std::vector<int64_t> setIds(numSets);
    check(ex_get_ids(exoid, EX_NODE_SET, setIds.data()), "ex_get_ids");
    const std::vector<std::string> setNames = names(EX_NODE_SET, numSets);
    std::map<std::string, long long> setOfName;
    for (std::size_t s = 0; s < numSets; ++s) {
      PointSet set;
      set.name = setNames[s].empty() ? "nodelist_" + std::to_string(setIds[s]) : setNames[s];
      const auto [it, inserted] = setOfName.emplace(set.name, setIds[s]);
      if (!inserted) {
        fail("node sets " + std::to_string(it->second) + " and " + std::to_string(setIds[s]) +
             " are both named \"" + set.name + "\"");
      }
      int64_t numEntries = 0;
      int64_t numFactors = 0;
      check(ex_get_set_param(exoid, EX_NODE_SET, setIds[s], &numEntries, &numFactors),
            "ex_get_set_param");
      if (numEntries < 0) fail("node set " + std::to_string(setIds[s]) + ": negative size");
      std::vector<int64_t> nodes(static_cast<std::size_t>(numEntries));
      if (numEntries > 0) {
        check(ex_get_set(exoid, EX_NODE_SET, setIds[s], nodes.data(), nullptr), "ex_get_set");
      }
      for (int64_t node : nodes) {
        if (node < 1 || node > init.num_nodes) {
          fail("node set " + std::to_string(setIds[s]) + " (\"" + set.name + "\") refers to node " +
               std::to_string(node) + ", outside 1.." + std::to_string(init.num_nodes) +
               "; the file may be truncated or corrupt");
        }
        const auto n = static_cast<std::size_t>(node - 1);
        set.globalIds.insert(set.globalIds.end(), incident.begin() + start[n],
                             incident.begin() + start[n + 1]);
      }
      std::sort(set.globalIds.begin(), set.globalIds.end());
      set.globalIds.erase(std::unique(set.globalIds.begin(), set.globalIds.end()),
                          set.globalIds.end());
      cloud.pointSets.push_back(std::move(set));
    }
  }
  return cloud;
}

}  // namespace

std::string exodusLastError() {
  const char* message = nullptr;
  const char* function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  std::string text = message != nullptr ? message : "";
  if (function != nullptr && *function != '\0') text = std::string(function) + ": " + text;
  // Codes beyond +-1000 are the Exodus library's own; the others are netCDF or errno codes.
  if (code != 0 && code > -1000 && code < 1000) {
    text += std::string(text.empty() ? "" : "; ") + nc_strerror(code);
  }
  return text.empty() ? "(no details)" : text;
}

ExodusInputFile::ExodusInputFile(const std::string& fileName, const std::string& kind,
                                 const std::string& deckPath) {
  const auto failOpen = [&](const std::string& reason) {
    throw InputError(deckPath, "cannot open Exodus " + kind + " \"" + fileName + "\": " + reason);
  };
  const std::string problem = openProblem(fileName);
  if (!problem.empty()) failOpen(problem);
  int cpuWordSize = sizeof(double);
  int ioWordSize = 0;
  float version = 0.0f;
  id_ = ex_open(fileName.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version);
  if (id_ < 0) {
    // A netCDF signature with a header that does not read is almost always a cut-off file.
    std::ifstream in(fileName, std::ios::binary);
    char magic[3] = {0, 0, 0};
    in.read(magic, 3);
    if (in && magic[0] == 'C' && magic[1] == 'D' && magic[2] == 'F') {
      failOpen("the file is truncated or damaged: its netCDF header cannot be read (" +
               exodusLastError() + ")");
    }
    failOpen("not a readable Exodus file (" + exodusLastError() + ")");
  }
  ex_set_int64_status(id_, EX_ALL_INT64_API);
  // Read names as long as the file stores them (the library default is 32 characters).
  const int64_t longestName = ex_inquire_int(id_, EX_INQ_DB_MAX_USED_NAME_LENGTH);
  if (longestName > 32 && longestName < static_cast<int64_t>(kNameBufferSize)) {
    ex_set_max_name_length(id_, static_cast<int>(longestName));
  }
}

ExodusInputFile::~ExodusInputFile() {
  if (id_ >= 0) ex_close(id_);
}

PointCloud readExodusMesh(const std::string& fileName, const std::string& deckPath,
                          double thickness) {
  MeshReader reader(fileName, deckPath, thickness);
  return reader.read();
}

}  // namespace peridot
