#include "evaluator/ModelEvaluator.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/HugePages.hpp"
#include "core/ProcessorsPerRank.hpp"
#include "deck/Expression.hpp"
#include "neighbor/PartialVolume.hpp"

namespace peridot {

ModelEvaluator::ModelEvaluator(const Topology& topology, FieldManager& fields,
                               std::vector<Block>& blocks, const std::string& influenceFunction,
                               Timers& timers)
    : topology_(topology),
      fields_(fields),
      blocks_(blocks),
      influenceFunction_(influenceFunction),
      timers_(timers) {}

void ModelEvaluator::initialize() {
  state_.topology = &topology_;
  state_.fields = &fields_;
  state_.x = fields_.node("Model_Coordinates", 3);
  state_.y = fields_.node("Coordinates", 3);
  state_.volume = fields_.node("Volume", 1);
  state_.horizon = fields_.node("Horizon", 1);
  state_.forceDensity = fields_.node("Force_Density", 3);
  // What every bond loop reads or writes at a bond's other end, in large pages
  // (core/HugePages.hpp).
  {
    const auto points = static_cast<std::size_t>(topology_.numOverlap) * sizeof(double);
    for (const double* v : {state_.x, static_cast<const double*>(state_.y),
                            static_cast<const double*>(state_.forceDensity)})
      collapseToHugePages(v, 3 * points);
    collapseToHugePages(state_.volume, points);
  }
  // Velocities only where some model reads them (a test scene without them allocates none).
  for (const auto& b : blocks_) velocityGhosts_ = velocityGhosts_ || b.material->needsVelocity();
  if (velocityGhosts_ || fields_.hasNode("Velocity")) state_.velocity = fields_.node("Velocity", 3);
  state_.bondSides = topology_.bondSides.empty() ? nullptr : topology_.bondSides.data();

  // Compact damage (1-byte broken flags instead of a float per bond): only if the caller allows
  // it (no checkpoint or implicit solver reads the float array), every damage model is a
  // critical stretch fused into its material's force loop, and every material reads the flags.
  {
    bool anyDamageModel = false, compact = compactDamageAllowed_;
    for (const auto& b : blocks_) {
      compact = compact && b.material->acceptsBrokenBondFlags();
      if (b.damage) {
        anyDamageModel = true;
        compact = compact && b.damage->fusableCriticalStretch() > 0 &&
                  b.material->fusesCriticalStretch() && !b.damage->initializesDamage();
      }
    }
    compactDamage_ = compact && anyDamageModel;
  }

  halfBondsBuilt_ =
      halfBondListApplies() && buildHalfBondList(topology_, halfBonds_, setUpThreads());
  storeBondLengthsIfRead();

  // Bond influence: stored per bond only when it is not the constant 1. The bond-based models'
  // micromoduli assume omega = 1 (Peridigm's PMB ignores the influence function): refuse rather
  // than ignore.
  state_.influenceFunction = influenceFunction_;
  for (const auto& b : blocks_) {
    if (!b.material->acceptsInfluenceFunction(influenceFunction_)) {
      throw InputError("Discretization -> Influence Function",
                       "the " + b.material->family() + " material of block " + b.name +
                           " does not support the influence function \"" + influenceFunction_ +
                           "\"; use \"One\" or a state-based material");
    }
    if (b.damage && b.damage->bondLaw().kind != BondLaw::Kind::Linear &&
        !b.material->acceptsSmoothBondLaw()) {
      throw InputError("Blocks -> " + b.name, "the damage model \"" + b.damageName +
                                                  "\" needs a material that applies its "
                                                  "smooth force law; the " +
                                                  b.material->family() + " material does not");
    }
    if (b.damage && b.material->requiresFusedCriticalStretch() &&
        !(b.damage->fusableCriticalStretch() > 0)) {
      throw InputError("Blocks -> " + b.name, "the " + b.material->family() +
                                                  " material supports only the \"Critical "
                                                  "Stretch\" damage model, not \"" +
                                                  b.damageName + "\"");
    }
  }
  if (influenceFunction_ != "One" || partialVolumes_) {
    std::vector<double>& omega = fields_.bond("Influence_Function");
    const bool one = influenceFunction_ == "One";
    const std::int64_t* offsets = topology_.bondOffsets.data();
    const int* nb = topology_.neighbors.data();
    const bool parabolic = influenceFunction_ == "Parabolic Decay";
    const bool gaussian = influenceFunction_ == "Gaussian";
    // Conical kernels of papers 001 and 002: 1 - zeta/delta, and that over zeta.
    const bool conical = influenceFunction_ == "Conical";
    const bool conicalOverZeta = influenceFunction_ == "Conical Over Zeta";
    std::unique_ptr<Expression> expr;
    if (!one && !parabolic && !gaussian && !conical && !conicalOverZeta) {
      expr = std::make_unique<Expression>(influenceFunction_,
                                          std::vector<std::string>{"zeta", "horizon"},
                                          "Discretization -> Influence Function");
    }
    CellFractionCache fractions;
    for (int i = 0; i < topology_.numOwned; ++i) {
      const double delta = state_.horizon[i];
      for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
        const int j = nb[b];
        double xi[3], z2 = 0;
        for (int d = 0; d < 3; ++d) {
          xi[d] = state_.x[3 * j + d] - state_.x[3 * i + d];
          z2 += xi[d] * xi[d];
        }
        // With partial volumes a bond may reach past the horizon (its cell overlaps it): the
        // part of the cell inside lies at zeta <= delta, so omega is taken there. (Without them
        // Peridigm's box neighbourhood also has bonds past delta; those keep omega(zeta).)
        const double z2At = partialVolumes_ ? std::min(z2, delta * delta) : z2;
        const double zeta = std::sqrt(z2At), r = zeta / delta;
        if (one) {
          omega[b] = 1.0;
        } else if (parabolic) {
          omega[b] = r < 0.5 ? 1.0 : -4.0 * r * r + 4.0 * r;
        } else if (gaussian) {
          omega[b] = std::exp(-z2At / (0.16 * delta * delta));
        } else if (conical) {
          omega[b] = 1.0 - r;
        } else if (conicalOverZeta) {
          omega[b] = (1.0 - r) / zeta;
        } else {
          const double vars[2] = {zeta, delta};
          omega[b] = expr->evaluate(vars);
          if (!std::isfinite(omega[b])) {
            throw InputError(
                "Discretization -> Influence Function",
                "the expression gives a non-finite value at zeta = " + std::to_string(zeta));
          }
        }
        if (partialVolumes_) {
          const double h = cellEdge(state_.volume[j], state_.dimension, state_.thickness);
          omega[b] *= fractions.fraction(xi, h, delta, state_.dimension);
        }
      }
    }
    state_.influence = omega.data();
  }

  bool anyDamage = false;
  for (const auto& b : blocks_) anyDamage = anyDamage || b.damage != nullptr;
  if (anyDamage) {
    hasDamage_ = true;
    if (compactDamage_) {
      bondBroken_ = fields_.bondByte("Bond_Broken").data();
      state_.bondBroken = bondBroken_;
    } else {
      bondDamage_ = fields_.bondFloat("Bond_Damage").data();
      state_.bondDamage = bondDamage_;
      for (auto& b : blocks_)
        if (b.damage) b.damage->initializeDamage(state_, b.points, bondDamage_);
    }
    // Whoever asks for the damage by name (a checkpoint, a test) gets it current.
    if (halfBondsBuilt_)
      fields_.setBondFieldUpdate(compactDamage_ ? "Bond_Broken" : "Bond_Damage", this,
                                 [this] { recordBreaks(); });
  }

  // Bonds may only join points whose models can read each other's per-point state. Every rank
  // has every block (some without points): with one kind of material (the usual deck) no bond
  // can join two, and no rank makes the pass over every bond.
  std::vector<std::string> families;
  for (const auto& b : blocks_)
    if (std::find(families.begin(), families.end(), b.material->family()) == families.end())
      families.push_back(b.material->family());
  if (families.size() > 1) {
    double* family = fields_.node("Material_Family_Index", 1);
    for (const auto& b : blocks_) {
      const auto it = std::find(families.begin(), families.end(), b.material->family());
      for (int i : b.points) family[i] = static_cast<double>(it - families.begin());
    }
    fields_.refreshGhosts("Material_Family_Index");
    std::string message;
    for (int i = 0; i < topology_.numOwned && message.empty(); ++i)
      for (std::int64_t b = topology_.bondOffsets[i]; b < topology_.bondOffsets[i + 1]; ++b)
        if (family[topology_.neighbors[b]] != family[i]) {
          message = "Blocks: bonds join blocks whose materials are of different kinds (" +
                    families[static_cast<int>(family[i])] + " and " +
                    families[static_cast<int>(family[topology_.neighbors[b]])] +
                    "); set Discretization -> Omit Bonds Between Blocks: All";
          break;
        }
    throwIfAnyRank(message, topology_.comm);
    fields_.release("Material_Family_Index");
  }

  std::set<MaterialModel*> declared;
  for (auto& b : blocks_)
    if (declared.insert(b.material.get()).second) b.material->declareFields(fields_);
  std::set<std::string> syncInit, syncPre;
  for (auto& b : blocks_) {
    b.material->initialize(state_, b.points);
    for (const auto& f : b.material->fieldsToSyncAfterInitialize()) syncInit.insert(f);
    for (const auto& f : b.material->fieldsToSyncAfterPrecompute()) syncPre.insert(f);
  }
  for (const auto& f : syncInit) fields_.refreshGhosts(f);
  syncAfterPrecompute_.assign(syncPre.begin(), syncPre.end());

  if (halfBondsBuilt_) {
    if (storeBondLengths_)
      halfBonds_.storeLengths(state_.x, HalfBondList::kLengthTableLimit, setUpThreads());
    if (state_.influence) halfBonds_.gatherInfluence(topology_, state_.influence);
    // The rows as built hold every pair intact, in order, and nothing has written damage yet:
    // the half list is not built where a damage model writes damage before the first step
    // (halfBondListApplies), so there is nothing to read again (bondDamageRewritten: a pass
    // over every pair, 2% of a 128^3 set-up).
  }
}

// Reference bond lengths, once, if some block reads them (MaterialModel::needsBondLength, or a
// damage pass that is not fused into the force loop): the kernels read them instead of the
// neighbours' reference coordinates. Others compute |xi| with referenceBondLength() (same bits)
// and save 8 bytes a bond. With the half bond list the pairs keep |xi| themselves (when lengths
// are stored at all): a half-list material's loops read those, its other passes compute it.
void ModelEvaluator::storeBondLengthsIfRead() {
  const bool half = halfBondsBuilt_;
  bool needLength = storeBondLengths_ && !half;
  for (const auto& b : blocks_)
    needLength = needLength || (b.material->needsBondLength() && !half) ||
                 (b.damage && b.damage->needsBondLength() && !fusesDamage(b));
  if (!needLength || state_.bondLength) return;
  std::vector<double>& length = fields_.bond("Reference_Bond_Length");
  for (int i = 0; i < topology_.numOwned; ++i)
    for (std::int64_t b = topology_.bondOffsets[i]; b < topology_.bondOffsets[i + 1]; ++b)
      length[b] = referenceBondLength(state_.x, i, topology_.neighbors[b]);
  state_.bondLength = length.data();
}

ModelEvaluator::~ModelEvaluator() {
  fields_.clearBondFieldUpdate("Bond_Broken", this);
  fields_.clearBondFieldUpdate("Bond_Damage", this);
}

void ModelEvaluator::recordBreaks() const {
  if (!halfBondsBuilt_ || !halfBonds_.breaksPending()) return;
  if (bondDamage_)
    halfBonds_.recordBreaks(topology_, bondDamage_);
  else if (bondBroken_)
    halfBonds_.recordBreaks(topology_, bondBroken_);
}

void ModelEvaluator::bondDamageRewritten() {
  if (halfBondsBuilt_) halfBonds_.gatherDamage(topology_, bondDamage_, bondBroken_);
}

bool ModelEvaluator::halfBondListApplies() const {
  // Every block with the same material instance (one force loop then covers every pair of the
  // rank's points: the deck's blocks that share a material entry) that walks pairs, and a pair
  // force that is the same bits read from either end: the linear law, an omega that is 1 or a
  // function of |xi| alone (one horizon everywhere, no partial volumes), bonds within both
  // horizons, and bond damage that only a fused critical stretch writes, the same for every
  // block (it breaks both entries of a bond together; a separate pass, or initial damage, might
  // leave the two ends apart). Every condition is the same on every rank.
  if (!halfBondListAllowed_ || blocks_.empty()) return false;
  const Block& first = blocks_.front();
  if (!first.material->computesOverHalfBondList() || !topology_.bondSides.empty()) return false;
  if (partialVolumes_) return false;
  if (influenceFunction_ != "One") {
    if (!first.material->halfBondListTakesInfluence()) return false;
    double range[2] = {-std::numeric_limits<double>::infinity(),
                       -std::numeric_limits<double>::infinity()};  // -min, max
    for (int i = 0; i < topology_.numOwned; ++i) {
      range[0] = std::max(range[0], -state_.horizon[i]);
      range[1] = std::max(range[1], state_.horizon[i]);
    }
    MPI_Allreduce(MPI_IN_PLACE, range, 2, MPI_DOUBLE, MPI_MAX, topology_.comm);
    if (-range[0] != range[1]) return false;
  }
  for (const Block& b : blocks_) {
    if (b.material != first.material || (b.damage == nullptr) != (first.damage == nullptr))
      return false;
    if (!b.damage) continue;
    if (b.damage->bondLaw().kind != BondLaw::Kind::Linear || !fusesCriticalStretch(b) ||
        b.damage->initializesDamage() ||
        b.damage->fusableCriticalStretch() != first.damage->fusableCriticalStretch())
      return false;
  }
  return true;
}

void ModelEvaluator::setThermal(const double* temperatureChange) {
  state_.temperatureChange = temperatureChange;
  bool expands = false;
  for (const auto& b : blocks_) expands = expands || b.material->thermalExpansionCoefficient() != 0;
  for (const auto& b : blocks_) {
    // A smooth law would need each end's F(s - alpha Delta T): not there yet.
    if (expands && b.damage && b.damage->bondLaw().kind != BondLaw::Kind::Linear) {
      throw InputError("Blocks -> " + b.name,
                       "thermal strains with the smooth force law of the damage model \"" +
                           b.damageName + "\" are not supported yet");
    }
  }
  // Without expanding materials nothing reads the strain (damage models read Delta T only).
  state_.thermalStrain = expands ? fields_.node(kThermalStrain, 1) : nullptr;
  thermal_ = expands;  // the pointer is null on a rank without points
  // The half list's loops have no thermal strains: its memory goes back (the same on every
  // rank), and the full lists' loops may need |xi| per bond.
  if (expands && halfBondsBuilt_) {
    recordBreaks();
    halfBonds_ = HalfBondList();
    halfBondsBuilt_ = false;
    storeBondLengthsIfRead();
  }
}

bool ModelEvaluator::hasHistory() const {
  for (const auto& b : blocks_)
    if (b.material->advancesHistory() || (b.damage && b.damage->integratesInTime())) return true;
  return false;
}

void ModelEvaluator::evaluate(double dt, bool updateDamage, bool commitHistory) {
  state_.dt = dt;
  state_.commitHistory = commitHistory;
  {
    Timers::Scope t(timers_, "Ghost exchange");
    fields_.refreshGhosts("Coordinates");
    if (velocityGhosts_) fields_.refreshGhosts("Velocity");
    if (thermal_) {
      // alpha of each point's own material: across a bond between blocks each end expands as
      // its material does.
      double* strain = fields_.node(kThermalStrain, 1);
      for (const auto& b : blocks_) {
        const double alpha = b.material->thermalExpansionCoefficient();
        for (int i : b.points) strain[i] = alpha * state_.temperatureChange[i];
      }
      fields_.refreshGhosts(kThermalStrain);
    }
  }
  // On every rank alike, also one without bonds (bondDamage_ null there): the timer names must
  // be the same on all ranks for their reduction at the end, and a damage model may stop the
  // run collectively.
  if (hasDamage_ && updateDamage) {
    Timers::Scope t(timers_, "Damage");
    for (auto& b : blocks_)
      if (b.damage && !fusesDamage(b)) b.damage->computeDamage(state_, b.points, bondDamage_);
  }
  // A fused damage update is handed to the block's first bond loop: precompute for a model that
  // breaks there (its dilatation must see this step's breaks), else computeForce. A fused
  // critical stretch comes as fusedCriticalStretch, a smooth law's damage (DTT) with
  // fusedCriticalStretch 0, LSJ-T's update as fusedLsjt (started here, once per evaluation, as
  // its computeDamage would be). Each point's loops read only its own bonds' damage, so the same
  // bonds break as in the pass above.
  const auto breakable = [&](const Block& b, bool inPrecompute) {
    const bool inLoop = b.material->breaksInPrecompute() == inPrecompute;
    const bool fused = updateDamage && fusesDamage(b) && inLoop;
    state_.breakableBondDamage = fused ? bondDamage_ : nullptr;
    state_.breakableBondBroken = fused ? bondBroken_ : nullptr;
    state_.fusedCriticalStretch =
        fused && fusesCriticalStretch(b) ? b.damage->fusableCriticalStretch() : 0.0;
    state_.fusedLsjt = fused && fusesLsjt(b) ? b.damage->beginLsjtStep(state_) : LsjtStep();
  };
  bool precompute = !syncAfterPrecompute_.empty();
  for (const auto& b : blocks_) precompute = precompute || b.material->breaksInPrecompute();
  // Over the half list the first block's loops walk every pair of every block.
  state_.halfBonds = halfBondsBuilt_ ? &halfBonds_ : nullptr;  // none with thermal strains
  if (precompute) {
    {
      Timers::Scope t(timers_, "Force");
      for (auto& b : blocks_) {
        state_.bondLaw = b.damage ? b.damage->bondLaw() : BondLaw();
        breakable(b, true);
        b.material->precompute(state_, b.points);
        if (state_.halfBonds) break;
      }
    }
    Timers::Scope t(timers_, "Ghost exchange");
    for (const auto& f : syncAfterPrecompute_) fields_.refreshGhosts(f);
  }
  Timers::Scope t(timers_, "Force");
  for (auto& b : blocks_) {
    state_.bondLaw = b.damage ? b.damage->bondLaw() : BondLaw();
    breakable(b, false);
    b.material->computeForce(state_, b.points);
    if (state_.halfBonds) break;
  }
  state_.halfBonds = nullptr;
  state_.breakableBondDamage = nullptr;
  state_.breakableBondBroken = nullptr;
  state_.fusedCriticalStretch = 0.0;
  state_.fusedLsjt = LsjtStep();
  state_.commitHistory = true;
}

bool ModelEvaluator::fusesCriticalStretch(const Block& b) const {
  // Only when nothing between the damage pass and the loop that breaks reads this block's bond
  // damage: each point's loops read only its own bond entries (see evaluate).
  // Compact damage has no float array for a separate pass: always fused.
  return (fuseCriticalStretch_ || compactDamage_ || b.material->requiresFusedCriticalStretch()) &&
         b.damage && b.damage->fusableCriticalStretch() > 0 && b.material->fusesCriticalStretch();
}

bool ModelEvaluator::fusesSmoothBreak(const Block& b) const {
  // Float bond damage only: a smooth law's damage is not a 0/1 flag (compact damage never
  // comes with it).
  return fuseCriticalStretch_ && b.damage && b.damage->fusesIntoSmoothBondLaw() &&
         b.damage->bondLaw().kind == BondLaw::Kind::Smooth && b.material->fusesSmoothBreak();
}

bool ModelEvaluator::fusesLsjt(const Block& b) const {
  // In the precompute loop only: the dilatation must see this step's damage. Float bond damage
  // (compact damage never comes with it).
  return fuseCriticalStretch_ && b.damage && b.damage->fusesIntoLinearizedStrain() &&
         b.material->fusesLsjtUpdate() && b.material->breaksInPrecompute();
}

bool ModelEvaluator::fusesDamage(const Block& b) const {
  return fusesCriticalStretch(b) || fusesSmoothBreak(b) || fusesLsjt(b);
}

void ModelEvaluator::saveDamage(DamageSnapshot& snapshot) const {
  recordBreaks();
  if (state_.bondDamage)
    snapshot.bondDamage = fields_.bondFloat("Bond_Damage");
  else
    snapshot.bondDamage.clear();
  if (state_.bondBroken) {
    const auto& broken = fields_.bondByte("Bond_Broken");
    snapshot.bondBroken.assign(broken.begin(), broken.end());
  } else {
    snapshot.bondBroken.clear();
  }
  snapshot.materials.resize(blocks_.size());
  for (std::size_t k = 0; k < blocks_.size(); ++k)
    blocks_[k].material->saveDamageState(snapshot.materials[k]);
}

void ModelEvaluator::restoreDamage(const DamageSnapshot& snapshot) {
  // Through the evaluator's pointers, not the fields by name: the half list's pending breaks
  // need not be recorded into arrays about to be overwritten (gatherDamage drops them).
  if (state_.bondDamage)
    std::copy(snapshot.bondDamage.begin(), snapshot.bondDamage.end(), bondDamage_);
  if (state_.bondBroken)
    std::copy(snapshot.bondBroken.begin(), snapshot.bondBroken.end(), bondBroken_);
  bondDamageRewritten();
  // Blocks sharing a material instance saved the same state; restoring it twice is harmless.
  for (std::size_t k = 0; k < blocks_.size() && k < snapshot.materials.size(); ++k)
    blocks_[k].material->restoreDamageState(snapshot.materials[k]);
}

void ModelEvaluator::nodeDamage(double* damage) const {
  if (halfBondsBuilt_ && (bondBroken_ || bondDamage_) && halfBonds_.pairDamage.empty()) {
    // Every bond intact or broken, and the rows' broken pairs are the broken bonds
    // (halfBondListApplies: a fused critical stretch breaks both entries of a bond together,
    // and what rewrites the full lists is read into the rows again): counting those reads
    // bytes per break, not a byte per bond, needs no pending break recorded (recordBreaks),
    // and leaves the flags' untouched pages untouched (on some kernels a read takes a fresh
    // page: core/ZeroedArray.hpp). Every bond is within both horizons here (no bondSides). The
    // counts are whole numbers, the same doubles as the passes below (a sum of 0s and 1s).
    std::fill(damage, damage + topology_.numOwned, 0.0);
    halfBonds_.addBrokenBonds(topology_.numOwned, damage);
    for (int i = 0; i < topology_.numOwned; ++i) {
      const std::int64_t count = topology_.bondOffsets[i + 1] - topology_.bondOffsets[i];
      damage[i] = count > 0 ? damage[i] / static_cast<double>(count) : 0.0;
    }
    return;
  }
  recordBreaks();
  if (bondBroken_ && !bondDamage_) {
    // Broken-bond flags: whole numbers, which the double sums below add exactly in any order,
    // so the counts are integers here and the pass vectorises (as a chain of double additions
    // it took 0.26 s per output at 128^3, a quarter of a step).
    const unsigned char* sides = topology_.bondSides.empty() ? nullptr : topology_.bondSides.data();
    for (int i = 0; i < topology_.numOwned; ++i) {
      const std::int64_t b0 = topology_.bondOffsets[i], b1 = topology_.bondOffsets[i + 1];
      std::int64_t broken = 0, count = b1 - b0;
      if (sides) {
        count = 0;
        for (std::int64_t b = b0; b < b1; ++b) {
          const int own = sides[b] & 1;
          count += own;
          broken += own * bondBroken_[b];
        }
      } else {
        for (std::int64_t b = b0; b < b1; ++b) broken += bondBroken_[b];
      }
      damage[i] = count > 0 ? static_cast<double>(broken) / static_cast<double>(count) : 0.0;
    }
    return;
  }
  for (int i = 0; i < topology_.numOwned; ++i) {
    const std::int64_t b0 = topology_.bondOffsets[i], b1 = topology_.bondOffsets[i + 1];
    // Over the bonds within the point's own horizon (all of them unless horizons differ).
    double broken = 0, count = 0;
    for (std::int64_t b = b0; b < b1; ++b) {
      if (!topology_.ownSide(b)) continue;
      count += 1;
      if (bondDamage_) broken += bondDamage_[b];
    }
    damage[i] = count > 0 ? broken / count : 0.0;
  }
}

void ModelEvaluator::storedEnergyDensity(double* energyDensity) const {
  recordBreaks();
  ModelState state = state_;
  for (const auto& b : blocks_) {
    state.bondLaw = b.damage ? b.damage->bondLaw() : BondLaw();
    b.material->storedEnergyDensity(state, b.points, energyDensity);
  }
}

}  // namespace peridot
