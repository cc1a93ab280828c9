// fields/FieldManager: a node field's values are allocated by the field (so that large ones take
// 2 MiB pages) and viewed by its Tpetra vector: they start at zero, are aligned to a cache line
// as Kokkos aligns its own, and the vector sees what the kernels write through the pointer.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdint>
#include <vector>

#include "fields/FieldManager.hpp"
#include "parallel/Topology.hpp"

using namespace peridot;

TEST(FieldStorage, ValuesAreZeroedAlignedAndViewedByTheVector) {
  PointCloud cloud;
  for (int i = 0; i < 5; ++i) {
    cloud.x.insert(cloud.x.end(), {static_cast<double>(i), 0.0, 0.0});
    cloud.volume.push_back(1.0);
    cloud.blockId.push_back(1);
    cloud.globalId.push_back(i);
  }
  cloud.blockNames[1] = "block_1";
  const Topology topology =
      buildTopology(cloud, std::vector<double>(5, 1.5), TopologyOptions(), MPI_COMM_SELF);
  FieldManager fields(topology);
  double* a = fields.node("A", 3);
  double* b = fields.node("B", 1);
  const std::size_t n = 3 * static_cast<std::size_t>(topology.numOverlap);
  for (double* p : {a, b}) EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % 64, 0u);
  for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(a[k], 0.0);
  const NodeField& f = fields.nodeField("A");
  ASSERT_EQ(f.overlap->getLocalLength(), n);
  EXPECT_EQ(f.overlap->getData().getRawPtr(), a);
  for (std::size_t k = 0; k < n; ++k) a[k] = static_cast<double>(k) + 1.0;
  // sum of 1..n, through Tpetra's own reduction over the view
  EXPECT_EQ(f.overlap->norm1(), 0.5 * static_cast<double>(n) * static_cast<double>(n + 1));
  // Asking again returns the same storage; a third field does not move the first.
  fields.node("C", 2);
  EXPECT_EQ(fields.node("A", 3), a);
  EXPECT_EQ(fields.nodeField("A").data, a);
}
