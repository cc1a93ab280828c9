// Writes the Exodus mesh of the restart test in Peridigm's form (test/restart/decks/peridigm):
// block 1, a cubic projectile of 4 x 4 x 4 HEX8 elements in front of block 2, a plate of
// 3 x 18 x 18 HEX8 elements whose normal is x; node set 1 holds every projectile node. Units
// are mm. The blocks share no node. Usage: make_perforation_mesh file.g
#include <exodusII.h>

#include <cstdint>
#include <cstdio>
#include <vector>

namespace {

struct Brick {
  double origin[3];
  int64_t n[3];
};

constexpr double kSpacing = 0.17;

bool ok(int status, const char* what) {
  if (status < 0) std::fprintf(stderr, "make_perforation_mesh: %s failed (%d)\n", what, status);
  return status >= 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_perforation_mesh file.g\n");
    return 2;
  }
  // The projectile's front face is 0.25 mm from the plate, centred on it.
  const Brick bricks[2] = {{{-0.25 - 4 * kSpacing, -2 * kSpacing, -2 * kSpacing}, {4, 4, 4}},
                           {{0.0, -9 * kSpacing, -9 * kSpacing}, {3, 18, 18}}};
  int64_t numNodes = 0, numElements = 0;
  for (const auto& b : bricks) {
    numNodes += (b.n[0] + 1) * (b.n[1] + 1) * (b.n[2] + 1);
    numElements += b.n[0] * b.n[1] * b.n[2];
  }
  int cpuWordSize = sizeof(double), ioWordSize = sizeof(double);
  const int exoid = ex_create(argv[1], EX_CLOBBER, &cpuWordSize, &ioWordSize);
  if (exoid < 0) {
    std::fprintf(stderr, "make_perforation_mesh: cannot create %s\n", argv[1]);
    return 1;
  }
  ex_set_int64_status(exoid, EX_ALL_INT64_API);
  if (!ok(ex_put_init(exoid, "perforation", 3, numNodes, numElements, 2, 1, 0), "ex_put_init")) {
    return 1;
  }
  std::vector<double> x, y, z;
  std::vector<int64_t> projectileNodes;
  int64_t firstNode = 1;
  for (int b = 0; b < 2; ++b) {
    const Brick& brick = bricks[b];
    const int64_t mx = brick.n[0] + 1, my = brick.n[1] + 1, mz = brick.n[2] + 1;
    for (int64_t k = 0; k < mz; ++k)
      for (int64_t j = 0; j < my; ++j)
        for (int64_t i = 0; i < mx; ++i) {
          x.push_back(brick.origin[0] + kSpacing * static_cast<double>(i));
          y.push_back(brick.origin[1] + kSpacing * static_cast<double>(j));
          z.push_back(brick.origin[2] + kSpacing * static_cast<double>(k));
          if (b == 0) projectileNodes.push_back(firstNode + i + mx * (j + my * k));
        }
    std::vector<int64_t> conn;
    const auto node = [&](int64_t i, int64_t j, int64_t k) {
      return firstNode + i + mx * (j + my * k);
    };
    for (int64_t k = 0; k < brick.n[2]; ++k)
      for (int64_t j = 0; j < brick.n[1]; ++j)
        for (int64_t i = 0; i < brick.n[0]; ++i)
          for (const int64_t v : {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k),
                                  node(i, j + 1, k), node(i, j, k + 1), node(i + 1, j, k + 1),
                                  node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)})
            conn.push_back(v);
    const int64_t count = brick.n[0] * brick.n[1] * brick.n[2];
    if (!ok(ex_put_block(exoid, EX_ELEM_BLOCK, b + 1, "HEX8", count, 8, 0, 0, 0), "ex_put_block") ||
        !ok(ex_put_conn(exoid, EX_ELEM_BLOCK, b + 1, conn.data(), nullptr, nullptr),
            "ex_put_conn")) {
      return 1;
    }
    firstNode += mx * my * mz;
  }
  if (!ok(ex_put_coord(exoid, x.data(), y.data(), z.data()), "ex_put_coord") ||
      !ok(ex_put_set_param(exoid, EX_NODE_SET, 1, static_cast<int64_t>(projectileNodes.size()), 0),
          "ex_put_set_param") ||
      !ok(ex_put_set(exoid, EX_NODE_SET, 1, projectileNodes.data(), nullptr), "ex_put_set")) {
    return 1;
  }
  return ok(ex_close(exoid), "ex_close") ? 0 : 1;
}
