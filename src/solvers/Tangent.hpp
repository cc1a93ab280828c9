#pragma once
// The distributed tangent stiffness of an implicit solver: a Tpetra::CrsMatrix with one row per
// owned degree of freedom (3 per point) and 3x3 blocks per coupled pair of points. Each rank
// fills the blocks of its owned points' bond families on the overlap points (TangentBlocks), and
// an Export (ADD) sums the rows that belong to other ranks into their owners' rows: a family of
// a state-based model couples every pair of its members, so rows of ghost points get entries
// too, and an owned row's columns reach two horizons (points this rank does not hold).
//
// Materials without an analytic tangent (MaterialModel::hasAnalyticTangent) are probed by finite
// differences (solvers/FiniteDifferenceTangent.hpp): then the whole tangent is probed, over the
// same pattern, directly into the owned rows.
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <memory>
#include <vector>

#include "evaluator/Block.hpp"
#include "parallel/Topology.hpp"
#include "solvers/FiniteDifferenceTangent.hpp"
#include "solvers/TangentBlocks.hpp"

namespace peridot {

class Tangent {
 public:
  // Builds the pattern from the bond lists and each block's material reach. Throws InputError
  // naming the block and material when a material has no tangent (or the deck asks for a
  // feature the tangent does not cover), with `solverPath` as the deck path.
  // `probe`: what finite-difference probing needs; without an evaluator there, a material
  // without an analytic tangent is refused.
  Tangent(const Topology& topology, const std::vector<Block>& blocks, const std::string& solverPath,
          const ProbeSettings& probe = ProbeSettings());
  ~Tangent();
  // The step size of the probing trial evaluations (the load or time step; rate models read it).
  // `velocityRate`: dv/du of the solver's update (1 / dt for the load steps, gamma / (beta dt)
  // for Newmark): a rate model's velocities move by it times the probe.
  void setProbeTimeStep(double dt, double velocityRate = 0.0) {
    probeDt_ = dt;
    probeVelocityRate_ = velocityRate > 0 ? velocityRate : (dt > 0 ? 1.0 / dt : 0.0);
  }
  // Whether the tangent is probed by finite differences, with how many colours (0 otherwise).
  bool finiteDifference() const { return fd_ != nullptr; }
  int colours() const { return fd_ ? fd_->colours() : 0; }
  double probeLength() const { return fd_ ? fd_->probeLength() : 0.0; }
  // Fills the blocks at the current state (after an evaluation) and assembles the owned matrix.
  // `held` (3 per overlap point, ghosts refreshed): 1 for a degree of freedom held fixed; its
  // row and column are zeroed and its diagonal set to `heldDiagonal`. `addedDiagonal` (owned, 3
  // per point, may be null) is added to the diagonal of the free degrees of freedom: the mass
  // term M / (beta dt^2) of Newmark's method.
  void assemble(const ModelState& state, const std::vector<Block>& blocks, const double* held,
                double heldDiagonal, const double* addedDiagonal = nullptr);
  Teuchos::RCP<CrsMatrix> matrix() const { return owned_; }
  // The point-level blocks of the last analytic assembly (overlap rows), for tests.
  const TangentBlocks& blocks() const { return blocks_; }
  // Bytes of the point-level blocks and the two Tpetra matrices (values and indices).
  double bytes() const;

 private:
  const Topology& topology_;
  int numRowPoints_ = 0;  // owned + ghosts
  TangentBlocks blocks_;
  Teuchos::RCP<const Map> overlapMap3_;
  Teuchos::RCP<CrsMatrix> overlap_, owned_;
  Teuchos::RCP<Tpetra::Export<LocalOrdinal, GlobalOrdinal>> export_;
  std::unique_ptr<FiniteDifferenceTangent> fd_;
  double probeDt_ = 0.0, probeVelocityRate_ = 0.0;
  std::vector<LocalOrdinal> rowColumns_;  // scratch: one matrix row's local columns
  std::vector<double> rowValues_;
};

}  // namespace peridot
