#include "deck/RunConfig.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"
#include "core/Format.hpp"
#include "deck/Expression.hpp"
#include "deck/OutputVariables.hpp"
#include "deck/PeridigmVocabulary.hpp"

namespace peridot {

namespace {

const std::vector<std::string> kXYZT = {"x", "y", "z", "t"};

std::vector<std::string> splitWords(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  std::string w;
  while (in >> w) out.push_back(w);
  return out;
}

std::string normalizedConditionType(std::string s) {
  // Peridigm compares condition types ignoring case and spaces.
  s.erase(std::remove_if(s.begin(), s.end(),
                         [](unsigned char c) { return std::isspace(c) || c == '_'; }),
          s.end());
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool containsNoCase(const std::string& haystack, const std::string& needle) {
  std::string h = haystack, n = needle;
  std::transform(h.begin(), h.end(), h.begin(), [](unsigned char c) { return std::tolower(c); });
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
  return h.find(n) != std::string::npos;
}

void readBoundaryConditions(ListReader bc, RunConfig& config) {
  for (const auto& key : bc.keys()) {
    if (!bc.isSublist(key)) {
      if (key == "Create Node Set For Rank Deficient Nodes") {
        bc.boolean(key, false);
        continue;
      }
      if (!containsNoCase(key, "Node Set")) {
        throw InputError(bc.pathOf(key),
                         "unknown parameter; node sets are parameters whose name "
                         "contains \"Node Set\", conditions are sublists");
      }
      config.nodeSets.push_back({key, bc.pathOf(key), bc.string(key)});
      continue;
    }
    ListReader c = bc.sublist(key);
    ConditionConfig cc;
    cc.name = key;
    cc.path = c.path();
    const std::string type = c.string("Type");
    const std::string t = normalizedConditionType(type);
    if (t == "initialdisplacement") {
      cc.kind = ConditionConfig::Kind::InitialDisplacement;
    } else if (t == "initialvelocity") {
      cc.kind = ConditionConfig::Kind::InitialVelocity;
    } else if (t == "prescribeddisplacement") {
      cc.kind = ConditionConfig::Kind::PrescribedDisplacement;
    } else if (t == "bodyforce") {
      cc.kind = ConditionConfig::Kind::BodyForce;
    } else if (t == "traction") {
      cc.kind = ConditionConfig::Kind::Traction;
      cc.surfaceArea = c.positiveNumber("Surface Area");
    } else if (t == "prescribedtemperature") {
      cc.kind = ConditionConfig::Kind::PrescribedTemperature;
    } else if (t == "initialtemperature") {
      cc.kind = ConditionConfig::Kind::InitialTemperature;
    } else if (t == "thermalflux" || t == "prescribedfluidpressureu" ||
               t == "initialfluidpressureu") {
      throw InputError(c.pathOf("Type"),
                       "\"" + type + "\" conditions are not supported by Peridot yet");
    } else {
      throw InputError(c.pathOf("Type"),
                       "unknown condition type \"" + type +
                           "\"; expected \"Initial Displacement\", \"Initial Velocity\", "
                           "\"Prescribed Displacement\", \"Body Force\", \"Traction\", "
                           "\"Prescribed Temperature\" or \"Initial Temperature\"");
    }
    cc.nodeSet = c.string("Node Set");
    if (cc.isTemperature()) {
      // A scalar field: Peridigm allows the coordinate x or none.
      if (c.has("Coordinate")) c.choice("Coordinate", {"x", "X"});
    } else {
      const std::string coordinate = c.choice("Coordinate", {"x", "y", "z", "X", "Y", "Z"});
      cc.coordinate = std::tolower(static_cast<unsigned char>(coordinate[0])) - 'x';
    }
    cc.value = c.numberOrExpression("Value");
    Expression check(cc.value, kXYZT, c.pathOf("Value"));
    (void)check;
    c.finish();
    config.conditions.push_back(cc);
  }
  bc.finish();
}

SolverConfig readSolver(ListReader s) {
  SolverConfig sc;
  sc.path = s.path();
  const bool verbose = s.boolean("Verbose", false);
  sc.initialTime = s.number("Initial Time", 0.0);
  sc.finalTime = s.number("Final Time", 1.0);
  if (!(sc.finalTime > sc.initialTime)) {
    throw InputError(s.pathOf("Final Time"), "must be larger than the Initial Time");
  }
  if (s.isSublist("ImplicitDiffusion")) {
    throw InputError(s.pathOf("ImplicitDiffusion"),
                     "this solver is not supported by Peridot yet; use Verlet, QuasiStatic, "
                     "NOXQuasiStatic, Implicit or Adaptive Dynamic Relaxation");
  }
  const std::string preconditioner =
      s.choice("Peridigm Preconditioner", {"Full Tangent", "Block 3x3", "None"}, "Full Tangent");
  sc.predictorFromPrevious = s.boolean("Initialize Predictor From Previous Solver", false);
  if (s.has("Finite Difference Probe Length"))
    sc.probeLength = s.positiveNumber("Finite Difference Probe Length");
  if (s.isSublist("QuasiStatic")) {
    if (s.has("Verlet")) {
      throw InputError(s.pathOf("Verlet"), "one solver list per Solver: QuasiStatic or Verlet");
    }
    ListReader qs = s.sublist("QuasiStatic");
    sc.quasiStatic = true;
    sc.quasiStaticConfig = readQuasiStatic(qs, sc.initialTime, sc.finalTime, s.has("Final Time"),
                                           preconditioner, verbose);
    sc.initialTime = sc.quasiStaticConfig.times.front();
    sc.finalTime = sc.quasiStaticConfig.times.back();
    s.finish();
    return sc;
  }
  if (s.isSublist("NOXQuasiStatic")) {
    for (const char* other : {"Verlet", "QuasiStatic", "Implicit", "Adaptive Dynamic Relaxation"}) {
      if (s.has(other)) {
        throw InputError(s.pathOf(other),
                         "one solver list per Solver: NOXQuasiStatic or " + std::string(other));
      }
    }
    ListReader nox = s.sublist("NOXQuasiStatic");
    sc.noxQuasiStatic = true;
    sc.noxQuasiStaticConfig = readNOXQuasiStatic(nox, sc.initialTime, sc.finalTime,
                                                 s.has("Final Time"), preconditioner, verbose);
    sc.initialTime = sc.noxQuasiStaticConfig.times.front();
    sc.finalTime = sc.noxQuasiStaticConfig.times.back();
    s.finish();
    return sc;
  }
  if (s.isSublist("Adaptive Dynamic Relaxation")) {
    for (const char* other : {"Verlet", "QuasiStatic", "Implicit"}) {
      if (s.has(other)) {
        throw InputError(
            s.pathOf(other),
            "one solver list per Solver: Adaptive Dynamic Relaxation or " + std::string(other));
      }
    }
    ListReader adr = s.sublist("Adaptive Dynamic Relaxation");
    sc.dynamicRelaxation = true;
    sc.dynamicRelaxationConfig =
        readDynamicRelaxation(adr, sc.initialTime, sc.finalTime, s.has("Final Time"), verbose);
    sc.initialTime = sc.dynamicRelaxationConfig.times.front();
    sc.finalTime = sc.dynamicRelaxationConfig.times.back();
    s.finish();
    return sc;
  }
  if (s.isSublist("Implicit")) {
    if (s.has("Verlet")) {
      throw InputError(s.pathOf("Verlet"), "one solver list per Solver: Implicit or Verlet");
    }
    ListReader im = s.sublist("Implicit");
    sc.implicit = true;
    sc.implicitConfig = readImplicit(im, preconditioner, verbose);
    sc.fixedDtGiven = true;
    sc.fixedDt = sc.implicitConfig.dt;
    s.finish();
    return sc;
  }
  ListReader v = s.sublist("Verlet");
  if (v.has("Fixed dt")) {
    sc.fixedDtGiven = true;
    sc.fixedDt = v.positiveNumber("Fixed dt");
  }
  sc.safetyFactor = v.positiveNumber("Safety Factor", 1.0);
  if (v.has("Stable Time Step Estimate")) {
    const std::string estimate = v.string("Stable Time Step Estimate");
    if (estimate != "Peridigm" && estimate != "Verlet Limit") {
      throw InputError(v.pathOf("Stable Time Step Estimate"),
                       "expected \"Peridigm\" or \"Verlet Limit\", got \"" + estimate + "\"");
    }
    sc.verletLimitEstimate = estimate == "Verlet Limit";
  }
  v.boolean("Verbose", false);
  v.finish();
  s.finish();
  return sc;
}

OutputConfig readOutput(ListReader o, const std::string& name) {
  OutputConfig oc;
  oc.name = name;
  oc.path = o.path();
  o.choice("Output File Type", {"ExodusII"}, "ExodusII");
  o.choice("Output Format", {"BINARY"}, "BINARY");
  oc.fileName = o.string("Output Filename", "dump");  // Peridigm's default
  if (oc.fileName.empty()) throw InputError(o.pathOf("Output Filename"), "the file name is empty");
  // As Peridigm does: dots and spaces in the base name become underscores.
  for (char& ch : oc.fileName)
    if (ch == '.' || ch == ' ') ch = '_';
  oc.frequency = o.integer("Output Frequency", -1);  // Peridigm's default: never
  if (oc.frequency == 0 || oc.frequency < -1) {
    throw InputError(o.pathOf("Output Frequency"), "expected a positive integer or -1 (never)");
  }
  oc.initialStep = o.integer("Initial Output Step", 0);
  oc.finalStep = o.integer("Final Output Step", -1);
  o.boolean("Parallel Write", true);
  if (o.has("Bond Family"))
    throw InputError(o.pathOf("Bond Family"), "not supported by Peridot yet");
  ListReader vars = o.sublist("Output Variables");
  for (const auto& key : vars.keys()) {
    if (vars.boolean(key, false)) oc.variables.push_back(key);
  }
  vars.finish();
  o.finish();
  return oc;
}

ComputeConfig readCompute(ListReader c, const std::string& name) {
  ComputeConfig cc;
  cc.name = name;
  cc.path = c.path();
  cc.computeClass =
      c.choice("Compute Class", {"Block_Data", "Node_Set_Data", "Nearest_Point_Data"});
  if (cc.computeClass == "Nearest_Point_Data") {
    // The point nearest (X, Y, Z) in the reference configuration, ties to the smallest id.
    const char* axes[3] = {"X", "Y", "Z"};
    for (int d = 0; d < 3; ++d) cc.point[d] = c.number(axes[d]);
  } else {
    cc.calculation = c.choice("Calculation Type", {"Sum", "Minimum", "Maximum"});
    cc.region = c.string(cc.computeClass == "Block_Data" ? "Block" : "Node Set");
  }
  cc.variable = c.string("Variable");
  cc.label = c.string("Output Label");
  if (cc.label.empty()) throw InputError(c.pathOf("Output Label"), "the label is empty");
  const VariableInfo* variable = findOutputVariable(cc.variable);
  if (!variable) {
    throw InputError(c.pathOf("Variable"), "unknown variable \"" + cc.variable + "\"");
  }
  if (variable->components == 0) {
    throw InputError(c.pathOf("Variable"), "\"" + cc.variable +
                                               "\" is a global variable; Block_Data and "
                                               "Node_Set_Data reduce point variables");
  }
  c.boolean("Verbose", false);
  c.finish();
  return cc;
}

}  // namespace

namespace {

// FNV-1a, 64 bits: stable across builds and platforms (std::hash is not).
void hashBytes(std::uint64_t& h, const std::string& text) {
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  h ^= 0xff;  // separator: "ab","c" differs from "a","bc"
  h *= 1099511628211ULL;
}

// Hashes every entry that decides the state of a continued run. Left out: what Peridigm's
// restart decks change between the runs (Initial Time, Final Time, output lists) and the
// Restart list itself.
void hashList(std::uint64_t& h, const Teuchos::ParameterList& list, bool top, bool solver) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& key = list.name(it);
    const auto& entry = list.entry(it);
    if (top && (key == "Restart" || (key.find("Output") != std::string::npos && entry.isList())))
      continue;
    if (solver && (key == "Initial Time" || key == "Final Time")) continue;
    hashBytes(h, key);
    if (entry.isList()) {
      hashList(h, Teuchos::getValue<Teuchos::ParameterList>(entry), false,
               top && key.find("Solver") != std::string::npos);
    } else {
      hashBytes(h, entry.getAny(false).typeName());
      hashBytes(h, describeEntry(entry));
    }
  }
}

std::uint64_t deckHash(const Teuchos::ParameterList& deck) {
  std::uint64_t h = 14695981039346656037ULL;
  hashList(h, deck, true, false);
  return h;
}

RestartConfig readRestart(ListReader& top, const Teuchos::ParameterList& deck) {
  RestartConfig r;
  if (!deck.getEntry("Restart").isList()) {
    r.enabled = top.boolean("Restart", false);
    return r;
  }
  ListReader list = top.sublist("Restart");
  // Peridigm's list form holds a "Restart" bool; the list alone also turns restart on.
  r.enabled = list.boolean("Restart", true);
  r.checkpointFrequency = list.integer("Checkpoint Frequency", 0);
  if (r.checkpointFrequency < 0) {
    throw InputError(list.pathOf("Checkpoint Frequency"),
                     "expected a number of steps >= 0 (0: only at the end)");
  }
  r.checkpointInterval = list.nonNegativeNumber("Checkpoint Interval", 0.0);
  r.wallClockLimit = list.nonNegativeNumber("Wall Clock Limit", 0.0);
  r.directory = list.string("Checkpoint Directory", ".");
  r.name = list.string("Checkpoint Name", "peridot.checkpoint");
  if (r.directory.empty()) throw InputError(list.pathOf("Checkpoint Directory"), "is empty");
  if (r.name.empty() || r.name.find('/') != std::string::npos) {
    throw InputError(list.pathOf("Checkpoint Name"),
                     "expected a file name without '/' (the directory is Checkpoint Directory)");
  }
  list.finish();
  return r;
}

}  // namespace

// Gmsh node sets grown into layers: the depth defaults to the horizon (the largest of the blocks').
static void setDefaultLayerDepth(RunConfig& config) {
  DiscretizationConfig& d = config.discretization;
  if (d.layerSets.empty() || d.layerDepth > 0) return;
  for (const BlockGroupConfig& g : config.blocks) {
    Expression horizon(g.horizon, {"x", "y", "z"}, g.path + " -> Horizon");
    if (!horizon.isConstant()) {
      throw InputError(d.layerSetsPath,
                       "the layer depth defaults to the horizon, but the horizon "
                       "of " +
                           g.path + " varies; give Node Set Layer Depth");
    }
    d.layerDepth = std::max(d.layerDepth, horizon.evaluate(nullptr));
  }
}

RunConfig readRunConfig(const Teuchos::ParameterList& deck) {
  RunConfig config;
  ListReader top(deck, "");
  config.verbose = top.boolean("Verbose", false);
  // Peridigm's RKPM (reproducing kernel particle method) decks: a meshfree discretization of
  // local continuum mechanics, not peridynamics; refused before anything else reads the deck.
  if (top.has("RKPM Kernels")) {
    throw InputError("RKPM Kernels",
                     "Peridigm's RKPM discretization (reproducing kernel particle method, a "
                     "meshfree discretization of local continuum mechanics, not peridynamics) is "
                     "not supported by Peridot");
  }
  // Peridigm's first deck layout (before Materials and Blocks existed) nested Discretization,
  // Material and Boundary Conditions in a Problem list; refused by name, not as a missing list.
  if (top.has("Problem")) {
    throw InputError("Problem",
                     "the old Peridigm deck layout (Discretization, Material and Boundary "
                     "Conditions inside a \"Problem\" list, the horizon in Discretization, "
                     "\"Material Output Fields\") is not supported; Peridot reads the current "
                     "one: Discretization, Materials, Blocks (with each block's Horizon) and "
                     "Boundary Conditions at the top level");
  }
  // Peridigm allocates the hypoelastic models' extra fields only when this is true; Peridot's
  // hypoelastic models always have them, so the switch changes nothing.
  top.boolean("Enable Bond-Associated Hypoelastic Model", false);
  config.discretization = readDiscretizationConfig(top.sublist("Discretization"));

  ListReader materials = top.sublist("Materials");
  for (const auto& name : materials.keys()) {
    ListReader m = materials.sublist(name);
    config.materials[name] = createMaterial(m);
  }
  materials.finish();
  if (config.materials.empty()) throw InputError("Materials", "no material is defined");

  if (top.has("Damage Models")) {
    ListReader damage = top.sublist("Damage Models");
    for (const auto& name : damage.keys()) {
      ListReader d = damage.sublist(name);
      config.damageModels[name] = createDamageModel(d);
      config.damageParameters[name] = d.list();
    }
    damage.finish();
  }

  ListReader blocks = top.sublist("Blocks");
  for (const auto& name : blocks.keys()) {
    ListReader b = blocks.sublist(name);
    BlockGroupConfig g;
    g.name = name;
    g.path = b.path();
    g.blockNames = splitWords(b.string("Block Names"));
    if (g.blockNames.empty()) throw InputError(b.pathOf("Block Names"), "no block name given");
    g.material = b.string("Material");
    if (!config.materials.count(g.material)) {
      throw InputError(b.pathOf("Material"), "unknown material \"" + g.material +
                                                 "\"; it must be the name of a list in Materials");
    }
    if (b.has("Damage Model")) {
      g.damageModel = b.string("Damage Model");
      if (!config.damageModels.count(g.damageModel)) {
        throw InputError(b.pathOf("Damage Model"),
                         "unknown damage model \"" + g.damageModel +
                             "\"; it must be the name of a list in Damage Models");
      }
    }
    g.horizon = b.numberOrExpression("Horizon");
    Expression horizon(g.horizon, {"x", "y", "z"}, b.pathOf("Horizon"));
    if (horizon.isConstant() && !(horizon.evaluate(nullptr) > 0)) {
      throw InputError(b.pathOf("Horizon"),
                       "expected a positive number, got \"" + g.horizon + "\"");
    }
    b.finish();
    config.blocks.push_back(g);
  }
  blocks.finish();
  if (config.blocks.empty()) throw InputError("Blocks", "no block group is defined");
  setDefaultLayerDepth(config);

  if (top.has("Boundary Conditions"))
    readBoundaryConditions(top.sublist("Boundary Conditions"), config);

  if (top.has("Compute Class Parameters")) {
    ListReader computes = top.sublist("Compute Class Parameters");
    for (const auto& name : computes.keys())
      config.computes.push_back(readCompute(computes.sublist(name), name));
    computes.finish();
  }

  bool haveSolver = false;
  for (const auto& key : top.keys()) {
    if (key.find("Solver") != std::string::npos && top.isSublist(key)) {
      SolverConfig next = readSolver(top.sublist(key));
      if (haveSolver) {
        // Chained solvers run one after the other on the same state: each starts at the time
        // the one before ends.
        const SolverConfig& previous =
            config.chainedSolvers.empty() ? config.solver : config.chainedSolvers.back();
        const double gap = std::fabs(next.initialTime - previous.finalTime);
        if (gap > 1e-12 * std::max(1.0, std::fabs(previous.finalTime))) {
          throw InputError(key + " -> Initial Time",
                           "a chained solver starts where the previous one (" + previous.path +
                               ") ends: expected " + formatNumber(previous.finalTime) + ", got " +
                               formatNumber(next.initialTime));
        }
        config.chainedSolvers.push_back(std::move(next));
      } else {
        config.solver = std::move(next);
      }
      haveSolver = true;
    } else if (key.find("Output") != std::string::npos && top.isSublist(key)) {
      config.outputs.push_back(readOutput(top.sublist(key), key));
    }
  }
  if (!haveSolver) throw InputError("Solver", "required list is missing");
  // Before the output variables: a Data Loader deck outputs the fields it loads.
  const std::pair<const char*, const char*> features[] = {
      {"Data Loader", "loading node data from an Exodus file"},
      {"Multiphysics", "multiphysics (pore pressure) degrees of freedom"},
      {"Optimization Based Coupling", "optimization-based coupling"}};
  for (const auto& f : features) {
    if (top.has(f.first)) {
      throw InputError(f.first, std::string("Peridigm's ") + f.second + " (\"" + f.first +
                                    "\") is not supported by Peridot yet");
    }
  }

  // Every requested output variable must be known (or a compute's label).
  for (const auto& out : config.outputs) {
    for (const auto& v : out.variables) {
      if (findOutputVariable(v)) continue;
      bool isLabel = false;
      for (const auto& c : config.computes) isLabel = isLabel || c.label == v;
      if (!isLabel && isIn(peridigmOutputVariablesNotYet(), v)) {
        throw InputError(joinPath(joinPath(out.path, "Output Variables"), v),
                         "the Peridigm output variable \"" + v +
                             "\" is not supported by Peridot yet (doc/deck-reference.md lists "
                             "the supported ones)");
      }
      if (!isLabel) {
        throw InputError(joinPath(joinPath(out.path, "Output Variables"), v),
                         "unknown output variable (see doc/deck-reference.md for the list)");
      }
    }
  }

  if (top.has("Contact")) config.contact = readContactConfig(top.sublist("Contact"));
  if (top.has("Restart")) config.restart = readRestart(top, deck);
  config.restart.deckHash = deckHash(deck);
  top.finish();
  return config;
}

}  // namespace peridot
