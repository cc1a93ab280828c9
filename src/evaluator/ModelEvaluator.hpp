#pragma once
// One model evaluation, in Peridigm's order: ghost refresh of the current coordinates, damage,
// state-based precompute (then a second ghost refresh of what it produced), force.
#include <string>
#include <vector>

#include "core/Timers.hpp"
#include "evaluator/Block.hpp"
#include "fields/FieldManager.hpp"
#include "neighbor/HalfBondList.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

class ModelEvaluator {
 public:
  // `influenceFunction`: "One", "Parabolic Decay", "Gaussian" or an expression in zeta, horizon.
  ModelEvaluator(const Topology& topology, FieldManager& fields, std::vector<Block>& blocks,
                 const std::string& influenceFunction, Timers& timers);
  ~ModelEvaluator();
  ModelEvaluator(const ModelEvaluator&) = delete;
  ModelEvaluator& operator=(const ModelEvaluator&) = delete;

  // A planar run: points in z = 0, volumes include `thickness`. Call before initialize().
  void setPlanar(double thickness) {
    state_.dimension = 2;
    state_.thickness = thickness;
  }
  // Whether blocks with "Critical Stretch" (bond-based and Linearized LPS blocks with "DTT",
  // Linearized LPS blocks with "LSJ-T") update their bond damage inside the material's bond loop
  // (default) or in a separate damage pass; both give the same bits (bench_roofline measures).
  void setFuseCriticalStretch(bool fuse) { fuseCriticalStretch_ = fuse; }
  // Allows compact bond damage (1-byte broken flags, ModelState::bondBroken) when every damage
  // model is a fused critical stretch and every material reads the flags. Off by default: the
  // caller allows it when nothing else needs the float `Bond_Damage` array (checkpoints, the
  // implicit solver's tangent). Before initialize().
  void setCompactDamageAllowed(bool allowed) { compactDamageAllowed_ = allowed; }
  // Stores |xi| per bond for every model (the default: the bond-based loops then read it, which
  // is faster than computing it); false lets models that do not need it compute it instead.
  void setStoreBondLengths(bool store) { storeBondLengths_ = store; }
  bool compactDamage() const { return compactDamage_; }
  // Allows the bond-based materials to walk each bond once (neighbor/HalfBondList.hpp) where the
  // scene allows it (the default); false keeps the two-sided loop. Before initialize().
  void setHalfBondListAllowed(bool allowed) { halfBondListAllowed_ = allowed; }
  // Whether initialize() built the half bond list (the same on every rank) and its evaluations
  // use it (setThermal with expanding materials drops it).
  bool usesHalfBondList() const { return halfBondsBuilt_; }
  std::size_t halfBondListBytes() const { return halfBonds_.bytes(); }
  HalfBondList* halfBondList() { return halfBondsBuilt_ ? &halfBonds_ : nullptr; }
  // To be called after the bond damage arrays were written from outside (a checkpoint read):
  // the half list's copy of the damage is gathered again.
  void bondDamageRewritten();
  // Partial-volume quadrature (topology built with the CellOverlap rule): every bond's influence
  // is multiplied by the fraction of the neighbour's cell inside the horizon. Before initialize().
  void setPartialVolumes(bool partial) {
    partialVolumes_ = partial;
    state_.partialVolumes = partial;
  }
  // The bond filters of the discretization (kept by the caller), for the models that pair
  // neighbours. Before initialize().
  void setBondFilters(const std::vector<BondFilter>* filters) { state_.bondFilters = filters; }
  // Declares fields, fills bond influence, initializes the models. Reference coordinates,
  // volumes and horizons must already be in their fields (owned and ghost).
  void initialize();
  // Computes the internal force density of all owned points from the current coordinates
  // (owned values; ghosts are refreshed here). With `updateDamage` false no bond breaks (the
  // linearized stiffness is probed this way). With `commitHistory` false the evaluation is a
  // trial: history models compute the force from the history of the step's start and store none
  // (ModelState::commitHistory); a solver commits a converged step with one committing
  // evaluation at its final state.
  void evaluate(double dt, bool updateDamage = true, bool commitHistory = true);
  // Whether some block's material or damage model keeps a history that a trial evaluation leaves
  // alone (then a converged step needs its committing evaluation).
  bool hasHistory() const;
  // Whether some block's material reads the velocities (rate models).
  bool readsVelocity() const { return velocityGhosts_; }
  // Thermal loading (after initialize): `temperatureChange` is the owned Delta T the run's
  // temperature conditions maintain. Materials with a thermal expansion coefficient then see the
  // thermal strain alpha Delta T of every point (own and ghost), refreshed at each evaluation;
  // damage models read Delta T of the owned points.
  void setThermal(const double* temperatureChange);
  static constexpr const char* kThermalStrain = "Thermal_Strain";
  // The time of the next evaluations (time-dependent damage laws read it).
  void setTime(double t) { state_.time = t; }

  // The models' state, its bond damage current (recordBreaks).
  const ModelState& state() const {
    recordBreaks();
    return state_;
  }
  // Fraction of broken bonds per owned point (0 where no damage model or no bonds).
  void nodeDamage(double* damage) const;
  // The irreversible damage of the run (float bond damage or broken-bond flags, and what
  // materials keep themselves, MaterialModel::saveDamageState): the load-stepped solvers save it
  // before a trial that may break bonds and restore it when they reject the trial.
  struct DamageSnapshot {
    std::vector<float> bondDamage;
    std::vector<unsigned char> bondBroken;
    std::vector<std::vector<float>> materials;  // per block, in block order
  };
  void saveDamage(DamageSnapshot& snapshot) const;
  void restoreDamage(const DamageSnapshot& snapshot);
  void storedEnergyDensity(double* energyDensity) const;
  std::vector<Block>& blocks() { return blocks_; }

 private:
  const Topology& topology_;
  FieldManager& fields_;
  std::vector<Block>& blocks_;
  std::string influenceFunction_;
  Timers& timers_;
  ModelState state_;
  bool fusesCriticalStretch(const Block& b) const;
  bool fusesSmoothBreak(const Block& b) const;
  bool fusesLsjt(const Block& b) const;
  // Whether the block's damage runs inside its material's bond loops instead of its own pass.
  bool fusesDamage(const Block& b) const;

  float* bondDamage_ = nullptr;  // null on a rank without bonds, or with compact damage
  unsigned char* bondBroken_ =
      nullptr;              // compact damage: 1 = broken (null on a rank without bonds)
  bool hasDamage_ = false;  // some block has a damage model (the same on every rank)
  bool thermal_ = false;    // some block's material expands (the same on every rank)
  bool fuseCriticalStretch_ = true;
  bool compactDamageAllowed_ = false;
  bool storeBondLengths_ = true;
  bool compactDamage_ = false;
  bool partialVolumes_ = false;
  bool halfBondListAllowed_ = true;
  bool halfBondsBuilt_ = false;
  // Mutable: its loops note breaks in its rows, and the full lists (bondDamage_, bondBroken_)
  // are brought up to date by recordBreaks when something reads them, also through a const
  // evaluator (an output): the damage the evaluator presents does not change.
  mutable HalfBondList halfBonds_;
  void recordBreaks() const;
  // Whether the scene allows the half list (see initialize()).
  bool halfBondListApplies() const;
  void storeBondLengthsIfRead();
  bool velocityGhosts_ =
      false;  // some block's material reads the velocities (the same on all ranks)
  std::vector<std::string> syncAfterPrecompute_;
};

}  // namespace peridot
