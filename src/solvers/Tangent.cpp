#include "solvers/Tangent.hpp"

#include <Tpetra_CrsGraph.hpp>
#include <algorithm>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"

namespace peridot {

using CrsGraph = Tpetra::CrsGraph<LocalOrdinal, GlobalOrdinal>;

Tangent::~Tangent() = default;

Tangent::Tangent(const Topology& topology, const std::vector<Block>& blocks,
                 const std::string& solverPath, const ProbeSettings& probe)
    : topology_(topology), numRowPoints_(topology.numOwned + topology.numGhosts) {
  bool probed = probe.always;
  for (const auto& b : blocks) {
    if (b.material->tangentReach() == TangentReach::None) {
      throw InputError(solverPath,
                       "material \"" + b.materialName + "\" of block " + b.name +
                           " has no tangent stiffness (it does not declare which points its "
                           "force depends on), so the implicit solvers cannot use it; use Verlet");
    }
    if (!b.material->hasAnalyticTangent()) {
      if (!probe.evaluator) {
        throw InputError(solverPath, "material \"" + b.materialName + "\" of block " + b.name +
                                         " has no analytic tangent, and this solver does not "
                                         "probe one by finite differences");
      }
      probed = true;
    }
  }
  for (const auto& b : blocks) {
    // Probing differentiates whatever force law the evaluation applies.
    if (!probed && b.damage && b.damage->bondLaw().kind != BondLaw::Kind::Linear) {
      throw InputError(solverPath, "block " + b.name +
                                       ": the tangent of the smooth bond law (DTT) is not "
                                       "available; the implicit solvers need the linear law");
    }
  }
  if (topology.numOverlap != numRowPoints_) {
    throw InputError(solverPath, "periodic boundaries are not supported by the implicit solvers");
  }
  // Point-level pattern: per row point, the columns its families touch.
  std::vector<std::vector<int>> rows(numRowPoints_);
  for (int i = 0; i < topology.numOwned; ++i) rows[i].push_back(i);
  for (const auto& b : blocks) {
    const bool family = b.material->tangentReach() == TangentReach::Family;
    for (int i : b.points) {
      const auto first = topology.bondOffsets[i], last = topology.bondOffsets[i + 1];
      for (auto k = first; k < last; ++k) rows[i].push_back(topology.neighbors[k]);
      if (!family) continue;
      for (auto k = first; k < last; ++k) {
        auto& row = rows[topology.neighbors[k]];
        row.push_back(i);
        for (auto l = first; l < last; ++l) row.push_back(topology.neighbors[l]);
      }
    }
  }
  blocks_.offsets.assign(numRowPoints_ + 1, 0);
  for (int a = 0; a < numRowPoints_; ++a) {
    auto& row = rows[a];
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    blocks_.offsets[a + 1] = blocks_.offsets[a] + static_cast<std::int64_t>(row.size());
  }
  blocks_.columns.reserve(blocks_.offsets.back());
  for (auto& row : rows) {
    blocks_.columns.insert(blocks_.columns.end(), row.begin(), row.end());
    row = std::vector<int>();
  }
  blocks_.values.assign(9 * blocks_.columns.size(), 0.0);

  // Tpetra: rows and columns on the overlap points (3 per point, gid 3g + d, in overlap order so
  // that a row's sorted local columns are its point columns in order, 3 at a time).
  std::vector<GlobalOrdinal> gids(3 * static_cast<std::size_t>(numRowPoints_));
  for (int k = 0; k < numRowPoints_; ++k)
    for (int d = 0; d < 3; ++d) gids[3 * k + d] = 3 * topology.overlapGlobalId[k] + d;
  const auto comm = topology.ownedMap3()->getComm();
  overlapMap3_ = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                      Teuchos::ArrayView<const GlobalOrdinal>(gids), 0, comm));
  std::vector<std::size_t> entries(3 * static_cast<std::size_t>(numRowPoints_));
  for (int a = 0; a < numRowPoints_; ++a)
    for (int d = 0; d < 3; ++d)
      entries[3 * a + d] =
          3 * static_cast<std::size_t>(blocks_.offsets[a + 1] - blocks_.offsets[a]);
  auto graph = Teuchos::rcp(
      new CrsGraph(overlapMap3_, overlapMap3_, Teuchos::ArrayView<const std::size_t>(entries)));
  for (int a = 0; a < numRowPoints_; ++a) {
    rowColumns_.clear();
    for (auto k = blocks_.offsets[a]; k < blocks_.offsets[a + 1]; ++k)
      for (int e = 0; e < 3; ++e) rowColumns_.push_back(3 * blocks_.columns[k] + e);
    for (int d = 0; d < 3; ++d)
      graph->insertLocalIndices(3 * a + d, Teuchos::ArrayView<const LocalOrdinal>(rowColumns_));
  }
  graph->fillComplete(topology.ownedMap3(), topology.ownedMap3());
  overlap_ = Teuchos::rcp(new CrsMatrix(graph));
  overlap_->fillComplete(topology.ownedMap3(), topology.ownedMap3());
  export_ = Teuchos::rcp(
      new Tpetra::Export<LocalOrdinal, GlobalOrdinal>(overlapMap3_, topology.ownedMap3()));
  if (probed) {
    blocks_.values = std::vector<double>();  // not filled: the probes go to the owned rows
    // The owned pattern (all zeros here), probed into at every assembly.
    owned_ = Tpetra::exportAndFillCompleteCrsMatrix<CrsMatrix>(
        Teuchos::rcp_const_cast<const CrsMatrix>(overlap_), *export_, topology.ownedMap3(),
        topology.ownedMap3());
    fd_ = std::make_unique<FiniteDifferenceTangent>(topology, owned_, probe);
    overlap_ = Teuchos::null;  // only the owned rows are probed
    export_ = Teuchos::null;
    blocks_.columns = std::vector<int>();
  }
}

void Tangent::assemble(const ModelState& state, const std::vector<Block>& blocks,
                       const double* held, double heldDiagonal, const double* addedDiagonal) {
  if (fd_) {
    fd_->fill(probeDt_, probeVelocityRate_, held, heldDiagonal, addedDiagonal);
    return;
  }
  std::fill(blocks_.values.begin(), blocks_.values.end(), 0.0);
  ModelState s = state;
  s.bondLaw = BondLaw();  // linear (checked at construction)
  for (const auto& b : blocks) b.material->addStiffness(s, b.points, blocks_);
  // Held degrees of freedom: rows and columns zeroed on every rank (ghost flags are current),
  // the diagonal set on the owner's row only, so that the export adds nothing to it.
  for (int a = 0; a < numRowPoints_; ++a) {
    for (auto k = blocks_.offsets[a]; k < blocks_.offsets[a + 1]; ++k) {
      const int c = blocks_.columns[k];
      double* v = &blocks_.values[9 * k];
      for (int r = 0; r < 3; ++r)
        for (int e = 0; e < 3; ++e)
          if (held[3 * a + r] != 0.0 || held[3 * c + e] != 0.0) v[3 * r + e] = 0.0;
      if (c == a && a < topology_.numOwned)
        for (int r = 0; r < 3; ++r) {
          if (held[3 * a + r] != 0.0)
            v[4 * r] = heldDiagonal;
          else if (addedDiagonal)
            v[4 * r] += addedDiagonal[3 * a + r];
        }
    }
  }
  overlap_->resumeFill();
  for (int a = 0; a < numRowPoints_; ++a) {
    const auto first = blocks_.offsets[a], last = blocks_.offsets[a + 1];
    rowColumns_.clear();
    for (auto k = first; k < last; ++k)
      for (int e = 0; e < 3; ++e) rowColumns_.push_back(3 * blocks_.columns[k] + e);
    for (int d = 0; d < 3; ++d) {
      rowValues_.clear();
      for (auto k = first; k < last; ++k)
        for (int e = 0; e < 3; ++e) rowValues_.push_back(blocks_.values[9 * k + 3 * d + e]);
      overlap_->replaceLocalValues(3 * a + d, static_cast<LocalOrdinal>(rowColumns_.size()),
                                   rowValues_.data(), rowColumns_.data());
    }
  }
  overlap_->fillComplete(topology_.ownedMap3(), topology_.ownedMap3());
  owned_ = Tpetra::exportAndFillCompleteCrsMatrix<CrsMatrix>(
      Teuchos::rcp_const_cast<const CrsMatrix>(overlap_), *export_, topology_.ownedMap3(),
      topology_.ownedMap3());
}

double Tangent::bytes() const {
  const double pointEntries = static_cast<double>(blocks_.columns.size());
  double matrixEntries =
      overlap_.is_null() ? 0.0 : static_cast<double>(overlap_->getNodeNumEntries());
  if (!owned_.is_null()) matrixEntries += static_cast<double>(owned_->getNodeNumEntries());
  return pointEntries * (9 * sizeof(double) + sizeof(int)) +
         matrixEntries * (sizeof(double) + sizeof(LocalOrdinal)) + (fd_ ? fd_->bytes() : 0.0);
}

}  // namespace peridot
