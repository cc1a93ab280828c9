#include "discretization/GmshReader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"
#include "discretization/ElementGeometry.hpp"
#include "discretization/GmshParser.hpp"
#include "discretization/Slicing.hpp"

namespace peridot {

namespace {

ElementKind kindOf(int type) {
  switch (type) {
    case 4:
    case 11:
      return ElementKind::Tet;
    case 5:
    case 12:
    case 17:
      return ElementKind::Hex;
    case 2:
    case 9:
      return ElementKind::Tri;
    case 3:
    case 10:
    case 16:
      return ElementKind::Quad;
    default:
      return ElementKind::Unsupported;
  }
}

// What the first pass learns: the cells' dimension and count, the blocks and the node sets.
struct Summary {
  int topDim = 0;
  long long cells[4] = {0, 0, 0, 0};
  long long withoutGroup[4] = {0, 0, 0, 0};  // elements in no physical group, per dimension
  std::set<int> groups[4];                   // physical groups of the elements, per dimension
  long long unsupportedTag = 0;              // first 3D element that is neither tet nor hex
  std::string unsupportedName;
};

struct SetKey {
  int dim, tag;
  std::string name;
};

// A facet of a group grown into a layer: its corners (1 point, 2 line ends, 3 or 4 corners).
struct Facet {
  long long node[4];
  int numCorners;
  int set;
};

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double distanceToSegment(const double* p, const double* a, const double* b) {
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ap[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
  const double d[3] = {ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]};
  return std::sqrt(dot(d, d));
}

// Distance from p to the triangle abc: the closest point is found by the Voronoi region of p
// (a vertex, an edge, or the face), the classical case analysis on barycentric coordinates.
double distanceToTriangle(const double* p, const double* a, const double* b, const double* c) {
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                       ab[0] * ac[1] - ab[1] * ac[0]};
  const double n2 = dot(n, n);
  const double edges = std::min(
      {distanceToSegment(p, a, b), distanceToSegment(p, b, c), distanceToSegment(p, c, a)});
  if (!(n2 > 0)) return edges;  // degenerate: a segment or a point
  // Projection of p onto the plane; inside the triangle when its barycentric coordinates are >= 0.
  const double ap[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
  const double h = dot(ap, n) / n2;
  const double q[3] = {ap[0] - h * n[0], ap[1] - h * n[1], ap[2] - h * n[2]};  // relative to a
  const double qxac[3] = {q[1] * ac[2] - q[2] * ac[1], q[2] * ac[0] - q[0] * ac[2],
                          q[0] * ac[1] - q[1] * ac[0]};
  const double abxq[3] = {ab[1] * q[2] - ab[2] * q[1], ab[2] * q[0] - ab[0] * q[2],
                          ab[0] * q[1] - ab[1] * q[0]};
  const double v = dot(qxac, n) / n2, w = dot(abxq, n) / n2;
  if (v >= 0 && w >= 0 && v + w <= 1) return std::fabs(h) * std::sqrt(n2);
  return edges;
}

class Reader {
 public:
  Reader(const std::string& fileName, const std::string& deckPath, const GmshOptions& options,
         MPI_Comm comm)
      : parser_(fileName, deckPath), deckPath_(deckPath), options_(options), comm_(comm) {
    MPI_Comm_rank(comm, &rank_);
    MPI_Comm_size(comm, &size_);
  }

  PointCloud read() {
    collective([&] { summarize(); });
    collective([&] { readShare(); });
    collective([&] { readNodes(); });
    PointCloud cloud;
    collective([&] { makePoints(cloud); });
    collective([&] { growLayers(cloud); });
    return cloud;
  }

 private:
  // Runs one step and settles its errors: every rank throws the lowest failing rank's message.
  // Slices are in file order, so that is the first failing cell, as on one rank.
  template <class F>
  void collective(F step) {
    std::string problem;
    try {
      step();
    } catch (const InputError& e) {
      problem = e.what();
    }
    throwIfAnyRank(problem, comm_);
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(deckPath_, parser_.label() + ": " + message);
  }

  void summarize() {
    Summary& s = summary_;
    header_ = parser_.parse(nullptr, [&](const GmshElement& e) {
      const int d = e.info.dimension;
      ++s.cells[d];
      if (e.physicals->empty()) ++s.withoutGroup[d];
      s.groups[d].insert(e.physicals->begin(), e.physicals->end());
      if (d == 3 && kindOf(e.type) == ElementKind::Unsupported && s.unsupportedTag == 0) {
        s.unsupportedTag = e.tag;
        s.unsupportedName = e.info.name;
      }
    });
    s.topDim = s.cells[3] > 0 ? 3 : s.cells[2] > 0 ? 2 : 0;
    if (s.topDim == 0) {
      fail(
          "has no 2D or 3D cells (triangles, quadrangles, tetrahedra or hexahedra); mesh the "
          "surfaces or volumes (gmsh -2 or -3)");
    }
    if (s.unsupportedTag != 0) {
      fail("element " + std::to_string(s.unsupportedTag) + " is a " + s.unsupportedName +
           "; Peridot turns only tetrahedra and hexahedra into points (mesh with tetrahedra, or "
           "recombine into hexahedra fully)");
    }
    const int top = s.topDim;
    if (!s.groups[top].empty() && s.withoutGroup[top] > 0) {
      fail(std::to_string(s.withoutGroup[top]) + " of the " + std::to_string(s.cells[top]) +
           " cells belong to no physical " + (top == 3 ? "volume" : "surface") +
           " while the others do; put every cell in one (or save without Mesh.SaveAll)");
    }
    for (int tag : s.groups[top]) {
      const auto it = header_.physicalNames.find({top, tag});
      blockNames_[tag] =
          it != header_.physicalNames.end() ? it->second : "block_" + std::to_string(tag);
    }
    if (blockNames_.empty()) blockNames_[1] = "block_1";  // no physical groups at all
    std::map<std::string, int> setOfName;
    for (int d = 0; d < top; ++d) {
      for (int tag : s.groups[d]) {
        const auto it = header_.physicalNames.find({d, tag});
        SetKey key{
            d, tag,
            it != header_.physicalNames.end() ? it->second : "nodelist_" + std::to_string(tag)};
        if (!setOfName.emplace(key.name, static_cast<int>(sets_.size())).second) {
          fail("two physical groups of lower dimension are both named \"" + key.name +
               "\"; give them distinct names");
        }
        setIndex_[{d, tag}] = static_cast<int>(sets_.size());
        sets_.push_back(key);
      }
    }
    layerOfSet_.assign(sets_.size(), false);
    for (const std::string& name : options_.layers) {
      const auto it = setOfName.find(name);
      if (it == setOfName.end()) {
        std::string known;
        for (const auto& kv : setOfName) known += (known.empty() ? "\"" : ", \"") + kv.first + "\"";
        throw InputError(options_.layersPath,
                         "\"" + name +
                             "\" is not a physical group of lower dimension than the "
                             "cells in " +
                             parser_.label() +
                             (known.empty() ? " (it has none)" : "; it has " + known));
      }
      layerOfSet_[static_cast<std::size_t>(it->second)] = true;
    }
    slice_ = Slicing{s.cells[top], size_};
  }

  // Pass 2: this rank's cells (their nodes and blocks) and the layer groups' facets.
  void readShare() {
    const long long begin = slice_.begin(rank_), end = slice_.begin(rank_ + 1);
    const int top = summary_.topDim;
    long long ordinal = 0;
    cellStart_.push_back(0);
    parser_.parse(nullptr, [&](const GmshElement& e) {
      const int d = e.info.dimension;
      if (d == top) {
        if (ordinal >= begin && ordinal < end) {
          cellNodes_.insert(cellNodes_.end(), e.nodes, e.nodes + e.info.numNodes);
          cellStart_.push_back(cellNodes_.size());
          cellTag_.push_back(e.tag);
          cellType_.push_back(e.type);
          cellBlock_.push_back(e.physicals->empty() ? 1 : e.physicals->front());
        }
        ++ordinal;
      } else if (d < top) {
        for (int g : *e.physicals) {
          const int set = setIndex_.at({d, g});
          if (!layerOfSet_[static_cast<std::size_t>(set)]) continue;
          Facet f{{0, 0, 0, 0}, std::min(e.info.numCorners, 4), set};
          std::copy(e.nodes, e.nodes + f.numCorners, f.node);
          facets_.push_back(f);
        }
      }
    });
    needed_ = cellNodes_;
    for (const Facet& f : facets_) needed_.insert(needed_.end(), f.node, f.node + f.numCorners);
    std::sort(needed_.begin(), needed_.end());
    needed_.erase(std::unique(needed_.begin(), needed_.end()), needed_.end());
  }

  std::size_t indexOf(long long node) const {
    const auto it = std::lower_bound(needed_.begin(), needed_.end(), node);
    return it != needed_.end() && *it == node ? static_cast<std::size_t>(it - needed_.begin())
                                              : needed_.size();
  }

  // Pass 3: the coordinates of the needed nodes and the groups they are in.
  void readNodes() {
    coords_.assign(3 * needed_.size(), 0.0);
    found_.assign(needed_.size(), 0);
    const int top = summary_.topDim;
    parser_.parse(
        [&](long long tag, const double* x) {
          const std::size_t i = indexOf(tag);
          if (i == needed_.size()) return;
          if (found_[i]) fail("node " + std::to_string(tag) + " is defined twice");
          found_[i] = 1;
          std::copy(x, x + 3, coords_.begin() + static_cast<std::ptrdiff_t>(3 * i));
        },
        [&](const GmshElement& e) {
          const int d = e.info.dimension;
          if (d >= top || e.physicals->empty()) return;
          for (int k = 0; k < e.info.numNodes; ++k) {
            const std::size_t i = indexOf(e.nodes[k]);
            if (i == needed_.size()) continue;
            for (int g : *e.physicals) membership_.push_back({i, setIndex_.at({d, g})});
          }
        });
    std::sort(membership_.begin(), membership_.end());
    membership_.erase(std::unique(membership_.begin(), membership_.end()), membership_.end());
  }

  const double* coordinate(long long node, long long cellTag) const {
    const std::size_t i = indexOf(node);
    if (i == needed_.size() || !found_[i]) {
      fail("element " + std::to_string(cellTag) + " refers to node " + std::to_string(node) +
           ", which $Nodes does not define");
    }
    return &coords_[3 * i];
  }

  void makePoints(PointCloud& cloud) {
    const std::size_t n = cellTag_.size();
    const bool planar = summary_.topDim == 2;
    const double thickness = options_.thickness;
    cloud.dimension = planar ? 2 : 3;
    if (planar) cloud.thickness = thickness;
    cloud.globalNumPoints = slice_.n;
    cloud.blockNames = blockNames_;
    cloud.x.reserve(3 * n);
    for (std::size_t c = 0; c < n; ++c) {
      const long long* conn = &cellNodes_[cellStart_[c]];
      const long long tag = cellTag_[c];
      const ElementKind kind = kindOf(cellType_[c]);
      double position[3] = {0, 0, 0};
      double volume = 0;
      if (planar) {
        const int corners = kind == ElementKind::Quad ? 4 : 3;
        double nodes[4][2];
        for (int a = 0; a < corners; ++a) {
          const double* x = coordinate(conn[a], tag);
          if (x[2] != 0.0) {
            fail("element " + std::to_string(tag) + ": node " + std::to_string(conn[a]) +
                 " has z = " + formatNumber(x[2]) + "; a 2D mesh must lie in the plane z = 0");
          }
          nodes[a][0] = x[0];
          nodes[a][1] = x[1];
        }
        // As the Exodus reader: the corner mean, the exact area, either orientation.
        if (kind == ElementKind::Quad) {
          if (!quadIsValid(nodes) && quadArea(nodes) != 0.0) {
            fail("element " + std::to_string(tag) +
                 ": the quadrangle is self-intersecting or not convex (inverted element)");
          }
          quadNodeAverage(nodes, position);
          volume = std::fabs(quadArea(nodes)) * thickness;
        } else {
          triCentroid(nodes, position);
          volume = std::fabs(triArea(nodes)) * thickness;
        }
      } else if (kind == ElementKind::Hex) {
        double nodes[8][3];
        for (int a = 0; a < 8; ++a) std::copy_n(coordinate(conn[a], tag), 3, nodes[a]);
        hexNodeAverage(nodes, position);  // Gmsh's hexahedron corners are in Exodus order
        volume = std::fabs(hexVolume(nodes));
      } else {
        double nodes[4][3];
        for (int a = 0; a < 4; ++a) std::copy_n(coordinate(conn[a], tag), 3, nodes[a]);
        tetCentroid(nodes, position);
        volume = tetVolume(nodes);
      }
      if (!(volume > 0.0) || !std::isfinite(volume)) {
        fail("element " + std::to_string(tag) + ": the " +
             (planar ? "area x thickness" : "volume") + " is " + formatNumber(volume) +
             "; it must be positive (degenerate element?)");
      }
      // Higher-order cells: their other nodes must exist too (they count for node sets).
      for (std::size_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k)
        coordinate(cellNodes_[k], tag);
      cloud.x.insert(cloud.x.end(), position, position + 3);
      cloud.volume.push_back(volume);
      cloud.blockId.push_back(cellBlock_[c]);
      cloud.globalId.push_back(slice_.begin(rank_) + static_cast<long long>(c));
    }
    // Node sets: a point is in a group when its cell has a node (corner or not) in it.
    cloud.pointSets.resize(sets_.size());
    for (std::size_t s = 0; s < sets_.size(); ++s) cloud.pointSets[s].name = sets_[s].name;
    for (std::size_t c = 0; c < n; ++c) {
      for (std::size_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
        const std::size_t i = indexOf(cellNodes_[k]);
        auto it = std::lower_bound(membership_.begin(), membership_.end(),
                                   std::pair<std::size_t, int>{i, -1});
        for (; it != membership_.end() && it->first == i; ++it) {
          cloud.pointSets[static_cast<std::size_t>(it->second)].globalIds.push_back(
              cloud.globalId[c]);
        }
      }
    }
  }

  // Adds to each layer set the points within the depth of one of its facets, found through a
  // uniform grid of the facets' boxes widened by the depth.
  void growLayers(PointCloud& cloud) {
    const double depth = options_.layerDepth;
    for (std::size_t s = 0; s < sets_.size(); ++s) {
      if (!layerOfSet_[s]) continue;
      std::vector<std::array<double, 12>> corners;
      std::vector<int> numCorners;
      double lo[3] = {1e308, 1e308, 1e308}, hi[3] = {-1e308, -1e308, -1e308}, extent = 0;
      for (const Facet& f : facets_) {
        if (f.set != static_cast<int>(s)) continue;
        std::array<double, 12> p{};
        for (int a = 0; a < f.numCorners; ++a) {
          const std::size_t i = indexOf(f.node[a]);
          if (i == needed_.size() || !found_[i]) {
            fail("physical group \"" + sets_[s].name + "\" refers to node " +
                 std::to_string(f.node[a]) + ", which $Nodes does not define");
          }
          std::copy_n(&coords_[3 * i], 3, &p[3 * static_cast<std::size_t>(a)]);
        }
        double flo[3] = {1e308, 1e308, 1e308}, fhi[3] = {-1e308, -1e308, -1e308};
        for (int a = 0; a < f.numCorners; ++a) {
          for (int d = 0; d < 3; ++d) {
            flo[d] = std::min(flo[d], p[3 * a + d]);
            fhi[d] = std::max(fhi[d], p[3 * a + d]);
          }
        }
        for (int d = 0; d < 3; ++d) {
          extent = std::max(extent, fhi[d] - flo[d]);
          lo[d] = std::min(lo[d], flo[d] - depth);
          hi[d] = std::max(hi[d], fhi[d] + depth);
        }
        corners.push_back(p);
        numCorners.push_back(f.numCorners);
      }
      if (corners.empty()) continue;
      // Cells at least as large as a facet and the depth (so a widened facet spans at most 4
      // cells per axis), and at most 10^6 per axis.
      double h = std::max(depth, extent);
      for (int d = 0; d < 3; ++d) h = std::max(h, (hi[d] - lo[d]) * 1e-6);
      const auto cellOf = [&](double v, int d) {
        return static_cast<long long>(std::floor((v - lo[d]) / h));
      };
      const auto key = [](long long i, long long j, long long k) {
        return (i * 1048583LL + j) * 1048583LL + k;  // indices below 2^20 + 1: no collision
      };
      std::unordered_map<long long, std::vector<int>> grid;
      for (std::size_t f = 0; f < corners.size(); ++f) {
        long long a[3], b[3];
        for (int d = 0; d < 3; ++d) {
          double fl = 1e308, fh = -1e308;
          for (int c = 0; c < numCorners[f]; ++c) {
            fl = std::min(fl, corners[f][3 * c + d]);
            fh = std::max(fh, corners[f][3 * c + d]);
          }
          a[d] = cellOf(fl - depth, d);
          b[d] = cellOf(fh + depth, d);
        }
        for (long long i = a[0]; i <= b[0]; ++i)
          for (long long j = a[1]; j <= b[1]; ++j)
            for (long long k = a[2]; k <= b[2]; ++k) grid[key(i, j, k)].push_back(int(f));
      }
      std::vector<long long>& ids = cloud.pointSets[s].globalIds;
      for (std::size_t p = 0; p < cloud.size(); ++p) {
        const double* x = &cloud.x[3 * p];
        if (x[0] < lo[0] || x[0] > hi[0] || x[1] < lo[1] || x[1] > hi[1] || x[2] < lo[2] ||
            x[2] > hi[2]) {
          continue;
        }
        const auto it = grid.find(key(cellOf(x[0], 0), cellOf(x[1], 1), cellOf(x[2], 2)));
        if (it == grid.end()) continue;
        for (int f : it->second) {
          const double* c = corners[static_cast<std::size_t>(f)].data();
          const int m = numCorners[static_cast<std::size_t>(f)];
          double dist = 0;
          if (m == 1) {
            const double v[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
            dist = std::sqrt(dot(v, v));
          } else if (m == 2) {
            dist = distanceToSegment(x, c, c + 3);
          } else {
            dist = distanceToTriangle(x, c, c + 3, c + 6);
            if (m == 4) dist = std::min(dist, distanceToTriangle(x, c, c + 6, c + 9));
          }
          if (dist <= depth) {
            ids.push_back(cloud.globalId[p]);
            break;
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

  GmshParser parser_;
  std::string deckPath_;
  GmshOptions options_;
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
  GmshHeader header_;
  Summary summary_;
  std::map<int, std::string> blockNames_;
  std::vector<SetKey> sets_;
  std::map<std::pair<int, int>, int> setIndex_;
  std::vector<bool> layerOfSet_;
  Slicing slice_;
  // This rank's cells: nodes (all of them, corners first), tag, type and block.
  std::vector<long long> cellNodes_;
  std::vector<std::size_t> cellStart_;
  std::vector<long long> cellTag_;
  std::vector<int> cellType_, cellBlock_;
  std::vector<Facet> facets_;
  std::vector<long long> needed_;  // sorted node tags whose coordinates this rank needs
  std::vector<double> coords_;
  std::vector<char> found_;
  std::vector<std::pair<std::size_t, int>> membership_;  // (needed index, set), sorted
};

}  // namespace

PointCloud readGmshMeshShare(const std::string& fileName, const std::string& deckPath,
                             const GmshOptions& options, MPI_Comm comm) {
  Reader reader(fileName, deckPath, options, comm);
  return reader.read();
}

}  // namespace peridot
