#pragma once
// What the loops over the half bond list share (HalfPairForce.cpp, HalfLps.cpp; both compiled
// without floating-point contraction, so that a pair rounds alike whichever rank computes it).
// Each row runs in two passes: a vector pass that computes every pair's direction and scalar in
// lanes (square roots and divisions are what a pair costs; no lane reads another's result, so
// the bits are those of a scalar loop) into a row buffer, then a scalar pass that adds to the
// row's point and subtracts from the later ends, in order (neighbor/HalfBondList.hpp).
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

#include "core/MulAdd.hpp"
#include "materials/MaterialModel.hpp"
#include "neighbor/HalfBondList.hpp"

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

// A row's buffers: the bond vector Y, the pair's scalar, and which pairs broke in this pass
// (int: a 1-byte type would make the vectors 32 pairs wide). Sized for the longest row.
struct RowBuffers {
  double *Y0, *Y1, *Y2, *q;
  int* broke;
};

inline RowBuffers rowBuffers(const HalfBondList& h) {
  thread_local std::vector<double> scratch;
  thread_local std::vector<int> brokeNow;
  const auto longest = static_cast<std::size_t>((h.longestRow + kLanes - 1) / kLanes * kLanes);
  if (scratch.size() < 4 * longest) scratch.resize(4 * longest);
  if (brokeNow.size() < longest) brokeNow.resize(longest);
  double* base = scratch.data();
  return {base, base + longest, base + 2 * longest, base + 3 * longest, brokeNow.data()};
}

// The scalar pass of a force row (row point a, its m later ends): the pair force q Y (q and Y
// from the vector pass) times the other end's volume is added to a and subtracted from each
// owned later end, in order; a's own sum is added after its row (only owned points, index < n,
// receive force).
inline void scatterForceRow(int a, int n, const int* later, int m, const double* volume,
                            const RowBuffers& buf, double* f) {
  const double va = volume[a];
  double f0 = 0, f1 = 0, f2 = 0;
  for (int k = 0; k < m; ++k) {
    const int b = later[k];
    const double sa = buf.q[k] * volume[b], sb = buf.q[k] * va;
    f0 = mulAdd(sa, buf.Y0[k], f0);
    f1 = mulAdd(sa, buf.Y1[k], f1);
    f2 = mulAdd(sa, buf.Y2[k], f2);
    if (b < n) {
      f[3 * b] = mulAdd(-sb, buf.Y0[k], f[3 * b]);
      f[3 * b + 1] = mulAdd(-sb, buf.Y1[k], f[3 * b + 1]);
      f[3 * b + 2] = mulAdd(-sb, buf.Y2[k], f[3 * b + 2]);
    }
  }
  if (a < n) {
    f[3 * a] += f0;
    f[3 * a + 1] += f1;
    f[3 * a + 2] += f2;
  }
}

// The run's bond damage in the form it keeps (float or broken-bond flags), where the fused
// critical stretch writes its breaks.
template <typename DamageT>
DamageT* breakableDamage(const ModelState& s) {
  if constexpr (std::is_same_v<DamageT, float>)
    return s.breakableBondDamage;
  else
    return s.breakableBondBroken;
}

// Calls loop(std::bool_constant<kStoredLength>, DamageT) for the run's storage: |xi| kept in the
// pairs or not, and the run's damage form (float, or unsigned char flags).
template <typename Loop>
void withStorage(const ModelState& s, Loop&& loop) {
  const bool flags = s.bondBroken != nullptr;
  const bool stored = !s.halfBonds->pairLength.empty();
  using Flag = unsigned char;
  if (stored && flags)
    loop(std::true_type{}, Flag{});
  else if (stored)
    loop(std::true_type{}, float{});
  else if (flags)
    loop(std::false_type{}, Flag{});
  else
    loop(std::false_type{}, float{});
}

}  // namespace peridot::half
