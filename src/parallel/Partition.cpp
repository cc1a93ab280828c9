#include "parallel/Partition.hpp"

#include <zoltan.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace peridot {

namespace {

// The points this rank hands to Zoltan (its share); Zoltan's global ids are begin + index.
struct Slice {
  const std::vector<double>* x;
  const std::vector<double>* weights;
  std::size_t begin, end;  // global numbering of this rank's points: [begin, end)
};

int numObjects(void* data, int* ierr) {
  auto* s = static_cast<Slice*>(data);
  *ierr = ZOLTAN_OK;
  return static_cast<int>(s->end - s->begin);
}

void objectList(void* data, int, int, ZOLTAN_ID_PTR globalIds, ZOLTAN_ID_PTR localIds, int wgtDim,
                float* weights, int* ierr) {
  auto* s = static_cast<Slice*>(data);
  for (std::size_t i = 0; i < s->end - s->begin; ++i) {
    globalIds[i] = static_cast<ZOLTAN_ID_TYPE>(s->begin + i);
    localIds[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    if (wgtDim > 0) weights[i] = static_cast<float>((*s->weights)[i]);
  }
  *ierr = ZOLTAN_OK;
}

int numGeometry(void*, int* ierr) {
  *ierr = ZOLTAN_OK;
  return 3;
}

void geometry(void* data, int, int, int numObj, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR localIds, int,
              double* coords, int* ierr) {
  auto* s = static_cast<Slice*>(data);
  for (int k = 0; k < numObj; ++k) {
    const std::size_t i = localIds[k];
    for (int d = 0; d < 3; ++d) coords[3 * k + d] = (*s->x)[3 * i + d];
  }
  *ierr = ZOLTAN_OK;
}

}  // namespace

std::vector<int> partitionAlongCurve(const std::vector<double>& x,
                                     const std::vector<double>& weights, int numParts) {
  const std::size_t n = x.size() / 3;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      lo[d] = i == 0 ? x[3 * i + d] : std::min(lo[d], x[3 * i + d]);
      hi[d] = i == 0 ? x[3 * i + d] : std::max(hi[d], x[3 * i + d]);
    }
  std::vector<std::size_t> order(n);
  std::vector<unsigned long long> key(n);
  for (std::size_t i = 0; i < n; ++i) {
    order[i] = i;
    key[i] = mortonKey(&x[3 * i], lo, hi);
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return key[a] != key[b] ? key[a] < key[b] : a < b;
  });
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) total += weights.empty() ? 1.0 : weights[i];
  std::vector<int> owner(n, 0);
  double running = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    const double w = weights.empty() ? 1.0 : weights[i];
    owner[i] = std::min(numParts - 1, static_cast<int>((running + 0.5 * w) / total * numParts));
    running += w;
  }
  return owner;
}

std::vector<int> partitionShare(const std::vector<double>& x, const std::vector<double>& weights,
                                MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const std::size_t n = x.size() / 3;
  std::vector<int> owner(n, rank);
  if (size == 1) return owner;
  long long local = static_cast<long long>(n), begin = 0, total = 0;
  MPI_Exscan(&local, &begin, 1, MPI_LONG_LONG, MPI_SUM, comm);
  if (rank == 0) begin = 0;
  MPI_Allreduce(&local, &total, 1, MPI_LONG_LONG, MPI_SUM, comm);
  // A rank that owns no point passes no weights: whether the partition is weighted is the
  // ranks' common decision.
  int weighted = weights.empty() ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &weighted, 1, MPI_INT, MPI_MAX, comm);
  // Zoltan's RCB refuses to cut fewer points than parts; a handful of points per rank needs no
  // balancing anyway, so split them along the space-filling curve instead (gathering them is
  // O(ranks)).
  if (total < 4LL * size) {
    std::vector<int> counts(size), displs(size, 0);
    const int mine = static_cast<int>(n);
    MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
    for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
    std::vector<double> allX(3 * static_cast<std::size_t>(total)), allW;
    std::vector<int> counts3(size), displs3(size);
    for (int r = 0; r < size; ++r) counts3[r] = 3 * counts[r], displs3[r] = 3 * displs[r];
    MPI_Allgatherv(x.data(), 3 * mine, MPI_DOUBLE, allX.data(), counts3.data(), displs3.data(),
                   MPI_DOUBLE, comm);
    if (weighted) {
      allW.resize(static_cast<std::size_t>(total));
      MPI_Allgatherv(weights.data(), mine, MPI_DOUBLE, allW.data(), counts.data(), displs.data(),
                     MPI_DOUBLE, comm);
    }
    const std::vector<int> all = partitionAlongCurve(allX, allW, size);
    return std::vector<int>(all.begin() + displs[rank], all.begin() + displs[rank] + mine);
  }

  Slice slice{&x, &weights, static_cast<std::size_t>(begin), static_cast<std::size_t>(begin) + n};
  float version = 0;
  Zoltan_Initialize(0, nullptr, &version);
  Zoltan_Struct* zz = Zoltan_Create(comm);
  Zoltan_Set_Param(zz, "DEBUG_LEVEL", "0");
  Zoltan_Set_Param(zz, "LB_METHOD", "RCB");
  Zoltan_Set_Param(zz, "NUM_GID_ENTRIES", "1");
  Zoltan_Set_Param(zz, "NUM_LID_ENTRIES", "1");
  Zoltan_Set_Param(zz, "RETURN_LISTS", "PARTS");
  Zoltan_Set_Param(zz, "OBJ_WEIGHT_DIM", weighted ? "1" : "0");
  Zoltan_Set_Param(zz, "RCB_REUSE", "0");
  Zoltan_Set_Num_Obj_Fn(zz, numObjects, &slice);
  Zoltan_Set_Obj_List_Fn(zz, objectList, &slice);
  Zoltan_Set_Num_Geom_Fn(zz, numGeometry, &slice);
  Zoltan_Set_Geom_Multi_Fn(zz, geometry, &slice);

  int changes = 0, numGid = 0, numLid = 0, numImport = 0, numExport = 0;
  ZOLTAN_ID_PTR importGlobal = nullptr, importLocal = nullptr, exportGlobal = nullptr,
                exportLocal = nullptr;
  int *importProcs = nullptr, *importParts = nullptr, *exportProcs = nullptr,
      *exportParts = nullptr;
  const int rc = Zoltan_LB_Partition(zz, &changes, &numGid, &numLid, &numImport, &importGlobal,
                                     &importLocal, &importProcs, &importParts, &numExport,
                                     &exportGlobal, &exportLocal, &exportProcs, &exportParts);
  if (rc != ZOLTAN_OK) {
    Zoltan_Destroy(&zz);
    throw std::runtime_error("Zoltan RCB partitioning failed (code " + std::to_string(rc) + ")");
  }
  (void)changes;
  // With RETURN_LISTS=PARTS the export lists hold the part of every local object.
  for (int k = 0; k < numExport; ++k) owner[exportLocal[k]] = exportParts[k];
  Zoltan_LB_Free_Part(&importGlobal, &importLocal, &importProcs, &importParts);
  Zoltan_LB_Free_Part(&exportGlobal, &exportLocal, &exportProcs, &exportParts);
  Zoltan_Destroy(&zz);
  return owner;
}

unsigned long long mortonKey(const double* x, const double* boxMin, const double* boxMax) {
  unsigned long long key = 0;
  unsigned int q[3];
  for (int d = 0; d < 3; ++d) {
    const double extent = boxMax[d] - boxMin[d];
    const double t = extent > 0 ? (x[d] - boxMin[d]) / extent : 0.0;
    q[d] = static_cast<unsigned int>(std::clamp(t, 0.0, 1.0) * 2097151.0);  // 21 bits per axis
  }
  for (int bit = 20; bit >= 0; --bit)
    for (int d = 0; d < 3; ++d) key = (key << 1) | ((q[d] >> bit) & 1u);
  return key;
}

}  // namespace peridot
