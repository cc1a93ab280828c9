#include "neighbor/HalfBondList.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstring>
#include <type_traits>

#include "core/ProcessorsPerRank.hpp"
#include "neighbor/BondGeometry.hpp"
#include "parallel/Partition.hpp"

namespace peridot {

namespace {

// Row entries p0 .. p0 + m of one per-pair array (if the run keeps it): entry k takes the old
// entry order[k].
template <typename T>
void permute(std::vector<T>& v, std::int64_t p0, const std::vector<int>& order) {
  if (v.empty()) return;
  thread_local std::vector<T> old;
  old.assign(v.begin() + p0, v.begin() + p0 + static_cast<std::int64_t>(order.size()));
  for (std::size_t k = 0; k < order.size(); ++k) v[p0 + k] = old[order[k]];
}

void permuteRow(HalfBondList& h, std::int64_t p0, const std::vector<int>& order) {
  permute(h.pairPoint, p0, order);
  permute(h.pairSlot, p0, order);
  permute(h.pairSlotHigh, p0, order);
  permute(h.pairLength, p0, order);
  permute(h.pairLengthIndex, p0, order);
  permute(h.pairLengthIndexHigh, p0, order);
  permute(h.pairDamage, p0, order);
  permute(h.pairInfluence, p0, order);
}

}  // namespace

std::size_t HalfBondList::bytes() const {
  return rowPoint.size() * sizeof(int) + rowIntact.size() * sizeof(int) +
         rowPairOffsets.size() * sizeof(std::int64_t) + pairPoint.size() * sizeof(int) +
         pairSlot.size() + pairSlotHigh.size() + pairLength.size() * sizeof(double) +
         pairLengthIndex.size() + pairLengthIndexHigh.size() + lengthTable.size() * sizeof(double) +
         pairDamage.size() * sizeof(float) + pairInfluence.size() * sizeof(double);
}

void HalfBondList::gatherDamage(const Topology& t, const float* bondDamage,
                                const unsigned char* bondBroken) {
  pending_ = false;
  // A pair's damage as the full lists hold it (0 in a run without damage).
  const auto damageOf = [&](std::size_t r, std::int64_t p) {
    const std::int64_t e = fullEntry(t, r, p);
    return bondDamage ? bondDamage[e] : (bondBroken && bondBroken[e] ? 1.0f : 0.0f);
  };
  // Bonds intact or broken (the critical stretch's): the rows' partition is the damage. A copy
  // only where some bond is partly damaged.
  bool partial = false;
  for (std::size_t r = 0; r < rowPoint.size() && bondDamage && !partial; ++r)
    for (std::int64_t p = rowPairOffsets[r]; p < rowPairOffsets[r + 1]; ++p) {
      const float d = damageOf(r, p);
      partial = partial || (d != 0.0f && d != 1.0f);
    }
  pairDamage.assign(partial ? static_cast<std::size_t>(numPairs() + kPadding) : 0, 0.0f);
  std::vector<int> order, partitioned;
  for (std::size_t r = 0; r < rowPoint.size(); ++r) {
    const std::int64_t p0 = rowPairOffsets[r];
    const int m = static_cast<int>(rowPairOffsets[r + 1] - p0);
    if (partial)
      for (std::int64_t p = p0; p < p0 + m; ++p) pairDamage[p] = damageOf(r, p);
    // The row's order (buildHalfBondList: an owned row's pairs in the order of its full list, a
    // ghost row's by owned point), then its intact pairs first. Nothing to move in a row in its
    // order without broken pairs (every row at the start of a run).
    const bool owned = rowPoint[r] < t.numOwned;
    const auto key = [&](int k) { return owned ? slot(p0 + k) : pairPoint[p0 + k]; };
    const auto intact = [&](int k) { return damageOf(r, p0 + k) != 1.0f; };
    bool inOrder = true, allIntact = true;
    for (int k = 0; k < m; ++k) {
      inOrder = inOrder && (k == 0 || key(k - 1) < key(k));
      allIntact = allIntact && intact(k);
    }
    rowIntact[r] = m;
    if (inOrder && allIntact) continue;
    order.resize(static_cast<std::size_t>(m));
    for (int k = 0; k < m; ++k) order[k] = k;
    if (!inOrder)
      std::sort(order.begin(), order.end(), [&](int i, int j) { return key(i) < key(j); });
    partitioned.clear();
    for (const int k : order)
      if (intact(k)) partitioned.push_back(k);
    rowIntact[r] = static_cast<int>(partitioned.size());
    for (const int k : order)
      if (!intact(k)) partitioned.push_back(k);
    permuteRow(*this, p0, partitioned);
  }
}

void HalfBondList::breakPairs(std::size_t r, const int* broke) {
  const std::int64_t p0 = rowPairOffsets[r];
  const int m = rowIntact[r];
  int first = 0;
  while (first < m && !broke[first]) ++first;
  if (first == m) return;
  if (!pending_) {
    rowRecorded_.assign(rowIntact.begin(), rowIntact.end());
    pending_ = true;
  }
  int intact = first;
  for (int k = first; k < m; ++k) intact += broke[k] ? 0 : 1;
  // Each array from the first broken pair on: the intact ones forward, in order, then the
  // broken ones (stashed in a buffer of the row's length).
  if (stash_.size() < static_cast<std::size_t>(m)) stash_.resize(static_cast<std::size_t>(m));
  const auto compact = [&](auto& v) {
    if (v.empty()) return;
    using T = typename std::decay_t<decltype(v)>::value_type;
    static_assert(sizeof(T) <= sizeof(double) && alignof(T) <= alignof(double));
    T* row = v.data() + p0;
    T* stash = reinterpret_cast<T*>(stash_.data());
    int w = first, nb = 0;
    for (int k = first; k < m; ++k) {
      if (broke[k])
        stash[nb++] = row[k];
      else
        row[w++] = row[k];
    }
    for (int k = 0; k < nb; ++k) row[w + k] = stash[k];
  };
  compact(pairPoint);
  compact(pairSlot);
  compact(pairSlotHigh);
  compact(pairLength);
  compact(pairLengthIndex);
  compact(pairLengthIndexHigh);
  compact(pairDamage);
  compact(pairInfluence);
  rowIntact[r] = intact;
}

void HalfBondList::addBrokenBonds(int numOwned, double* brokenBonds) const {
  // Each bond of an owned point is one pair on this rank (no periodic images here), and a row's
  // broken pairs follow its intact ones: a pass over the breaks, not over every bond.
  for (std::size_t r = 0; r < rowPoint.size(); ++r) {
    const int a = rowPoint[r];
    for (std::int64_t p = rowPairOffsets[r] + rowIntact[r]; p < rowPairOffsets[r + 1]; ++p) {
      if (a < numOwned) brokenBonds[a] += 1.0;
      if (pairPoint[p] < numOwned) brokenBonds[pairPoint[p]] += 1.0;
    }
  }
}

void HalfBondList::gatherInfluence(const Topology& t, const double* influence) {
  pairInfluence.assign(static_cast<std::size_t>(numPairs() + kPadding), 1.0);
  for (std::size_t r = 0; r + 1 < rowPairOffsets.size(); ++r)
    for (std::int64_t p = rowPairOffsets[r]; p < rowPairOffsets[r + 1]; ++p)
      pairInfluence[p] = influence[fullEntry(t, r, p)];
}

namespace {

// Distinct doubles in the order first seen, found by an open-addressed hash of their bits, at
// least twice the limit in size (a lookup per pair: it must cost little beside the square root).
// Entry 0 is the padding's 1.
class DistinctValues {
 public:
  explicit DistinctValues(std::size_t limit) : limit_(limit) {
    while ((std::size_t{1} << log2Slots_) < 2 * limit) ++log2Slots_;
    mask_ = (std::size_t{1} << log2Slots_) - 1;
    slot_.assign(mask_ + 1, -1);
    values.push_back(1.0);
    slot_[home(bits(1.0))] = 0;
  }
  // The index of v (added if new), or -1 when it is new and the limit is reached.
  std::int64_t indexOf(double v) {
    const std::uint64_t b = bits(v);
    for (std::size_t h = home(b);; h = (h + 1) & mask_) {
      if (slot_[h] < 0) {
        if (values.size() >= limit_) return -1;
        slot_[h] = static_cast<std::int32_t>(values.size());
        values.push_back(v);
        return slot_[h];
      }
      if (bits(values[static_cast<std::size_t>(slot_[h])]) == b) return slot_[h];
    }
  }
  std::vector<double> values;

 private:
  static std::uint64_t bits(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  }
  std::size_t home(std::uint64_t b) const {
    return static_cast<std::size_t>((b * 0x9E3779B97F4A7C15ull) >> (64 - log2Slots_));
  }
  std::size_t limit_;
  int log2Slots_ = 1;
  std::size_t mask_ = 0;
  std::vector<std::int32_t> slot_;
};

}  // namespace

void HalfBondList::storeLengths(const double* x, std::size_t tableLimit, int threads) {
  const auto entries = static_cast<std::size_t>(numPairs() + kPadding);
  pairLength = std::vector<double>();
  pairLengthIndexHigh = std::vector<std::uint8_t>();
  lengthTable = std::vector<double>();
  pairLengthIndex.assign(entries, 0);
  // Runs of rows with about equal shares of the pairs, a few per thread, which the threads take
  // as they come free. Each run's distinct lengths are found (in the order met) and its own
  // indices written; the tables are then joined in run order, which puts every length where one
  // thread would have (at its first pair), and each run's indices are translated. A table thus
  // depends neither on the threads nor on the runs.
  const std::size_t numRows = rowPoint.size();
  const int numThreads = threadsFor(threads, numRows);
  const int numRuns = numThreads == 1 ? 1 : 8 * numThreads;
  const std::vector<std::size_t> runRow = runsOfRows(rowPairOffsets.data(), numRows, numRuns);
  std::vector<std::int64_t> runPair(runRow.size(), 0);
  for (std::size_t k = 0; k < runRow.size() && numRows > 0; ++k)
    runPair[k] = rowPairOffsets[runRow[k]];
  struct Run {
    std::vector<double> distinct;      // the run's lengths in the order it met them
    std::vector<std::uint8_t> high;    // per pair of the run, where an index needs it
    std::vector<std::int32_t> global;  // per run index: the joined table's
    bool fits = true;
  };
  std::vector<Run> runs(static_cast<std::size_t>(numRuns));
  runTasksOnThreads(numThreads, numRuns, [&](int t) {
    // Locals only in the loop: the runs' records share cache lines, and a store to a byte
    // array may alias anything the loop would otherwise reload.
    DistinctValues table(tableLimit);
    std::vector<std::uint8_t> high;
    std::uint8_t* low = pairLengthIndex.data();
    const std::int64_t* offsets = rowPairOffsets.data();
    const int* rows = rowPoint.data();
    const int* points = pairPoint.data();
    const std::int64_t p0 = runPair[t];
    bool fits = true;
    for (std::size_t r = runRow[t]; r < runRow[t + 1] && fits; ++r) {
      const int a = rows[r];
      const std::int64_t end = offsets[r + 1];
      for (std::int64_t p = offsets[r]; p < end; ++p) {
        const std::int64_t index = table.indexOf(referenceBondLength(x, a, points[p]));
        if (index < 0) {
          fits = false;
          break;
        }
        low[p] = static_cast<std::uint8_t>(index);
        if (index > 255 && high.empty())
          high.assign(static_cast<std::size_t>(runPair[t + 1] - p0), 0);
        if (!high.empty()) high[p - p0] = static_cast<std::uint8_t>(index >> 8);
      }
    }
    runs[t].fits = fits;
    runs[t].high = std::move(high);
    runs[t].distinct = std::move(table.values);
  });
  bool fits = true;
  for (const Run& run : runs) fits = fits && run.fits;
  DistinctValues joined(tableLimit);
  for (std::size_t t = 0; t < runs.size() && fits; ++t)
    for (const double v : runs[t].distinct) {
      const std::int64_t index = joined.indexOf(v);
      fits = fits && index >= 0;
      runs[t].global.push_back(static_cast<std::int32_t>(index));
    }
  if (fits) {
    lengthTable = std::move(joined.values);
    if (lengthTable.size() > 256) pairLengthIndexHigh.assign(entries, 0);
    runTasksOnThreads(numThreads, numRuns, [&](int t) {
      const Run& run = runs[t];
      bool same = run.high.empty();
      for (std::size_t k = 0; k < run.global.size() && same; ++k)
        same = run.global[k] == static_cast<std::int32_t>(k);
      if (same) return;  // indices and (absent) high bytes already the joined table's
      for (std::int64_t p = runPair[t]; p < runPair[t + 1]; ++p) {
        const int local =
            int{pairLengthIndex[p]} | (run.high.empty() ? 0 : int{run.high[p - runPair[t]]} << 8);
        const std::int32_t index = run.global[static_cast<std::size_t>(local)];
        pairLengthIndex[p] = static_cast<std::uint8_t>(index);
        if (!pairLengthIndexHigh.empty())
          pairLengthIndexHigh[p] = static_cast<std::uint8_t>(index >> 8);
      }
    });
    return;
  }
  // Too many distinct lengths (an irregular mesh): one double per pair.
  runs = std::vector<Run>();
  pairLengthIndex = std::vector<std::uint8_t>();
  pairLength.assign(entries, 1.0);
  runTasksOnThreads(numThreads, numRuns, [&](int t) {
    for (std::size_t r = runRow[t]; r < runRow[t + 1]; ++r)
      for (std::int64_t p = rowPairOffsets[r]; p < rowPairOffsets[r + 1]; ++p)
        pairLength[p] = referenceBondLength(x, rowPoint[r], pairPoint[p]);
  });
}

bool buildHalfBondList(const Topology& t, HalfBondList& list, int threads) {
  list = HalfBondList();
  const int n = t.numOwned;
  const int numReal = t.numOwned + t.numGhosts;
  int usable = t.hasCurveBox && t.numOverlap == numReal ? 1 : 0;
  for (int i = 0; i < n && usable; ++i)
    if (t.bondOffsets[i + 1] - t.bondOffsets[i] > 65536) usable = 0;
  MPI_Allreduce(MPI_IN_PLACE, &usable, 1, MPI_INT, MPI_MIN, t.comm);
  if (!usable) return false;

  // The curve order of every point this rank sees, read where a ghost is compared (between
  // owned points the local order is the curve order): without ghosts, no key.
  std::vector<unsigned long long> key(t.numGhosts > 0 ? static_cast<std::size_t>(numReal) : 0);
  for (std::size_t k = 0; k < key.size(); ++k)
    key[k] = mortonKey(&t.referencePosition[3 * k], t.curveLo, t.curveHi);
  const auto before = [&](int a, int b) {
    return key[a] != key[b] ? key[a] < key[b] : t.overlapGlobalId[a] < t.overlapGlobalId[b];
  };
  // Whether owned point i's neighbour j comes after it.
  const auto after = [&](int i, int j) { return j < n ? j > i : before(i, j); };

  // Pairs per owned row (its neighbours after it) and per ghost row (its owned neighbours after
  // it, found from their rows).
  // (Here and below the arrays are read through local pointers and a row's count is kept in a
  // register: through the vectors, a store -- of a count, or of a 1-byte slot that may alias
  // anything -- made the next bond reload the row's bounds and the lists' addresses.)
  const std::int64_t* offsets = t.bondOffsets.data();
  const int* neighbors = t.neighbors.data();
  // Runs of rows with about equal shares of the bonds, which the threads (the rank's spare
  // processors) take as they come free. A ghost row's pairs come from the owned rows before it
  // in row order: each run counts its own (ghostCountOf), and writes them after those of the
  // runs before it, so the pairs are where one thread would put them. Up to 8 runs a thread, as
  // long as their ghost counts take no more than the owned rows' counts.
  const int numThreads = threadsFor(threads, static_cast<std::size_t>(n));
  const std::int64_t ghostCounts = std::int64_t{t.numGhosts} * numThreads;
  const int runsPerThread = numThreads == 1
                                ? 1
                                : static_cast<int>(std::clamp<std::int64_t>(
                                      n / std::max<std::int64_t>(ghostCounts, 1), 1, 8));
  const int numRuns = numThreads * runsPerThread;
  std::vector<int> runStart;
  for (const std::size_t i : runsOfRows(offsets, static_cast<std::size_t>(n), numRuns))
    runStart.push_back(static_cast<int>(i));
  std::vector<std::int64_t> ownedCount(static_cast<std::size_t>(n), 0);
  std::vector<std::vector<std::int64_t>> ghostCountOf(
      static_cast<std::size_t>(numRuns),
      std::vector<std::int64_t>(static_cast<std::size_t>(t.numGhosts), 0));
  runTasksOnThreads(numThreads, numRuns, [&](int k) {
    std::int64_t* ghostCount = ghostCountOf[k].data();
    for (int i = runStart[k]; i < runStart[k + 1]; ++i) {
      std::int64_t count = 0;
      const std::int64_t end = offsets[i + 1];
      for (std::int64_t e = offsets[i]; e < end; ++e) {
        const int j = neighbors[e];
        if (after(i, j))
          ++count;
        else if (j >= n)
          ++ghostCount[j - n];
      }
      ownedCount[i] = count;
    }
  });
  std::vector<std::int64_t> ghostCount(static_cast<std::size_t>(t.numGhosts), 0);
  for (int k = 0; k < numRuns; ++k)
    for (int g = 0; g < t.numGhosts; ++g) ghostCount[g] += ghostCountOf[k][g];
  // Rows: every owned point (local order is curve order), and the ghosts with pairs merged in.
  std::vector<int> ghosts;
  for (int g = 0; g < t.numGhosts; ++g)
    if (ghostCount[g] > 0) ghosts.push_back(n + g);
  std::sort(ghosts.begin(), ghosts.end(), before);
  list.rowPoint.reserve(static_cast<std::size_t>(n) + ghosts.size());
  {
    std::size_t g = 0;
    for (int i = 0; i < n; ++i) {
      for (; g < ghosts.size() && before(ghosts[g], i); ++g) list.rowPoint.push_back(ghosts[g]);
      list.rowPoint.push_back(i);
    }
    for (; g < ghosts.size(); ++g) list.rowPoint.push_back(ghosts[g]);
  }
  const std::size_t rows = list.rowPoint.size();
  list.rowPairOffsets.assign(rows + 1, 0);
  std::vector<std::int64_t> ghostRowStart(static_cast<std::size_t>(t.numGhosts), -1);
  for (std::size_t r = 0; r < rows; ++r) {
    const int a = list.rowPoint[r];
    list.rowPairOffsets[r + 1] =
        list.rowPairOffsets[r] + (a < n ? ownedCount[a] : ghostCount[a - n]);
    list.longestRow =
        std::max(list.longestRow, list.rowPairOffsets[r + 1] - list.rowPairOffsets[r]);
    if (a >= n) ghostRowStart[a - n] = list.rowPairOffsets[r];
  }
  const std::int64_t pairs = list.rowPairOffsets.back();
  list.rowIntact.resize(rows);
  for (std::size_t r = 0; r < rows; ++r)
    list.rowIntact[r] = static_cast<int>(list.rowPairOffsets[r + 1] - list.rowPairOffsets[r]);
  list.pairPoint.assign(static_cast<std::size_t>(pairs + HalfBondList::kPadding), 0);
  list.pairSlot.resize(static_cast<std::size_t>(pairs));
  std::int64_t longestFullRow = 0;
  for (int i = 0; i < n; ++i)
    longestFullRow = std::max(longestFullRow, t.bondOffsets[i + 1] - t.bondOffsets[i]);
  if (longestFullRow > 256) list.pairSlotHigh.resize(static_cast<std::size_t>(pairs));
  const bool wide = !list.pairSlotHigh.empty();
  std::vector<std::int64_t> ownedRowStart(static_cast<std::size_t>(n));
  for (std::size_t r = 0; r < rows; ++r)
    if (list.rowPoint[r] < n) ownedRowStart[list.rowPoint[r]] = list.rowPairOffsets[r];
  int* pairPoint = list.pairPoint.data();
  std::uint8_t* pairSlot = list.pairSlot.data();
  std::uint8_t* pairSlotHigh = list.pairSlotHigh.data();
  // Where each run's pairs of each ghost row start: after the earlier runs' (in place of the
  // runs' counts).
  for (int g = 0; g < t.numGhosts; ++g) {
    std::int64_t next = ghostRowStart[g];
    for (int k = 0; k < numRuns; ++k) {
      const std::int64_t count = ghostCountOf[k][g];
      ghostCountOf[k][g] = next;
      next += count;
    }
  }
  runTasksOnThreads(numThreads, numRuns, [&](int k) {
    std::int64_t* ghostNext = ghostCountOf[k].data();
    for (int i = runStart[k]; i < runStart[k + 1]; ++i) {
      std::int64_t next = ownedRowStart[i];
      const std::int64_t begin = offsets[i], end = offsets[i + 1];
      for (std::int64_t e = begin; e < end; ++e) {
        const int j = neighbors[e];
        const auto slot = static_cast<int>(e - begin);
        std::int64_t p;
        if (after(i, j)) {
          p = next++;
          pairPoint[p] = j;
        } else if (j >= n) {
          p = ghostNext[j - n]++;
          pairPoint[p] = i;
        } else {
          continue;
        }
        pairSlot[p] = static_cast<std::uint8_t>(slot & 0xff);
        if (wide) pairSlotHigh[p] = static_cast<std::uint8_t>(slot >> 8);
      }
    }
  });

  return true;
}

std::int64_t mirrorBond(const Topology& t, int j, int i) {
  // A scan for i's index (no global ids read; it vectorises) rather than a binary search by
  // global id, whose every step waits on two dependent loads: 5% less force time where a third
  // of the bonds break.
  const int* row = t.neighbors.data() + t.bondOffsets[j];
  const int length = static_cast<int>(t.bondOffsets[j + 1] - t.bondOffsets[j]);
  int found = -1;
  for (int k = 0; k < length; ++k)
    if (row[k] == i) found = k;
  return found < 0 ? -1 : t.bondOffsets[j] + found;
}

}  // namespace peridot
