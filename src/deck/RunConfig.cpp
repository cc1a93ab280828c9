#include "deck/RunConfig.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"
#include "core/Format.hpp"
#include "deck/Expression.hpp"
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

// Each full tensor is also known by its nine components <name>XX, XY, ..., ZZ: Peridigm
// registers the tensors of its correspondence models (and of the Deformation_Gradient compute)
// as nine scalar element fields, and its decks ask for them by these names.
std::vector<VariableInfo> withTensorComponents(std::vector<VariableInfo> vars) {
  const std::size_t n = vars.size();
  for (std::size_t v = 0; v < n; ++v) {
    if (vars[v].components != 9) continue;
    for (const char* suffix : kTensorComponentSuffixes) {
      vars.push_back(
          {vars[v].name + suffix, 1, std::string("component ") + suffix + " of " + vars[v].name});
    }
  }
  return vars;
}

}  // namespace

const std::vector<VariableInfo>& knownOutputVariables() {
  static const std::vector<VariableInfo> vars = withTensorComponents({
      {"Volume", 1, "point volume"},
      {"Block_Id", 1, "block id of the point"},
      {"Element_Id", 1, "global point id (Exodus element id)"},
      {"Proc_Num", 1, "MPI rank owning the point"},
      {"Horizon", 1, "horizon of the point"},
      {"Number_Of_Neighbors", 1, "bonds of the point (at the start)"},
      {"Radius", 1, "radius of the sphere of the point's volume, (3V/(4 pi))^(1/3)"},
      {"Model_Coordinates", 3, "reference coordinates"},
      {"Coordinates", 3, "current coordinates"},
      {"Displacement", 3, "displacement"},
      {"Velocity", 3, "velocity"},
      {"Acceleration", 3, "acceleration"},
      {"Force_Density", 3, "internal force density"},
      {"Force", 3, "internal force density x volume"},
      {"External_Force_Density", 3, "body force density"},
      {"Contact_Force_Density", 3, "short-range contact force density"},
      {"Damage", 1, "fraction of broken bonds"},
      {"Dilatation", 1, "LPS dilatation"},
      {"Weighted_Volume", 1, "LPS weighted volume"},
      {"Lambda", 1, "plastic multiplier of the elastic-plastic models"},
      // Correspondence models (materials/Correspondence.hpp); full tensors are written as 9
      // element variables <name>XX, XY, XZ, YX, ..., ZZ, as Peridigm does.
      {"Deformation_Gradient", 9,
       "deformation gradient F (correspondence models; for other models F = N K^-1 from the "
       "current positions, without bond damage, as Peridigm's compute)"},
      {"Partial_Stress", 9,
       "Peridigm's partial stress of an \"Elastic\" block with Compute Partial Stress: sum of "
       "the point's own pair forces (x) xi V_j"},
      {"Shape_Tensor_Inverse", 9, "inverse of the shape tensor K (correspondence models)"},
      {"Cauchy_Stress", 9, "Cauchy stress (correspondence models)"},
      {"Unrotated_Cauchy_Stress", 9,
       "Cauchy stress in the frame of F's polar rotation, R^T sigma R"},
      {"Von_Mises_Stress", 1, "von Mises stress of the Cauchy stress (correspondence models)"},
      {"Rotation_Tensor", 9, "rotation R of the polar decomposition F = R U (correspondence)"},
      {"Left_Stretch_Tensor", 9, "left stretch V = F R^T (correspondence models)"},
      {"Velocity_Gradient", 9,
       "velocity gradient L = Fdot F^-1 (correspondence models, rate form; zero with the Green "
       "strain)"},
      {"Unrotated_Rate_Of_Deformation", 9,
       "unrotated rate of deformation d = R^T sym(L) R (correspondence models, rate form)"},
      {"Hourglass_Force_Density", 3, "hourglass part of the force density (correspondence)"},
      {"Equivalent_Plastic_Strain", 1, "equivalent plastic strain (plastic correspondence models)"},
      {"Jacobian_Determinant", 1,
       "J = det F, advanced as J (1 + tr L dt) (hypoelastic correspondence models)"},
      {"Green_Lagrange_Strain", 9,
       "Green strain (F^T F - I) / 2 of the advanced F (hypoelastic correspondence models)"},
      {"Stress_Triaxiality", 1,
       "mean stress over von Mises stress of the Cauchy stress (plastic bond-associated and "
       "hypoelastic correspondence models)"},
      {"Contact_Force", 3, "Contact_Force_Density x volume"},
      {"Neighborhood_Volume", 1,
       "volume of the point's family: sum of its neighbours' volumes (times their cell "
       "fraction inside the horizon under partial-volume quadrature)"},
      {"Linear_Momentum", 3, "linear momentum of the point, rho V v"},
      {"Angular_Momentum", 3,
       "angular momentum of the point in Peridigm's convention, rho V v x y (y the current "
       "position)"},
      {"Global_Linear_Momentum", 0,
       "|sum of Linear_Momentum| per block, summed over blocks (Peridigm's definition)"},
      {"Global_Angular_Momentum", 0,
       "|sum of Angular_Momentum| per block, summed over blocks (Peridigm's definition)"},
      {"Nonlinear_Solver_Iterations", 0,
       "nonlinear iterations of the last step: Newton (QuasiStatic, Implicit), relaxation "
       "(Adaptive Dynamic Relaxation); 0 under Verlet (global variable)"},
      {"Kinetic_Energy", 1, "kinetic energy of the point, 1/2 rho V |v|^2"},
      {"Stored_Elastic_Energy", 1, "stored elastic energy of the point (density x volume)"},
      {"Stored_Elastic_Energy_Density", 1, "stored elastic energy density"},
      {"Temperature", 1, "temperature (Initial / Prescribed Temperature conditions; 0 elsewhere)"},
      {"Temperature_Change", 1,
       "temperature change Delta T = f(t) - f(0) of Prescribed Temperature (thermal strains)"},
      {"Global_Kinetic_Energy", 0, "sum of Kinetic_Energy (global variable)"},
      {"Global_Stored_Elastic_Energy", 0, "sum of Stored_Elastic_Energy (global variable)"},
      // Older Peridigm names of the stored energy (compute classes not registered in 1.5).
      {"Strain_Energy", 1, "stored elastic energy of the point (= Stored_Elastic_Energy)"},
      {"Strain_Energy_Density", 1,
       "stored elastic energy density (= Stored_Elastic_Energy_Density)"},
      {"Global_Strain_Energy", 0, "sum of Strain_Energy (global variable)"},
      // Fields of the Pals material and of Interface Aware damage.
      {"Pals_Pressure", 1, "Pals: the pressure-like scalar p of the force state"},
      {"Dilatation_Normalization", 1, "Pals: normalization of omega (1, as Peridigm)"},
      {"Deviatoric_Normalization", 1, "Pals: normalization of sigma (1, as Peridigm)"},
      {"Lagrange_Multiplier_Dilatation_1", 1, "Pals: dilatation multiplier (xx)"},
      {"Lagrange_Multiplier_Dilatation_2", 1, "Pals: dilatation multiplier (yy)"},
      {"Lagrange_Multiplier_Dilatation_3", 1, "Pals: dilatation multiplier (zz)"},
      {"Lagrange_Multiplier_Dilatation_4", 1, "Pals: dilatation multiplier (xy)"},
      {"Lagrange_Multiplier_Dilatation_5", 1, "Pals: dilatation multiplier (xz)"},
      {"Lagrange_Multiplier_Dilatation_6", 1, "Pals: dilatation multiplier (yz)"},
      {"Lagrange_Multiplier_Deviatoric_1", 1, "Pals: deviatoric multiplier (xx)"},
      {"Lagrange_Multiplier_Deviatoric_2", 1, "Pals: deviatoric multiplier (yy)"},
      {"Lagrange_Multiplier_Deviatoric_3", 1, "Pals: deviatoric multiplier (zz)"},
      {"Lagrange_Multiplier_Deviatoric_4", 1, "Pals: deviatoric multiplier (xy)"},
      {"Lagrange_Multiplier_Deviatoric_5", 1, "Pals: deviatoric multiplier (xz)"},
      {"Lagrange_Multiplier_Deviatoric_6", 1, "Pals: deviatoric multiplier (yz)"},
      {"Critical_Stretch", 1,
       "Interface Aware damage: critical stretch of the point (0 elsewhere)"},
  });
  return vars;
}

bool tensorComponent(const std::string& name, std::string& tensor, int& component) {
  if (name.size() < 3) return false;
  const char row = name[name.size() - 2], column = name[name.size() - 1];
  if (row < 'X' || row > 'Z' || column < 'X' || column > 'Z') return false;
  const VariableInfo* base = findOutputVariable(name.substr(0, name.size() - 2));
  if (!base || base->components != 9) return false;
  tensor = base->name;
  component = 3 * (row - 'X') + (column - 'X');
  return true;
}

const VariableInfo* findOutputVariable(const std::string& name) {
  for (const auto& v : knownOutputVariables())
    if (v.name == name) return &v;
  return nullptr;
}

std::vector<std::string> distinctOutputVariables(const std::vector<std::string>& requested) {
  auto has = [&](const std::string& name) {
    return std::find(requested.begin(), requested.end(), name) != requested.end();
  };
  std::vector<std::string> out;
  for (const auto& v : requested) {
    if (std::find(out.begin(), out.end(), v) != out.end()) continue;
    std::string tensor;
    int component = 0;
    if (tensorComponent(v, tensor, component) && has(tensor)) continue;
    out.push_back(v);
  }
  return out;
}

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
