#pragma once
// Registry of named fields. Node fields are Tpetra vectors on the overlap map (owned points
// first, then ghosts) with their components interleaved per point; bond fields are flat arrays
// aligned with the CSR bond lists (global values are computed by the output). Nothing is allocated
// until a model, a boundary condition or an output asks for it by name.
#include <Tpetra_Vector.hpp>
#include <functional>
#include <map>
#include <memory>
#include <new>
#include <set>
#include <string>
#include <vector>

#include "core/ZeroedArray.hpp"
#include "fields/PointValues.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

using Vector = Tpetra::Vector<double, LocalOrdinal, GlobalOrdinal>;

struct NodeField {
  std::string name;
  int components = 1;
  // The values, allocated here rather than by Kokkos (which mallocs and clears them at once), so
  // that a large field is faulted in 2 MiB pages (app/LargeAllocations.cpp), aligned to a cache
  // line as Kokkos aligns them; `overlap` views them.
  static constexpr std::align_val_t kAlignment{64};
  struct Release {
    void operator()(double* p) const { ::operator delete[](p, kAlignment); }
  };
  std::unique_ptr<double[], Release> storage;
  Teuchos::RCP<Vector> overlap;
  Teuchos::RCP<PointValues> owned;   // the owned prefix, by point (ownedMap)
  Teuchos::RCP<PointValues> ghosts;  // the regular ghosts that follow it (ghostMap)
  double* data = nullptr;            // components * numOverlap values
};

class FieldManager {
 public:
  explicit FieldManager(const Topology& topology);

  // Returns the field's storage, allocating it (zeroed) on first request.
  double* node(const std::string& name, int components);
  const NodeField& nodeField(const std::string& name) const;
  // Frees a node field that nothing reads any more (a set-up check's); asking for it again
  // allocates it anew, zeroed.
  void release(const std::string& name) { nodeFields_.erase(name); }
  // Copies owned values to the ghost copies on other ranks, and to periodic images.
  void refreshGhosts(const std::string& name);
  // A position field's periodic images are shifted by the box, not plain copies.
  void markPosition(const std::string& name) { positionFields_.insert(name); }
  // A deformable periodic box: images of the positions marked current (markCurrentPosition)
  // sit at F s from their point (s the reference shift) from the next refresh on. F row-major.
  void markCurrentPosition(const std::string& name) { currentPositionFields_.insert(name); }
  void setPeriodicDeformation(const double F[9]);

  // One value per one-sided bond entry, allocated on first request with `initial`.
  std::vector<double>& bond(const std::string& name, double initial = 0.0);
  // Single precision, for bond state that needs no more (bond damage).
  std::vector<float>& bondFloat(const std::string& name, float initial = 0.0f);
  // One byte, for flags (compact bond damage: 1 = broken), all 0 at first. Not saved by
  // checkpoints: a run with a checkpoint keeps float damage
  // (ModelEvaluator::setCompactDamageAllowed). Its pages are not written until a flag in them is
  // set (core/ZeroedArray.hpp).
  ZeroedArray<unsigned char>& bondByte(const std::string& name);

  // A bond field that its writer brings up to date only when it is read (the bond damage of a
  // run whose loops note breaks in the half bond list: ModelEvaluator): every request for it by
  // name (bondFloat, bondByte) calls `update` first, so that no reader sees it stale. `owner`
  // marks the registration: clearing it with another owner leaves it (an evaluator replaced by
  // a new one on the same fields).
  void setBondFieldUpdate(const std::string& name, const void* owner, std::function<void()> update);
  void clearBondFieldUpdate(const std::string& name, const void* owner);

  // Names of the bond fields allocated so far (double, then float), e.g. for a checkpoint.
  std::vector<std::string> bondFieldNames() const;
  std::vector<std::string> floatBondFieldNames() const;
  bool hasNode(const std::string& name) const { return nodeFields_.count(name) > 0; }

  std::size_t bytesAllocated() const;

 private:
  const Topology& topology_;
  std::map<std::string, NodeField> nodeFields_;
  std::map<std::string, std::vector<double>> bondFields_;
  std::map<std::string, std::vector<float>> floatBondFields_;
  std::map<std::string, ZeroedArray<unsigned char>> byteBondFields_;
  struct BondFieldUpdate {
    const void* owner;
    std::function<void()> update;
  };
  std::map<std::string, BondFieldUpdate> bondFieldUpdates_;
  void updateBondField(const std::string& name) const {
    auto it = bondFieldUpdates_.find(name);
    if (it != bondFieldUpdates_.end()) it->second.update();
  }
  std::set<std::string> positionFields_, currentPositionFields_;
  bool deformedBox_ = false;
  double boxF_[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
};

}  // namespace peridot
