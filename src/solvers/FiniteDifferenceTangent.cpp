#include "solvers/FiniteDifferenceTangent.hpp"

#include <zoltan.h>

#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/Error.hpp"

namespace peridot {

namespace {

using Vector = Tpetra::Vector<double, LocalOrdinal, GlobalOrdinal>;

// The owned points' graph for Zoltan: each point's adjacent points (the columns of its rows
// other than itself) with their owners.
struct PointGraph {
  std::vector<ZOLTAN_ID_TYPE> ids;
  std::vector<int> offsets;
  std::vector<ZOLTAN_ID_TYPE> neighbors;
  std::vector<int> owners;
};

int numObjects(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<int>(static_cast<PointGraph*>(data)->ids.size());
}

void objectList(void* data, int, int, ZOLTAN_ID_PTR global, ZOLTAN_ID_PTR local, int, float*,
                int* ierr) {
  const auto& g = *static_cast<PointGraph*>(data);
  for (std::size_t k = 0; k < g.ids.size(); ++k) {
    global[k] = g.ids[k];
    local[k] = static_cast<ZOLTAN_ID_TYPE>(k);
  }
  *ierr = ZOLTAN_OK;
}

void numEdges(void* data, int, int, int count, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR local, int* edges,
              int* ierr) {
  const auto& g = *static_cast<PointGraph*>(data);
  for (int k = 0; k < count; ++k) edges[k] = g.offsets[local[k] + 1] - g.offsets[local[k]];
  *ierr = ZOLTAN_OK;
}

void edgeList(void* data, int, int, int count, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR local, int*,
              ZOLTAN_ID_PTR neighbors, int* owners, int, float*, int* ierr) {
  const auto& g = *static_cast<PointGraph*>(data);
  int out = 0;
  for (int k = 0; k < count; ++k)
    for (int e = g.offsets[local[k]]; e < g.offsets[local[k] + 1]; ++e, ++out) {
      neighbors[out] = g.neighbors[e];
      owners[out] = g.owners[e];
    }
  *ierr = ZOLTAN_OK;
}

}  // namespace

FiniteDifferenceTangent::FiniteDifferenceTangent(const Topology& topology,
                                                 Teuchos::RCP<CrsMatrix> matrix,
                                                 const ProbeSettings& settings)
    : topology_(topology), matrix_(std::move(matrix)), settings_(settings) {
  const int n = topology.numOwned;
  const auto colMap = matrix_->getColMap();
  // The matrix rows as plain CSR (local column indices).
  rowOffsets_.assign(3 * static_cast<std::size_t>(n) + 1, 0);
  for (int r = 0; r < 3 * n; ++r) {
    CrsMatrix::local_inds_host_view_type cols;
    CrsMatrix::values_host_view_type vals;
    matrix_->getLocalRowView(r, cols, vals);
    rowOffsets_[r + 1] = rowOffsets_[r] + cols.extent(0);
    for (std::size_t k = 0; k < cols.extent(0); ++k) columns_.push_back(cols(k));
  }
  values_.assign(columns_.size(), 0.0);

  // The point graph from the first row of each point (its three rows share one pattern).
  PointGraph graph;
  graph.offsets.push_back(0);
  std::vector<GlobalOrdinal> adjacent, row;
  for (int a = 0; a < n; ++a) {
    const GlobalOrdinal self = topology.overlapGlobalId[a];
    graph.ids.push_back(static_cast<ZOLTAN_ID_TYPE>(self));
    row.clear();
    for (std::size_t k = rowOffsets_[3 * a]; k < rowOffsets_[3 * a + 1]; ++k) {
      const GlobalOrdinal point = colMap->getGlobalElement(columns_[k]) / 3;
      if (point != self) row.push_back(point);
    }
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    for (GlobalOrdinal point : row) {
      graph.neighbors.push_back(static_cast<ZOLTAN_ID_TYPE>(point));
      adjacent.push_back(point);
    }
    graph.offsets.push_back(static_cast<int>(graph.neighbors.size()));
  }
  graph.owners.assign(adjacent.size(), 0);
  {
    std::vector<LocalOrdinal> lids(adjacent.size());
    topology.ownedMap->getRemoteIndexList(Teuchos::ArrayView<const GlobalOrdinal>(adjacent),
                                          Teuchos::ArrayView<int>(graph.owners),
                                          Teuchos::ArrayView<LocalOrdinal>(lids));
  }
  std::vector<int> colour(static_cast<std::size_t>(n), 0);
  {
    float version = 0;
    Zoltan_Initialize(0, nullptr, &version);
    Zoltan_Struct* zz = Zoltan_Create(topology.comm);
    Zoltan_Set_Param(zz, "DEBUG_LEVEL", "0");
    Zoltan_Set_Param(zz, "NUM_GID_ENTRIES", "1");
    Zoltan_Set_Param(zz, "NUM_LID_ENTRIES", "1");
    Zoltan_Set_Param(zz, "COLORING_PROBLEM", "DISTANCE-2");
    Zoltan_Set_Num_Obj_Fn(zz, numObjects, &graph);
    Zoltan_Set_Obj_List_Fn(zz, objectList, &graph);
    Zoltan_Set_Num_Edges_Multi_Fn(zz, numEdges, &graph);
    Zoltan_Set_Edge_List_Multi_Fn(zz, edgeList, &graph);
    std::vector<ZOLTAN_ID_TYPE> ids = graph.ids;
    const int rc = Zoltan_Color(zz, 1, n, ids.data(), colour.data());
    Zoltan_Destroy(&zz);
    if (rc != ZOLTAN_OK && rc != ZOLTAN_WARN)
      throw std::runtime_error("Zoltan_Color failed (code " + std::to_string(rc) + ")");
  }
  int localMax = 0;
  for (int& c : colour) {
    c -= 1;  // Zoltan's colours start at 1
    localMax = std::max(localMax, c + 1);
  }
  MPI_Allreduce(&localMax, &numColours_, 1, MPI_INT, MPI_MAX, topology.comm);

  // Colour of every column (imported onto the column map).
  std::vector<int> columnColour(colMap->getNodeNumElements(), 0);
  {
    Vector owned(topology.ownedMap3()), onColumns(colMap);
    {
      auto view = owned.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (int a = 0; a < n; ++a)
        for (int d = 0; d < 3; ++d) view(3 * a + d, 0) = colour[a];
    }
    Tpetra::Import<LocalOrdinal, GlobalOrdinal> import(topology.ownedMap3(), colMap);
    onColumns.doImport(owned, import, Tpetra::INSERT);
    auto view = onColumns.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t k = 0; k < columnColour.size(); ++k)
      columnColour[k] = static_cast<int>(view(k, 0));
  }
  // A valid colouring leaves no row with two columns of one colour and component.
  std::string invalid;
  std::vector<int> seen(3 * static_cast<std::size_t>(numColours_), -1);
  for (int r = 0; r < 3 * n && invalid.empty(); ++r)
    for (std::size_t k = rowOffsets_[r]; k < rowOffsets_[r + 1]; ++k) {
      const GlobalOrdinal g = colMap->getGlobalElement(columns_[k]);
      const int bucket = 3 * columnColour[columns_[k]] + static_cast<int>(g % 3);
      if (seen[bucket] == r) {
        invalid = "the distance-2 colouring of the tangent's graph is not valid";
        break;
      }
      seen[bucket] = r;
    }
  if (!invalid.empty()) throw std::logic_error(invalid);

  // Entries by bucket, and owned points by colour.
  bucketOffsets_.assign(3 * static_cast<std::size_t>(numColours_) + 1, 0);
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    const GlobalOrdinal g = colMap->getGlobalElement(columns_[k]);
    ++bucketOffsets_[3 * columnColour[columns_[k]] + g % 3 + 1];
  }
  for (std::size_t b = 1; b < bucketOffsets_.size(); ++b)
    bucketOffsets_[b] += bucketOffsets_[b - 1];
  entries_.resize(columns_.size());
  entryRow_.resize(columns_.size());
  {
    std::vector<std::size_t> next(bucketOffsets_.begin(), bucketOffsets_.end() - 1);
    for (int r = 0; r < 3 * n; ++r)
      for (std::size_t k = rowOffsets_[r]; k < rowOffsets_[r + 1]; ++k) {
        const GlobalOrdinal g = colMap->getGlobalElement(columns_[k]);
        entries_[next[3 * columnColour[columns_[k]] + g % 3]++] = k;
        entryRow_[k] = r;
      }
  }
  pointOffsets_.assign(static_cast<std::size_t>(numColours_) + 1, 0);
  for (int a = 0; a < n; ++a) ++pointOffsets_[colour[a] + 1];
  for (int k = 1; k <= numColours_; ++k) pointOffsets_[k] += pointOffsets_[k - 1];
  points_.resize(static_cast<std::size_t>(n));
  {
    std::vector<int> next(pointOffsets_.begin(), pointOffsets_.end() - 1);
    for (int a = 0; a < n; ++a) points_[next[colour[a]]++] = a;
  }

  // Peridigm's default probe: 1e-6 x the smallest element radius (3 V / (4 pi))^(1/3).
  eps_ = settings_.probeLength;
  if (!(eps_ > 0)) {
    double radius = std::numeric_limits<double>::max();
    for (int a = 0; a < n; ++a)
      radius = std::min(radius, std::cbrt(0.238732414637843 * settings_.volume[a]));
    MPI_Allreduce(MPI_IN_PLACE, &radius, 1, MPI_DOUBLE, MPI_MIN, topology.comm);
    eps_ = 1e-6 * radius;
  }
  saved_.assign(3 * static_cast<std::size_t>(n), 0.0);
  savedVelocity_.assign(3 * static_cast<std::size_t>(n), 0.0);
  plus_.assign(3 * static_cast<std::size_t>(n), 0.0);
}

void FiniteDifferenceTangent::fill(double dt, double velocityRate, const double* held,
                                   double heldDiagonal, const double* addedDiagonal) {
  const int n = topology_.numOwned;
  ModelEvaluator& evaluator = *settings_.evaluator;
  double* y = settings_.y;
  double* v = settings_.v;
  const double* f = settings_.f;
  // A rate model sees the probe as a velocity change too (Peridigm: eps / dt).
  const bool rate = evaluator.readsVelocity() && velocityRate > 0 && v;
  const double eps = eps_;
  std::fill(values_.begin(), values_.end(), 0.0);
  for (int k = 0; k < numColours_; ++k) {
    const int* first = points_.data() + pointOffsets_[k];
    const int* last = points_.data() + pointOffsets_[k + 1];
    for (int e = 0; e < 3; ++e) {
      for (double sign : {1.0, -1.0}) {
        for (const int* p = first; p != last; ++p) {
          const int q = 3 * *p + e;
          if (sign > 0) {
            saved_[q] = y[q];
            if (rate) savedVelocity_[q] = v[q];
          }
          y[q] = saved_[q] + sign * eps;
          if (rate) v[q] = savedVelocity_[q] + sign * eps * velocityRate;
        }
        evaluator.evaluate(dt, false, false);
        if (sign > 0) std::copy(f, f + 3 * n, plus_.begin());
        for (const int* p = first; p != last; ++p) {
          const int q = 3 * *p + e;
          y[q] = saved_[q];
          if (rate) v[q] = savedVelocity_[q];
        }
      }
      for (std::size_t b = bucketOffsets_[3 * k + e]; b < bucketOffsets_[3 * k + e + 1]; ++b) {
        const std::size_t entry = entries_[b];
        const int r = entryRow_[entry];
        values_[entry] = -settings_.volume[r / 3] * (plus_[r] - f[r]) / (2.0 * eps);
      }
    }
  }
  evaluator.evaluate(dt, false, false);  // the state of the unperturbed configuration again

  // Held degrees of freedom: zero rows and columns, `heldDiagonal` on the diagonal.
  const auto colMap = matrix_->getColMap();
  Vector heldOwned(topology_.ownedMap3()), heldColumns(colMap);
  {
    auto view = heldOwned.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (int r = 0; r < 3 * n; ++r) view(r, 0) = held[r];
  }
  const auto importer = matrix_->getGraph()->getImporter();
  if (importer.is_null())
    heldColumns.assign(heldOwned);
  else
    heldColumns.doImport(heldOwned, *importer, Tpetra::INSERT);
  auto heldColumn = heldColumns.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto rowMap = matrix_->getRowMap();
  matrix_->resumeFill();
  for (int r = 0; r < 3 * n; ++r) {
    const GlobalOrdinal row = rowMap->getGlobalElement(r);
    for (std::size_t k = rowOffsets_[r]; k < rowOffsets_[r + 1]; ++k) {
      if (held[r] != 0.0 || heldColumn(columns_[k], 0) != 0.0) values_[k] = 0.0;
      if (colMap->getGlobalElement(columns_[k]) == row) {
        if (held[r] != 0.0)
          values_[k] = heldDiagonal;
        else if (addedDiagonal)
          values_[k] += addedDiagonal[r];
      }
    }
    matrix_->replaceLocalValues(r, static_cast<LocalOrdinal>(rowOffsets_[r + 1] - rowOffsets_[r]),
                                values_.data() + rowOffsets_[r], columns_.data() + rowOffsets_[r]);
  }
  matrix_->fillComplete(topology_.ownedMap3(), topology_.ownedMap3());
}

double FiniteDifferenceTangent::bytes() const {
  return static_cast<double>(columns_.size()) *
             (sizeof(LocalOrdinal) + sizeof(double) + sizeof(std::size_t) + sizeof(int)) +
         static_cast<double>(rowOffsets_.size()) * sizeof(std::size_t);
}

}  // namespace peridot
