#include "deck/OutputVariables.hpp"

#include <algorithm>

namespace peridot {

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

}  // namespace peridot
