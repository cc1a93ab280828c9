#pragma once
// What the loops over the half bond list share (HalfPairForce.cpp, HalfLps.cpp; both compiled
// without floating-point contraction, so that a pair rounds alike whichever rank computes it).
// Each row runs in two passes: a vector pass that computes every pair's direction and scalar in
// lanes (square roots and divisions are what a pair costs; no lane reads another's result, so
// the bits are those of a scalar loop) into a row buffer, then a scalar pass that adds to the
// row's point and subtracts from the later ends, in order (neighbor/HalfBondList.hpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "core/MulAdd.hpp"
#include "materials/MaterialModel.hpp"
#include "neighbor/HalfBondList.hpp"

#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace peridot::half {

// The vector pass's width in pairs: 8 float damage values fill a 256-bit vector (the padding of
// the pair arrays allows up to HalfBondList::kPadding).
constexpr int kLanes = 8;
static_assert(kLanes <= HalfBondList::kPadding, "a row's vector pass reads past its end");

// What a pair's scalar is divided by instead of |Y| where its ends coincide (no direction): the
// scalar is then 0 without a select of the quotient, under which GCC would compute the quotient
// behind a mask, and masked emulated gathers (those of Zen CPUs) do not vectorize.
constexpr double kCoincident = std::numeric_limits<double>::infinity();

// a b + c: one rounding with FMA hardware, two without; either way the same at every call.
using peridot::mulAdd;

#ifdef __SSE2__
// The same, lane by lane, for two values at once.
inline __m128d mulAdd(__m128d a, __m128d b, __m128d c) {
#ifdef __FMA__
  return _mm_fmadd_pd(a, b, c);
#else
  return _mm_add_pd(_mm_mul_pd(a, b), c);
#endif
}
#endif

// A row's buffers: the bond vector Y (its x and y components interleaved, Y01[2k], Y01[2k + 1],
// so that the scalar pass reads and writes them as one pair; z in Y2), the pair's scalar, and
// which pairs broke in this pass (int: a 1-byte type would make the vectors 32 pairs wide).
// Sized for the longest row.
struct RowBuffers {
  double *Y01, *Y2, *q, *zeta;
  int* broke;
};

inline RowBuffers rowBuffers(const HalfBondList& h) {
  thread_local std::vector<double> scratch;
  thread_local std::vector<int> brokeNow;
  const auto longest = static_cast<std::size_t>((h.longestRow + kLanes - 1) / kLanes * kLanes);
  if (scratch.size() < 5 * longest) scratch.resize(5 * longest);
  if (brokeNow.size() < longest) brokeNow.resize(longest);
  double* base = scratch.data();
  return {base, base + 2 * longest, base + 3 * longest, base + 4 * longest, brokeNow.data()};
}

// The scalar pass of a force row (row point a, its m later ends): the pair force q Y (q and Y
// from the vector pass) times the other end's volume is added to a and subtracted from each
// owned later end, in order; a's own sum is added after its row (only owned points, index < n,
// receive force). The x and y components go together in one 128-bit register, each rounded as
// its own multiply-add (mulAdd) would: the same bits, for 9 memory accesses a pair instead of 12
// (they, not the arithmetic, are what this pass waits on: 4% less force time at 64^3).
inline void scatterForceRow(int a, int n, const int* later, int m, const double* volume,
                            const RowBuffers& buf, double* f) {
  const double va = volume[a];
#ifdef __SSE2__
  __m128d fa01 = _mm_setzero_pd();
  double fa2 = 0;
  for (int k = 0; k < m; ++k) {
    const int b = later[k];
    const double sa = buf.q[k] * volume[b], sb = buf.q[k] * va;
    const __m128d Y01 = _mm_loadu_pd(buf.Y01 + 2 * k);
    fa01 = mulAdd(_mm_set1_pd(sa), Y01, fa01);
    fa2 = mulAdd(sa, buf.Y2[k], fa2);
    if (b < n) {
      double* fb = f + 3 * b;
      _mm_storeu_pd(fb, mulAdd(_mm_set1_pd(-sb), Y01, _mm_loadu_pd(fb)));
      fb[2] = mulAdd(-sb, buf.Y2[k], fb[2]);
    }
  }
  const double fa0 = _mm_cvtsd_f64(fa01), fa1 = _mm_cvtsd_f64(_mm_unpackhi_pd(fa01, fa01));
#else
  double fa0 = 0, fa1 = 0, fa2 = 0;
  for (int k = 0; k < m; ++k) {
    const int b = later[k];
    const double sa = buf.q[k] * volume[b], sb = buf.q[k] * va;
    const double Y0 = buf.Y01[2 * k], Y1 = buf.Y01[2 * k + 1], Y2 = buf.Y2[k];
    fa0 = mulAdd(sa, Y0, fa0);
    fa1 = mulAdd(sa, Y1, fa1);
    fa2 = mulAdd(sa, Y2, fa2);
    if (b < n) {
      f[3 * b] = mulAdd(-sb, Y0, f[3 * b]);
      f[3 * b + 1] = mulAdd(-sb, Y1, f[3 * b + 1]);
      f[3 * b + 2] = mulAdd(-sb, Y2, f[3 * b + 2]);
    }
  }
#endif
  if (a < n) {
    f[3 * a] += fa0;
    f[3 * a + 1] += fa1;
    f[3 * a + 2] += fa2;
  }
}

// Whether this pass breaks bonds (a fused critical stretch): the breaks go into the rows, and
// the run's full lists (float damage or broken-bond flags) are brought up to date when read
// (HalfBondList::recordBreaks).
inline bool breaksBonds(const ModelState& s) {
  return s.breakableBondDamage != nullptr || s.breakableBondBroken != nullptr;
}

// Where a loop reads a pair's |xi| (HalfBondList::storeLengths): computed from the reference
// positions, per pair, or through the table of the rank's distinct lengths. The same bits.
enum LengthSource : int { kComputedLength, kPairLength, kTabledLength };

struct PairLengths {
  const double* perPair;
  const std::uint8_t* index;      // the low byte
  const std::uint8_t* indexHigh;  // null where the table has at most 256 entries
  const double* table;
};

inline PairLengths pairLengths(const HalfBondList& h) {
  return {h.pairLength.data(), h.pairLengthIndex.data(),
          h.pairLengthIndexHigh.empty() ? nullptr : h.pairLengthIndexHigh.data(),
          h.lengthTable.data()};
}

// The |xi| of a row's pairs p0 .. p0 + lanes as one contiguous array (index k for pair p0 + k),
// or null where the loop computes them: the table's values are looked up here, in a scalar pass
// into `buffer`, before the vector pass (whose gathers would be emulated, element by element,
// on CPUs without fast ones: slower than these plain loads).
template <int kSource>
inline const double* rowLengths(const PairLengths& l, std::int64_t p0, int lanes, double* buffer) {
  if constexpr (kSource == kPairLength) {
    return l.perPair + p0;
  } else if constexpr (kSource == kTabledLength) {
    const std::uint8_t* index = l.index + p0;
    if (l.indexHigh) {
      const std::uint8_t* high = l.indexHigh + p0;
#pragma GCC unroll 4
      for (int k = 0; k < lanes; ++k) buffer[k] = l.table[index[k] | high[k] << 8];
    } else {
#pragma GCC unroll 4
      for (int k = 0; k < lanes; ++k) buffer[k] = l.table[index[k]];
    }
    return buffer;
  } else {
    return nullptr;
  }
}

// |xi| of the row's k-th pair, whose later end is b (xa: the row point's reference position).
template <int kSource>
inline double pairZeta(const double* rowLength, int k, int b, const double* x, const double* xa) {
  if constexpr (kSource == kComputedLength)
    return std::sqrt(sumOfSquares(x[3 * b] - xa[0], x[3 * b + 1] - xa[1], x[3 * b + 2] - xa[2]));
  else
    return rowLength[k];
}

// Calls loop(std::integral_constant<int, LengthSource>) for where the pairs keep |xi|.
template <typename Loop>
void withLengthSource(const HalfBondList& h, Loop&& loop) {
  if (!h.pairLengthIndex.empty())
    loop(std::integral_constant<int, kTabledLength>{});
  else if (!h.pairLength.empty())
    loop(std::integral_constant<int, kPairLength>{});
  else
    loop(std::integral_constant<int, kComputedLength>{});
}

}  // namespace peridot::half
