#pragma once
// Interface of a damage model: updates the bond damage (0 intact .. 1 broken) of a block's
// owned points before the material computes forces.
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "core/Registry.hpp"
#include "materials/MaterialModel.hpp"

namespace peridot {

class DamageModel {
 public:
  virtual ~DamageModel() = default;
  virtual void computeDamage(const ModelState& state, const std::vector<int>& points,
                             float* bondDamage) = 0;
  // Called once at set-up, after the bond damage is allocated (zero) and before the first
  // evaluation: models that start with broken bonds (`Initial Damage`) set them here.
  virtual void initializeDamage(const ModelState& /*state*/, const std::vector<int>& /*points*/,
                                float* /*bondDamage*/) {}
  // Models whose parameters depend on the block (material, horizon) get one instance per block
  // and are bound to it before the run; `log` receives what was derived (rank 0 prints it).
  virtual bool bindsToBlock() const { return false; }
  virtual void bind(const MaterialModel& /*material*/, double /*horizon*/,
                    const std::string& /*blockName*/, std::ostream& /*log*/) {}
  // The force law the block's material must apply with this damage (see BondLaw.hpp).
  virtual BondLaw bondLaw() const { return BondLaw(); }
  // A positive critical stretch when the model is nothing but "break for good when the stretch
  // exceeds it": a material that fuses that check into its force loop may then replace
  // computeDamage (MaterialModel::fusesCriticalStretch).
  virtual double fusableCriticalStretch() const { return 0.0; }
  // Whether the model is nothing but "bond damage = the history maximum of its Smooth bond law's
  // brokenFraction(stretch)" (DTT): a material that applies the smooth law in its force loop
  // may then replace computeDamage (MaterialModel::fusesSmoothBreak).
  virtual bool fusesIntoSmoothBondLaw() const { return false; }
  // Whether the model is LSJ-T's update of each bond's history integral from its linearized
  // strain (damage/LsjtStep.hpp): a material whose first bond loop forms that strain may then
  // apply it there (MaterialModel::fusesLsjtUpdate) in place of computeDamage.
  virtual bool fusesIntoLinearizedStrain() const { return false; }
  // For such a model, in place of computeDamage: what it does before its walk over the bonds
  // (the first evaluation starts its clock) and the data of this evaluation's update, which the
  // material's loop applies with lsjtStrains / lsjtUpdateBonds. Called once per evaluation that
  // updates damage.
  virtual LsjtStep beginLsjtStep(const ModelState& /*state*/) { return LsjtStep(); }
  // Whether computeDamage reads ModelState::bondLength (stored only if some model asks for it;
  // a model that returns false computes |xi| with referenceBondLength()).
  virtual bool needsBondLength() const { return true; }
  // Whether initializeDamage may break bonds (then the run keeps float bond damage).
  virtual bool initializesDamage() const { return false; }
  // A run continued from a checkpoint: the model's history fields are restored and the next
  // evaluation closes a step (it is not the initial state).
  virtual void resume() {}
  // Whether the damage integrates a rate over time (ModelState::dt): it then needs a solver
  // with time steps; the load-stepped solvers evaluate with dt = 0 and refuse it.
  virtual bool integratesInTime() const { return false; }
  // Node fields that carry the model's history from step to step (the Johnson-Cook damage
  // parameter): the checkpoint saves and restores their owned values, as a material's.
  virtual std::vector<std::string> historyNodeFields() const { return {}; }
};

using DamageRegistry = Registry<DamageModel>;

std::unique_ptr<DamageModel> createDamageModel(ListReader& params);

}  // namespace peridot

#define PERIDOT_REGISTER_DAMAGE(DeckName, Class, Summary, Params)                             \
  namespace {                                                                                 \
  const bool kRegistered##Class = ::peridot::DamageRegistry::add(                             \
      DeckName, [](::peridot::ListReader& p) { return std::make_unique<Class>(p); }, Summary, \
      Params);                                                                                \
  }
