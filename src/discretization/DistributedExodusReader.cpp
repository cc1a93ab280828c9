#include "discretization/DistributedExodusReader.hpp"

#include <exodusII.h>
#include <netcdf.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <vector>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "discretization/ElementGeometry.hpp"
#include "discretization/ExodusMeshReader.hpp"
#include "discretization/NodeSetExchange.hpp"
#include "discretization/Slicing.hpp"

namespace peridot {

namespace {

// Room for the longest name netCDF allows (NC_MAX_NAME) plus the terminator.
constexpr std::size_t kNameBufferSize = NC_MAX_NAME + 1;

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

// Where in the serial read's order a problem is met: (major, stage, minor) compared in that
// order. major is the block index (numBlocks for the element count, numBlocks + 1 + s for node
// set s); stage the step within the block; minor the element (or node, or set entry) index.
struct Key {
  long long major = LLONG_MAX, stage = 0, minor = 0;
  bool operator<(const Key& o) const {
    if (major != o.major) return major < o.major;
    if (stage != o.stage) return stage < o.stage;
    return minor < o.minor;
  }
  bool operator==(const Key& o) const { return !(*this < o) && !(o < *this); }
};

// A problem found locally, thrown within a step and settled collectively after it.
struct Failure {
  Key key;
  std::string message;  // the full InputError text
};

// Stages within a block, in the order the serial read checks them.
enum Stage : long long {
  kBlockHeader = 0,  // ids, names, counts, element type
  kPlanarZ = 1,      // the first planar block of a num_dim = 3 file: every z = 0
  kDimension = 2,    // solid block in a 2D file, planar and solid blocks mixed
  kConnectivity = 3,
  kAttributes = 4,  // SPHERE blocks need two attributes
  kElement = 5,     // geometry of each element
};

class ShareReader {
 public:
  ShareReader(const std::string& fileName, const std::string& deckPath, double thickness,
              MPI_Comm comm)
      : fileName_(fileName), deckPath_(deckPath), thickness_(thickness), comm_(comm) {
    MPI_Comm_rank(comm, &rank_);
    MPI_Comm_size(comm, &size_);
  }

  PointCloud read();

 private:
  struct Block {
    long long id = 0, numElements = 0, nodesPerElement = 0, numAttributes = 0;
    long long first = 0;  // file index of the block's first element
    ElementKind kind = ElementKind::Unsupported;
    std::string label;      // "element block <id>"
    std::string described;  // with its name and type, for the planar z check
  };
  // This rank's elements of one block: [begin, end) as file element indices.
  struct Chunk {
    std::size_t block = 0;
    long long begin = 0, end = 0;
    std::vector<int64_t> connectivity;  // 1-based nodes, nodesPerElement per element
    std::vector<double> attributes;     // SPHERE blocks: numAttributes per element
  };

  [[noreturn]] void fail(const Key& key, const std::string& message) const {
    throw Failure{key,
                  InputError(deckPath_, "Exodus mesh \"" + fileName_ + "\": " + message).what()};
  }
  void check(int status, const char* call, const Key& key) const {
    if (status < 0) {
      fail(key, std::string(call) + " failed (" + exodusLastError() +
                    "); the file may be truncated or corrupt");
    }
  }
  // Keeps the earliest problem met on this rank.
  void note(const Failure& f) {
    if (f.key < first_.key) first_ = f;
  }
  // Collective: throws on every rank the earliest problem met on any rank, if any.
  void settle();
  std::vector<std::string> names(ex_entity_type type, std::size_t count, const Key& key) const;

  void readHeader();
  void readCoordinates();
  void readElementIds();
  void readBlocks(PointCloud& cloud);
  void checkPlanarZ();
  void readChunks();
  void fetchNodes();
  void buildPoints(PointCloud& cloud);
  void readNodeSets(PointCloud& cloud);

  std::string fileName_, deckPath_;
  double thickness_ = 1.0;
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
  std::unique_ptr<ExodusInputFile> file_;
  int exoid_ = -1;
  ex_init_params init_{};
  Slicing nodes_, elements_;
  std::vector<double> coord_[3];  // of this rank's node slice
  std::vector<int64_t> ids_;      // element ids of this rank's element slice
  std::vector<Block> blocks_;
  std::size_t blocksRead_ = 0;  // blocks whose elements are read (before any header problem)
  long long zCheckBlock_ = -1;  // the block whose planar z check applies, or -1
  bool connOnlyBlock_ = false;  // blocks_[blocksRead_]: read the connectivity, then stop
  std::vector<Chunk> chunks_;
  std::vector<int64_t> needed_;      // sorted unique nodes of this rank's elements
  std::vector<double> neededCoord_;  // 3 per needed node
  std::vector<int64_t> requests_;    // nodes other ranks asked this rank about, by rank
  std::vector<int> requestCounts_;   // per rank
  Failure first_;
};

void ShareReader::settle() {
  const long long mine[3] = {first_.key.major, first_.key.stage, first_.key.minor};
  std::vector<long long> all(3 * static_cast<std::size_t>(size_));
  MPI_Allgather(mine, 3, MPI_LONG_LONG, all.data(), 3, MPI_LONG_LONG, comm_);
  Key earliest;
  for (int r = 0; r < size_; ++r) {
    const Key k{all[3 * r], all[3 * r + 1], all[3 * r + 2]};
    if (k < earliest) earliest = k;
  }
  if (earliest.major == LLONG_MAX) return;
  throwIfAnyRank(first_.key == earliest ? first_.message : std::string(), comm_);
}

std::vector<std::string> ShareReader::names(ex_entity_type type, std::size_t count,
                                            const Key& key) const {
  std::vector<std::string> result(count);
  if (count == 0) return result;
  std::vector<std::vector<char>> buffers(count, std::vector<char>(kNameBufferSize, '\0'));
  std::vector<char*> pointers(count);
  for (std::size_t i = 0; i < count; ++i) pointers[i] = buffers[i].data();
  check(ex_get_names(exoid_, type, pointers.data()), "ex_get_names", key);
  for (std::size_t i = 0; i < count; ++i) {
    buffers[i].back() = '\0';
    result[i] = trimmed(buffers[i].data());
  }
  return result;
}

PointCloud ShareReader::read() {
  {
    std::string problem;
    try {
      file_ = std::make_unique<ExodusInputFile>(fileName_, "mesh", deckPath_);
      exoid_ = file_->id();
    } catch (const InputError& e) {
      problem = e.what();
    }
    throwIfAnyRank(problem, comm_);
  }
  // Each step notes what it finds and the ranks settle before the next step needs its result.
  const auto step = [&](auto&& body) {
    try {
      body();
    } catch (const Failure& f) {
      note(f);
    }
  };
  step([&] { readHeader(); });
  settle();
  nodes_ = Slicing{init_.num_nodes, size_};
  elements_ = Slicing{init_.num_elem, size_};
  step([&] { readCoordinates(); });
  settle();
  step([&] { readElementIds(); });
  settle();
  PointCloud cloud;
  cloud.dimension = init_.num_dim == 2 ? 2 : 3;
  cloud.thickness = thickness_;
  cloud.globalNumPoints = init_.num_elem;
  step([&] { readBlocks(cloud); });
  step([&] { checkPlanarZ(); });
  step([&] { readChunks(); });
  fetchNodes();  // collective: every rank takes part, whatever it found
  for (auto& c : coord_) c = std::vector<double>();  // the node slice has been served
  step([&] { buildPoints(cloud); });
  settle();
  if (init_.num_node_sets > 0) readNodeSets(cloud);
  return cloud;
}

void ShareReader::readHeader() {
  const Key key{-1, 0, 0};
  check(ex_get_init_ext(exoid_, &init_), "ex_get_init_ext", key);
  if (init_.num_dim != 2 && init_.num_dim != 3) {
    fail(key, "the mesh is " + std::to_string(init_.num_dim) +
                  "-dimensional; only 2D and 3D meshes are supported");
  }
  if (init_.num_elem <= 0) fail(key, "the mesh has no elements");
  if (init_.num_nodes <= 0) fail(key, "the mesh has no nodes");
  if (init_.num_elem_blk <= 0) fail(key, "the mesh has no element blocks");
}

void ShareReader::readCoordinates() {
  const Key key{-1, 1, 0};
  const long long begin = nodes_.begin(rank_), count = nodes_.begin(rank_ + 1) - begin;
  for (auto& c : coord_) c.assign(static_cast<std::size_t>(count), 0.0);
  if (count == 0) return;
  // A 2D file has no z coordinates: they stay 0.
  check(ex_get_partial_coord(exoid_, begin + 1, count, coord_[0].data(), coord_[1].data(),
                             init_.num_dim == 3 ? coord_[2].data() : nullptr),
        "ex_get_partial_coord", key);
  for (const auto& c : coord_) {
    for (double v : c) {
      if (!std::isfinite(v)) fail(key, "the node coordinates contain a non-finite value");
    }
  }
}

void ShareReader::readElementIds() {
  const Key key{-1, 2, 0};
  const long long begin = elements_.begin(rank_), count = elements_.begin(rank_ + 1) - begin;
  ids_.assign(static_cast<std::size_t>(count), 0);
  try {
    // Without a number map the library numbers the elements 1..n, as ex_get_id_map does.
    if (count > 0) {
      check(ex_get_partial_id_map(exoid_, EX_ELEM_MAP, begin + 1, count, ids_.data()),
            "ex_get_partial_id_map", key);
    }
  } catch (const Failure& f) {
    note(f);
  }
  settle();  // before the collective checks below
  long long lowest = LLONG_MAX;
  for (int64_t id : ids_) lowest = std::min<long long>(lowest, id);
  MPI_Allreduce(MPI_IN_PLACE, &lowest, 1, MPI_LONG_LONG, MPI_MIN, comm_);
  if (lowest < 1) {
    fail(key, "the element number map contains the id " + std::to_string(lowest) +
                  "; element ids must be positive");
  }
  // Duplicates meet at one rank, chosen by a multiplicative hash of the id so that ids with a
  // stride (all even, say) still spread evenly.
  const auto meet = [&](int64_t id) {
    return static_cast<std::size_t>((static_cast<uint64_t>(id) * 0x9E3779B97F4A7C15ull >> 32) %
                                    static_cast<uint64_t>(size_));
  };
  std::vector<int> counts(static_cast<std::size_t>(size_), 0), recvCounts;
  for (int64_t id : ids_) ++counts[meet(id)];
  std::vector<int64_t> send(ids_.size());
  {
    std::vector<int> fill(static_cast<std::size_t>(size_), 0);
    for (int r = 1; r < size_; ++r) fill[r] = fill[r - 1] + counts[r - 1];
    for (int64_t id : ids_) send[static_cast<std::size_t>(fill[meet(id)]++)] = id;
  }
  std::vector<int64_t> mine = exchange(send, counts, recvCounts, comm_);
  send = std::vector<int64_t>();
  std::sort(mine.begin(), mine.end());
  const auto dup = std::adjacent_find(mine.begin(), mine.end());
  long long duplicate = dup != mine.end() ? *dup : LLONG_MAX;
  MPI_Allreduce(MPI_IN_PLACE, &duplicate, 1, MPI_LONG_LONG, MPI_MIN, comm_);
  if (duplicate != LLONG_MAX) {
    fail(key, "the element number map contains the id " + std::to_string(duplicate) + " twice");
  }
}

// Every rank reads every block's header (O(blocks)) and stops at the first bad one, which the
// serial read would report once it has read the blocks before it.
void ShareReader::readBlocks(PointCloud& cloud) {
  const auto numBlocks = static_cast<std::size_t>(init_.num_elem_blk);
  const Key listKey{0, kBlockHeader, 0};
  std::vector<int64_t> blockIds(numBlocks);
  check(ex_get_ids(exoid_, EX_ELEM_BLOCK, blockIds.data()), "ex_get_ids", listKey);
  const std::vector<std::string> blockNames = names(EX_ELEM_BLOCK, numBlocks, listKey);
  std::map<std::string, long long> blockOfName;
  // The first non-empty block of each kind, to name both when a mesh mixes planar and solid ones.
  std::string firstPlanar, firstSolid;
  long long element = 0;
  for (std::size_t b = 0; b < numBlocks; ++b, blocksRead_ = b) {
    const auto key = [&](long long stage) { return Key{static_cast<long long>(b), stage, 0}; };
    blocks_.emplace_back();
    Block& block = blocks_.back();
    block.id = blockIds[b];
    block.first = element;
    block.label = "element block " + std::to_string(block.id);
    if (block.id < std::numeric_limits<int>::min() || block.id > std::numeric_limits<int>::max()) {
      fail(key(kBlockHeader), block.label + ": the block id does not fit in an int");
    }
    if (cloud.blockNames.count(static_cast<int>(block.id)) != 0) {
      fail(key(kBlockHeader), "two element blocks have the id " + std::to_string(block.id));
    }
    const std::string name =
        blockNames[b].empty() ? "block_" + std::to_string(block.id) : blockNames[b];
    const auto [it, inserted] = blockOfName.emplace(name, block.id);
    if (!inserted) {
      fail(key(kBlockHeader), "element blocks " + std::to_string(it->second) + " and " +
                                  std::to_string(block.id) + " are both named \"" + name + "\"");
    }
    cloud.blockNames[static_cast<int>(block.id)] = name;

    ex_block param{};
    param.id = block.id;
    param.type = EX_ELEM_BLOCK;
    check(ex_get_block_param(exoid_, &param), "ex_get_block_param", key(kBlockHeader));
    block.numElements = param.num_entry;
    block.nodesPerElement = param.num_nodes_per_entry;
    block.numAttributes = param.num_attribute;
    if (block.numElements < 0 || block.nodesPerElement < 0 || param.num_attribute < 0 ||
        element + block.numElements > init_.num_elem) {
      fail(key(kBlockHeader),
           block.label + ": inconsistent element counts; the file may be corrupt");
    }
    element += block.numElements;
    if (block.numElements == 0) continue;  // an empty block: nothing to read, any topology

    const std::string topology = upperTrimmed(param.topology);
    block.kind = classify(topology, block.nodesPerElement);
    if (block.kind == ElementKind::Unsupported) {
      fail(key(kBlockHeader),
           block.label + " (\"" + name + "\") has element type \"" + topology + "\" with " +
               std::to_string(block.nodesPerElement) +
               " nodes per element, which is not supported yet (supported: HEX8, HEX20, HEX27, "
               "TET4, TET10, SPHERE in 3D; QUAD4, QUAD8, QUAD9, SHELL4, TRI3, TRI6 in 2D)");
    }
    block.described = block.label + " (\"" + name + "\", " + topology + ")";
    const std::string& described = block.described;
    if (isPlanar(block.kind)) {
      if (firstPlanar.empty()) {
        firstPlanar = described;
        // A planar mesh written with three coordinates must lie in z = 0 (checkPlanarZ).
        if (init_.num_dim == 3) zCheckBlock_ = static_cast<long long>(b);
      }
      cloud.dimension = 2;
    } else {
      if (firstSolid.empty()) firstSolid = described;
      if (init_.num_dim == 2) {
        fail(key(kDimension), described +
                                  " is a 3D element block in a 2D mesh (num_dim = 2); 2D meshes "
                                  "take QUAD and TRI elements");
      }
    }
    if (!firstPlanar.empty() && !firstSolid.empty()) {
      fail(key(kDimension), "the mesh mixes 2D and 3D element blocks: " + firstPlanar + " and " +
                                firstSolid + "; a run is either planar or 3D");
    }
    if (block.kind == ElementKind::Sphere && block.numAttributes < 2) {
      connOnlyBlock_ = true;  // the serial read checks this block's connectivity first
      fail(key(kAttributes), block.label + " (\"" + name + "\") is a SPHERE block with " +
                                 std::to_string(block.numAttributes) +
                                 " attribute(s); the sphere volume is read from the second "
                                 "attribute");
    }
  }
  blocksRead_ = numBlocks;
  if (element != init_.num_elem) {
    fail(Key{static_cast<long long>(numBlocks), 0, 0},
         "the element blocks hold " + std::to_string(element) + " elements but the file declares " +
             std::to_string(init_.num_elem));
  }
}

void ShareReader::checkPlanarZ() {
  if (zCheckBlock_ < 0) return;
  const long long begin = nodes_.begin(rank_);
  const std::vector<double>& z = coord_[2];
  for (std::size_t n = 0; n < z.size(); ++n) {
    if (z[n] != 0.0) {
      const std::string& described = blocks_[static_cast<std::size_t>(zCheckBlock_)].described;
      const long long node = begin + static_cast<long long>(n);
      fail(Key{zCheckBlock_, kPlanarZ, node},
           described + " is a planar element block, but node " + std::to_string(node + 1) +
               " has z = " + std::to_string(z[n]) +
               "; a 2D mesh must lie in the plane z = 0 (or be written with num_dim = 2)");
    }
  }
}

// Reads the connectivity (and SPHERE attributes) of this rank's elements, block by block.
void ShareReader::readChunks() {
  const long long begin = elements_.begin(rank_), end = elements_.begin(rank_ + 1);
  const std::size_t last = blocksRead_ + (connOnlyBlock_ ? 1 : 0);
  for (std::size_t b = 0; b < last && b < blocks_.size(); ++b) {
    const Block& block = blocks_[b];
    const long long from = std::max(begin, block.first);
    const long long to = std::min(end, block.first + block.numElements);
    if (from >= to) continue;
    Chunk chunk;
    chunk.block = b;
    chunk.begin = from;
    chunk.end = to;
    const long long count = to - from;
    const auto sb = static_cast<long long>(b);
    chunk.connectivity.resize(static_cast<std::size_t>(count * block.nodesPerElement));
    check(ex_get_partial_conn(exoid_, EX_ELEM_BLOCK, block.id, from - block.first + 1, count,
                              chunk.connectivity.data(), nullptr, nullptr),
          "ex_get_partial_conn", Key{sb, kConnectivity, from});
    for (std::size_t i = 0; i < chunk.connectivity.size(); ++i) {
      const int64_t node = chunk.connectivity[i];
      if (node < 1 || node > init_.num_nodes) {
        fail(Key{sb, kConnectivity, from + static_cast<long long>(i) / block.nodesPerElement},
             block.label + ": the connectivity refers to node " + std::to_string(node) +
                 ", outside 1.." + std::to_string(init_.num_nodes) +
                 "; the file may be truncated or corrupt");
      }
    }
    if (b == blocksRead_) return;  // a SPHERE block without its volume attribute
    if (block.kind == ElementKind::Sphere) {
      chunk.attributes.resize(static_cast<std::size_t>(count * block.numAttributes));
      check(ex_get_partial_attr(exoid_, EX_ELEM_BLOCK, block.id, from - block.first + 1, count,
                                chunk.attributes.data()),
            "ex_get_partial_attr", Key{sb, kAttributes, from});
    }
    chunks_.push_back(std::move(chunk));
  }
}

// Collective: the coordinates of every node of this rank's elements, from the ranks whose node
// slices hold them. The requests are kept: node sets are answered for the same nodes.
void ShareReader::fetchNodes() {
  for (const Chunk& chunk : chunks_) {
    needed_.insert(needed_.end(), chunk.connectivity.begin(), chunk.connectivity.end());
  }
  std::sort(needed_.begin(), needed_.end());
  needed_.erase(std::unique(needed_.begin(), needed_.end()), needed_.end());
  std::vector<int> counts(static_cast<std::size_t>(size_), 0);
  for (int64_t node : needed_) ++counts[static_cast<std::size_t>(nodes_.home(node - 1))];
  requests_ = exchange(needed_, counts, requestCounts_, comm_);  // sorted by home already
  const long long begin = nodes_.begin(rank_);
  std::vector<double> answers(3 * requests_.size());
  for (std::size_t i = 0; i < requests_.size(); ++i) {
    const auto n = static_cast<std::size_t>(requests_[i] - 1 - begin);
    for (int k = 0; k < 3; ++k) answers[3 * i + static_cast<std::size_t>(k)] = coord_[k][n];
  }
  for (int& c : requestCounts_) c *= 3;
  std::vector<int> ignored;
  neededCoord_ = exchange(answers, requestCounts_, ignored, comm_);
  for (int& c : requestCounts_) c /= 3;
}

void ShareReader::buildPoints(PointCloud& cloud) {
  const long long elementBegin = elements_.begin(rank_);
  const auto numPoints = static_cast<std::size_t>(elements_.begin(rank_ + 1) - elementBegin);
  cloud.x.reserve(3 * numPoints);
  cloud.volume.reserve(numPoints);
  cloud.blockId.reserve(numPoints);
  cloud.globalId.reserve(numPoints);
  const auto coordinate = [&](int64_t node, int k) {
    const auto at = std::lower_bound(needed_.begin(), needed_.end(), node) - needed_.begin();
    return neededCoord_[3 * static_cast<std::size_t>(at) + static_cast<std::size_t>(k)];
  };
  for (const Chunk& chunk : chunks_) {
    const Block& block = blocks_[chunk.block];
    const ElementKind kind = block.kind;
    const auto npe = static_cast<std::size_t>(block.nodesPerElement);
    for (long long element = chunk.begin; element < chunk.end; ++element) {
      const auto e = static_cast<std::size_t>(element - chunk.begin);
      const int64_t* conn = chunk.connectivity.data() + e * npe;
      const int64_t id = ids_[static_cast<std::size_t>(element - elementBegin)];
      const Key key{static_cast<long long>(chunk.block), kElement, element};
      double position[3] = {0.0, 0.0, 0.0};
      double volume = 0.0;
      if (kind == ElementKind::Hex) {
        double nodes[8][3];
        for (int a = 0; a < 8; ++a) {
          for (int k = 0; k < 3; ++k) nodes[a][k] = coordinate(conn[a], k);
        }
        // Peridigm's point and volume: the hex as 24 tetrahedra around its face and body
        // centres, their volume-weighted centroid (not the corner mean, which differs on any
        // non-parallelepiped hex). Unsigned, so a mirrored node order is accepted.
        volume = std::fabs(hexTetCentroid(nodes, position));
      } else if (kind == ElementKind::Tet) {
        double nodes[4][3];
        for (int a = 0; a < 4; ++a) {
          for (int k = 0; k < 3; ++k) nodes[a][k] = coordinate(conn[a], k);
        }
        tetCentroid(nodes, position);
        volume = tetVolume(nodes);
      } else if (kind == ElementKind::Quad) {
        double nodes[4][2];
        for (int a = 0; a < 4; ++a) {
          for (int k = 0; k < 2; ++k) nodes[a][k] = coordinate(conn[a], k);
        }
        // As for hexes: the area-weighted centroid, the exact area, either orientation; but a
        // bow tie or a re-entrant quad has no meaningful area (its bilinear map folds over).
        if (!quadIsValid(nodes) && quadArea(nodes) != 0.0) {
          fail(key, block.label + ", element " + std::to_string(id) +
                        ": the quadrilateral is self-intersecting or not convex (inverted "
                        "element)");
        }
        quadCentroid(nodes, position);
        volume = std::fabs(quadArea(nodes)) * thickness_;
      } else if (kind == ElementKind::Tri) {
        double nodes[3][2];
        for (int a = 0; a < 3; ++a) {
          for (int k = 0; k < 2; ++k) nodes[a][k] = coordinate(conn[a], k);
        }
        triCentroid(nodes, position);
        volume = std::fabs(triArea(nodes)) * thickness_;
      } else {
        for (int k = 0; k < 3; ++k) position[k] = coordinate(conn[0], k);
        volume = chunk.attributes[e * static_cast<std::size_t>(block.numAttributes) + 1];
      }
      if (!(volume > 0.0) || !std::isfinite(volume)) {
        fail(key, block.label + ", element " + std::to_string(id) + ": the element " +
                      (isPlanar(kind) ? "area x thickness" : "volume") + " is " +
                      std::to_string(volume) +
                      (kind == ElementKind::Sphere ? " (second attribute)" : "") +
                      "; it must be positive (degenerate element?)");
      }
      cloud.x.insert(cloud.x.end(), position, position + 3);
      cloud.volume.push_back(volume);
      cloud.blockId.push_back(static_cast<int>(block.id));
      cloud.globalId.push_back(static_cast<long long>(id) - 1);
    }
  }
}

// A point is in a node set when its element has a node (corner or not) in the set. Each rank
// reads a slice of every set and sends (node, set) to the node's home rank, which then tells
// each rank the sets of the nodes it asked about in fetchNodes.
void ShareReader::readNodeSets(PointCloud& cloud) {
  const auto numSets = static_cast<std::size_t>(init_.num_node_sets);
  const auto setMajor = [&](std::size_t s) {
    return static_cast<long long>(blocks_.size() + 1 + s);
  };
  std::vector<int64_t> setIds(numSets);
  std::vector<std::string> setNames;
  std::vector<NodeInSet> pairs;  // read by this rank
  try {
    check(ex_get_ids(exoid_, EX_NODE_SET, setIds.data()), "ex_get_ids", Key{setMajor(0), 0, 0});
    setNames = names(EX_NODE_SET, numSets, Key{setMajor(0), 0, 0});
    std::map<std::string, long long> setOfName;
    for (std::size_t s = 0; s < numSets; ++s) {
      const Key key{setMajor(s), 0, 0};
      PointSet set;
      set.name = setNames[s].empty() ? "nodelist_" + std::to_string(setIds[s]) : setNames[s];
      const auto [it, inserted] = setOfName.emplace(set.name, setIds[s]);
      if (!inserted) {
        fail(key, "node sets " + std::to_string(it->second) + " and " + std::to_string(setIds[s]) +
                      " are both named \"" + set.name + "\"");
      }
      int64_t numEntries = 0;
      int64_t numFactors = 0;
      check(ex_get_set_param(exoid_, EX_NODE_SET, setIds[s], &numEntries, &numFactors),
            "ex_get_set_param", key);
      if (numEntries < 0) fail(key, "node set " + std::to_string(setIds[s]) + ": negative size");
      const Slicing slice{numEntries, size_};
      const long long begin = slice.begin(rank_), count = slice.begin(rank_ + 1) - begin;
      std::vector<int64_t> nodes(static_cast<std::size_t>(count));
      if (count > 0) {
        check(ex_get_partial_node_set(exoid_, setIds[s], begin + 1, count, nodes.data()),
              "ex_get_partial_node_set", Key{setMajor(s), 1, begin});
      }
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const int64_t node = nodes[i];
        if (node < 1 || node > init_.num_nodes) {
          fail(Key{setMajor(s), 1, begin + static_cast<long long>(i)},
               "node set " + std::to_string(setIds[s]) + " (\"" + set.name + "\") refers to node " +
                   std::to_string(node) + ", outside 1.." + std::to_string(init_.num_nodes) +
                   "; the file may be truncated or corrupt");
        }
        pairs.push_back(NodeInSet{node, static_cast<int64_t>(s)});
      }
      cloud.pointSets.push_back(std::move(set));
    }
  } catch (const Failure& f) {
    note(f);
  }
  settle();

  const NodeSetsOfNodes sets = nodeSetsOfRequested(std::move(pairs), nodes_, requests_,
                                                   requestCounts_, needed_.size(), comm_);
  requests_ = {};
  std::size_t point = 0;
  for (const Chunk& chunk : chunks_) {
    const auto npe = static_cast<std::size_t>(blocks_[chunk.block].nodesPerElement);
    for (long long element = chunk.begin; element < chunk.end; ++element, ++point) {
      const int64_t* conn =
          chunk.connectivity.data() + static_cast<std::size_t>(element - chunk.begin) * npe;
      for (std::size_t a = 0; a < npe; ++a) {
        const auto i = static_cast<std::size_t>(
            std::lower_bound(needed_.begin(), needed_.end(), conn[a]) - needed_.begin());
        for (std::size_t k = sets.start[i]; k < sets.start[i + 1]; ++k) {
          cloud.pointSets[static_cast<std::size_t>(sets.sets[k])].globalIds.push_back(
              cloud.globalId[point]);
        }
      }
    }
  }
  for (PointSet& set : cloud.pointSets) {
    std::sort(set.globalIds.begin(), set.globalIds.end());
    set.globalIds.erase(std::unique(set.globalIds.begin(), set.globalIds.end()),
                        set.globalIds.end());
  }
}

}  // namespace

PointCloud readExodusMeshShare(const std::string& fileName, const std::string& deckPath,
                               double thickness, MPI_Comm comm) {
  ShareReader reader(fileName, deckPath, thickness, comm);
  return reader.read();
}

}  // namespace peridot
