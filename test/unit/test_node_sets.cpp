// Node sets: ids read from a deck's list (comments, any whitespace, errors that name the word) and
// turned into owned local indices, sorted and each once.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "bc/NodeSets.hpp"
#include "core/Error.hpp"
#include "core/IdIndex.hpp"
#include "parallel/Topology.hpp"

using namespace peridot;

namespace {

// One rank owning global ids `ids` (0-based), in that local order.
Topology ownerOf(const std::vector<long long>& ids) {
  Topology t;
  t.comm = MPI_COMM_SELF;
  t.numOwned = static_cast<int>(ids.size());
  t.overlapGlobalId = ids;
  return t;
}

std::vector<long long> readSet(const Topology& t, const std::string& value) {
  NodeSetSpec spec;
  spec.name = "S";
  spec.path = "Boundary Conditions -> S";
  spec.value = value;
  return collectNodeSets(t, {spec}).at("S");
}

// The set read from a file holding `text` (a deck's value that is not all integers names a file).
std::vector<long long> readFile(const Topology& t, const std::string& text) {
  const std::string name = ::testing::TempDir() + "peridot_node_set.txt";
  std::ofstream(name) << text;
  std::vector<long long> ids = readSet(t, name);
  std::remove(name.c_str());
  return ids;
}

std::string errorOf(const Topology& t, const std::string& text) {
  try {
    readFile(t, text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(NodeSets, ReadsIdsBetweenAnyWhitespaceAndSkipsComments) {
  // Owned: global ids 0 .. 9 (1-based 1 .. 10).
  std::vector<long long> ids(10);
  for (int k = 0; k < 10; ++k) ids[k] = k;
  const Topology t = ownerOf(ids);
  EXPECT_EQ(readFile(t, "3 1\t\t7\r\n  # 5 6\n/ 8\n* 9\n\n+2 10 3\v4\f"),
            (std::vector<long long>{0, 1, 2, 3, 6, 9}));
  EXPECT_EQ(readSet(t, " 10 9\n  1 "), (std::vector<long long>{0, 8, 9}));  // in the deck
}

TEST(NodeSets, NamesTheWordItCannotRead) {
  std::vector<long long> ids(10);
  for (int k = 0; k < 10; ++k) ids[k] = k;
  const Topology t = ownerOf(ids);
  EXPECT_NE(errorOf(t, "1 2 3x 4").find("\"3x\" is not a point id"), std::string::npos)
      << errorOf(t, "1 2 3x 4");
  EXPECT_NE(errorOf(t, "1 - 4").find("\"-\" is not a point id"), std::string::npos);
  EXPECT_NE(errorOf(t, "1 11").find("point id 11 is out of range"), std::string::npos);
  EXPECT_NE(errorOf(t, "1\n0").find("point id 0 is out of range"), std::string::npos);
}

TEST(NodeSets, OwnedPointsAreSortedAndOnlyTheRanksOwn) {
  // Owned: a shuffle of even global ids 0 .. 398 (local k holds ids[k]).
  std::vector<long long> ids;
  for (long long k = 0; k < 200; ++k) ids.push_back(2 * ((k * 37) % 200));
  const IdIndex owned(ids.data(), ids.size());
  for (const std::size_t size : {std::size_t{5}, std::size_t{150}}) {  // both of its paths
    std::vector<long long> set;
    for (std::size_t k = 0; k < size; ++k) set.push_back(static_cast<long long>(3 * k));
    std::vector<int> expected;
    for (std::size_t local = 0; local < ids.size(); ++local)
      if (std::find(set.begin(), set.end(), ids[local]) != set.end())
        expected.push_back(static_cast<int>(local));
    EXPECT_EQ(ownedPoints(set, owned), expected) << size << " ids";
  }
}
