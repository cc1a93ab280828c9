#include "app/Simulation.hpp"

#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <ostream>
#include <set>
#include <sstream>

#include "bc/NodeSets.hpp"
#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"
#include "core/ProcessorsPerRank.hpp"
#include "deck/Expression.hpp"
#include "neighbor/NeighborSearch.hpp"
#include "solvers/DynamicRelaxation.hpp"
#include "solvers/Implicit.hpp"
#include "solvers/NOXQuasiStatic.hpp"
#include "solvers/QuasiStatic.hpp"

namespace peridot {

Simulation::Simulation(RunConfig config, MPI_Comm comm, std::ostream& log)
    : config_(std::move(config)), comm_(comm), log_(log) {
  Timers::Scope setup(timers_, "Setup");
  MPI_Comm_rank(comm_, &rank_);
  PointCloud cloud;  // this rank's share, until the topology has moved it to the owners
  {
    Timers::Scope t(timers_, "Setup: read mesh");
    cloud = buildPointCloud(config_.discretization, comm_);
  }
  blockNames_ = cloud.blockNames;
  thickness_ = cloud.thickness;
  planar_ = cloud.dimension == 2;
  checkDimension();
  checkPeriodicBox();
  // Blocks of the mesh -> block groups of the deck, and each point's horizon.
  std::map<int, int> groupOfBlock;  // mesh block id -> index in config_.blocks
  std::map<std::string, int> blockIdOfName;
  for (const auto& kv : blockNames_) blockIdOfName[kv.second] = kv.first;
  int defaultGroup = -1;
  for (std::size_t g = 0; g < config_.blocks.size(); ++g) {
    for (const auto& name : config_.blocks[g].blockNames) {
      if (name == "Default" || name == "default") {  // Peridigm accepts both spellings
        if (defaultGroup >= 0 && defaultGroup != static_cast<int>(g)) {
          throw InputError(config_.blocks[g].path + " -> Block Names",
                           "\"" + name + "\" is already used by " +
                               config_.blocks[static_cast<std::size_t>(defaultGroup)].path +
                               "; only one block group may take the remaining blocks");
        }
        defaultGroup = static_cast<int>(g);
        continue;
      }
      auto it = blockIdOfName.find(name);
      if (it == blockIdOfName.end()) {
        std::string known;
        for (const auto& kv : blockIdOfName) known += (known.empty() ? "" : ", ") + kv.first;
        throw InputError(config_.blocks[g].path + " -> Block Names",
                         "unknown block \"" + name + "\"; the discretization has " + known);
      }
      if (groupOfBlock.count(it->second)) {
        throw InputError(config_.blocks[g].path + " -> Block Names",
                         "block \"" + name + "\" is already assigned by another block group");
      }
      groupOfBlock[it->second] = static_cast<int>(g);
    }
  }
  for (const auto& kv : blockNames_) {
    if (groupOfBlock.count(kv.first)) continue;
    if (defaultGroup < 0) {
      throw InputError("Blocks", "block \"" + kv.second +
                                     "\" of the discretization has no block group (name it in "
                                     "a group's Block Names, or use Default)");
    }
    groupOfBlock[kv.first] = defaultGroup;
  }
  std::vector<std::unique_ptr<Expression>> horizonOf(config_.blocks.size());
  for (std::size_t g = 0; g < config_.blocks.size(); ++g)
    horizonOf[g] = std::make_unique<Expression>(config_.blocks[g].horizon,
                                                std::vector<std::string>{"x", "y", "z"},
                                                config_.blocks[g].path + " -> Horizon");
  std::vector<double> cloudHorizon(cloud.size());
  double horizonRange[2] = {std::numeric_limits<double>::max(), 0.0};  // smallest, largest
  {
    std::string bad;
    for (std::size_t p = 0; p < cloud.size() && bad.empty(); ++p) {
      const int g = groupOfBlock.at(cloud.blockId[p]);
      cloudHorizon[p] = horizonOf[g]->evaluate(&cloud.x[3 * p]);
      if (!(cloudHorizon[p] > 0) || !std::isfinite(cloudHorizon[p])) {
        bad = config_.blocks[g].path + " -> Horizon: the horizon must be positive, got " +
              formatNumber(cloudHorizon[p]) + " at point " + std::to_string(cloud.globalId[p] + 1);
      } else if (cloud.globalId[p] + 1 > 2147483647LL) {
        bad = config_.discretization.meshFilePath + ": point id " +
              std::to_string(cloud.globalId[p] + 1) +
              " does not fit the 32-bit ids of Peridot's Exodus output";
      }
      horizonRange[0] = std::min(horizonRange[0], cloudHorizon[p]);
      horizonRange[1] = std::max(horizonRange[1], cloudHorizon[p]);
    }
    throwIfAnyRank(bad, comm_);
    MPI_Allreduce(MPI_IN_PLACE, &horizonRange[0], 1, MPI_DOUBLE, MPI_MIN, comm_);
    MPI_Allreduce(MPI_IN_PLACE, &horizonRange[1], 1, MPI_DOUBLE, MPI_MAX, comm_);
  }

  if (config_.discretization.periodic.any()) {
    // Images are taken one box length away: the box must be longer than the reach, or the
    // images two boxes away would be missed. (Shorter than twice the reach, a point meets both a
    // neighbour and its image, as the periodic lattice it stands for does.)
    const double reach = searchReach(neighborhoodRule(config_.discretization), horizonRange[1]);
    for (int d = 0; d < 3; ++d) {
      const auto& box = config_.discretization.periodic;
      if (box.periodic[d] && box.upper[d] - box.lower[d] <= reach) {
        throw InputError("Discretization -> Periodic " + std::string(1, "XYZ"[d]),
                         "the periodic box (" + formatNumber(box.upper[d] - box.lower[d]) +
                             ") must be longer than the neighbourhood reach (" +
                             formatNumber(reach) + ")");
      }
    }
  }
  std::vector<long long> bondFilterCuts(config_.discretization.bondFilters.size(), 0);
  {
    Timers::Scope t(timers_, "Setup: partition + search");
    TopologyOptions options;
    options.rule = neighborhoodRule(config_.discretization);
    options.bondFilters = &config_.discretization.bondFilters;
    options.bondFilterCuts = &bondFilterCuts;
    options.omitBondsBetweenBlocks = config_.discretization.omitBondsBetweenBlocks;
    options.periodic = config_.discretization.periodic;
    options.searchThreads = setUpThreads();
    topology_ = buildTopology(std::move(cloud), std::move(cloudHorizon), options, comm_);
  }
  cloud = PointCloud();
  cloudHorizon = std::vector<double>();
  if (!bondFilterCuts.empty()) {
    MPI_Allreduce(MPI_IN_PLACE, bondFilterCuts.data(), static_cast<int>(bondFilterCuts.size()),
                  MPI_LONG_LONG, MPI_SUM, comm_);
    for (std::size_t k = 0; k < bondFilterCuts.size() && rank_ == 0; ++k)
      if (bondFilterCuts[k] == 0) {
        // Usually a plane turned the wrong way (its normal or bottom vector) or placed beside
        // the body: the crack it stands for is not there.
        std::cerr << "peridot: warning: Discretization -> Bond Filters -> "
                  << config_.discretization.bondFilters[k].name
                  << ": the filter cuts no bond (check its corner, normal, bottom unit vector "
                     "and lengths: the plane must cross the body)"
                  << std::endl;
      }
  }
  if (topology_.globalNumPoints == 1) {
    throw InputError("Discretization",
                     "the discretization has a single point; a peridynamic body needs at least "
                     "two points within a horizon of each other");
  }
  // Without bonds the points interact only through contact: a valid Peridigm deck (contact-only
  // runs use a horizon below the spacing). Without contact nothing would interact at all.
  if (topology_.globalNumBonds == 0 && !config_.contact.enabled) {
    throw InputError("Blocks", "no point has a neighbour: the horizon (smallest " +
                                   formatNumber(horizonRange[0]) +
                                   ") is smaller than the point spacing, and there is no "
                                   "Contact section through which the points could interact");
  }
  nodeSetIds_ = collectNodeSets(topology_, config_.nodeSets);
  {
    std::vector<long long> lonely;
    for (int i = 0; i < topology_.numOwned; ++i)
      if (topology_.numNeighbors(i) == 0) lonely.push_back(topology_.overlapGlobalId[i] + 1);
    long long count = static_cast<long long>(lonely.size()), total = 0;
    MPI_Allreduce(&count, &total, 1, MPI_LONG_LONG, MPI_SUM, comm_);
    if (total > 0) {
      std::ostringstream msg;
      msg << "peridot: warning: " << lonely.size() << " point(s) on rank " << rank_
          << " have no neighbour ("
          << (config_.contact.enabled ? "only contact acts on them" : "they move freely")
          << "); ids:";
      for (std::size_t k = 0; k < lonely.size() && k < 10; ++k) msg << " " << lonely[k];
      if (lonely.size() > 10) msg << " ...";
      if (!lonely.empty()) std::cerr << msg.str() << std::endl;
    }
  }

  // The set-up after the search, timed in parts (bench/RESULTS.md splits the set-up).
  auto fieldsTimer = std::make_unique<Timers::Scope>(timers_, "Setup: fields + models");
  fields_ = std::make_unique<FieldManager>(topology_);
  x_ = fields_->node("Model_Coordinates", 3);
  y_ = fields_->node("Coordinates", 3);
  volume_ = fields_->node("Volume", 1);
  double* horizon = fields_->node("Horizon", 1);
  fields_->markPosition("Model_Coordinates");
  fields_->markPosition("Coordinates");
  fields_->markCurrentPosition("Coordinates");
  for (const std::string& source : config_.discretization.periodic.deformation)
    boxDeformation_.emplace_back(source, std::vector<std::string>{"t"},
                                 config_.discretization.periodic.deformationPath);
  deformPeriodicBox();
  for (int k = 0; k < topology_.numOverlap; ++k) {
    for (int d = 0; d < 3; ++d)
      x_[3 * k + d] = y_[3 * k + d] = topology_.referencePosition[3 * k + d];
    volume_[k] = topology_.volume[k];
    horizon[k] = topology_.horizon[k];
  }
  u_ = fields_->node("Displacement", 3);
  v_ = fields_->node("Velocity", 3);
  a_ = fields_->node("Acceleration", 3);

  // Blocks with their owned points.
  for (const auto& kv : blockNames_) {
    const auto& group = config_.blocks[groupOfBlock.at(kv.first)];
    Block b;
    b.name = kv.second;
    b.id = kv.first;
    b.materialName = group.material;
    b.damageName = group.damageModel;
    b.material = config_.materials.at(group.material);
    if (!group.damageModel.empty()) {
      b.damage = config_.damageModels.at(group.damageModel);
      if (b.damage->bindsToBlock()) {
        // A copy of its own, bound to this block's material and (constant) horizon.
        ListReader params(config_.damageParameters.at(group.damageModel),
                          "Damage Models -> " + group.damageModel);
        b.damage = createDamageModel(params);
        Expression horizonOfBlock(group.horizon, {"x", "y", "z"}, group.path + " -> Horizon");
        std::ostringstream derived;
        // The derivation of s_c from G0 depends on the influence function.
        b.material->setInfluenceFunction(config_.discretization.influenceFunction);
        b.damage->bind(*b.material,
                       horizonOfBlock.isConstant() ? horizonOfBlock.evaluate(nullptr) : -1.0,
                       b.name, derived);
        if (rank_ == 0) log_ << derived.str();
      }
    }
    blocks_.push_back(b);
  }
  blockIndexOfPoint_.resize(topology_.numOwned);
  density_.resize(topology_.numOwned);
  for (int i = 0; i < topology_.numOwned; ++i) {
    const int id = topology_.blockId[i];
    const int index = static_cast<int>(
        std::find_if(blocks_.begin(), blocks_.end(), [&](const Block& b) { return b.id == id; }) -
        blocks_.begin());
    blockIndexOfPoint_[i] = index;
    blocks_[index].points.push_back(i);
    density_[i] = blocks_[index].material->density();
  }

  evaluator_ = std::make_unique<ModelEvaluator>(topology_, *fields_, blocks_,
                                                config_.discretization.influenceFunction, timers_);
  if (planar_) evaluator_->setPlanar(thickness_);
  evaluator_->setPartialVolumes(config_.discretization.partialVolumes);
  evaluator_->setBondFilters(&config_.discretization.bondFilters);
  // `Bond Storage: "Compact"` (opt-in): |xi| computed in the PMB force loop instead of stored
  // costs ~1.25x there (a square root and the neighbours' reference coordinates per bond), so a
  // run pays for it only when it asks (bench/RESULTS.md).
  const bool compact = config_.discretization.compactBonds;
  evaluator_->setStoreBondLengths(!compact);
  // Bond damage as 1-byte broken flags wherever nothing needs the float array (checkpoints save
  // it, the implicit solvers' tangents read it) and the models allow it (ModelEvaluator): 3
  // bytes a bond less, whatever the storage, for the same results to the bit and no slower a
  // loop (the half list's loops read no damage; the full lists' read a byte instead of four).
  evaluator_->setCompactDamageAllowed(!config_.restart.enabled && !config_.solver.quasiStatic &&
                                      !config_.solver.noxQuasiStatic);
  evaluator_->setHalfBondListAllowed(config_.discretization.halfBondList);
  evaluator_->initialize();
  f_ = fields_->node("Force_Density", 3);
  fieldsTimer.reset();

  {
    const IdIndex owned(topology_.overlapGlobalId.data(),
                        static_cast<std::size_t>(topology_.numOwned));
    for (const auto& kv : nodeSetIds_) nodeSets_[kv.first] = ownedPoints(kv.second, owned);
  }
  std::vector<long long> setSizes;  // over all ranks, in the map's (name) order
  for (const auto& kv : nodeSetIds_) setSizes.push_back(static_cast<long long>(kv.second.size()));
  MPI_Allreduce(MPI_IN_PLACE, setSizes.data(), static_cast<int>(setSizes.size()), MPI_LONG_LONG,
                MPI_SUM, comm_);
  std::size_t setIndex = 0;
  for (const auto& kv : nodeSetIds_) {
    if (setSizes[setIndex++] == 0) {
      for (const auto& c : config_.conditions)
        if (c.nodeSet == kv.first)
          throw InputError(c.path + " -> Node Set", "node set \"" + kv.first + "\" is empty");
    }
  }
  // Peridigm's node set FULL_DOMAIN (any case, spaces for underscores): every point.
  for (const auto& c : config_.conditions) {
    std::string tidy = c.nodeSet;
    for (char& ch : tidy) ch = ch == ' ' ? '_' : static_cast<char>(std::toupper(ch));
    if (tidy == "FULL_DOMAIN" && !nodeSets_.count(c.nodeSet)) {
      std::vector<int> all(topology_.numOwned);
      for (int i = 0; i < topology_.numOwned; ++i) all[i] = i;
      nodeSets_[c.nodeSet] = all;
    } else if (tidy == "ALL_SETS" && !nodeSets_.count(c.nodeSet)) {
      throw InputError(c.path + " -> Node Set",
                       "Peridigm's ALL_SETS (every node set in turn) is not supported yet");
    }
  }
  conditions_ = std::make_unique<BoundaryConditions>(
      config_.conditions, nodeSets_, x_, topology_.overlapGlobalId.data(), volume_, comm_);
  if (conditions_->hasBodyForce()) b_ = fields_->node("External_Force_Density", 3);
  if (conditions_->hasTemperature()) {
    temperature_ = fields_->node("Temperature", 1);
    temperatureChange_ = fields_->node("Temperature_Change", 1);
    evaluator_->setThermal(temperatureChange_);
  }

  if (config_.contact.enabled && config_.discretization.periodic.any()) {
    throw InputError(config_.contact.path, "contact with periodic boundaries is not supported yet");
  }
  if (config_.contact.enabled) {
    std::vector<std::string> blockName(topology_.numOwned);
    for (int i = 0; i < topology_.numOwned; ++i) blockName[i] = blocks_[blockIndexOfPoint_[i]].name;
    for (const auto& pair : config_.contact.pairs) {
      for (const auto& name : {pair.first, pair.second}) {
        if (!std::any_of(blocks_.begin(), blocks_.end(),
                         [&](const Block& b) { return b.name == name; })) {
          throw InputError(config_.contact.path + " -> Interactions",
                           "unknown block \"" + name + "\"");
        }
      }
    }
    fc_ = fields_->node("Contact_Force_Density", 3);
    contact_ = std::make_unique<ShortRangeContact>(config_.contact, topology_, blockName, horizon,
                                                   volume_, timers_);
    if (config_.contact.timeDependentFriction) {
      friction_ =
          std::make_unique<Expression>(config_.contact.frictionExpression,
                                       std::vector<std::string>{"t"}, config_.contact.frictionPath);
    }
  }
  checkVariables();
  RunVariables::Sources sources;
  sources.config = &config_;
  sources.comm = comm_;
  sources.rank = rank_;
  sources.topology = &topology_;
  sources.fields = fields_.get();
  sources.blocks = &blocks_;
  sources.evaluator = evaluator_.get();
  sources.nodeSets = &nodeSets_;
  sources.density = &density_;
  sources.blockIndexOfPoint = &blockIndexOfPoint_;
  sources.externalForceDensity = b_;
  sources.contactForceDensity = fc_;
  sources.nonlinearIterations = &nonlinearIterations_;
  variables_ = std::make_unique<RunVariables>(sources);

  // Initial conditions now, so that a bad value stops the run before any file is written.
  time_ = config_.solver.initialTime;
  throwIfAnyRank(conditions_->applyInitial(time_, u_, v_), comm_);
  if (conditions_->hasTemperature()) {  // not the pointer: null on a rank without points
    throwIfAnyRank(conditions_->applyInitialTemperature(time_, temperature_), comm_);
    throwIfAnyRank(conditions_->applyPrescribedTemperature(time_, temperature_, temperatureChange_),
                   comm_);
  }

  prepareSolver();
  if (config_.restart.enabled && !config_.chainedSolvers.empty()) {
    throw InputError(config_.restart.path, "Restart with chained solvers (" +
                                               config_.chainedSolvers[0].path +
                                               ") is not supported yet");
  }
  if (config_.restart.enabled) {
    // The continuum-kinematics material keeps damage history the checkpoint does not hold
    // (the bonds between neighbours each point tracks): refuse rather than lose it.
    for (const auto& b : blocks_)
      if (b.damage && b.material->requiresFusedCriticalStretch())
        throw InputError(config_.restart.path, "restart of block " + b.name +
                                                   " (continuum-kinematics material with "
                                                   "damage) is not supported yet");
    checkpoint_ = std::make_unique<Checkpoint>(config_.restart, topology_, *fields_);
    if (checkpoint_->exists()) resume();
  }
  control_ = std::make_unique<RunControl>(config_.restart, comm_);
#if defined(__GLIBC__)
  // The set-up's freed temporaries stay in the heap for reuse (main.cpp); what no later
  // allocation took goes back to the system now, before the run: without this the peak resident
  // size at 128^3 was 10 MB above the default allocator's, with it 45 MB below (bench/RESULTS.md).
  malloc_trim(0);
#endif
}

void Simulation::openOutputs() {
  outputs_ = std::make_unique<OutputManager>(config_, blockNames_, planar_ ? 2 : 3, nodeSetIds_,
                                             topology_, *variables_, timers_);
}

Simulation::~Simulation() = default;

void Simulation::deformPeriodicBox() {
  if (boxDeformation_.empty()) return;
  double F[9];
  for (int k = 0; k < 9; ++k) {
    F[k] = boxDeformation_[k].evaluate(&time_);
    if (!std::isfinite(F[k])) {
      RunError error(config_.discretization.periodic.deformationPath +
                     ": the periodic box's deformation gradient at t = " + formatNumber(time_) +
                     " is not finite");
      error.markCollective();
      throw error;
    }
  }
  fields_->setPeriodicDeformation(F);
}

void Simulation::evaluateForces(long long step) {
  if (contact_ && step == 0) searchContact();
  deformPeriodicBox();
  evaluator_->setTime(time_);
  // Step 0 evaluates the state the run starts from: nothing has moved since, so no rate-form
  // history (correspondence stress, viscous back state) may advance by a step.
  evaluator_->evaluate(step == 0 ? 0.0 : dt_);
  if (friction_) {
    // The same value on every rank (it depends on the time alone).
    const double mu = friction_->evaluate(&time_);
    if (!(mu >= 0.0) || !std::isfinite(mu)) {
      RunError error(config_.contact.frictionPath +
                     ": the friction coefficient at t = " + formatNumber(time_) + " is " +
                     formatNumber(mu) + "; it must be a finite number >= 0");
      error.markCollective();
      throw error;
    }
    contact_->setFrictionCoefficient(mu);
  }
  if (contact_) contact_->computeForce(y_, v_, fc_);
}

void Simulation::accelerate(long long step) {
  DivergenceMonitor::LocalSums sums;
  bool finite;
  {
    Timers::Scope t(timers_, "Integration");
    finite = verlet_->accelerate(step > 0, *divergence_, sums);
  }
  checkFinite(step, time_, finite);
  Timers::Scope t(timers_, "Divergence check");
  divergence_->conclude(step, time_, sums);
}

void Simulation::checkFinite(long long step, double time, bool finite) {
  int bad = -1;
  for (int i = 0; !finite && i < topology_.numOwned && bad < 0; ++i)
    for (int d = 0; d < 3; ++d)
      if (!std::isfinite(f_[3 * i + d]) || !std::isfinite(u_[3 * i + d])) bad = i;
  std::ostringstream msg;
  if (bad >= 0) {
    const bool displacement = !std::isfinite(u_[3 * bad] + u_[3 * bad + 1] + u_[3 * bad + 2]);
    msg << "non-finite " << (displacement ? "displacement" : "force") << " at point "
        << topology_.overlapGlobalId[bad] + 1 << " (block " << blocks_[blockIndexOfPoint_[bad]].name
        << ") at step " << step << ", time " << formatNumber(time);
    if (dt_ > stableDt_) {
      msg << "; the time step (" << formatNumber(dt_) << ") exceeds the stable estimate ("
          << formatNumber(stableDt_) << ")";
    }
  }
  std::string message = msg.str();
  if (message.empty()) message = temperatureProblem_;
  throwIfAnyRank(message, comm_, true);
}

void Simulation::run() {
  runSolver();
  // Chained solvers (Solver1, Solver2, ...): each continues from the state the one before left,
  // with step numbers and times continuing in the same output files.
  for (std::size_t k = 0; k < config_.chainedSolvers.size() && !stopped_; ++k) {
    stepOffset_ = lastStep_;
    config_.solver = config_.chainedSolvers[k];
    time_ = config_.solver.initialTime;
    quasiStatic_.reset();
    noxQuasiStatic_.reset();
    implicit_.reset();
    relaxation_.reset();
    prepareSolver();
    // Prescribed displacements continue from their values at the new initial time.
    conditions_->resume(time_);
    if (rank_ == 0) {
      log_ << config_.solver.path << ": from time " << time_ << ", step " << stepOffset_ << "\n"
           << std::flush;
    }
    runSolver();
  }
}

void Simulation::runSolver() {
  if (!config_.solver.explicitVerlet()) {
    runImplicit();
    return;
  }
  // Continued from a checkpoint at the final time: complete, and its outputs stay as they are.
  if (resumed_ && firstStep_ > numSteps_) return;
  reportSetup();
  if (!resumed_) {
    for (int k = 0; k < 3 * topology_.numOwned; ++k) y_[k] = x_[k] + u_[k];
    if (b_) conditions_->applyBodyForce(time_, b_, topology_.numOwned);
    evaluateForces(0);
    accelerate(0);
    // A chained solver starts from the state the previous one wrote as its last record.
    if (stepOffset_ == 0) {
      outputs_->write(0, time_);
      if (observer_) observer_(0, time_);
    }
  }
  if (resumed_) {
    // Output files of this deck that match the run keep their records up to the checkpoint
    // and continue after them; others (Peridigm's Run2 names its own) are created anew.
    for (const auto& message : outputs_->resume(firstStep_ - 1, time_))
      if (rank_ == 0) log_ << message << "\n";
  }

  const auto start = std::chrono::steady_clock::now();
  auto lastReport = start;
  for (long long step = firstStep_; step <= numSteps_; ++step) {
    const double next = origin_ + step * dt_;
    // The contact lists follow the current configuration (Peridigm searches at these steps).
    if (contact_ && step % config_.contact.searchFrequency == 0) searchContact();
    {
      Timers::Scope t(timers_, "Integration");
      verlet_->kickAndDrift();
    }
    {
      Timers::Scope t(timers_, "Boundary conditions");
      conditions_->applyPrescribedVelocity(next, dt_, v_);
      if (b_) conditions_->applyBodyForce(next, b_, topology_.numOwned);
      if (conditions_->hasTemperature())
        temperatureProblem_ =
            conditions_->applyPrescribedTemperature(next, temperature_, temperatureChange_);
      verlet_->driftPrescribed();  // with the velocities the conditions gave
    }
    time_ = next;
    evaluateForces(step);
    accelerate(step);
    if (outputs_->due(stepOffset_ + step)) outputs_->write(stepOffset_ + step, time_);
    if (observer_) observer_(stepOffset_ + step, time_);
    lastStep_ = stepOffset_ + step;
    const auto decision = control_->afterStep(step, step == numSteps_,
                                              checkpoint_ ? checkpoint_->lastWriteSeconds() : 0.0);
    if (decision.checkpoint) writeCheckpoint(step);
    if (decision.stop) {
      stopped_ = true;
      stopSignal_ = decision.signal;
      break;
    }
    if (rank_ == 0) {
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - lastReport).count() > 5.0 ||
          (step == numSteps_ && std::chrono::duration<double>(now - start).count() > 5.0)) {
        lastReport = now;
        const double elapsed = std::chrono::duration<double>(now - start).count();
        const double left = elapsed / (step - firstStep_ + 1) * (numSteps_ - step);
        log_ << progressLine(step, numSteps_, time_, elapsed, left) << std::endl;
      }
    }
  }
}

}  // namespace peridot
