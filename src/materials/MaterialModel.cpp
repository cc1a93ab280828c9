#include "materials/MaterialModel.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/Error.hpp"
#include "core/ProcessorsPerRank.hpp"
#include "neighbor/PartialVolume.hpp"

namespace peridot {

std::unique_ptr<MaterialModel> createMaterial(ListReader& params) {
  if (params.has("Horizon")) {
    throw InputError(params.pathOf("Horizon"),
                     "the horizon belongs in the Blocks section (Blocks -> <group> -> Horizon)");
  }
  // Keys every material accepts (elastic constants are checked by the model).
  static const std::vector<std::string> common = {"Density",
                                                  "Bulk Modulus",
                                                  "Shear Modulus",
                                                  "Young's Modulus",
                                                  "Poisson's Ratio",
                                                  "Verbose",
                                                  "Finite Difference Probe Length",
                                                  "Apply Automatic Differentiation Jacobian",
                                                  "Apply Shear Correction Factor",
                                                  "Thermal Expansion Coefficient",
                                                  "Compute Partial Stress"};
  // A Peridigm model Peridot lacks is named as such by the registry (deck/PeridigmVocabulary).
  const auto& entry = MaterialRegistry::lookup(params, "Material Model", "material model", common);
  auto material = entry.create(params);
  params.finish();
  return material;
}

double bondBasedPoissonsRatio(PlaneMode mode) {
  return mode == PlaneMode::PlaneStress ? 1.0 / 3.0 : 0.25;
}

PlaneMode readPlaneMode(ListReader& p) {
  const bool stress = p.has("Plane Stress") && p.boolean("Plane Stress", false);
  const bool strain = p.has("Plane Strain") && p.boolean("Plane Strain", false);
  if (stress && strain)
    throw InputError(p.path(), "\"Plane Stress\" and \"Plane Strain\" are exclusive");
  return stress ? PlaneMode::PlaneStress : strain ? PlaneMode::PlaneStrain : PlaneMode::ThreeD;
}

double inPlaneBulkModulus(double E, double nu, PlaneMode mode) {
  switch (mode) {
    case PlaneMode::PlaneStress:
      return E / (2.0 * (1.0 - nu));
    case PlaneMode::PlaneStrain:
      return E / (2.0 * (1.0 + nu) * (1.0 - 2.0 * nu));
    default:
      return E / (3.0 * (1.0 - 2.0 * nu));
  }
}

bool influenceIntegral(const std::string& w, int k, double delta, double& value) {
  const double dk = std::pow(delta, k);
  if (w == "One") {
    value = dk * delta / (k + 1);
  } else if (w == "Conical") {
    value = dk * delta / ((k + 1) * (k + 2));
  } else if (w == "Conical Over Zeta" && k >= 1) {
    value = dk / (k * (k + 1));
  } else {
    return false;
  }
  return true;
}

double readBondBasedBulkModulus(ListReader& p, PlaneMode mode) {
  const double nu = bondBasedPoissonsRatio(mode);
  const std::string fixed = mode == PlaneMode::PlaneStress   ? "1/3 in plane stress"
                            : mode == PlaneMode::PlaneStrain ? "1/4 in plane strain"
                                                             : "1/4";
  for (const char* k : {"Shear Modulus", "Poisson's Ratio"}) {
    if (p.has(k)) {
      throw InputError(p.pathOf(k),
                       "a bond-based material has one elastic constant (Poisson's "
                       "ratio is fixed at " +
                           fixed + "); give only Bulk Modulus or Young's Modulus");
    }
  }
  if (p.has("Bulk Modulus") == p.has("Young's Modulus")) {
    throw InputError(p.path(), "give exactly one of \"Bulk Modulus\" and \"Young's Modulus\"");
  }
  if (p.has("Bulk Modulus")) return p.positiveNumber("Bulk Modulus");
  const double E = p.positiveNumber("Young's Modulus");
  // K = E / (3 (1 - 2 nu)); for nu = 1/4 written as before (2E/3) so that 3D keeps its bits.
  return mode == PlaneMode::PlaneStress ? E / (3.0 * (1.0 - 2.0 * nu)) : E * 2.0 / 3.0;
}

void MaterialModel::checkAssumedInfluenceFunction(const ModelState& s) const {
  if (influenceFunctionAssumed_ && influenceFunction_ != s.influenceFunction) {
    throw InputError("Discretization -> Influence Function",
                     "the critical stretch was derived from the fracture energy for the "
                     "influence function \"" +
                         influenceFunction_ + "\" but the run uses \"" + s.influenceFunction +
                         "\" (the set-up did not pass it to the material before binding the "
                         "damage model); give Critical Stretch instead");
  }
}

void MaterialModel::checkDimension(const ModelState& s, const std::string& modelName) const {
  const bool planar = planeMode() != PlaneMode::ThreeD;
  if (planar && s.dimension != 2 && !acceptsPlaneModeIn3D()) {
    throw InputError("Materials", "the \"" + modelName +
                                      "\" material is plane stress or plane strain but the "
                                      "discretization is 3-dimensional");
  }
  if (!planar && s.dimension != 3) {
    throw InputError("Materials", "the \"" + modelName +
                                      "\" material is 3-dimensional but the discretization is "
                                      "planar: set \"Plane Stress\" or \"Plane Strain\"");
  }
}

namespace {

// sum_i = sum over i's own-side bonds, in bond order, of V_j c_i / |xi| (the same bits as
// Peridigm's loop), in three passes over a row buffer: the neighbours' data copied into
// contiguous arrays (scalar loads), the terms' square roots and divisions in vector lanes, then
// the terms summed in order. The one-pass loop was bound by the scalar square root and division
// (and, while the partial-volume call shared the loop, by a stack round trip of the running sum
// at every bond); a vector loop gathering the neighbours' coordinates was slower still
// (bench/RESULTS.md). A bond outside the owner's horizon adds an exact zero, which leaves the
// sum's bits as they are (the terms are positive).
template <bool kStoredLength, bool kOneSided, typename Constant>
void plainStiffnessSum(const ModelState& s, const std::vector<int>& points, Constant constantOf,
                       double* sum) {
  const Topology& t = *s.topology;
  const std::int64_t* offsets = t.bondOffsets.data();
  const int* neighbors = t.neighbors.data();
  const unsigned char* sides = t.bondSides.data();
  const double* volume = s.volume;
  const double* x = s.x;
  std::int64_t longest = 0;
  for (int i : points) longest = std::max(longest, offsets[i + 1] - offsets[i]);
  const std::size_t n = static_cast<std::size_t>(longest);
  // The points [first, last) of `points`, with a row buffer of their own.
  const auto sumRange = [&](std::size_t firstPoint, std::size_t lastPoint) {
    std::vector<double> buffer(4 * n);
    double *X0 = buffer.data(), *X1 = X0 + n, *X2 = X1 + n, *term = X2 + n;
    for (std::size_t p = firstPoint; p < lastPoint; ++p) {
      const int i = points[p];
      const double c = constantOf(i);
      const std::int64_t first = offsets[i];
      const int m = static_cast<int>(offsets[i + 1] - first);
      const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
      for (int k = 0; k < m; ++k) {
        const int j = neighbors[first + k];
        // The volume, or zero for a bond outside the owner's horizon: its term is then 0.
        term[k] = kOneSided && !(sides[first + k] & 1) ? 0.0 : volume[j];
        if (!kStoredLength) {
          X0[k] = x[3 * j] - xi0;
          X1[k] = x[3 * j + 1] - xi1;
          X2[k] = x[3 * j + 2] - xi2;
        }
      }
      const double* length = kStoredLength ? s.bondLength + first : nullptr;
      for (int k = 0; k < m; ++k) {
        const double zeta =
            kStoredLength ? length[k] : std::sqrt(sumOfSquares(X0[k], X1[k], X2[k]));
        term[k] = term[k] * c / zeta;
      }
      double total = 0;
      for (int k = 0; k < m; ++k) total += term[k];
      sum[i] = total;
    }
  };
  // Each sum is one point's, made in the same order whoever makes it: the set-up's threads take
  // runs of points as they come free (the estimate was 0.55 s of a 128^3 set-up on one thread).
  const auto numThreads = static_cast<std::size_t>(threadsFor(setUpThreads(), points.size()));
  runChunksOnThreads(static_cast<int>(numThreads), points.size(),
                     std::max<std::size_t>(points.size() / (32 * numThreads), 1024),
                     [&](int, std::size_t first, std::size_t last) { sumRange(first, last); });
}

}  // namespace

void MaterialModel::stiffnessSum(const ModelState& s, const std::vector<int>& points,
                                 double* sum) const {
  const double pi = 3.14159265358979323846;
  // 2D: the bond-based plane constant 12 kappa / (pi t delta^3) of omega = 1 (W = 2 kappa s^2
  // for an in-plane dilatation), kappa the in-plane bulk modulus of the material.
  const bool planar = s.dimension == 2;
  const double kappa =
      planar ? inPlaneBulkModulus(youngsModulus(), poissonsRatio(), planeMode()) : 0.0;
  const double K = planar || points.empty() ? 0.0 : bulkModulus();
  const auto constantOf = [&](int i) {
    const double d = s.horizon[i];
    return planar ? 12.0 * kappa / (pi * s.thickness * d * d * d) : 18.0 * K / (pi * d * d * d * d);
  };
  if (!s.partialVolumes) {
    const bool stored = s.bondLength != nullptr, oneSided = !s.topology->bondSides.empty();
    if (stored && oneSided) plainStiffnessSum<true, true>(s, points, constantOf, sum);
    if (stored && !oneSided) plainStiffnessSum<true, false>(s, points, constantOf, sum);
    if (!stored && oneSided) plainStiffnessSum<false, true>(s, points, constantOf, sum);
    if (!stored && !oneSided) plainStiffnessSum<false, false>(s, points, constantOf, sum);
    return;
  }
  // With partial volumes each neighbour counts with the fraction of its cell inside the
  // horizon, as in the models' sums (Peridigm's estimate has no such fraction to ignore).
  CellFractionCache fractions;
  for (int i : points) {
    const double d = s.horizon[i];
    const double c = constantOf(i);
    double total = 0;
    for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
      if (!s.topology->ownSide(b)) continue;
      const int j = s.topology->neighbors[b];
      double k = s.volume[j] * c / bondLengthOf(s, i, b);
      double xi[3];
      for (int e = 0; e < 3; ++e) xi[e] = s.x[3 * j + e] - s.x[3 * i + e];
      k *= fractions.fraction(xi, cellEdge(s.volume[j], s.dimension, s.thickness), d, s.dimension);
      total += k;
    }
    sum[i] = total;
  }
}

ElasticConstants readTwoElasticConstants(ListReader& p) {
  const char* keys[4] = {"Bulk Modulus", "Shear Modulus", "Young's Modulus", "Poisson's Ratio"};
  int count = 0;
  for (const char* k : keys) count += p.has(k) ? 1 : 0;
  if (count != 2) {
    throw InputError(p.path(),
                     "exactly two of \"Bulk Modulus\", \"Shear Modulus\", \"Young's "
                     "Modulus\" and \"Poisson's Ratio\" are required, got " +
                         std::to_string(count));
  }
  ElasticConstants c;
  const bool hasK = p.has("Bulk Modulus"), hasG = p.has("Shear Modulus"),
             hasE = p.has("Young's Modulus"), hasNu = p.has("Poisson's Ratio");
  double K = hasK ? p.positiveNumber("Bulk Modulus") : 0;
  double G = hasG ? p.positiveNumber("Shear Modulus") : 0;
  double E = hasE ? p.positiveNumber("Young's Modulus") : 0;
  double nu = hasNu ? p.number("Poisson's Ratio") : 0;
  if (hasNu && !(nu > -1.0 && nu < 0.5)) {
    throw InputError(p.pathOf("Poisson's Ratio"),
                     "expected a number in (-1, 0.5), got " + std::to_string(nu));
  }
  if (hasK && hasG) {
    E = 9 * K * G / (3 * K + G);
    nu = (3 * K - 2 * G) / (2 * (3 * K + G));
  } else if (hasE && hasNu) {
    K = E / (3 * (1 - 2 * nu));
    G = E / (2 * (1 + nu));
  } else if (hasK && hasE) {
    if (!(E < 9 * K))
      throw InputError(p.path(), "Young's Modulus must be less than 9 x Bulk Modulus");
    G = 3 * K * E / (9 * K - E);
    nu = (3 * K - E) / (6 * K);
  } else if (hasK && hasNu) {
    E = 3 * K * (1 - 2 * nu);
    G = E / (2 * (1 + nu));
  } else if (hasG && hasE) {
    nu = E / (2 * G) - 1;
    if (!(nu > -1.0 && nu < 0.5))
      throw InputError(p.path(), "these moduli give a Poisson's ratio outside (-1, 0.5)");
    K = E / (3 * (1 - 2 * nu));
  } else {  // G and nu
    E = 2 * G * (1 + nu);
    K = E / (3 * (1 - 2 * nu));
  }
  c.bulkModulus = K;
  c.shearModulus = G;
  c.youngsModulus = E;
  c.poissonsRatio = nu;
  return c;
}

void acceptCommonMaterialKeys(ListReader& p, bool hasShearCorrection, bool hasThermalExpansion,
                              bool hasPartialStress) {
  p.positiveNumber("Finite Difference Probe Length", 1.0);
  p.boolean("Verbose", false);
  // Peridigm's implicit-solver options do not change explicit dynamics.
  p.boolean("Apply Automatic Differentiation Jacobian", true);
  if (!hasShearCorrection && p.has("Apply Shear Correction Factor") &&
      p.boolean("Apply Shear Correction Factor", false)) {
    throw InputError(p.pathOf("Apply Shear Correction Factor"),
                     "not available for this material model");
  }
  if (!hasThermalExpansion && p.has("Thermal Expansion Coefficient") &&
      p.number("Thermal Expansion Coefficient") != 0.0) {
    throw InputError(p.pathOf("Thermal Expansion Coefficient"),
                     "thermal strains are not supported by this material model yet (they are by "
                     "\"Elastic\" and \"Elastic Bond Based\")");
  }
  if (!hasPartialStress && p.has("Compute Partial Stress") &&
      p.boolean("Compute Partial Stress", false)) {
    throw InputError(p.pathOf("Compute Partial Stress"),
                     "not supported by Peridot yet for this material (it is by \"Elastic\")");
  }
}

}  // namespace peridot
