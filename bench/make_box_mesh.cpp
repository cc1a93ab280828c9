// Writes an Exodus HEX8 box mesh of n x n x n unit-spacing elements (one block, node sets on the
// faces x = 0 and x = n), to measure the distributed reader on large meshes.
// Usage: bench_make_box_mesh n file.g      (n = 128: 2.1M elements, about 130 MB)
#include <exodusII.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

bool ok(int status, const char* call) {
  if (status < 0) std::fprintf(stderr, "bench_make_box_mesh: %s failed (%d)\n", call, status);
  return status >= 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 || std::atoll(argv[1]) < 1) {
    std::fprintf(stderr, "usage: bench_make_box_mesh n file.g\n");
    return 2;
  }
  const int64_t n = std::atoll(argv[1]), m = n + 1;
  int cpuWordSize = sizeof(double), ioWordSize = sizeof(double);
  const int exoid = ex_create(argv[2], EX_CLOBBER | EX_LARGE_MODEL, &cpuWordSize, &ioWordSize);
  if (exoid < 0) {
    std::fprintf(stderr, "bench_make_box_mesh: cannot create %s\n", argv[2]);
    return 1;
  }
  ex_set_int64_status(exoid, EX_ALL_INT64_API);
  const int64_t numNodes = m * m * m, numElements = n * n * n;
  if (!ok(ex_put_init(exoid, "box", 3, numNodes, numElements, 1, 2, 0), "ex_put_init")) return 1;
  // One z layer of nodes at a time keeps the tool's memory at O(n^2) for the coordinates.
  std::vector<double> x(static_cast<std::size_t>(m * m)), y(x.size()), z(x.size());
  for (int64_t k = 0; k < m; ++k) {
    for (int64_t j = 0; j < m; ++j)
      for (int64_t i = 0; i < m; ++i) {
        const auto a = static_cast<std::size_t>(i + m * j);
        x[a] = static_cast<double>(i);
        y[a] = static_cast<double>(j);
        z[a] = static_cast<double>(k);
      }
    if (!ok(ex_put_partial_coord(exoid, 1 + k * m * m, m * m, x.data(), y.data(), z.data()),
            "ex_put_partial_coord")) {
      return 1;
    }
  }
  if (!ok(ex_put_block(exoid, EX_ELEM_BLOCK, 1, "HEX8", numElements, 8, 0, 0, 0), "ex_put_block")) {
    return 1;
  }
  std::vector<int64_t> conn(static_cast<std::size_t>(8 * numElements));
  std::size_t at = 0;
  const auto node = [&](int64_t i, int64_t j, int64_t k) { return 1 + i + m * (j + m * k); };
  for (int64_t k = 0; k < n; ++k)
    for (int64_t j = 0; j < n; ++j)
      for (int64_t i = 0; i < n; ++i) {
        for (const int64_t v : {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k),
                                node(i, j + 1, k), node(i, j, k + 1), node(i + 1, j, k + 1),
                                node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)}) {
          conn[at++] = v;
        }
      }
  if (!ok(ex_put_conn(exoid, EX_ELEM_BLOCK, 1, conn.data(), nullptr, nullptr), "ex_put_conn")) {
    return 1;
  }
  conn = std::vector<int64_t>();
  for (int face = 0; face < 2; ++face) {
    std::vector<int64_t> nodes;
    for (int64_t k = 0; k < m; ++k)
      for (int64_t j = 0; j < m; ++j) nodes.push_back(node(face == 0 ? 0 : n, j, k));
    const int64_t id = face + 1;
    if (!ok(ex_put_set_param(exoid, EX_NODE_SET, id, static_cast<int64_t>(nodes.size()), 0),
            "ex_put_set_param") ||
        !ok(ex_put_set(exoid, EX_NODE_SET, id, nodes.data(), nullptr), "ex_put_set") ||
        !ok(ex_put_name(exoid, EX_NODE_SET, id, face == 0 ? "x_min" : "x_max"), "ex_put_name")) {
      return 1;
    }
  }
  return ok(ex_close(exoid), "ex_close") ? 0 : 1;
}
