#pragma once
// The tangent stiffness as 3x3 blocks on the overlap points: a CSR pattern of point rows (owned
// points, then ghosts) and point columns, each row's columns sorted, 9 values a block (row-major,
// row component then column component). Materials add their families' blocks here; the Tangent
// then hands the values to Tpetra. Contiguous arrays: no allocation while a model adds.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace peridot {

struct TangentBlocks {
  std::vector<std::int64_t> offsets;  // number of row points + 1
  std::vector<int> columns;           // overlap point indices, sorted in each row
  std::vector<double> values;         // 9 per entry

  // The block of row point a and column point c; both must be in the pattern (the pattern is
  // built from the same reach the models fill).
  double* block(int a, int c) {
    const int* first = columns.data() + offsets[a];
    const int* last = columns.data() + offsets[a + 1];
    const int* it = std::lower_bound(first, last, c);
    return values.data() + 9 * (it - columns.data());
  }
  // K_ac += scale * (p q^T)
  void addOuter(int a, int c, double scale, const double* p, const double* q) {
    double* k = block(a, c);
    for (int r = 0; r < 3; ++r)
      for (int e = 0; e < 3; ++e) k[3 * r + e] += scale * p[r] * q[e];
  }
  // K_ac += scale * D (D a 3x3 row-major block)
  void add(int a, int c, double scale, const double* D) {
    double* k = block(a, c);
    for (int r = 0; r < 9; ++r) k[r] += scale * D[r];
  }
};

}  // namespace peridot
