#include "parallel/Partition.hpp"

#include <zoltan.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace peridot {

namespace {

// The slice of the cloud this rank hands to Zoltan: a contiguous block of point indices.
struct Slice {
  const std::vector<double>* x;
  const std::vector<double>* weights;
  std::size_t begin, end;
};

int numObjects(void* data, int* ierr) {
  auto* s = static_cast<Slice*>(data);
  *ierr = ZOLTAN_OK;
  return static_cast<int>(s->end - s->begin);
}

void objectList(void* data, int, int, ZOLTAN_ID_PTR globalIds, ZOLTAN_ID_PTR localIds, int wgtDim,
                float* weights, int* ierr) {
  auto* s = static_cast<Slice*>(data);
  for (std::size_t i = s->begin; i < s->end; ++i) {
    globalIds[i - s->begin] = static_cast<ZOLTAN_ID_TYPE>(i);
    localIds[i - s->begin] = static_cast<ZOLTAN_ID_TYPE>(i - s->begin);
    if (wgtDim > 0) weights[i - s->begin] = static_cast<float>((*s->weights)[i]);
  }
  *ierr = ZOLTAN_OK;
}

int numGeometry(void*, int* ierr) {
  *ierr = ZOLTAN_OK;
  return 3;
}

void geometry(void* data, int, int, int numObj, ZOLTAN_ID_PTR globalIds, ZOLTAN_ID_PTR, int,
              double* coords, int* ierr) {
  auto* s = static_cast<Slice*>(data);
  for (int k = 0; k < numObj; ++k) {
    const std::size_t i = globalIds[k];
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

std::vector<int> partitionPoints(const std::vector<double>& x, const std::vector<double>& weights,
                                 MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const std::size_t n = x.size() / 3;
  std::vector<int> owner(n, 0);
  if (size == 1) return owner;
  // Zoltan's RCB refuses to cut fewer points than parts; a handful of points per rank needs no
  // balancing anyway, so split them along the space-filling curve instead.
  if (n < static_cast<std::size_t>(4 * size)) return partitionAlongCurve(x, weights, size);

  Slice slice{&x, &weights, n * rank / size, n * (rank + 1) / size};
  float version = 0;
  Zoltan_Initialize(0, nullptr, &version);
  Zoltan_Struct* zz = Zoltan_Create(comm);
  Zoltan_Set_Param(zz, "DEBUG_LEVEL", "0");
  Zoltan_Set_Param(zz, "LB_METHOD", "RCB");
  Zoltan_Set_Param(zz, "NUM_GID_ENTRIES", "1");
  Zoltan_Set_Param(zz, "NUM_LID_ENTRIES", "1");
  Zoltan_Set_Param(zz, "RETURN_LISTS", "PARTS");
  Zoltan_Set_Param(zz, "OBJ_WEIGHT_DIM", weights.empty() ? "0" : "1");
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
  std::vector<int> local(slice.end - slice.begin, rank);
  for (int k = 0; k < numExport; ++k) local[exportLocal[k]] = exportParts[k];
  Zoltan_LB_Free_Part(&importGlobal, &importLocal, &importProcs, &importParts);
  Zoltan_LB_Free_Part(&exportGlobal, &exportLocal, &exportProcs, &exportParts);
  Zoltan_Destroy(&zz);

  std::vector<int> counts(size), displs(size);
  for (int r = 0; r < size; ++r) {
    const std::size_t b = n * r / size, e = n * (r + 1) / size;
    counts[r] = static_cast<int>(e - b);
    displs[r] = static_cast<int>(b);
  }
  MPI_Allgatherv(local.data(), static_cast<int>(local.size()), MPI_INT, owner.data(), counts.data(),
                 displs.data(), MPI_INT, comm);
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
