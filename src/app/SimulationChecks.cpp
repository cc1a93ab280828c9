// Set-up checks and reports of a Simulation: the deck's dimension and outputs against the
// models, the cause of a zero stable time step, and what `--check` and the log print about the
// set-up and memory. (The set-up pipeline itself is in Simulation.cpp.)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <ostream>
#include <set>
#include <sstream>
#include <string>

#include "app/Simulation.hpp"
#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"
#include "deck/OutputVariables.hpp"

namespace peridot {

void Simulation::checkDimension() {
  for (const auto& c : config_.conditions) {
    if (planar_ && c.coordinate == 2) {
      throw InputError(c.path + " -> Coordinate",
                       "z in a 2D discretization; points move in the x-y plane only");
    }
  }
  const char* modeName[3] = {"3D", "plane stress", "plane strain"};
  for (const auto& g : config_.blocks) {
    const auto& material = config_.materials.at(g.material);
    const PlaneMode mode = material->planeMode();
    if (planar_ && mode == PlaneMode::ThreeD) {
      throw InputError(g.path + " -> Material",
                       "material \"" + g.material +
                           "\" is 3D but the discretization is 2D; set \"Plane Stress: true\" or "
                           "\"Plane Strain: true\" in Materials -> " +
                           g.material);
    }
    if (!planar_ && mode != PlaneMode::ThreeD && !material->acceptsPlaneModeIn3D()) {
      throw InputError(g.path + " -> Material",
                       "material \"" + g.material + "\" is " + modeName[static_cast<int>(mode)] +
                           " but the discretization is 3D; use a 2D discretization "
                           "(TensorProduct2DMeshGenerator, a planar Exodus mesh, or a Text File "
                           "with Dimension: 2) or remove the plane setting");
    }
  }
  // Planar contact: the points lie in z = 0, so the search is in-plane and the pair forces have
  // no z component; the force law is paper 004's eq. (2.34) as written, 9 C (l_c - d)/(pi
  // delta^5) V_j, with the points' volumes (area x thickness).
}

void Simulation::checkPeriodicBox() {
  if (config_.discretization.periodic.deformation.empty()) return;
  // Periodic images copy their point's velocity; in a deforming box an image also moves with the
  // box (Fdot s), which the copy lacks.
  for (const auto& g : config_.blocks)
    if (config_.materials.at(g.material)->needsVelocity())
      throw InputError(config_.discretization.periodic.deformationPath,
                       "the material \"" + g.material + "\" of block " + g.name +
                           " reads node velocities (the correspondence rate form), and the "
                           "periodic images of a deforming box do not carry the box's rate yet; "
                           "use \"Stress Integration: Total Lagrangian Green Strain\"");
}

void Simulation::explainZeroTimeStep(const double* stiffness) {
  // A zero stable time step has one of two causes: two points at the same place (a bond of
  // zero length is infinitely stiff) or a stiffness that overflows (a huge modulus). Name it,
  // with the point, rather than report "dt = 0".
  std::string why;
  for (int i = 0; i < topology_.numOwned && why.empty(); ++i) {
    if (std::isfinite(stiffness[i]) && !(stiffness[i] > 0 && density_[i] / stiffness[i] == 0))
      continue;
    const double* xi = &topology_.referencePosition[3 * i];
    for (auto b = topology_.bondOffsets[i]; b < topology_.bondOffsets[i + 1]; ++b) {
      const int j = topology_.neighbors[b];
      const double* xj = &topology_.referencePosition[3 * j];
      if (xi[0] == xj[0] && xi[1] == xj[1] && xi[2] == xj[2] && topology_.imageSource.empty()) {
        why = "points " + std::to_string(topology_.overlapGlobalId[i] + 1) + " and " +
              std::to_string(topology_.overlapGlobalId[j] + 1) + " lie at the same position (" +
              formatNumber(xi[0]) + ", " + formatNumber(xi[1]) + ", " + formatNumber(xi[2]) +
              "): a bond of zero length is infinitely stiff, so no time step is stable; remove "
              "the duplicate point from the mesh";
        break;
      }
    }
    if (why.empty()) {
      why = "the bond stiffness at point " + std::to_string(topology_.overlapGlobalId[i] + 1) +
            " (block " + blocks_[blockIndexOfPoint_[i]].name +
            ") overflows (a modulus too large for double precision?), so the stable time step "
            "is 0; check the material's moduli and density";
    }
  }
  if (why.empty()) why = "the stable time step is 0; check the material's moduli and density";
  throwIfAnyRank(why, comm_);
  throw InputError(why);  // unreachable: throwIfAnyRank throws on every rank
}

void Simulation::checkVariables() {
  bool lps = false;
  std::set<std::string> modelFields;  // node fields the materials maintain
  for (const auto& b : blocks_) {
    lps = lps || b.material->family() == "LPS";
    for (const auto& f : b.material->outputFields()) modelFields.insert(f);
  }
  auto check = [&](const std::string& name, const std::string& path) {
    // A tensor's component (Cauchy_StressXX) needs what its tensor needs.
    std::string v = name;
    int component = 0;
    if (std::string tensor; tensorComponent(name, tensor, component)) v = tensor;
    if ((v == "Dilatation" || v == "Weighted_Volume") && !lps && !modelFields.count(v)) {
      throw InputError(path, "\"" + v + "\" needs a state-based material (e.g. \"Elastic\")");
    }
    const bool palsField = v == "Pals_Pressure" || v.rfind("Lagrange_Multiplier_", 0) == 0 ||
                           v.find("_Normalization") != std::string::npos;
    if (palsField && !modelFields.count(v)) {
      throw InputError(path, "\"" + v + "\" needs a \"Pals\" material");
    }
    if ((v == "Shape_Tensor_Inverse" || v == "Cauchy_Stress" || v == "Unrotated_Cauchy_Stress" ||
         v == "Von_Mises_Stress" || v == "Hourglass_Force_Density" ||
         v == "Equivalent_Plastic_Strain" || v == "Rotation_Tensor" || v == "Left_Stretch_Tensor" ||
         v == "Velocity_Gradient" || v == "Unrotated_Rate_Of_Deformation" ||
         v == "Jacobian_Determinant" || v == "Green_Lagrange_Strain" ||
         v == "Stress_Triaxiality") &&
        !modelFields.count(v)) {
      throw InputError(path, "\"" + v + "\" needs a correspondence material (e.g. \"Elastic " +
                                 "Correspondence\"" +
                                 (v == "Equivalent_Plastic_Strain" ? ", a plastic one)"
                                  : v == "Stress_Triaxiality" ? ", a plastic bond-associated one)"
                                                              : ")"));
    }
    if (v == "Partial_Stress" && !modelFields.count(v)) {
      throw InputError(path,
                       "\"Partial_Stress\" needs an \"Elastic\" material with \"Compute "
                       "Partial Stress: true\"");
    }
    if (v == "Lambda" && !modelFields.count(v)) {
      throw InputError(path,
                       "\"Lambda\" needs an elastic-plastic material (e.g. \"Elastic "
                       "Plastic\")");
    }
  };
  for (const auto& out : config_.outputs)
    for (const auto& v : out.variables) check(v, out.path + " -> Output Variables -> " + v);
  for (const auto& c : config_.computes) {
    check(c.variable, c.path + " -> Variable");
    if (c.computeClass == "Nearest_Point_Data") {
      continue;
    } else if (c.computeClass == "Block_Data") {
      bool found = false;
      for (const auto& b : blocks_) found = found || b.name == c.region;
      if (!found) throw InputError(c.path + " -> Block", "unknown block \"" + c.region + "\"");
    } else if (!nodeSetIds_.count(c.region)) {
      throw InputError(c.path + " -> Node Set", "unknown node set \"" + c.region + "\"");
    }
  }
}

namespace {

// Peak resident memory of this process in bytes (Linux), 0 where unknown.
double peakResidentBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return 1024.0 * std::atof(line.c_str() + 6);
  }
  return 0.0;
}

}  // namespace

void Simulation::reportMemory(std::ostream& out) {
  double local[3] = {
      static_cast<double>(fields_->bytesAllocated()),
      static_cast<double>(topology_.neighbors.size() * sizeof(int) +
                          topology_.bondOffsets.size() * sizeof(std::int64_t) +
                          topology_.bondSides.size() + evaluator_->halfBondListBytes()),
      peakResidentBytes()};
  double total[3], largest = 0;
  MPI_Allreduce(local, total, 3, MPI_DOUBLE, MPI_SUM, comm_);
  // On a cluster the largest rank decides whether a run fits in a node's memory.
  MPI_Allreduce(&local[2], &largest, 1, MPI_DOUBLE, MPI_MAX, comm_);
  if (rank_ != 0) return;
  const double bonds = static_cast<double>(std::max(1LL, topology_.globalNumBonds));
  char text[320];
  std::snprintf(text, sizeof text,
                "Memory (all ranks): fields %.1f MB, bond lists %.1f MB, peak resident %.1f MB "
                "= %.1f bytes per bond; largest rank's peak resident %.1f MB\n",
                total[0] / 1e6, total[1] / 1e6, total[2] / 1e6, total[2] / bonds, largest / 1e6);
  out << text;
}

void Simulation::reportSetup() {
  const auto& s = config_.solver;
  if (!outputs_) openOutputs();
  long long myBonds = topology_.numBonds(), maxBonds = 0;
  MPI_Allreduce(&myBonds, &maxBonds, 1, MPI_LONG_LONG, MPI_MAX, comm_);
  // Communication volume: what a rank sends in one ghost exchange of a 3-vector field (the
  // positions, refreshed once per force evaluation), from the ghost Import's export list.
  long long sent[2] = {24 * static_cast<long long>(topology_.ghostImport->getNumExportIDs()),
                       static_cast<long long>(topology_.numGhosts)};
  long long sentMax[2] = {0, 0}, sentSum[2] = {0, 0};
  MPI_Allreduce(sent, sentMax, 2, MPI_LONG_LONG, MPI_MAX, comm_);
  MPI_Allreduce(sent, sentSum, 2, MPI_LONG_LONG, MPI_SUM, comm_);
  if (rank_ == 0) {
    log_ << "Points: " << topology_.globalNumPoints
         << ", bonds (one-sided): " << topology_.globalNumBonds
         << ", ranks: " << topology_.numRanks;
    if (topology_.numRanks > 1) {
      // Load balance: the busiest rank's bonds over the average.
      char text[32];
      std::snprintf(text, sizeof text, "%.3f",
                    static_cast<double>(maxBonds) * topology_.numRanks /
                        static_cast<double>(std::max(1LL, topology_.globalNumBonds)));
      log_ << ", bond imbalance (max/avg): " << text;
    }
    log_ << "\n";
    if (topology_.numRanks > 1) {
      log_ << "Ghost points per rank (max/avg): " << sentMax[1] << " / "
           << sentSum[1] / topology_.numRanks
           << "; bytes sent per ghost exchange of a 3-vector field, per rank (max/avg): "
           << sentMax[0] << " / " << sentSum[0] / topology_.numRanks << "\n";
    }
    if (planar_) log_ << "Planar (2D) run, thickness " << thickness_ << "\n";
    if (evaluator_->usesHalfBondList())
      log_ << "Bond loop: each bond once (half bond list; Discretization -> Half Bond List)\n";
    if (s.verletLimitEstimate) {
      log_ << "Stable time step estimate: " << stableDt_ << " (Verlet limit, "
           << verletLimitIterations_ << " Lanczos iterations; Peridigm's estimate " << peridigmDt_
           << ")\n";
    } else {
      log_ << "Stable time step estimate: " << stableDt_ << "\n";
    }
    log_ << "Time step: " << dt_ << (s.fixedDtGiven ? " (Fixed dt)" : " (estimate x Safety Factor)")
         << ", steps: " << numSteps_ << "\n";
    if (s.fixedDtGiven && dt_ > stableDt_) {
      // The estimate is a conservative bound: runs somewhat above it are often stable (the V2
      // bar of doc/verification.md is to 2.0x), so say how far above and what will happen.
      // Where every component's motion is prescribed, nothing is integrated: no warning.
      char text[240];
      if (freeComponents_ == 0)
        std::snprintf(text, sizeof text,
                      "Fixed dt is %.3g x the stable time step estimate; every point's motion is "
                      "prescribed, so no step can diverge\n",
                      dt_ / stableDt_);
      else
        std::snprintf(text, sizeof text,
                      "peridot: warning: Fixed dt is %.3g x the stable time step estimate; the "
                      "run may be stable or diverge, and is stopped with an error if it "
                      "diverges\n",
                      dt_ / stableDt_);
      log_ << text;
    }
    for (const auto& f : outputs_->fileNames()) log_ << "Output: " << f << "\n";
    log_ << std::flush;
  }
}

}  // namespace peridot
