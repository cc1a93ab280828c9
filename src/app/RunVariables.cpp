#include "app/RunVariables.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "deck/OutputVariables.hpp"
#include "materials/Correspondence.hpp"
#include "neighbor/PartialVolume.hpp"

namespace peridot {

RunVariables::RunVariables(const Sources& sources)
    : s_(sources),
      x_(sources.fields->node("Model_Coordinates", 3)),
      y_(sources.fields->node("Coordinates", 3)),
      u_(sources.fields->node("Displacement", 3)),
      v_(sources.fields->node("Velocity", 3)),
      a_(sources.fields->node("Acceleration", 3)),
      f_(sources.fields->node("Force_Density", 3)),
      volume_(sources.fields->node("Volume", 1)) {}

int RunVariables::components(const std::string& name) const {
  if (const VariableInfo* v = findOutputVariable(name)) return v->components;
  return 0;  // a compute's label: global
}

int RunVariables::globalSize(const std::string& name) const {
  for (const auto& c : s_.config->computes)
    if (c.label == name) return components(c.variable) == 3 ? 3 : 1;
  return 1;
}

std::string RunVariables::globalComponentName(const std::string& name, int d) const {
  // Peridigm names Nearest_Point_Data's vector components <label>_X, _Y, _Z.
  for (const auto& c : s_.config->computes)
    if (c.label == name && c.computeClass == "Nearest_Point_Data")
      return name + "_" + std::string(1, "XYZ"[d]);
  return VariableSource::globalComponentName(name, d);
}

void RunVariables::nodeVariable(const std::string& name, std::vector<double>& out) {
  const int n = s_.topology->numOwned;
  const int c = components(name);
  int component = 0;
  out.assign(static_cast<std::size_t>(n) * c, 0.0);
  auto copy = [&](const double* src) {
    std::copy(src, src + static_cast<std::size_t>(n) * c, out.begin());
  };
  if (name == "Volume") {
    copy(volume_);
  } else if (name == "Horizon") {
    copy(s_.fields->node("Horizon", 1));
  } else if (name == "Block_Id") {
    for (int i = 0; i < n; ++i) out[i] = (*s_.blocks)[(*s_.blockIndexOfPoint)[i]].id;
  } else if (name == "Element_Id") {
    for (int i = 0; i < n; ++i) out[i] = static_cast<double>(s_.topology->overlapGlobalId[i] + 1);
  } else if (name == "Proc_Num") {
    for (int i = 0; i < n; ++i) out[i] = s_.rank;
  } else if (name == "Radius") {
    // Peridigm's Radius compute: the sphere of the point's volume, in its arithmetic.
    const double constant = 0.75 / std::acos(-1.0), oneThird = 1.0 / 3.0;
    for (int i = 0; i < n; ++i) out[i] = std::pow(constant * volume_[i], oneThird);
  } else if (name == "Number_Of_Neighbors") {
    for (int i = 0; i < n; ++i) {
      int count = 0;
      for (auto b = s_.topology->bondOffsets[i]; b < s_.topology->bondOffsets[i + 1]; ++b)
        count += s_.topology->ownSide(b) ? 1 : 0;
      out[i] = count;
    }
  } else if (name == "Model_Coordinates") {
    copy(x_);
  } else if (name == "Coordinates") {
    copy(y_);
  } else if (name == "Displacement") {
    copy(u_);
  } else if (name == "Velocity") {
    copy(v_);
  } else if (name == "Acceleration") {
    copy(a_);
  } else if (name == "Force_Density") {
    copy(f_);
  } else if (name == "Force") {
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) out[3 * i + d] = f_[3 * i + d] * volume_[i];
  } else if (name == "External_Force_Density") {
    if (s_.externalForceDensity) copy(s_.externalForceDensity);
  } else if (name == "Contact_Force_Density") {
    if (s_.contactForceDensity) copy(s_.contactForceDensity);
  } else if (name == "Temperature" || name == "Temperature_Change") {
    // Allocated (zero) only in runs with temperature conditions or thermal expansion.
    if (s_.fields->hasNode(name)) copy(s_.fields->node(name, 1));
  } else if (name == "Damage") {
    s_.evaluator->nodeDamage(out.data());
  } else if (name == "Dilatation" || name == "Weighted_Volume" || name == "Lambda") {
    copy(s_.fields->node(name, 1));
  } else if (name == "Pals_Pressure" || name == "Critical_Stretch" ||
             name.rfind("Lagrange_Multiplier_", 0) == 0 ||
             name.find("_Normalization") != std::string::npos) {
    // Fields of a material or damage model (Pals, Interface Aware): 0 at points without one.
    if (s_.fields->hasNode(name)) copy(s_.fields->node(name, 1));
  } else if (std::string tensor; c == 1 && tensorComponent(name, tensor, component)) {
    // One component of a full tensor (Peridigm's scalar fields <tensor>XX ... ZZ).
    std::vector<double> full;
    nodeVariable(tensor, full);
    for (int i = 0; i < n; ++i) out[i] = full[9 * static_cast<std::size_t>(i) + component];
  } else if (name == "Deformation_Gradient") {
    // The correspondence models' own F (with bond damage); elsewhere Peridigm's compute:
    // F = N K^-1 from the current positions, zero where the shape tensor is singular.
    const double* own = s_.fields->hasNode(name) ? s_.fields->node(name, 9) : nullptr;
    const ModelState& state = s_.evaluator->state();
    double Kinv[9];
    for (int i = 0; i < n; ++i) {
      const bool model = own && (*s_.blocks)[(*s_.blockIndexOfPoint)[i]].material->family().find(
                                    "correspondence") != std::string::npos;
      if (model)
        std::copy(own + 9 * i, own + 9 * i + 9, out.begin() + 9 * i);
      else
        correspondence::shapeTensorAndDeformationGradient(state, i, Kinv, out.data() + 9 * i,
                                                          false);
    }
  } else if (name == "Partial_Stress" || name == "Shape_Tensor_Inverse" ||
             name == "Cauchy_Stress" || name == "Unrotated_Cauchy_Stress" ||
             name == "Von_Mises_Stress" || name == "Hourglass_Force_Density" ||
             name == "Equivalent_Plastic_Strain" || name == "Rotation_Tensor" ||
             name == "Left_Stretch_Tensor" || name == "Velocity_Gradient" ||
             name == "Unrotated_Rate_Of_Deformation" || name == "Jacobian_Determinant" ||
             name == "Green_Lagrange_Strain" || name == "Stress_Triaxiality") {
    // Maintained by the correspondence models (zero at the points of other blocks).
    if (s_.fields->hasNode(name)) copy(s_.fields->node(name, c));
  } else if (name == "Contact_Force") {
    if (s_.contactForceDensity)
      for (int i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d) out[3 * i + d] = s_.contactForceDensity[3 * i + d] * volume_[i];
  } else if (name == "Linear_Momentum") {
    for (int i = 0; i < n; ++i) {
      const double mass = (*s_.density)[i] * volume_[i];
      for (int d = 0; d < 3; ++d) out[3 * i + d] = mass * v_[3 * i + d];
    }
  } else if (name == "Angular_Momentum") {
    // Peridigm's convention: m v x y (the opposite sign of y x m v), y the current position.
    for (int i = 0; i < n; ++i) {
      const double mass = (*s_.density)[i] * volume_[i];
      const double* v = v_ + 3 * i;
      const double* r = y_ + 3 * i;
      out[3 * i] = mass * (v[1] * r[2] - v[2] * r[1]);
      out[3 * i + 1] = mass * (v[2] * r[0] - v[0] * r[2]);
      out[3 * i + 2] = mass * (v[0] * r[1] - v[1] * r[0]);
    }
  } else if (name == "Neighborhood_Volume") {
    // The volume of the point's family: its neighbours' volumes, each times the fraction of its
    // cell inside the horizon under partial-volume quadrature (the volume the models integrate).
    const ModelState& state = s_.evaluator->state();
    const Topology& t = *s_.topology;
    CellFractionCache fractions;
    for (int i = 0; i < n; ++i) {
      double total = 0;
      for (auto b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b) {
        if (!t.ownSide(b)) continue;
        const int j = t.neighbors[b];
        double w = volume_[j];
        if (state.partialVolumes) {
          double xi[3];
          for (int e = 0; e < 3; ++e) xi[e] = x_[3 * j + e] - x_[3 * i + e];
          w *= fractions.fraction(xi, cellEdge(volume_[j], state.dimension, state.thickness),
                                  state.horizon[i], state.dimension);
        }
        total += w;
      }
      out[i] = total;
    }
  } else if (name == "Kinetic_Energy") {
    for (int i = 0; i < n; ++i) {
      const double v2 =
          v_[3 * i] * v_[3 * i] + v_[3 * i + 1] * v_[3 * i + 1] + v_[3 * i + 2] * v_[3 * i + 2];
      out[i] = 0.5 * (*s_.density)[i] * volume_[i] * v2;
    }
  } else if (name == "Stored_Elastic_Energy" || name == "Stored_Elastic_Energy_Density" ||
             name == "Strain_Energy" || name == "Strain_Energy_Density") {
    std::vector<double> w(s_.topology->numOverlap, 0.0);
    s_.evaluator->storedEnergyDensity(w.data());
    const bool perVolume =
        name == "Stored_Elastic_Energy_Density" || name == "Strain_Energy_Density";
    for (int i = 0; i < n; ++i) out[i] = perVolume ? w[i] : w[i] * volume_[i];
  } else {
    throw std::logic_error("no node variable " + name);
  }
}

double RunVariables::reduce(const std::vector<int>* points, const std::string& variable,
                            int component, const std::string& calculation) {
  std::vector<double> values;
  nodeVariable(variable, values);
  const int c = components(variable);
  double result = calculation == "Sum"       ? 0.0
                  : calculation == "Minimum" ? std::numeric_limits<double>::max()
                                             : std::numeric_limits<double>::lowest();
  auto take = [&](int i) {
    const double v = values[static_cast<std::size_t>(i) * c + component];
    if (calculation == "Sum") {
      result += v;
    } else if (calculation == "Minimum") {
      result = std::min(result, v);
    } else {
      result = std::max(result, v);
    }
  };
  if (points) {
    for (int i : *points) take(i);
  } else {
    for (int i = 0; i < s_.topology->numOwned; ++i) take(i);
  }
  double global = 0;
  MPI_Op op = calculation == "Sum" ? MPI_SUM : calculation == "Minimum" ? MPI_MIN : MPI_MAX;
  MPI_Allreduce(&result, &global, 1, MPI_DOUBLE, op, s_.comm);
  return global;
}

int RunVariables::nearestPoint(const ComputeConfig& c) {
  const auto found = nearest_.find(c.label);
  if (found != nearest_.end()) return found->second;
  // Smallest squared distance over all ranks, then the smallest global id at that distance.
  double best = std::numeric_limits<double>::max();
  long long bestId = std::numeric_limits<long long>::max();
  int bestIndex = -1;
  for (int i = 0; i < s_.topology->numOwned; ++i) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += (x_[3 * i + k] - c.point[k]) * (x_[3 * i + k] - c.point[k]);
    const long long id = s_.topology->overlapGlobalId[i];
    if (d2 < best || (d2 == best && id < bestId)) {
      best = d2;
      bestId = id;
      bestIndex = i;
    }
  }
  double globalBest = best;
  MPI_Allreduce(&best, &globalBest, 1, MPI_DOUBLE, MPI_MIN, s_.comm);
  long long candidate = best == globalBest ? bestId : std::numeric_limits<long long>::max();
  long long chosen = candidate;
  MPI_Allreduce(&candidate, &chosen, 1, MPI_LONG_LONG, MPI_MIN, s_.comm);
  const int index = candidate == chosen && bestIndex >= 0 ? bestIndex : -1;
  nearest_[c.label] = index;
  return index;
}

void RunVariables::globalVariable(const std::string& name, std::vector<double>& values) {
  values.clear();
  if (name == "Global_Kinetic_Energy") {
    values.push_back(reduce(nullptr, "Kinetic_Energy", 0, "Sum"));
    return;
  }
  if (name == "Global_Stored_Elastic_Energy" || name == "Global_Strain_Energy") {
    values.push_back(reduce(nullptr, "Stored_Elastic_Energy", 0, "Sum"));
    return;
  }
  if (name == "Nonlinear_Solver_Iterations") {
    values.push_back(s_.nonlinearIterations ? static_cast<double>(*s_.nonlinearIterations) : 0.0);
    return;
  }
  if (name == "Global_Linear_Momentum" || name == "Global_Angular_Momentum") {
    // Peridigm's definition: the magnitude of each block's total momentum, summed over blocks.
    std::vector<double> perPoint;
    nodeVariable(name.substr(7), perPoint);  // the point values once, for all blocks
    std::vector<double> sums(3 * s_.blocks->size(), 0.0);
    for (std::size_t k = 0; k < s_.blocks->size(); ++k)
      for (int i : (*s_.blocks)[k].points)
        for (int d = 0; d < 3; ++d)
          sums[3 * k + d] += perPoint[3 * static_cast<std::size_t>(i) + d];
    MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM,
                  s_.comm);
    double total = 0;
    for (std::size_t k = 0; k < s_.blocks->size(); ++k)
      total += std::sqrt(sums[3 * k] * sums[3 * k] + sums[3 * k + 1] * sums[3 * k + 1] +
                         sums[3 * k + 2] * sums[3 * k + 2]);
    values.push_back(total);
    return;
  }
  for (const auto& c : s_.config->computes) {
    if (c.label != name) continue;
    const int n = components(c.variable);
    if (c.computeClass == "Nearest_Point_Data") {
      // The owner contributes the value, the others zeros: the sum is the value, exactly.
      const int p = nearestPoint(c);
      std::vector<double> mine(static_cast<std::size_t>(n), 0.0), all;
      if (p >= 0) {
        nodeVariable(c.variable, all);
        for (int d = 0; d < n; ++d) mine[d] = all[static_cast<std::size_t>(p) * n + d];
      }
      values.assign(static_cast<std::size_t>(n), 0.0);
      MPI_Allreduce(mine.data(), values.data(), n, MPI_DOUBLE, MPI_SUM, s_.comm);
      return;
    }
    const std::vector<int>* points = nullptr;
    if (c.computeClass == "Block_Data") {
      for (const auto& b : *s_.blocks)
        if (b.name == c.region) points = &b.points;
    } else {
      points = &s_.nodeSets->at(c.region);
    }
    for (int d = 0; d < n; ++d) values.push_back(reduce(points, c.variable, d, c.calculation));
    return;
  }
  throw std::logic_error("no global variable " + name);
}

}  // namespace peridot
