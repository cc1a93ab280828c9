#pragma once
// A small Exodus mesh writer for the tests: blocks of any element type, attributes, names, an
// element number map and node sets.
#include <exodusII.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace peridot {
namespace testing {

struct TestBlock {
  int64_t id = 1;
  std::string type = "HEX8";
  int64_t nodesPerElement = 8;
  int64_t numAttributes = 0;
  std::vector<int64_t> connectivity;  // 1-based
  std::vector<double> attributes;     // numAttributes per element
  std::string name;                   // empty: unnamed
  int64_t size() const { return static_cast<int64_t>(connectivity.size()) / nodesPerElement; }
};

struct TestNodeSet {
  int64_t id = 1;
  std::string name;
  std::vector<int64_t> nodes;
};

struct TestMesh {
  int dimension = 3;
  std::vector<double> x, y, z;
  std::vector<TestBlock> blocks;
  std::vector<int64_t> elementIds;  // empty: no element number map
  std::vector<TestNodeSet> nodeSets;
};

inline void writeMesh(const std::string& path, const TestMesh& mesh) {
  int cpuWordSize = sizeof(double);
  int ioWordSize = sizeof(double);
  const int exoid = ex_create(path.c_str(), EX_CLOBBER, &cpuWordSize, &ioWordSize);
  ASSERT_GE(exoid, 0);
  ex_set_int64_status(exoid, EX_ALL_INT64_API);
  int64_t numElements = 0;
  for (const auto& b : mesh.blocks) numElements += b.size();
  ASSERT_GE(
      ex_put_init(exoid, "peridot test mesh", mesh.dimension, static_cast<int64_t>(mesh.x.size()),
                  numElements, static_cast<int64_t>(mesh.blocks.size()),
                  static_cast<int64_t>(mesh.nodeSets.size()), 0),
      0);
  ASSERT_GE(ex_put_coord(exoid, mesh.x.data(), mesh.y.data(),
                         mesh.dimension > 2 ? mesh.z.data() : nullptr),
            0);
  for (const auto& b : mesh.blocks) {
    ASSERT_GE(ex_put_block(exoid, EX_ELEM_BLOCK, b.id, b.type.c_str(), b.size(), b.nodesPerElement,
                           0, 0, b.numAttributes),
              0);
    if (b.size() > 0) {
      ASSERT_GE(ex_put_conn(exoid, EX_ELEM_BLOCK, b.id, b.connectivity.data(), nullptr, nullptr),
                0);
    }
    if (b.numAttributes > 0) {
      ASSERT_GE(ex_put_attr(exoid, EX_ELEM_BLOCK, b.id, b.attributes.data()), 0);
    }
    if (!b.name.empty()) {
      ASSERT_GE(ex_put_name(exoid, EX_ELEM_BLOCK, b.id, b.name.c_str()), 0);
    }
  }
  if (!mesh.elementIds.empty()) {
    std::size_t numElements = 0;
    for (const auto& b : mesh.blocks) numElements += b.connectivity.size() / b.nodesPerElement;
    ASSERT_EQ(mesh.elementIds.size(), numElements) << "the test mesh needs one id per element";
    ASSERT_GE(ex_put_id_map(exoid, EX_ELEM_MAP, mesh.elementIds.data()), 0);
  }
  for (const auto& s : mesh.nodeSets) {
    ASSERT_GE(ex_put_set_param(exoid, EX_NODE_SET, s.id, static_cast<int64_t>(s.nodes.size()), 0),
              0);
    ASSERT_GE(ex_put_set(exoid, EX_NODE_SET, s.id, s.nodes.data(), nullptr), 0);
    if (!s.name.empty()) {
      ASSERT_GE(ex_put_name(exoid, EX_NODE_SET, s.id, s.name.c_str()), 0);
    }
  }
  ASSERT_EQ(ex_close(exoid), 0);
}

inline void addNode(TestMesh& mesh, double x, double y, double z) {
  mesh.x.push_back(x);
  mesh.y.push_back(y);
  mesh.z.push_back(z);
}

}  // namespace testing
}  // namespace peridot
