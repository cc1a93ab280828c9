#pragma once
// A field's values at the points of one Map, `components` of them interleaved per point, as a
// Tpetra distributed object whose packet is a whole point: the Map's own scalar Import then
// moves a 3-vector (or a wider field) with no Map of 3 entries a point. (Peridigm's Epetra block
// maps did the same.) A non-contiguous Map keeps every global id and a hash table of them: the
// 3-entry owned Map took 200 MB of a 128^3 run on one rank (bench/RESULTS.md). The object views
// storage it does not own (FieldManager's overlap vectors).
#include <Tpetra_DistObject.hpp>

#include "parallel/Topology.hpp"

namespace peridot {

class PointValues : public Tpetra::DistObject<double, LocalOrdinal, GlobalOrdinal> {
  using Base = Tpetra::DistObject<double, LocalOrdinal, GlobalOrdinal>;

 public:
  // `values`: components values for each of map's local points, in local order.
  PointValues(const Teuchos::RCP<const Map>& map, double* values, int components)
      : Base(map), values_(values), components_(components) {}
  int components() const { return components_; }

 protected:
  using LidView = Kokkos::DualView<const LocalOrdinal*, Base::buffer_device_type>;
  using PacketView = Kokkos::DualView<double*, Base::buffer_device_type>;
  using CountView = Kokkos::DualView<std::size_t*, Base::buffer_device_type>;

  // Every point a packet of the same size: no per-point counts to exchange.
  std::size_t constantNumberOfPackets() const override {
    return static_cast<std::size_t>(components_);
  }
  bool checkSizes(const Tpetra::SrcDistObject& source) override;
  void copyAndPermute(const Tpetra::SrcDistObject& source, std::size_t numSameIDs,
                      const LidView& permuteToLIDs, const LidView& permuteFromLIDs,
                      Tpetra::CombineMode mode) override;
  void packAndPrepare(const Tpetra::SrcDistObject& source, const LidView& exportLIDs,
                      PacketView& exports, CountView numPacketsPerLID,
                      std::size_t& constantNumPackets) override;
  void unpackAndCombine(const LidView& importLIDs, PacketView imports, CountView numPacketsPerLID,
                        std::size_t constantNumPackets, Tpetra::CombineMode mode) override;

 private:
  double* values_;
  int components_;
};

}  // namespace peridot
