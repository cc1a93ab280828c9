#pragma once
// Interface of a material model. The evaluator calls it once per block per step with the
// block's owned points; the bond loops inside run on raw CSR arrays.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/Registry.hpp"
#include "damage/BondLaw.hpp"
#include "damage/LsjtStep.hpp"
#include "fields/FieldManager.hpp"
#include "neighbor/BondGeometry.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

struct HalfBondList;

// Everything a kernel reads or writes, as raw arrays (overlap-indexed unless noted).
struct ModelState {
  const Topology* topology = nullptr;
  FieldManager* fields = nullptr;
  const double* x = nullptr;  // reference coordinates, 3 per point
  const double* y = nullptr;  // current coordinates, 3 per point
  // Node velocities, 3 per point, ghosted before each evaluation when some block's material
  // reads them (MaterialModel::needsVelocity); at an evaluation of step n -> n+1 they are the
  // mid-step velocities that moved y (y_{n+1} = y_n + dt v).
  const double* velocity = nullptr;
  const double* volume = nullptr;   // per point
  const double* horizon = nullptr;  // per point
  double* forceDensity = nullptr;   // 3 per point; kernels write owned points only
  // Per bond entry, 0 intact .. 1 broken; float: 4 bytes a bond, exact for broken/intact.
  // Null when no damage model, and also when the run keeps its damage as broken-bond flags
  // (`bondBroken`; only when every material accepts them, MaterialModel::acceptsBrokenBondFlags).
  const float* bondDamage = nullptr;
  const double* influence = nullptr;  // per bond entry; null means omega = 1
  // Per bond entry: |xi|, the reference bond length. Stored only when some material or damage
  // pass asks for it (MaterialModel::needsBondLength, the default); otherwise null, and loops
  // compute it from `x` with referenceBondLength() (the same bits as the stored value).
  const double* bondLength = nullptr;
  // Per bond entry, 1 if broken, 0 if intact: the compact damage of a run whose every damage
  // model is a critical stretch applied in its material's force loop (1 byte a bond instead of
  // 4). Null otherwise; at most one of bondDamage and bondBroken is set.
  const unsigned char* bondBroken = nullptr;
  // Per bond entry, where horizons differ: bit 0 set if the bond is within the owner's horizon,
  // bit 1 if within the neighbour's (Topology::bondSides); null when all bonds are two-sided.
  const unsigned char* bondSides = nullptr;
  double dt = 0.0;
  // Set by the evaluator while a block's force is computed when the block's critical-stretch
  // check is fused into the material's bond loop (see MaterialModel::fusesCriticalStretch):
  // bonds whose stretch exceeds it break (bond damage 1) before their force is taken.
  float* breakableBondDamage = nullptr;
  unsigned char* breakableBondBroken = nullptr;  // the same with compact damage (bondBroken)
  double fusedCriticalStretch = 0.0;
  // Set likewise when the block's LSJ-T update is fused into the material's precompute loop
  // (MaterialModel::fusesLsjtUpdate): active() then, and breakableBondDamage is its damage.
  LsjtStep fusedLsjt;
  // 2 for a planar run (points in z = 0; volumes already include the thickness), else 3.
  int dimension = 3;
  double thickness = 1.0;  // out-of-plane thickness of a 2D run
  // Set per block by the evaluator from the block's damage model (Linear without one).
  BondLaw bondLaw;
  // The deck's influence function ("One", "Conical", ...); `influence` holds its values.
  std::string influenceFunction = "One";
  // Partial-volume quadrature: `influence` includes each bond's cell fraction (see
  // evaluator/ModelEvaluator.hpp).
  bool partialVolumes = false;
  // Time of the evaluation (time-dependent damage laws).
  double time = 0.0;
  // Thermal loading (null without one): the temperature change Delta T of each point and its
  // thermal strain alpha Delta T (alpha of the point's material); both overlap-indexed and
  // ghosted. A bond's extension at end i is |Y| - |xi| - alpha_i Delta T_i |xi| (Peridigm).
  const double* temperatureChange = nullptr;
  const double* thermalStrain = nullptr;
  // The discretization's bond filters (pre-cracks), for models that form interactions between
  // neighbours (continuum kinematics); null when none.
  const std::vector<BondFilter>* bondFilters = nullptr;
  // Trial and commit evaluations (Peridigm's states N and N+1). True (Verlet, and the final
  // evaluation of a converged load or time step): a model with a history (advancesHistory(), a
  // damage model's own bond history) advances it from the start of the step to this state and
  // stores it. False (a trial: a Newton iterate, a line-search point, a finite-difference
  // probe, a relaxation iteration): the force is computed from the history at the start of the
  // step exactly as a committing evaluation at the same state would compute it, and no history
  // is written, so any number of trials may precede the one commit. (Bond damage is not such a
  // history: it is irreversible and the solvers restore it themselves where they must.)
  bool commitHistory = true;
  // Set by the evaluator for a material that walks each bond once (computesOverHalfBondList)
  // where the scene allows it (ModelEvaluator::usesHalfBondList); null otherwise.
  HalfBondList* halfBonds = nullptr;  // its pair damage is written where bonds break
};

// |xi| of bond entry b of owned point i, stored or computed (for loops off the hot path).
inline double bondLengthOf(const ModelState& s, int i, std::int64_t b) {
  return s.bondLength ? s.bondLength[b] : referenceBondLength(s.x, i, s.topology->neighbors[b]);
}

// 1 - bond damage of bond entry b, from whichever form the run stores (1 without damage).
inline double intactFraction(const ModelState& s, std::int64_t b) {
  if (s.bondDamage) return 1.0 - s.bondDamage[b];
  if (s.bondBroken) return s.bondBroken[b] ? 0.0 : 1.0;
  return 1.0;
}

// The point-level 3x3 blocks of the tangent stiffness (solvers/Tangent.hpp).
struct TangentBlocks;

// Which entries of the tangent a point's bond family fills: none (the model has no tangent),
// the row of the point and the columns of its family (bond-based: f_i depends on y_i and its
// neighbours only), or every (row, column) pair of the family (state-based: the family's
// dilatation couples all its members).
enum class TangentReach { None, Bond, Family };

// How a material reads its elastic constants: in 3D, or in plane stress / plane strain.
enum class PlaneMode { ThreeD, PlaneStress, PlaneStrain };

class MaterialModel {
 public:
  virtual ~MaterialModel() = default;
  virtual double density() const = 0;
  // The bulk modulus used by the stable time step estimate (Peridigm's convention).
  virtual double bulkModulus() const = 0;
  // Allocates the fields the model needs (called once, before initialize).
  virtual void declareFields(FieldManager&) {}
  // Called for every block using the model after all blocks declared their fields; may fill
  // per-point constants that neighbouring points read (they are ghosted afterwards).
  virtual void initialize(const ModelState&, const std::vector<int>& points) = 0;
  // Fields the evaluator must ghost after initialize / after precompute.
  virtual std::vector<std::string> fieldsToSyncAfterInitialize() const { return {}; }
  virtual std::vector<std::string> fieldsToSyncAfterPrecompute() const { return {}; }
  virtual void precompute(const ModelState&, const std::vector<int>&) {}
  virtual void computeForce(const ModelState& state, const std::vector<int>& points) = 0;
  // Stored elastic energy density (per unit volume) of each point in `points`.
  virtual void storedEnergyDensity(const ModelState& state, const std::vector<int>& points,
                                   double* energyDensity) const = 0;
  // For the stable time step: sum over the bonds of each point of its bond stiffness (force
  // density per unit relative displacement). The default is Peridigm's estimate for every
  // model: the bond-based spring constant 18 K / (pi delta^4) / |xi| times the neighbour volume.
  virtual void stiffnessSum(const ModelState& state, const std::vector<int>& points,
                            double* sum) const;
  // The tangent for implicit solvers. tangentReach(): which entries the force of a point
  // depends on (its sparsity); None: the model cannot be used by the implicit solvers.
  // hasAnalyticTangent(): addStiffness adds K_ac = -V_a d f_a / d y_c (the stiffness in force
  // units, symmetric for the elastic models) of the families of `points` into `K`, at the
  // current coordinates and bond damage; called after an evaluation (precomputed fields such as
  // the dilatation are current). Without it the solvers probe K by central finite differences of
  // trial evaluations (solvers/FiniteDifferenceTangent.hpp): a model only declares its reach,
  // and must then compute the force of owned point a from the coordinates (and, for a rate
  // model, the velocities) of the points within its reach of a only: Bond, a and its neighbours;
  // Family, a, its neighbours and theirs.
  virtual TangentReach tangentReach() const { return TangentReach::None; }
  virtual bool hasAnalyticTangent() const { return false; }
  virtual void addStiffness(const ModelState&, const std::vector<int>&, TangentBlocks&) const {}
  // Node fields the model maintains that a user may output (e.g. "Dilatation").
  virtual std::vector<std::string> outputFields() const { return {}; }
  // Node fields that carry history from step to step (e.g. the plastic multiplier "Lambda"):
  // the checkpoint saves and restores their owned values. (Bond fields are always saved.)
  virtual std::vector<std::string> historyNodeFields() const { return {}; }
  // True when computeForce advances a history (plastic or viscous state) by one step. Such a
  // model must honour ModelState::commitHistory: trial evaluations (commitHistory false) read
  // the history of the start of the step and write none of it; precompute never writes it.
  // The implicit solvers, dynamic relaxation and the "Verlet Limit" estimate probe with trials
  // and commit once per converged step. Rate models (ModelState::dt, velocity) also get, in the
  // load-stepped solvers, dt = the load step and velocity = its displacement increment / dt.
  virtual bool advancesHistory() const { return false; }
  // Irreversible damage the model keeps itself, besides the bond damage (the continuum-kinematics
  // model's bonds between neighbours): a solver that undoes a rejected trial's breaks restores it
  // with the bond damage (ModelEvaluator::saveDamage / restoreDamage).
  virtual void saveDamageState(std::vector<float>& state) const { state.clear(); }
  virtual void restoreDamageState(const std::vector<float>& /*state*/) {}
  // True when the model reads ModelState::velocity of its points and their neighbours (the rate
  // form of the correspondence models): the evaluator then ghosts the velocities.
  virtual bool needsVelocity() const { return false; }
  // A tag shared by models whose points may be bonded to each other.
  virtual std::string family() const = 0;
  // ThreeD unless the deck asks for "Plane Stress" or "Plane Strain"; the run checks that it
  // matches the discretization's dimension.
  virtual PlaneMode planeMode() const { return PlaneMode::ThreeD; }
  // Whether a plane mode may also run on a 3D cloud (Peridigm's 2D bond-based form: one layer
  // of solid elements, 3D points, a 2D micromodulus).
  virtual bool acceptsPlaneModeIn3D() const { return false; }
  // Whether the model honours the influence function of that name (bond-based micromoduli
  // are derived for omega = 1 only unless the model says otherwise).
  virtual bool acceptsInfluenceFunction(const std::string& name) const { return name == "One"; }
  // Whether the model applies a Smooth BondLaw (DTT); damage models that need one check this.
  virtual bool acceptsSmoothBondLaw() const { return false; }
  // Whether the model can apply a critical-stretch check in its own bond loop (one pass over
  // the bonds less; the same bits as the separate damage loop): in computeForce, or in
  // precompute when breaksInPrecompute.
  virtual bool fusesCriticalStretch() const { return false; }
  // Whether the model can also apply a Smooth law's damage (DamageModel::fusesIntoSmoothBondLaw)
  // in its computeForce bond loop, the same bits as the separate pass (float bond damage).
  virtual bool fusesSmoothBreak() const { return false; }
  // Whether the model can apply LSJ-T's update (DamageModel::fusesIntoLinearizedStrain,
  // ModelState::fusedLsjt) in its precompute bond loop, with LSJ-T's own per-point functions
  // (damage/LsjtStep.hpp): the same bits as the separate pass (float bond damage).
  virtual bool fusesLsjtUpdate() const { return false; }
  // Where a fused check runs: in computeForce (false), or in precompute (true: a state-based
  // model whose first bond loop, e.g. the dilatation, must already see this step's breaks). The
  // evaluator hands the model the breakable damage for that call only.
  virtual bool breaksInPrecompute() const { return false; }
  // Whether the model reads ModelState::bondLength. The evaluator stores |xi| per bond (8 bytes
  // a bond) only if some block's material (or a damage pass that is not fused) asks for it; a
  // model that returns false computes |xi| with referenceBondLength().
  virtual bool needsBondLength() const { return true; }
  // Whether the model reads bond damage from ModelState::bondBroken as well as bondDamage. The
  // evaluator keeps compact broken-bond flags (1 byte a bond instead of a 4-byte float) only if
  // every block's material accepts them and every damage model is a fused critical stretch.
  virtual bool acceptsBrokenBondFlags() const { return false; }
  // Whether precompute and computeForce walk each bond once when the evaluator hands them a half
  // bond list (ModelState::halfBonds): forces with the linear law, no bond sides, no thermal
  // strain, at most a fused critical stretch (ModelEvaluator::usesHalfBondList); each call then
  // covers every owned point. The evaluator keeps no |xi| per bond then (ModelState::bondLength
  // null): the model's other passes compute it with referenceBondLength().
  virtual bool computesOverHalfBondList() const { return false; }
  // Whether those loops take the influence omega per pair (HalfBondList::pairInfluence); if not,
  // the half list is used only with omega = 1.
  virtual bool halfBondListTakesInfluence() const { return false; }
  // Whether the model must apply its block's damage itself (it also breaks state the damage
  // pass does not know of): it then accepts only a fusable damage model (Critical Stretch).
  virtual bool requiresFusedCriticalStretch() const { return false; }
  // Young's modulus and Poisson's ratio of the material as the deck defines it (for a bond-based
  // material, nu is the fixed value of its plane mode); 0 where a model does not define them.
  virtual double youngsModulus() const { return 0.0; }
  // `Thermal Expansion Coefficient` alpha (0: no thermal strain). Models that do not apply
  // thermal strains refuse a non-zero value when they read their parameters.
  virtual double thermalExpansionCoefficient() const { return 0.0; }
  virtual double poissonsRatio() const { return 0.0; }

  // The influence function of the run, for derivations made before the model state exists
  // (fracture energy -> critical stretch at bind time). Set by the set-up; "One" otherwise.
  void setInfluenceFunction(const std::string& name) { influenceFunction_ = name; }
  // Records that a derivation assumed this influence function; initialize() then checks that
  // the run uses it (checkAssumedInfluenceFunction), so that a mismatch is an error, not a
  // silently wrong critical stretch.
  const std::string& influenceFunctionAssumed() const {
    influenceFunctionAssumed_ = true;
    return influenceFunction_;
  }

 protected:
  // Throws InputError if a derivation assumed another influence function than the run's.
  void checkAssumedInfluenceFunction(const ModelState& state) const;
  // Throws InputError if the model's plane mode does not match the run's dimension.
  void checkDimension(const ModelState& state, const std::string& modelName) const;

 private:
  std::string influenceFunction_ = "One";
  mutable bool influenceFunctionAssumed_ = false;
};

using MaterialRegistry = Registry<MaterialModel>;

// Creates the model named by `Material Model` and validates all of its parameters.
std::unique_ptr<MaterialModel> createMaterial(ListReader& params);

// Elastic constants from "exactly two of" Bulk Modulus, Shear Modulus, Young's Modulus,
// Poisson's Ratio (as Peridigm reads them). Marks the keys as read.
struct ElasticConstants {
  double bulkModulus = 0, shearModulus = 0, youngsModulus = 0, poissonsRatio = 0;
};
ElasticConstants readTwoElasticConstants(ListReader& params);

// The one elastic constant of a bond-based material, as its (3D) bulk modulus K: Bulk Modulus,
// or Young's Modulus with the Poisson's ratio the model has in `mode` (1/4 in 3D and in plane
// strain, 1/3 in plane stress), K = E / (3 (1 - 2 nu)); other constants are errors.
double readBondBasedBulkModulus(ListReader& params, PlaneMode mode = PlaneMode::ThreeD);

// The fixed Poisson's ratio of a bond-based material: 1/4 in 3D and plane strain, 1/3 in plane
// stress (the Cauchy relation lambda = mu of the in-plane or 3D elastic tensor).
double bondBasedPoissonsRatio(PlaneMode mode);

// "Plane Stress: true" / "Plane Strain: true" (at most one), else ThreeD. Marks the keys read.
PlaneMode readPlaneMode(ListReader& params);

// The in-plane (areal) bulk modulus kappa = lambda_2D + mu of a 2D mode, such that a pure
// in-plane dilatation eps = s I_2 stores W = 2 kappa s^2: E / (2 (1 - nu)) in plane stress,
// E / (2 (1 + nu) (1 - 2 nu)) in plane strain; the 3D bulk modulus E / (3 (1 - 2 nu)) in 3D.
double inPlaneBulkModulus(double youngsModulus, double poissonsRatio, PlaneMode mode);

// J_k = integral_0^delta omega(zeta) zeta^k dzeta for the influence functions with a closed
// form ("One", "Conical" = 1 - zeta/delta, "Conical Over Zeta" = (1 - zeta/delta)/zeta, k >= 1);
// returns false for any other.
bool influenceIntegral(const std::string& influenceFunction, int k, double delta, double& value);

// Keys every material accepts and ignores or checks (Peridigm compatibility).
// `hasThermalExpansion`: the model reads `Thermal Expansion Coefficient` itself; otherwise a
// non-zero value is refused as not supported. `hasPartialStress`: the model reads `Compute
// Partial Stress` itself; otherwise true is refused.
void acceptCommonMaterialKeys(ListReader& params, bool hasShearCorrection = false,
                              bool hasThermalExpansion = false, bool hasPartialStress = false);

}  // namespace peridot

#define PERIDOT_REGISTER_MATERIAL(DeckName, Class, Summary, Params)                           \
  namespace {                                                                                 \
  const bool kRegistered##Class = ::peridot::MaterialRegistry::add(                           \
      DeckName, [](::peridot::ListReader& p) { return std::make_unique<Class>(p); }, Summary, \
      Params);                                                                                \
  }
