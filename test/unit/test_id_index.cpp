// IdIndex: the same answers from its table (dense ids) and its sorted copy (sparse ids).
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/IdIndex.hpp"

using peridot::IdIndex;

namespace {

// find() and forEachInOrder() against a linear scan of the ids.
void expectLikeAScan(const std::vector<long long>& ids, long long probeFrom, long long probeTo) {
  const IdIndex index(ids.data(), ids.size());
  for (long long id = probeFrom; id <= probeTo; ++id) {
    int expected = -1;
    for (std::size_t k = 0; k < ids.size() && expected < 0; ++k)
      if (ids[k] == id) expected = static_cast<int>(k);
    EXPECT_EQ(index.find(id), expected) << "id " << id;
  }
  std::vector<long long> visited;
  index.forEachInOrder([&](long long id, int local) {
    EXPECT_EQ(ids[static_cast<std::size_t>(local)], id);
    EXPECT_EQ(index.find(id), local);
    visited.push_back(id);
  });
  std::vector<long long> distinct(ids);
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  EXPECT_EQ(visited, distinct);
}

}  // namespace

TEST(IdIndex, DenseIdsThroughTheTable) {
  // A permutation of 10 .. 29 with a gap (range 20 over 19 ids: the table).
  std::vector<long long> ids;
  for (long long k = 0; k < 20; ++k)
    if (k != 7) ids.push_back(10 + (k * 7) % 20);
  expectLikeAScan(ids, 0, 40);
}

TEST(IdIndex, SparseIdsThroughTheSortedCopy) {
  // Ids 1000 apart: far too wide a range for a table.
  std::vector<long long> ids = {5000, 1000, 9000000, 3000, 0, 777777};
  expectLikeAScan(ids, -2, 10);
  expectLikeAScan(ids, 995, 1005);
  EXPECT_EQ(IdIndex(ids.data(), ids.size()).find(9000000), 2);
  EXPECT_EQ(IdIndex(ids.data(), ids.size()).find(777777), 5);
}

TEST(IdIndex, AnIdListedTwiceKeepsItsFirstIndexEitherWay) {
  const std::vector<long long> dense = {3, 4, 5, 4, 6};
  const std::vector<long long> sparse = {3, 40000, 5, 40000, 600000};
  expectLikeAScan(dense, 0, 8);
  expectLikeAScan(sparse, 0, 8);
  EXPECT_EQ(IdIndex(dense.data(), dense.size()).find(4), 1);
  EXPECT_EQ(IdIndex(sparse.data(), sparse.size()).find(40000), 1);
}

TEST(IdIndex, NoIds) {
  const IdIndex index(nullptr, 0);
  EXPECT_EQ(index.find(0), -1);
  int visits = 0;
  index.forEachInOrder([&](long long, int) { ++visits; });
  EXPECT_EQ(visits, 0);
}
