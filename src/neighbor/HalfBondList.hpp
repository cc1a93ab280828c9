#pragma once
// Each bond once: the half bond list over which a pairwise (bond-based) force loop applies
// Newton's third law, adding the pair force to one end and subtracting it from the other, so
// that it computes each bond's stretch, square root and division once instead of twice.
//
// Results identical at any rank count need every point's force summed in one order whatever the
// partition. The pairs are ordered by the space-filling curve of the topology (Morton key of the
// reference position in the global box, then global id: Topology::curveLo/Hi), an order of all
// points that does not depend on the partition. A pair belongs to the row of its earlier end;
// rows are walked in curve order, and a point's force is the sum, in that order, of the pairs
// of the earlier rows that reach it, then of its own row's pairs (in global-id order). A rank
// walks the rows of its owned points and also the rows of those ghosts that precede one of its
// owned neighbours, so that it sees every pair of its owned points in that same order: bonds
// between ranks are computed on both (a surface's worth of duplicated work, no reverse
// communication). Only owned points receive force.
//
// The pairs carry what the loop reads, contiguous: the later end, |xi| (optional: else computed
// from the reference positions, the same bits), the influence omega where it is not 1; their
// damage is which of its row's pairs are intact (rowIntact), with a copy of its value only where
// some bond is partly damaged. The full (two-sided) lists stay what the rest of the code reads
// (outputs, checkpoints, tangents), but the loops write their breaks into the rows only: the
// full lists are brought up to date when something reads them (recordBreaks), which a run that
// reads only point damage (addBrokenBonds) never does. The rows are read again from the full
// lists whenever something else rewrites them (gatherDamage: a restored trial, a restart).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "parallel/Topology.hpp"

namespace peridot {

struct HalfBondList {
  // The per-pair arrays a vector loop reads (pairPoint, pairLength or pairLengthIndex,
  // pairDamage) have kPadding entries more than there are pairs, so that a row's loop may run in
  // whole vectors past its last pair (into the next row's pairs, or this padding: point 0, |xi|
  // 1, intact).
  static constexpr int kPadding = 8;
  std::vector<int> rowPoint;                 // per row, in curve order: its overlap index
  std::vector<std::int64_t> rowPairOffsets;  // rows + 1
  std::vector<int> pairPoint;                // per pair: the later end (overlap index)
  // Per pair: its entry in the full list row of its earlier end if that is owned, else of its
  // later end (then owned): bondOffsets[holder] + slot(p). The low byte, and the high byte only
  // where some full row of the rank is longer than 256 entries (delta = 3 dx gives ~120): one
  // byte a pair instead of two, 124 MB of a 128^3 run on one rank.
  std::vector<std::uint8_t> pairSlot;
  std::vector<std::uint8_t> pairSlotHigh;
  int slot(std::int64_t p) const { return joinBytes(pairSlot, pairSlotHigh, p); }
  // Per pair |xi|, where the run stores it (else the loops compute it, the same bits): as an
  // index into lengthTable, the rank's distinct values, when there are at most
  // kLengthTableLimit of them (a lattice has a few hundred, and the table stays in cache), else
  // in pairLength. The index in bytes as the slot: the low byte, and the high byte only where
  // the table has more than 256 entries (231 at 128^3 on one rank: 1 byte a pair instead of 8;
  // 345 at 216^3: 2 bytes). The unused forms are empty.
  static constexpr std::size_t kLengthTableLimit = 65536;
  std::vector<std::uint8_t> pairLengthIndex;
  std::vector<std::uint8_t> pairLengthIndexHigh;
  std::vector<double> lengthTable;
  std::vector<double> pairLength;
  int lengthIndex(std::int64_t p) const {
    return joinBytes(pairLengthIndex, pairLengthIndexHigh, p);
  }
  // Per pair, only where some bond on this rank is partly damaged (0 < d < 1): a copy of its
  // damage. Empty where every bond is intact or broken (the critical stretch's damage): the
  // intact pairs are the first rowIntact of each row, and the loops read no damage.
  std::vector<float> pairDamage;
  // Per pair omega, when the run stores an influence per bond and it is the same from either
  // end (a function of |xi| with one horizon everywhere); empty otherwise (omega = 1).
  std::vector<double> pairInfluence;

  // Per row, how many of its pairs are intact. They come first, in the row's order; its broken
  // pairs (damage 1) follow, and the loops stop before them: a broken pair's terms are zeros
  // (1 - d = 0 times finite values), which leave every sum's bits as they are (a sum starts at +0,
  // so to nearest it is never -0, and s + (+-0) = s for every other s), so skipping them changes
  // no result, while a run that breaks a third of its bonds saves a third of its loop. A row is
  // partitioned again when a pass breaks some of its pairs (breakPairs), and put back in its order
  // when the damage is read anew (gatherDamage: a restored trial may mend bonds).
  std::vector<int> rowIntact;

  // An index kept as a low byte per pair and a high byte only where one is needed (empty).
  static int joinBytes(const std::vector<std::uint8_t>& low, const std::vector<std::uint8_t>& high,
                       std::int64_t p) {
    return high.empty() ? int{low[p]} : int{low[p]} | int{high[p]} << 8;
  }

  std::int64_t numPairs() const { return rowPairOffsets.empty() ? 0 : rowPairOffsets.back(); }
  // The most pairs of any row (a row's vector pass buffers that many).
  std::int64_t longestRow = 0;
  std::size_t bytes() const;
  // The full-list entry of pair p of row r.
  std::int64_t fullEntry(const Topology& t, std::size_t r, std::int64_t p) const {
    const int a = rowPoint[r];
    const int holder = a < t.numOwned ? a : pairPoint[p];
    return t.bondOffsets[holder] + slot(p);
  }
  // Stores each pair's |xi| from the reference coordinates x (overlap-indexed): in
  // pairLengthIndex and lengthTable if the rank has at most tableLimit distinct values, else in
  // pairLength. `threads` (the rank's spare processors) share the passes: the arrays are the same.
  void storeLengths(const double* x, std::size_t tableLimit = kLengthTableLimit, int threads = 1);
  bool storesLengths() const { return !pairLength.empty() || !pairLengthIndex.empty(); }
  // Copies the run's bond damage (float or flags; null: none) into the pairs, every row in its
  // order with its broken pairs last (rowIntact). The full lists are the damage then: breaks
  // pending in the rows are dropped (for a caller that rewrote the full lists).
  void gatherDamage(const Topology& t, const float* bondDamage, const unsigned char* bondBroken);
  // After a pass broke some of row r's intact pairs (broke[k] != 0 for its k-th pair): moves
  // them behind the row's intact ones (which keep their order), in every per-pair array. They
  // then sit just after the intact ones, before the pairs broken earlier: the full lists'
  // pending breaks of a row are its pairs from rowIntact up to the count recordBreaks last saw.
  void breakPairs(std::size_t r, const int* broke);
  // Adds, per owned point, 1 for each of its broken bonds to brokenBonds (numOwned entries),
  // reading only the rows' broken pairs. Valid where the rows' partition is the whole damage
  // (pairDamage empty: every bond intact or broken).
  void addBrokenBonds(int numOwned, double* brokenBonds) const;
  // Copies the per-bond influence (full lists) into the pairs.
  void gatherInfluence(const Topology& t, const double* influence);
  // Whether some pair broke since the full lists were last brought up to date.
  bool breaksPending() const { return pending_; }
  // Brings the full lists' damage `full` (the run's Bond_Damage or Bond_Broken) up to date: marks
  // broken every bond broken in the rows since the last call (this rank's entry of each, and
  // the other end's when that is owned too). The same entries, whenever it runs: the loops
  // never read the full lists. Batched: finding the other end's entry reads a full-list row
  // (cache misses per break), and in one tight loop over a batch those rows can be fetched
  // ahead of their searches (sorting the searches by row first cost more than it saved). Done
  // inside the force loop at every pass, this was 6% of a 64^3 run that breaks half its bonds.
  template <typename DamageT>
  void recordBreaks(const Topology& t, DamageT* full);
  // The breaks are recorded in batches of this many, which bounds the notes' memory.
  static constexpr std::size_t kBreakBatch = std::size_t{1} << 16;

 private:
  std::vector<double> stash_;  // breakPairs's buffer
  // Per row, its intact count when the full lists were last brought up to date; only while
  // breaks are pending (copied from rowIntact at the first break after an update).
  std::vector<int> rowRecorded_;
  bool pending_ = false;
};

namespace halfbreaks {
// A batch of recordBreaks: this rank's entries of the broken bonds (fullEntry), and (later end,
// earlier end) where both ends are owned. Written into `full` and cleared.
struct Batch {
  std::vector<std::int64_t> entries;
  std::vector<std::uint64_t> mirrors;
};
template <typename DamageT>
void write(const Topology& t, Batch& batch, DamageT* full);
}  // namespace halfbreaks

// Builds the rows and pairs (not pairLength nor the damage copies), or returns false (and leaves
// `list` empty) where it cannot be used: a topology without a curve box, periodic images, a full
// row longer than 65536 entries. Collective: every rank returns the same answer. `threads` (the
// rank's spare processors) share the passes over the full lists: the list is the same.
bool buildHalfBondList(const Topology& topology, HalfBondList& list, int threads = 1);

// The full-list entry of owned point j that holds its bond to point i, or -1 if j's row has
// none. Where a bond breaks (rare) the loop finds the later end's entry
// this way: a table of them would cost 2 bytes a bond and a set-up pass of random reads.
std::int64_t mirrorBond(const Topology& topology, int j, int i);

template <typename DamageT>
void HalfBondList::recordBreaks(const Topology& t, DamageT* full) {
  if (!pending_) return;
  pending_ = false;
  halfbreaks::Batch batch;
  for (std::size_t r = 0; r < rowPoint.size(); ++r) {
    const int a = rowPoint[r];
    const std::int64_t p0 = rowPairOffsets[r];
    for (std::int64_t p = p0 + rowIntact[r]; p < p0 + rowRecorded_[r]; ++p) {
      const int b = pairPoint[p];
      batch.entries.push_back(fullEntry(t, r, p));
      if (a < t.numOwned && b < t.numOwned)
        batch.mirrors.push_back(static_cast<std::uint64_t>(b) << 32 |
                                static_cast<std::uint32_t>(a));
      if (batch.entries.size() >= kBreakBatch) halfbreaks::write(t, batch, full);
    }
  }
  halfbreaks::write(t, batch, full);
}

template <typename DamageT>
void halfbreaks::write(const Topology& t, Batch& batch, DamageT* full) {
  for (const std::int64_t e : batch.entries) full[e] = DamageT(1);
  // The other end's row and damage entries, asked for this many searches ahead: the searches
  // then find them in cache (4% less force time at 64^3, where a third of the bonds break). The
  // first 128 entries (a row at delta = 3 dx has ~120), without reading where the row ends.
  constexpr std::size_t kAhead = 64;
  constexpr std::int64_t kEntries = 128, kLine = 64;
  const std::vector<std::uint64_t>& mirrors = batch.mirrors;
  const std::size_t count = mirrors.size();
  const auto last = static_cast<std::int64_t>(t.neighbors.size()) - 1;
  for (std::size_t k = 0; k < count; ++k) {
    if (k + kAhead < count) {
      const std::int64_t b0 = t.bondOffsets[mirrors[k + kAhead] >> 32];
      for (std::int64_t b = 0; b < kEntries; b += kLine / std::int64_t{sizeof(int)})
        __builtin_prefetch(&t.neighbors[std::min(b0 + b, last)]);
      for (std::int64_t b = 0; b < kEntries; b += kLine / std::int64_t{sizeof(DamageT)})
        __builtin_prefetch(full + std::min(b0 + b, last), 1);
    }
    const std::uint64_t key = mirrors[k];
    const std::int64_t mirror =
        mirrorBond(t, static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu));
    if (mirror >= 0) full[mirror] = DamageT(1);
  }
  batch.entries.clear();
  batch.mirrors.clear();
}
}  // namespace peridot
