#include "discretization/FacetMesh.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/Error.hpp"
#include "discretization/ExodusMeshReader.hpp"

namespace peridot {

namespace {

inline void sub(const double* a, const double* b, double* out) {
  for (int d = 0; d < 3; ++d) out[d] = a[d] - b[d];
}
inline void cross(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}
inline double dot(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

}  // namespace

void FacetMesh::splitQuad(const double* a, const double* b, const double* c, const double* d,
                          std::vector<double>& corners) {
  for (const double* v : {a, b, c, a, c, d}) corners.insert(corners.end(), v, v + 3);
}

FacetMesh FacetMesh::fromTriangles(const std::vector<double>& corners) {
  FacetMesh m;
  m.corners_ = corners;
  m.buildGrid();
  return m;
}

FacetMesh FacetMesh::read(const std::string& fileName, const std::string& deckPath) {
  ExodusInputFile file(fileName, "shell mesh", deckPath);
  const int id = file.id();
  ex_init_params init{};
  if (ex_get_init_ext(id, &init) < 0) {
    throw InputError(deckPath,
                     "cannot read the header of \"" + fileName + "\": " + exodusLastError());
  }
  if (init.num_dim != 3) {
    throw InputError(deckPath, "the shell mesh \"" + fileName +
                                   "\" must be 3D (num_dim = 3), not " +
                                   std::to_string(init.num_dim) + "D");
  }
  const auto numNodes = static_cast<std::size_t>(init.num_nodes);
  std::vector<double> x(numNodes), y(numNodes), z(numNodes);
  if (numNodes > 0 && ex_get_coord(id, x.data(), y.data(), z.data()) < 0) {
    throw InputError(deckPath,
                     "cannot read the coordinates of \"" + fileName + "\": " + exodusLastError());
  }
  std::vector<int64_t> blockIds(static_cast<std::size_t>(init.num_elem_blk));
  if (!blockIds.empty() && ex_get_ids(id, EX_ELEM_BLOCK, blockIds.data()) < 0) {
    throw InputError(deckPath,
                     "cannot read the blocks of \"" + fileName + "\": " + exodusLastError());
  }
  FacetMesh m;
  for (const int64_t block : blockIds) {
    char type[MAX_STR_LENGTH + 1] = {0};
    int64_t numElements = 0, nodesPerElement = 0, numEdges = 0, numFaces = 0, numAttributes = 0;
    if (ex_get_block(id, EX_ELEM_BLOCK, block, type, &numElements, &nodesPerElement, &numEdges,
                     &numFaces, &numAttributes) < 0) {
      throw InputError(deckPath, "cannot read block " + std::to_string(block) + " of \"" +
                                     fileName + "\": " + exodusLastError());
    }
    if (numElements == 0) continue;
    const std::string t = upper(type);
    const bool tri = t == "TRI" || t == "TRI3" || t == "TRIANGLE" || t == "TRISHELL" ||
                     t == "TRISHELL3" || t == "SHELL3";
    const bool quad = t == "QUAD" || t == "QUAD4" || t == "SHELL" || t == "SHELL4";
    if ((!tri && !quad) || nodesPerElement != (tri ? 3 : 4)) {
      throw InputError(deckPath, "block " + std::to_string(block) + " of the shell mesh \"" +
                                     fileName + "\" has elements of type " + t + " with " +
                                     std::to_string(nodesPerElement) +
                                     " nodes; a bond filter takes TRI3, QUAD4 or SHELL4 facets");
    }
    std::vector<int64_t> conn(static_cast<std::size_t>(numElements * nodesPerElement));
    if (ex_get_conn(id, EX_ELEM_BLOCK, block, conn.data(), nullptr, nullptr) < 0) {
      throw InputError(deckPath, "cannot read the connectivity of block " + std::to_string(block) +
                                     " of \"" + fileName + "\": " + exodusLastError());
    }
    for (int64_t e = 0; e < numElements; ++e) {
      double v[4][3];
      for (int64_t k = 0; k < nodesPerElement; ++k) {
        const int64_t node = conn[static_cast<std::size_t>(e * nodesPerElement + k)] - 1;
        if (node < 0 || node >= static_cast<int64_t>(numNodes)) {
          throw InputError(deckPath, "element " + std::to_string(e + 1) + " of block " +
                                         std::to_string(block) + " of \"" + fileName +
                                         "\" refers to a node that does not exist");
        }
        v[k][0] = x[node];
        v[k][1] = y[node];
        v[k][2] = z[node];
      }
      if (tri) {
        for (int k = 0; k < 3; ++k) m.corners_.insert(m.corners_.end(), v[k], v[k] + 3);
      } else {
        splitQuad(v[0], v[1], v[2], v[3], m.corners_);
      }
    }
  }
  if (m.corners_.empty()) {
    throw InputError(deckPath, "the shell mesh \"" + fileName + "\" has no facets");
  }
  m.buildGrid();
  return m;
}

void FacetMesh::buildGrid() {
  const std::size_t n = numTriangles();
  double hi[3];
  for (int d = 0; d < 3; ++d) {
    lo_[d] = std::numeric_limits<double>::max();
    hi[d] = std::numeric_limits<double>::lowest();
  }
  for (std::size_t k = 0; k < 3 * n; ++k)
    for (int d = 0; d < 3; ++d) {
      lo_[d] = std::min(lo_[d], corners_[3 * k + d]);
      hi[d] = std::max(hi[d], corners_[3 * k + d]);
    }
  double largest = 0;
  for (int d = 0; d < 3; ++d) largest = std::max(largest, hi[d] - lo_[d]);
  if (!(largest > 0)) largest = 1.0;
  // A crack surface is two-dimensional: about sqrt(n) cells along its longest extent keep a few
  // facets per cell.
  const double h = largest / std::max(1.0, std::ceil(std::sqrt(static_cast<double>(n))));
  std::size_t total = 1;
  for (int d = 0; d < 3; ++d) {
    const double pad = 1e-9 * largest;
    lo_[d] -= pad;
    const double extent = hi[d] + pad - lo_[d];
    dims_[d] = std::clamp(static_cast<int>(extent / h) + 1, 1, 512);
    cell_[d] = extent / dims_[d];
    total *= static_cast<std::size_t>(dims_[d]);
  }
  auto cellRange = [&](const double* a, const double* b, const double* c, int* c0, int* c1) {
    for (int d = 0; d < 3; ++d) {
      const double mn = std::min({a[d], b[d], c[d]}), mx = std::max({a[d], b[d], c[d]});
      c0[d] = std::clamp(static_cast<int>(std::floor((mn - lo_[d]) / cell_[d])), 0, dims_[d] - 1);
      c1[d] = std::clamp(static_cast<int>(std::floor((mx - lo_[d]) / cell_[d])), 0, dims_[d] - 1);
    }
  };
  cellStart_.assign(total + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::size_t> fill;
    if (pass == 1) {
      for (std::size_t c = 0; c < total; ++c) cellStart_[c + 1] += cellStart_[c];
      cellTriangles_.resize(cellStart_[total]);
      fill.assign(cellStart_.begin(), cellStart_.end() - 1);
    }
    for (std::size_t t = 0; t < n; ++t) {
      const double* v = &corners_[9 * t];
      int c0[3], c1[3];
      cellRange(v, v + 3, v + 6, c0, c1);
      for (int k = c0[2]; k <= c1[2]; ++k)
        for (int j = c0[1]; j <= c1[1]; ++j)
          for (int i = c0[0]; i <= c1[0]; ++i) {
            const std::size_t c = (static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i;
            if (pass == 0)
              ++cellStart_[c + 1];
            else
              cellTriangles_[fill[c]++] = t;
          }
    }
  }
}

bool FacetMesh::cutsTriangle(std::size_t t, const double* p, const double* q) const {
  const double* a = &corners_[9 * t];
  const double* b = a + 3;
  const double* c = a + 6;
  double ab[3], ac[3], n[3], pa[3], qa[3];
  sub(b, a, ab);
  sub(c, a, ac);
  cross(ab, ac, n);
  sub(p, a, pa);
  sub(q, a, qa);
  const double dp = dot(n, pa), dq = dot(n, qa);
  // Both ends strictly on one side, or the segment parallel to (or in) the plane: no crossing.
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return false;
  const double s = dp / (dp - dq);
  double h[3];
  for (int d = 0; d < 3; ++d) h[d] = p[d] + s * (q[d] - p[d]);
  // Barycentric weights as signed sub-areas (times |n|^2 in total): inside when none is
  // negative beyond the tolerance, so a crossing on a shared edge belongs to both facets.
  const double n2 = dot(n, n);
  const double tol = -1e-12 * n2;
  double u[3], v[3], w[3];
  sub(a, h, u);
  sub(b, h, v);
  sub(c, h, w);
  double k[3];
  cross(v, w, k);
  if (dot(n, k) < tol) return false;
  cross(w, u, k);
  if (dot(n, k) < tol) return false;
  cross(u, v, k);
  return dot(n, k) >= tol;
}

bool FacetMesh::cuts(const double* p0, const double* q0) const {
  // Ends in lexicographic order: cuts(p, q) and cuts(q, p) do the same arithmetic, so the two
  // entries of a bond (searched from either end, on any rank) always agree.
  const bool swap = std::lexicographical_compare(q0, q0 + 3, p0, p0 + 3);
  const double* p = swap ? q0 : p0;
  const double* q = swap ? p0 : q0;
  int c0[3], c1[3];
  for (int d = 0; d < 3; ++d) {
    const double mn = std::min(p[d], q[d]), mx = std::max(p[d], q[d]);
    const double top = lo_[d] + cell_[d] * dims_[d];
    if (mx < lo_[d] || mn > top) return false;  // outside the facets' box
    c0[d] = std::clamp(static_cast<int>(std::floor((mn - lo_[d]) / cell_[d])), 0, dims_[d] - 1);
    c1[d] = std::clamp(static_cast<int>(std::floor((mx - lo_[d]) / cell_[d])), 0, dims_[d] - 1);
  }
  for (int k = c0[2]; k <= c1[2]; ++k)
    for (int j = c0[1]; j <= c1[1]; ++j)
      for (int i = c0[0]; i <= c1[0]; ++i) {
        const std::size_t c = (static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i;
        for (std::size_t e = cellStart_[c]; e < cellStart_[c + 1]; ++e)
          if (cutsTriangle(cellTriangles_[e], p, q)) return true;
      }
  return false;
}

}  // namespace peridot
