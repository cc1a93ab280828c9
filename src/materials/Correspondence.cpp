#include "materials/Correspondence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"

namespace peridot {

namespace correspondence {

void multiply(const double* a, const double* b, double* c) {
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k)
      c[3 * r + k] = a[3 * r] * b[k] + a[3 * r + 1] * b[3 + k] + a[3 * r + 2] * b[6 + k];
}

void multiplyTransposed(const double* a, const double* b, double* c) {
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k)
      c[3 * r + k] =
          a[3 * r] * b[3 * k] + a[3 * r + 1] * b[3 * k + 1] + a[3 * r + 2] * b[3 * k + 2];
}

double determinant(const double* a) {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
         a[2] * (a[3] * a[7] - a[4] * a[6]);
}

bool invert(const double* a, double* inverse, double tolerance) {
  const double det = determinant(a);
  double norm2 = 0;
  for (int k = 0; k < 9; ++k) norm2 += a[k] * a[k];
  const double scale = std::pow(norm2 / 3.0, 1.5);  // |det| of a multiple of the identity
  if (!(std::abs(det) > tolerance * scale)) {
    std::fill(inverse, inverse + 9, 0.0);
    return false;
  }
  inverse[0] = (a[4] * a[8] - a[5] * a[7]) / det;
  inverse[1] = (a[2] * a[7] - a[1] * a[8]) / det;
  inverse[2] = (a[1] * a[5] - a[2] * a[4]) / det;
  inverse[3] = (a[5] * a[6] - a[3] * a[8]) / det;
  inverse[4] = (a[0] * a[8] - a[2] * a[6]) / det;
  inverse[5] = (a[2] * a[3] - a[0] * a[5]) / det;
  inverse[6] = (a[3] * a[7] - a[4] * a[6]) / det;
  inverse[7] = (a[1] * a[6] - a[0] * a[7]) / det;
  inverse[8] = (a[0] * a[4] - a[1] * a[3]) / det;
  return true;
}

bool polarRotation(const double* F, double* R) {
  if (!(determinant(F) > 0)) return false;
  std::copy(F, F + 9, R);
  double inverse[9];
  for (int iteration = 0; iteration < 100; ++iteration) {
    if (!invert(R, inverse, 0.0)) return false;
    double change = 0;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const double next = 0.5 * (R[3 * r + c] + inverse[3 * c + r]);
        change = std::max(change, std::abs(next - R[3 * r + c]));
        R[3 * r + c] = next;
      }
    if (change < 1e-15) break;  // quadratic convergence: one more step gains nothing
  }
  return true;
}

double vonMises(const double* a) {
  const double mean = (a[0] + a[4] + a[8]) / 3.0;
  double ss = 0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const double sym = 0.5 * (a[3 * r + c] + a[3 * c + r]) - (r == c ? mean : 0.0);
      ss += sym * sym;
    }
  return std::sqrt(1.5 * ss);
}

bool shapeTensorAndDeformationGradient(const ModelState& s, int i, double* Kinv, double* F,
                                       bool useDamage) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  double K[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, N[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  const double* xi0 = s.x + 3 * i;
  const double* yi0 = s.y + 3 * i;
  for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
    const int j = neighbors[b];
    double w = s.volume[j];
    if (s.influence) w *= s.influence[b];
    if (useDamage && s.bondDamage) w *= 1.0 - s.bondDamage[b];
    if (s.bondSides) w *= (s.bondSides[b] & 1);
    const double xi[3] = {s.x[3 * j] - xi0[0], s.x[3 * j + 1] - xi0[1], s.x[3 * j + 2] - xi0[2]};
    const double Y[3] = {s.y[3 * j] - yi0[0], s.y[3 * j + 1] - yi0[1], s.y[3 * j + 2] - yi0[2]};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        K[3 * r + c] += w * xi[r] * xi[c];
        N[3 * r + c] += w * Y[r] * xi[c];
      }
  }
  if (!invert(K, Kinv)) {
    std::fill(F, F + 9, 0.0);
    return false;
  }
  multiply(N, Kinv, F);
  return true;
}

std::string describePoint(const ModelState& s, int i) {
  int intact = 0, total = 0;
  for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b) {
    if (!s.topology->ownSide(b)) continue;
    ++total;
    if (!s.bondDamage || s.bondDamage[b] < 1.0f) ++intact;
  }
  char text[256];
  std::snprintf(text, sizeof text, "point %lld at (%.6g, %.6g, %.6g) has %d intact bonds of %d",
                s.topology->overlapGlobalId[i] + 1, s.x[3 * i], s.x[3 * i + 1], s.x[3 * i + 2],
                intact, total);
  return text;
}

}  // namespace correspondence

namespace {
const double kPi = 3.14159265358979323846;
}

CorrespondenceMaterial::CorrespondenceMaterial(ListReader& p, const std::string& name)
    : name_(name) {
  density_ = p.positiveNumber("Density");
  constants_ = readTwoElasticConstants(p);
  lame_ = constants_.bulkModulus - 2.0 * constants_.shearModulus / 3.0;
  // Peridigm requires the key; 0 turns the stabilisation off.
  if (!p.has("Hourglass Coefficient"))
    throw InputError(p.pathOf("Hourglass Coefficient"), "required (a number >= 0, e.g. 0.02)");
  hourglassCoefficient_ = p.nonNegativeNumber("Hourglass Coefficient", 0.0);
  if (p.has("Apply Shear Correction Factor")) {
    throw InputError(p.pathOf("Apply Shear Correction Factor"),
                     "not available for the correspondence models (as in Peridigm)");
  }
  acceptCommonMaterialKeys(p);
}

void CorrespondenceMaterial::declareFields(FieldManager& fields) {
  shapeTensorInverse_ = fields.node(kShapeTensorInverse, 9);
  deformationGradient_ = fields.node(kDeformationGradient, 9);
  cauchy_ = fields.node(kCauchyStress, 9);
  unrotated_ = fields.node(kUnrotatedCauchyStress, 9);
  vonMises_ = fields.node(kVonMisesStress, 1);
  hourglass_ = fields.node(kHourglassForceDensity, 3);
  for (int r = 0; r < 3; ++r) {
    fRow_[r] = fields.node(kDeformationGradientRows[r], 3);
    aRow_[r] = fields.node(kForceTensorRows[r], 3);
  }
}

std::vector<std::string> CorrespondenceMaterial::outputFields() const {
  return {kShapeTensorInverse,    kDeformationGradient, kCauchyStress,
          kUnrotatedCauchyStress, kVonMisesStress,      kHourglassForceDensity};
}

void CorrespondenceMaterial::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, name_);
  std::string message;
  for (int i : points) {
    double F[9];
    if (!correspondence::shapeTensorAndDeformationGradient(s, i, shapeTensorInverse_ + 9 * i, F) &&
        message.empty()) {
      message = "Materials -> \"" + name_ + "\": the shape tensor of " +
                correspondence::describePoint(s, i) +
                ": a correspondence model needs at least three non-coplanar neighbours per "
                "point (as Peridigm, which stops with \"failed to compute shape tensor\"); is "
                "the horizon too small?";
    }
    for (int k = 0; k < 9; ++k) {
      deformationGradient_[9 * i + k] = (k % 4 == 0) ? 1.0 : 0.0;
      cauchy_[9 * i + k] = unrotated_[9 * i + k] = 0.0;
      fRow_[k / 3][3 * i + k % 3] = deformationGradient_[9 * i + k];
      aRow_[k / 3][3 * i + k % 3] = 0.0;
    }
    vonMises_[i] = 0.0;
    for (int d = 0; d < 3; ++d) hourglass_[3 * i + d] = 0.0;
  }
  throwIfAnyRank(message, s.topology->comm);
}

void CorrespondenceMaterial::elasticStress(const double* E, double* S) const {
  const double trace = E[0] + E[4] + E[8];
  for (int k = 0; k < 9; ++k) S[k] = 2.0 * constants_.shearModulus * E[k];
  for (int k = 0; k < 9; k += 4) S[k] += lame_ * trace;
}

double CorrespondenceMaterial::energyDensity(int, const double* E) const {
  const double trace = E[0] + E[4] + E[8];
  double EE = 0;
  for (int k = 0; k < 9; ++k) EE += E[k] * E[k];
  return 0.5 * lame_ * trace * trace + constants_.shearModulus * EE;
}

void CorrespondenceMaterial::precompute(const ModelState& s, const std::vector<int>& points) {
  using namespace correspondence;
  std::string message;
  for (int i : points) {
    double* Kinv = shapeTensorInverse_ + 9 * i;
    double* F = deformationGradient_ + 9 * i;
    if (!shapeTensorAndDeformationGradient(s, i, Kinv, F)) {
      // Zero force state and outputs, then stop the run on every rank (below).
      if (message.empty()) {
        char when[64];
        std::snprintf(when, sizeof when, " at time %.9g", s.time);
        message = "Materials -> \"" + name_ + "\": the shape tensor of " + describePoint(s, i) +
                  " became singular" + when +
                  " (fewer than three non-coplanar intact bonds); Peridigm stops here too "
                  "(\"failed to compute shape tensor\")";
      }
      for (int k = 0; k < 9; ++k) fRow_[k / 3][3 * i + k % 3] = aRow_[k / 3][3 * i + k % 3] = 0.0;
      continue;
    }
    double E[9], S[9], P[9];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        // Green strain E = (F^T F - I) / 2
        double ftf = F[r] * F[c] + F[3 + r] * F[3 + c] + F[6 + r] * F[6 + c];
        E[3 * r + c] = 0.5 * (ftf - (r == c ? 1.0 : 0.0));
      }
    secondPiolaKirchhoff(i, E, S);
    multiply(F, S, P);  // first Piola-Kirchhoff P = F S
    double A[9];
    multiply(P, Kinv, A);  // A = P K^-1
    for (int k = 0; k < 9; ++k) {
      fRow_[k / 3][3 * i + k % 3] = F[k];
      aRow_[k / 3][3 * i + k % 3] = A[k];
    }
    // Cauchy sigma = P F^T / J; unrotated R^T sigma R = U S U / J (F = R U).
    const double J = determinant(F);
    double* sigma = cauchy_ + 9 * i;
    double* unrotated = unrotated_ + 9 * i;
    if (J > 0) {
      multiplyTransposed(P, F, sigma);
      for (int k = 0; k < 9; ++k) sigma[k] /= J;
      double R[9], tmp[9];
      if (polarRotation(F, R)) {
        // R^T sigma R
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            tmp[3 * r + c] =
                sigma[3 * r] * R[c] + sigma[3 * r + 1] * R[3 + c] + sigma[3 * r + 2] * R[6 + c];
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            unrotated[3 * r + c] = R[r] * tmp[c] + R[3 + r] * tmp[3 + c] + R[6 + r] * tmp[6 + c];
      } else {
        std::copy(sigma, sigma + 9, unrotated);
      }
    } else {
      // An inverted or flattened point: the force (from P) stays defined, the Cauchy stress
      // does not; report the Piola-Kirchhoff stress's symmetric part rather than a NaN.
      for (int k = 0; k < 9; ++k) sigma[k] = unrotated[k] = S[k];
    }
    vonMises_[i] = vonMises(sigma);
  }
  throwIfAnyRank(message, s.topology->comm, true);
}

void CorrespondenceMaterial::computeForce(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double *A0 = aRow_[0], *A1 = aRow_[1], *A2 = aRow_[2];
  const double *F0 = fRow_[0], *F1 = fRow_[1], *F2 = fRow_[2];
  const double hourglassScale =
      18.0 * hourglassCoefficient_ * constants_.bulkModulus / kPi;  // / delta^4 per end
  for (int i : points) {
    const double* xi0 = s.x + 3 * i;
    const double* yi0 = s.y + 3 * i;
    const double Ai[9] = {A0[3 * i],     A0[3 * i + 1], A0[3 * i + 2], A1[3 * i],    A1[3 * i + 1],
                          A1[3 * i + 2], A2[3 * i],     A2[3 * i + 1], A2[3 * i + 2]};
    const double Fi[9] = {F0[3 * i],     F0[3 * i + 1], F0[3 * i + 2], F1[3 * i],    F1[3 * i + 1],
                          F1[3 * i + 2], F2[3 * i],     F2[3 * i + 1], F2[3 * i + 2]};
    const double di = s.horizon[i];
    const double Ci = hourglassScale / (di * di * di * di);
    double f0 = 0, f1 = 0, f2 = 0, h0 = 0, h1 = 0, h2 = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Aj[9] = {A0[3 * j], A0[3 * j + 1], A0[3 * j + 2],
                            A1[3 * j], A1[3 * j + 1], A1[3 * j + 2],
                            A2[3 * j], A2[3 * j + 1], A2[3 * j + 2]};
      const double Fj[9] = {F0[3 * j], F0[3 * j + 1], F0[3 * j + 2],
                            F1[3 * j], F1[3 * j + 1], F1[3 * j + 2],
                            F2[3 * j], F2[3 * j + 1], F2[3 * j + 2]};
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double omega = s.influence ? s.influence[b] : 1.0;
      const double ownI = s.bondSides ? (s.bondSides[b] & 1) : 1.0;
      const double ownJ = s.bondSides ? ((s.bondSides[b] >> 1) & 1) : 1.0;
      const double wI = ownI * omega * intact, wJ = ownJ * omega * intact;
      const double xi[3] = {s.x[3 * j] - xi0[0], s.x[3 * j + 1] - xi0[1], s.x[3 * j + 2] - xi0[2]};
      const double Y[3] = {s.y[3 * j] - yi0[0], s.y[3 * j + 1] - yi0[1], s.y[3 * j + 2] - yi0[2]};
      const double vj = s.volume[j];
      // T_i<xi> - T_j<-xi> = (w_ij A_i + w_ji A_j) xi
      double t[3];
      for (int r = 0; r < 3; ++r)
        t[r] = wI * (Ai[3 * r] * xi[0] + Ai[3 * r + 1] * xi[1] + Ai[3 * r + 2] * xi[2]) +
               wJ * (Aj[3 * r] * xi[0] + Aj[3 * r + 1] * xi[1] + Aj[3 * r + 2] * xi[2]);
      f0 += t[0] * vj;
      f1 += t[1] * vj;
      f2 += t[2] * vj;
      // Hourglass: each end's spring on the part of Y its F does not predict.
      const double YY = Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2];
      if (Ci > 0 && YY > 0) {
        double dotI = 0, dotJ = 0;
        for (int r = 0; r < 3; ++r) {
          const double predictedI =
              Fi[3 * r] * xi[0] + Fi[3 * r + 1] * xi[1] + Fi[3 * r + 2] * xi[2];
          const double predictedJ =
              Fj[3 * r] * xi[0] + Fj[3 * r + 1] * xi[1] + Fj[3 * r + 2] * xi[2];
          dotI += (Y[r] - predictedI) * Y[r];
          dotJ += (Y[r] - predictedJ) * Y[r];
        }
        const double dj = s.horizon[j];
        const double Cj = hourglassScale / (dj * dj * dj * dj);
        const double zeta = s.bondLength[b];
        // Peridigm's scaling: C dot / (|xi| |Y|) times the deformed bond Y itself.
        const double magnitude =
            intact * (ownI * Ci * dotI + ownJ * Cj * dotJ) / (zeta * std::sqrt(YY)) * vj;
        h0 += magnitude * Y[0];
        h1 += magnitude * Y[1];
        h2 += magnitude * Y[2];
      }
    }
    hourglass_[3 * i] = h0;
    hourglass_[3 * i + 1] = h1;
    hourglass_[3 * i + 2] = h2;
    s.forceDensity[3 * i] = f0 + h0;
    s.forceDensity[3 * i + 1] = f1 + h1;
    s.forceDensity[3 * i + 2] = f2 + h2;
  }
  commitHistory(points);
}

void CorrespondenceMaterial::storedEnergyDensity(const ModelState&, const std::vector<int>& points,
                                                 double* out) const {
  for (int i : points) {
    const double* F = deformationGradient_ + 9 * i;
    double E[9];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        E[3 * r + c] =
            0.5 * (F[r] * F[c] + F[3 + r] * F[3 + c] + F[6 + r] * F[6 + c] - (r == c ? 1.0 : 0.0));
    out[i] = energyDensity(i, E);
  }
}

}  // namespace peridot
