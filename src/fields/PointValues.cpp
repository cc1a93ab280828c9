#include "fields/PointValues.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace peridot {

namespace {

// Inserts (replaces) or adds the c values at `from` into those at `to`.
void combine(double* to, const double* from, int c, Tpetra::CombineMode mode) {
  switch (mode) {
    case Tpetra::INSERT:
    case Tpetra::REPLACE:
      for (int d = 0; d < c; ++d) to[d] = from[d];
      break;
    case Tpetra::ADD:
    case Tpetra::ADD_ASSIGN:
      for (int d = 0; d < c; ++d) to[d] += from[d];
      break;
    case Tpetra::ABSMAX:
      for (int d = 0; d < c; ++d) to[d] = std::max(std::abs(to[d]), std::abs(from[d]));
      break;
    case Tpetra::ZERO:
      break;
  }
}

const PointValues& asPointValues(const Tpetra::SrcDistObject& source) {
  const auto* p = dynamic_cast<const PointValues*>(&source);
  if (!p) throw std::logic_error("PointValues: the source of a transfer is not a PointValues");
  return *p;
}

}  // namespace

bool PointValues::checkSizes(const Tpetra::SrcDistObject& source) {
  const auto* p = dynamic_cast<const PointValues*>(&source);
  return p != nullptr && p->components_ == components_;
}

void PointValues::copyAndPermute(const Tpetra::SrcDistObject& source, std::size_t numSameIDs,
                                 const LidView& permuteToLIDs, const LidView& permuteFromLIDs,
                                 Tpetra::CombineMode mode) {
  const PointValues& from = asPointValues(source);
  const int c = components_;
  for (std::size_t i = 0; i < numSameIDs; ++i)
    combine(values_ + c * i, from.values_ + c * i, c, mode);
  const auto to = permuteToLIDs.view_host();
  const auto fromLids = permuteFromLIDs.view_host();
  for (std::size_t k = 0; k < to.extent(0); ++k)
    combine(values_ + static_cast<std::size_t>(c) * to(k),
            from.values_ + static_cast<std::size_t>(c) * fromLids(k), c, mode);
}

void PointValues::packAndPrepare(const Tpetra::SrcDistObject& source, const LidView& exportLIDs,
                                 PacketView& exports, CountView /*numPacketsPerLID*/,
                                 std::size_t& constantNumPackets) {
  const PointValues& from = asPointValues(source);
  const int c = from.components_;
  constantNumPackets = static_cast<std::size_t>(c);
  const auto lids = exportLIDs.view_host();
  const std::size_t size = lids.extent(0) * static_cast<std::size_t>(c);
  if (exports.extent(0) != size) exports = PacketView("PointValues exports", size);
  exports.clear_sync_state();
  exports.modify_host();
  double* out = exports.view_host().data();
  for (std::size_t k = 0; k < lids.extent(0); ++k) {
    const double* v = from.values_ + static_cast<std::size_t>(c) * lids(k);
    for (int d = 0; d < c; ++d) out[c * k + d] = v[d];
  }
}

void PointValues::unpackAndCombine(const LidView& importLIDs, PacketView imports,
                                   CountView /*numPacketsPerLID*/, std::size_t constantNumPackets,
                                   Tpetra::CombineMode mode) {
  const int c = components_;
  if (constantNumPackets != static_cast<std::size_t>(c))
    throw std::logic_error("PointValues: received " + std::to_string(constantNumPackets) +
                           " values a point, expected " + std::to_string(c));
  if (imports.need_sync_host()) imports.sync_host();
  const auto lids = importLIDs.view_host();
  const double* in = imports.view_host().data();
  for (std::size_t k = 0; k < lids.extent(0); ++k)
    combine(values_ + static_cast<std::size_t>(c) * lids(k), in + c * k, c, mode);
}

}  // namespace peridot
