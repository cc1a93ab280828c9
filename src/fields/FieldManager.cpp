#include "fields/FieldManager.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace peridot {

FieldManager::FieldManager(const Topology& topology) : topology_(topology) {}

double* FieldManager::node(const std::string& name, int components) {
  auto it = nodeFields_.find(name);
  if (it != nodeFields_.end()) {
    if (it->second.components != components) {
      throw std::logic_error("field " + name + " requested with " + std::to_string(components) +
                             " components but it has " + std::to_string(it->second.components));
    }
    return it->second.data;
  }
  NodeField f;
  f.name = name;
  f.components = components;
  const int n = topology_.numOverlap * components;
  // The overlap vector's map only sizes the storage; the exchanges move whole points with the
  // scalar maps' Import (PointValues).
  auto teuchosComm = topology_.ownedMap->getComm();
  auto storageMap = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                         static_cast<size_t>(n), 0, teuchosComm));
  f.storage.reset(static_cast<double*>(
      ::operator new[](static_cast<std::size_t>(n) * sizeof(double), NodeField::kAlignment)));
  f.data = f.storage.get();
  std::fill_n(f.data, n, 0.0);
  // A view of the storage it does not own (Kokkos frees nothing of it); the storage keeps its
  // address when the field is moved into the map.
  Vector::dual_view_type::t_dev values(f.data, static_cast<std::size_t>(n), 1);
  f.overlap = Teuchos::rcp(new Vector(storageMap, Vector::dual_view_type(values, values)));
  f.owned = Teuchos::rcp(new PointValues(topology_.ownedMap, f.data, components));
  f.ghosts = Teuchos::rcp(new PointValues(
      topology_.ghostMap, f.data + static_cast<std::size_t>(topology_.numOwned) * components,
      components));  // regular ghosts; periodic images follow them
  return nodeFields_.emplace(name, std::move(f)).first->second.data;
}

const NodeField& FieldManager::nodeField(const std::string& name) const {
  auto it = nodeFields_.find(name);
  if (it == nodeFields_.end()) throw std::logic_error("no node field " + name);
  return it->second;
}

void FieldManager::refreshGhosts(const std::string& name) {
  auto it = nodeFields_.find(name);
  if (it == nodeFields_.end()) throw std::logic_error("no node field " + name);
  NodeField& f = it->second;
  if (topology_.numRanks > 1) f.ghosts->doImport(*f.owned, *topology_.ghostImport, Tpetra::INSERT);
  // Periodic images copy their real point; positions move with the image's shift.
  const int c = f.components;
  const bool position = positionFields_.count(name) > 0;
  const int first = topology_.numOwned + topology_.numGhosts;
  if (position && deformedBox_ && currentPositionFields_.count(name) > 0) {
    for (std::size_t m = 0; m < topology_.imageSource.size(); ++m) {
      const int source = topology_.imageSource[m], image = first + static_cast<int>(m);
      const double* s = &topology_.imageShift[3 * m];
      for (int d = 0; d < 3; ++d) {
        f.data[3 * image + d] = f.data[3 * source + d] + boxF_[3 * d] * s[0] +
                                boxF_[3 * d + 1] * s[1] + boxF_[3 * d + 2] * s[2];
      }
    }
    return;
  }
  for (std::size_t m = 0; m < topology_.imageSource.size(); ++m) {
    const int source = topology_.imageSource[m], image = first + static_cast<int>(m);
    for (int d = 0; d < c; ++d) {
      f.data[c * image + d] =
          f.data[c * source + d] + (position ? topology_.imageShift[3 * m + d] : 0.0);
    }
  }
}

void FieldManager::setPeriodicDeformation(const double F[9]) {
  deformedBox_ = true;
  for (int k = 0; k < 9; ++k) boxF_[k] = F[k];
}

std::vector<double>& FieldManager::bond(const std::string& name, double initial) {
  auto it = bondFields_.find(name);
  if (it != bondFields_.end()) return it->second;
  return bondFields_
      .emplace(name, std::vector<double>(static_cast<std::size_t>(topology_.numBonds()), initial))
      .first->second;
}

std::vector<float>& FieldManager::bondFloat(const std::string& name, float initial) {
  updateBondField(name);
  auto it = floatBondFields_.find(name);
  if (it != floatBondFields_.end()) return it->second;
  return floatBondFields_
      .emplace(name, std::vector<float>(static_cast<std::size_t>(topology_.numBonds()), initial))
      .first->second;
}

ZeroedArray<unsigned char>& FieldManager::bondByte(const std::string& name) {
  updateBondField(name);
  auto it = byteBondFields_.find(name);
  if (it != byteBondFields_.end()) return it->second;
  return byteBondFields_
      .emplace(name, ZeroedArray<unsigned char>(static_cast<std::size_t>(topology_.numBonds())))
      .first->second;
}

void FieldManager::setBondFieldUpdate(const std::string& name, const void* owner,
                                      std::function<void()> update) {
  bondFieldUpdates_[name] = BondFieldUpdate{owner, std::move(update)};
}

void FieldManager::clearBondFieldUpdate(const std::string& name, const void* owner) {
  auto it = bondFieldUpdates_.find(name);
  if (it != bondFieldUpdates_.end() && it->second.owner == owner) bondFieldUpdates_.erase(it);
}

std::vector<std::string> FieldManager::bondFieldNames() const {
  std::vector<std::string> names;
  for (const auto& kv : bondFields_) names.push_back(kv.first);
  return names;
}

std::vector<std::string> FieldManager::floatBondFieldNames() const {
  std::vector<std::string> names;
  for (const auto& kv : floatBondFields_) names.push_back(kv.first);
  return names;
}

std::size_t FieldManager::bytesAllocated() const {
  std::size_t bytes = 0;
  for (const auto& kv : nodeFields_)
    bytes += sizeof(double) * kv.second.components * topology_.numOverlap;
  for (const auto& kv : bondFields_) bytes += sizeof(double) * kv.second.size();
  for (const auto& kv : floatBondFields_) bytes += sizeof(float) * kv.second.size();
  for (const auto& kv : byteBondFields_) bytes += kv.second.size();
  return bytes;
}

}  // namespace peridot
