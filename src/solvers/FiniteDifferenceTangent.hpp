#pragma once
// The tangent of materials without an analytic one, by finite-difference probing of whole
// evaluations (Peridigm's "Finite Difference Probe Length"; central differences, as Peridigm's
// default): K_ac = -V_a (f_a(y + eps e_c) - f_a(y - eps e_c)) / (2 eps) for every column c and
// component.
//
// Our computeForce gives the force of each owned point (pull form), not one family's
// contribution, so columns are probed together: the points get a distance-2 colouring of the
// tangent's point graph (Zoltan_Color), so that no row holds two columns of one colour, and
// each (colour, component) costs two trial evaluations of the whole model. The force of row a
// depends only on the columns of its pattern row, and these have distinct colours: f_a is
// computed from exactly the same operands whichever other columns move with c. The tangent is
// therefore the same, bit for bit, for any valid colouring, and so for any rank count.
//
// The probing fills owned rows only (f is known on the owner), over all the columns of the
// owned pattern (two horizons for a state-based model: points this rank may not hold).
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <vector>

#include "evaluator/ModelEvaluator.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

using CrsMatrix = Tpetra::CrsMatrix<double, LocalOrdinal, GlobalOrdinal>;

// What probing needs of the run (the solver's arrays, overlap layout; the owned part of y and v
// is perturbed and restored).
struct ProbeSettings {
  ModelEvaluator* evaluator = nullptr;
  double* y = nullptr;        // current coordinates
  double* v = nullptr;        // velocities (perturbed with the probe for rate models)
  const double* f = nullptr;  // force density the evaluator writes
  const double* volume = nullptr;
  // eps; 0: Peridigm's default, 1e-6 x the smallest element radius (3 V / (4 pi))^(1/3).
  double probeLength = 0.0;
  // Probe also when every material has an analytic tangent (comparisons and tests).
  bool always = false;
};

class FiniteDifferenceTangent {
 public:
  // `matrix`: the owned tangent with its final pattern (values are overwritten). Colours the
  // points (collective).
  FiniteDifferenceTangent(const Topology& topology, Teuchos::RCP<CrsMatrix> matrix,
                          const ProbeSettings& settings);
  // Probes at the current state with trial evaluations of step size dt (no bond breaks, no
  // history is written), then holds and shifts the diagonal as Tangent::assemble describes, and
  // restores the state with one more trial evaluation. Collective.
  // A rate model's velocities move by velocityRate x the probe (dv/du of the solver).
  void fill(double dt, double velocityRate, const double* held, double heldDiagonal,
            const double* addedDiagonal);
  int colours() const { return numColours_; }
  double probeLength() const { return eps_; }
  double bytes() const;

 private:
  const Topology& topology_;
  Teuchos::RCP<CrsMatrix> matrix_;
  ProbeSettings settings_;
  double eps_ = 0.0;
  int numColours_ = 0;
  // The matrix's local rows (3 per owned point) as CSR over its column map.
  std::vector<std::size_t> rowOffsets_;
  std::vector<LocalOrdinal> columns_;
  std::vector<double> values_;
  // Entries by (colour, component): bucketOffsets_[3 k + e] .. [3 k + e + 1] in entries_.
  std::vector<std::size_t> bucketOffsets_, entries_;
  std::vector<int> entryRow_;  // local row of each entry (by entry index)
  // Owned points by colour.
  std::vector<int> pointOffsets_, points_;
  std::vector<double> saved_, savedVelocity_, plus_;  // scratch, owned
};

}  // namespace peridot
