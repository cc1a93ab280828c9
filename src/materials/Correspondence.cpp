#include "materials/Correspondence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "materials/CorrespondenceRate.hpp"

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
  // |det| of a multiple of the identity, (norm2 / 3)^1.5 (without pow: this runs once per bond
  // in the bond-associated models; the value only gates the singularity test).
  const double mean2 = norm2 / 3.0;
  const double scale = mean2 * std::sqrt(mean2);
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

namespace {

// K (symmetric: 6 sums) and N over point i's bonds, and with kVelocity the velocity sums
// M = sum_j w (v_j - v_i) (x) xi V_j of the rate form, in one vectorisable pass; the options are
// compile-time so that the loop has no branch.
template <bool kDamage, bool kSides, bool kInfluence, bool kVelocity>
void shapeSums(const ModelState& s, int i, double* K, double* N, double* M) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* x = s.x;
  const double* y = s.y;
  const double* v = s.velocity;
  const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
  const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
  double vi0 = 0, vi1 = 0, vi2 = 0;
  if constexpr (kVelocity) vi0 = v[3 * i], vi1 = v[3 * i + 1], vi2 = v[3 * i + 2];
  double k00 = 0, k01 = 0, k02 = 0, k11 = 0, k12 = 0, k22 = 0;
  double n00 = 0, n01 = 0, n02 = 0, n10 = 0, n11 = 0, n12 = 0, n20 = 0, n21 = 0, n22 = 0;
  double m00 = 0, m01 = 0, m02 = 0, m10 = 0, m11 = 0, m12 = 0, m20 = 0, m21 = 0, m22 = 0;
#pragma omp simd reduction(+ : k00, k01, k02, k11, k12, k22, n00, n01, n02, n10, n11, n12, n20, \
                               n21, n22, m00, m01, m02, m10, m11, m12, m20, m21, m22)
  for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
    const int j = neighbors[b];
    double w = s.volume[j];
    if constexpr (kInfluence) w *= s.influence[b];
    if constexpr (kDamage) w *= 1.0 - s.bondDamage[b];
    if constexpr (kSides) w *= (s.bondSides[b] & 1);
    const double e0 = x[3 * j] - xi0, e1 = x[3 * j + 1] - xi1, e2 = x[3 * j + 2] - xi2;
    const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
    const double w0 = w * e0, w1 = w * e1, w2 = w * e2;
    k00 += w0 * e0;
    k01 += w0 * e1;
    k02 += w0 * e2;
    k11 += w1 * e1;
    k12 += w1 * e2;
    k22 += w2 * e2;
    n00 += Y0 * w0;
    n01 += Y0 * w1;
    n02 += Y0 * w2;
    n10 += Y1 * w0;
    n11 += Y1 * w1;
    n12 += Y1 * w2;
    n20 += Y2 * w0;
    n21 += Y2 * w1;
    n22 += Y2 * w2;
    if constexpr (kVelocity) {
      const double V0 = v[3 * j] - vi0, V1 = v[3 * j + 1] - vi1, V2 = v[3 * j + 2] - vi2;
      m00 += V0 * w0;
      m01 += V0 * w1;
      m02 += V0 * w2;
      m10 += V1 * w0;
      m11 += V1 * w1;
      m12 += V1 * w2;
      m20 += V2 * w0;
      m21 += V2 * w1;
      m22 += V2 * w2;
    }
  }
  const double k[9] = {k00, k01, k02, k01, k11, k12, k02, k12, k22};
  const double n[9] = {n00, n01, n02, n10, n11, n12, n20, n21, n22};
  std::copy(k, k + 9, K);
  std::copy(n, n + 9, N);
  if constexpr (kVelocity) {
    const double m[9] = {m00, m01, m02, m10, m11, m12, m20, m21, m22};
    std::copy(m, m + 9, M);
  }
}

template <bool kDamage, bool kSides, bool kVelocity>
void shapeSums(const ModelState& s, int i, double* K, double* N, double* M) {
  if (s.influence)
    shapeSums<kDamage, kSides, true, kVelocity>(s, i, K, N, M);
  else
    shapeSums<kDamage, kSides, false, kVelocity>(s, i, K, N, M);
}

template <bool kVelocity>
void shapeSums(const ModelState& s, int i, double* K, double* N, double* M, bool damage) {
  if (damage)
    s.bondSides ? shapeSums<true, true, kVelocity>(s, i, K, N, M)
                : shapeSums<true, false, kVelocity>(s, i, K, N, M);
  else
    s.bondSides ? shapeSums<false, true, kVelocity>(s, i, K, N, M)
                : shapeSums<false, false, kVelocity>(s, i, K, N, M);
}

}  // namespace

bool shapeTensorAndDeformationGradient(const ModelState& s, int i, double* Kinv, double* F,
                                       bool useDamage, double* velocitySums) {
  double K[9], N[9];
  const bool damage = useDamage && s.bondDamage;
  if (velocitySums)
    shapeSums<true>(s, i, K, N, velocitySums, damage);
  else
    shapeSums<false>(s, i, K, N, nullptr, damage);
  if (s.dimension == 2) {
    // A planar run's bonds all lie in z = 0: K's z row and column are zero. A unit zz entry
    // in K and N leaves the in-plane blocks as they are and gives the plane F_zz = 1.
    K[8] = 1.0;
    N[8] = 1.0;
  }
  if (!invert(K, Kinv)) {
    std::fill(F, F + 9, 0.0);
    return false;
  }
  multiply(N, Kinv, F);
  return true;
}

bool detached(const ModelState& s, int i) {
  if (!s.bondDamage) return false;
  for (std::int64_t b = s.topology->bondOffsets[i]; b < s.topology->bondOffsets[i + 1]; ++b)
    if (s.topology->ownSide(b) && s.bondDamage[b] < 1.0f) return false;
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
  std::snprintf(text, sizeof text, "point %lld at (%.6g, %.6g, %.6g) (%d intact bonds of %d)",
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
  integration_ =
      p.choice("Stress Integration", {"Hypoelastic Rate", "Total Lagrangian Green Strain"},
               "Hypoelastic Rate") == "Hypoelastic Rate"
          ? StressIntegration::HypoelasticRate
          : StressIntegration::GreenStrain;
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
  rotation_ = fields.node(kRotationTensor, 9);
  leftStretch_ = fields.node(kLeftStretchTensor, 9);
  velocityGradient_ = fields.node(kVelocityGradient, 9);
  unrotatedRate_ = fields.node(kUnrotatedRateOfDeformation, 9);
  for (int r = 0; r < 3; ++r) {
    fRow_[r] = fields.node(kDeformationGradientRows[r], 3);
    aRow_[r] = fields.node(kForceTensorRows[r], 3);
  }
}

std::vector<std::string> CorrespondenceMaterial::outputFields() const {
  return {kShapeTensorInverse, kDeformationGradient,       kCauchyStress,   kUnrotatedCauchyStress,
          kVonMisesStress,     kHourglassForceDensity,     kRotationTensor, kLeftStretchTensor,
          kVelocityGradient,   kUnrotatedRateOfDeformation};
}

std::vector<std::string> CorrespondenceMaterial::historyNodeFields() const {
  if (!rateForm()) return {};
  return {kUnrotatedCauchyStress, kRotationTensor, kLeftStretchTensor};
}

void CorrespondenceMaterial::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, name_);
  // C = 18 c_hg K / (pi delta^4) of every overlap point (the horizon is known on all of them).
  hourglassConstant_.resize(static_cast<std::size_t>(s.topology->numOverlap));
  if (rateForm()) {
    const std::size_t n = 9 * static_cast<std::size_t>(s.topology->numOverlap);
    unrotatedNew_.resize(n, 0.0);
    rotationNew_.resize(n, 0.0);
    leftStretchNew_.resize(n, 0.0);
  }
  for (int p = 0; p < s.topology->numOverlap; ++p) {
    const double d = s.horizon[p];
    hourglassConstant_[p] =
        18.0 * hourglassCoefficient_ * constants_.bulkModulus / (kPi * d * d * d * d);
  }
  std::string message;
  for (int i : points) {
    double F[9];
    if (!correspondence::shapeTensorAndDeformationGradient(s, i, shapeTensorInverse_ + 9 * i, F) &&
        message.empty()) {
      message =
          "Materials -> \"" + name_ + "\": the shape tensor of " +
          correspondence::describePoint(s, i) +
          " is singular: a correspondence model needs at least three non-coplanar neighbours per "
          "point (as Peridigm, which stops with \"failed to compute shape tensor\"); is "
          "the horizon too small?";
    }
    for (int k = 0; k < 9; ++k) {
      deformationGradient_[9 * i + k] = rotation_[9 * i + k] = leftStretch_[9 * i + k] =
          (k % 4 == 0) ? 1.0 : 0.0;
      cauchy_[9 * i + k] = unrotated_[9 * i + k] = 0.0;
      velocityGradient_[9 * i + k] = unrotatedRate_[9 * i + k] = 0.0;
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

void CorrespondenceMaterial::unrotatedCauchyStress(int, const double* d, double dt,
                                                   const double* sigmaN, double* sigma) {
  correspondence::hypoelasticIncrement(lame_, constants_.shearModulus, d, dt, sigmaN, sigma);
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
    double M[9];  // the rate form's velocity sums, from the same pass
    if (!shapeTensorAndDeformationGradient(s, i, Kinv, F, true, rateForm() ? M : nullptr)) {
      // Zero force state and outputs, then stop the run on every rank (below) — unless damage
      // broke every bond of the point: a point cut loose carries no stress and is no error.
      if (detached(s, i)) {
        holdHistory(i);
        for (int k = 0; k < 9; ++k) {
          fRow_[k / 3][3 * i + k % 3] = aRow_[k / 3][3 * i + k % 3] = 0.0;
          cauchy_[9 * i + k] = 0.0;
        }
        vonMises_[i] = 0.0;
        continue;
      }
      if (message.empty()) {
        char when[64];
        std::snprintf(when, sizeof when, " at time %.9g", s.time);
        message = "Materials -> \"" + name_ + "\": the shape tensor of " + describePoint(s, i) +
                  " became singular" + when +
                  ": its intact bonds no longer span three non-coplanar directions; Peridigm stops "
                  "here too "
                  "(\"failed to compute shape tensor\")";
      }
      for (int k = 0; k < 9; ++k) fRow_[k / 3][3 * i + k % 3] = aRow_[k / 3][3 * i + k % 3] = 0.0;
      continue;
    }
    double P[9];
    if (rateForm()) {
      if (!rateStress(s, i, F, Kinv, M, P) && message.empty()) {
        char what[160];
        std::snprintf(what, sizeof what,
                      " has an inverted or singular deformation gradient "
                      "(det F = %.6g) at time %.9g",
                      determinant(F), s.time);
        message = "Materials -> \"" + name_ + "\": " + describePoint(s, i) + what +
                  ": the rate form needs F^-1 (Peridigm stops here too, \"failed to invert "
                  "deformation gradient\")";
      }
    } else {
      greenStress(i, F, P);
    }
    double A[9];
    multiply(P, Kinv, A);  // A = P K^-1
    for (int k = 0; k < 9; ++k) {
      fRow_[k / 3][3 * i + k % 3] = F[k];
      aRow_[k / 3][3 * i + k % 3] = A[k];
    }
    vonMises_[i] = vonMises(cauchy_ + 9 * i);
  }
  throwIfAnyRank(message, s.topology->comm, true);
}

void CorrespondenceMaterial::holdHistory(int i) {
  if (!rateForm()) return;
  std::copy(unrotated_ + 9 * i, unrotated_ + 9 * i + 9, unrotatedNew_.begin() + 9 * i);
  std::copy(rotation_ + 9 * i, rotation_ + 9 * i + 9, rotationNew_.begin() + 9 * i);
  std::copy(leftStretch_ + 9 * i, leftStretch_ + 9 * i + 9, leftStretchNew_.begin() + 9 * i);
}

bool CorrespondenceMaterial::rateStress(const ModelState& s, int i, const double* F,
                                        const double* Kinv, const double* M, double* P) {
  using namespace correspondence;
  double* L = velocityGradient_ + 9 * i;
  double* d = unrotatedRate_ + 9 * i;
  double* sigmaNew = unrotatedNew_.data() + 9 * i;
  double* Rnew = rotationNew_.data() + 9 * i;
  double* Vnew = leftStretchNew_.data() + 9 * i;
  double Finv[9];
  const double J = determinant(F);
  if (!(J > 0) || !invert(F, Finv)) {
    // Keep the history as it was; the run stops (the caller's collective error).
    std::fill(P, P + 9, 0.0);
    std::fill(L, L + 9, 0.0);
    std::fill(d, d + 9, 0.0);
    std::copy(unrotated_ + 9 * i, unrotated_ + 9 * i + 9, sigmaNew);
    std::copy(rotation_ + 9 * i, rotation_ + 9 * i + 9, Rnew);
    std::copy(leftStretch_ + 9 * i, leftStretch_ + 9 * i + 9, Vnew);
    return false;
  }
  velocityGradient(M, Kinv, Finv, L);
  flanaganTaylorStep(L, leftStretch_ + 9 * i, rotation_ + 9 * i, s.dt, Vnew, Rnew, d);
  unrotatedCauchyStress(i, d, s.dt, unrotated_ + 9 * i, sigmaNew);
  // sigma = R sigma_u R^T, P = J sigma F^-T
  double tmp[9];
  double* sigma = cauchy_ + 9 * i;
  multiply(Rnew, sigmaNew, tmp);
  multiplyTransposed(tmp, Rnew, sigma);
  multiplyTransposed(sigma, Finv, P);
  for (int k = 0; k < 9; ++k) P[k] *= J;
  return true;
}

void CorrespondenceMaterial::greenStress(int i, const double* F, double* P) {
  using namespace correspondence;
  double E[9], S[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      // Green strain E = (F^T F - I) / 2
      double ftf = F[r] * F[c] + F[3 + r] * F[3 + c] + F[6 + r] * F[6 + c];
      E[3 * r + c] = 0.5 * (ftf - (r == c ? 1.0 : 0.0));
    }
  secondPiolaKirchhoff(i, E, S);
  multiply(F, S, P);  // first Piola-Kirchhoff P = F S
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
      std::copy(R, R + 9, rotation_ + 9 * i);
      multiplyTransposed(F, R, leftStretch_ + 9 * i);  // V = F R^T
    } else {
      std::copy(sigma, sigma + 9, unrotated);
    }
  } else {
    // An inverted or flattened point: the force (from P) stays defined, the Cauchy stress
    // and the polar decomposition do not; report S for sigma rather than a NaN, and keep the
    // last rotation and stretch.
    for (int k = 0; k < 9; ++k) sigma[k] = unrotated[k] = S[k];
  }
}

void CorrespondenceMaterial::computeForce(const ModelState& s, const std::vector<int>& points) {
  const bool damage = s.bondDamage != nullptr, sides = s.bondSides != nullptr;
  if (s.influence) {
    if (damage)
      sides ? forceLoop<true, true, true>(s, points) : forceLoop<true, false, true>(s, points);
    else
      sides ? forceLoop<false, true, true>(s, points) : forceLoop<false, false, true>(s, points);
  } else {
    if (damage)
      sides ? forceLoop<true, true, false>(s, points) : forceLoop<true, false, false>(s, points);
    else
      sides ? forceLoop<false, true, false>(s, points) : forceLoop<false, false, false>(s, points);
  }
  // A trial keeps the history of the step's start (precompute wrote only the scratch copies).
  if (!s.commitHistory) return;
  if (rateForm()) {
    for (int i : points) {
      std::copy(unrotatedNew_.begin() + 9 * i, unrotatedNew_.begin() + 9 * i + 9,
                unrotated_ + 9 * i);
      std::copy(rotationNew_.begin() + 9 * i, rotationNew_.begin() + 9 * i + 9, rotation_ + 9 * i);
      std::copy(leftStretchNew_.begin() + 9 * i, leftStretchNew_.begin() + 9 * i + 9,
                leftStretch_ + 9 * i);
    }
  }
  commitHistory(points);
}

// f_i = sum_j [(w_ij A_i + w_ji A_j) xi + (1 - d)(C_i (Y - F_i xi).Y + C_j (Y - F_j xi).Y)
// / (|xi| |Y|) Y] V_j, with (Y - F xi).Y = |Y|^2 - Y.(F xi); one vectorisable pass.
template <bool kDamage, bool kSides, bool kInfluence>
void CorrespondenceMaterial::forceLoop(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double *A0 = aRow_[0], *A1 = aRow_[1], *A2 = aRow_[2];
  const double *F0 = fRow_[0], *F1 = fRow_[1], *F2 = fRow_[2];
  const double* C = hourglassConstant_.data();
  const double* x = s.x;
  const double* y = s.y;
  for (int i : points) {
    const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    const double a00 = A0[3 * i], a01 = A0[3 * i + 1], a02 = A0[3 * i + 2];
    const double a10 = A1[3 * i], a11 = A1[3 * i + 1], a12 = A1[3 * i + 2];
    const double a20 = A2[3 * i], a21 = A2[3 * i + 1], a22 = A2[3 * i + 2];
    const double g00 = F0[3 * i], g01 = F0[3 * i + 1], g02 = F0[3 * i + 2];
    const double g10 = F1[3 * i], g11 = F1[3 * i + 1], g12 = F1[3 * i + 2];
    const double g20 = F2[3 * i], g21 = F2[3 * i + 1], g22 = F2[3 * i + 2];
    const double Ci = C[i];
    double f0 = 0, f1 = 0, f2 = 0, h0 = 0, h1 = 0, h2 = 0;
#pragma omp simd reduction(+ : f0, f1, f2, h0, h1, h2)
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double intact = kDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double omega = kInfluence ? s.influence[b] : 1.0;
      const double ownI = kSides ? (s.bondSides[b] & 1) : 1.0;
      const double ownJ = kSides ? ((s.bondSides[b] >> 1) & 1) : 1.0;
      const double wI = ownI * omega * intact, wJ = ownJ * omega * intact;
      const double e0 = x[3 * j] - xi0, e1 = x[3 * j + 1] - xi1, e2 = x[3 * j + 2] - xi2;
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      const double vj = s.volume[j];
      // T_i<xi> - T_j<-xi> = (w_ij A_i + w_ji A_j) xi
      const double t0 = wI * (a00 * e0 + a01 * e1 + a02 * e2) +
                        wJ * (A0[3 * j] * e0 + A0[3 * j + 1] * e1 + A0[3 * j + 2] * e2);
      const double t1 = wI * (a10 * e0 + a11 * e1 + a12 * e2) +
                        wJ * (A1[3 * j] * e0 + A1[3 * j + 1] * e1 + A1[3 * j + 2] * e2);
      const double t2 = wI * (a20 * e0 + a21 * e1 + a22 * e2) +
                        wJ * (A2[3 * j] * e0 + A2[3 * j + 1] * e1 + A2[3 * j + 2] * e2);
      f0 += t0 * vj;
      f1 += t1 * vj;
      f2 += t2 * vj;
      // Hourglass: each end's spring on the part of Y its F does not predict.
      const double YY = Y0 * Y0 + Y1 * Y1 + Y2 * Y2;
      const double YFiXi = Y0 * (g00 * e0 + g01 * e1 + g02 * e2) +
                           Y1 * (g10 * e0 + g11 * e1 + g12 * e2) +
                           Y2 * (g20 * e0 + g21 * e1 + g22 * e2);
      const double YFjXi = Y0 * (F0[3 * j] * e0 + F0[3 * j + 1] * e1 + F0[3 * j + 2] * e2) +
                           Y1 * (F1[3 * j] * e0 + F1[3 * j + 1] * e1 + F1[3 * j + 2] * e2) +
                           Y2 * (F2[3 * j] * e0 + F2[3 * j + 1] * e1 + F2[3 * j + 2] * e2);
      const double cI = ownI * Ci, cJ = ownJ * C[j];
      // Peridigm's scaling: C dot / (|xi| |Y|) times the deformed bond Y itself; coincident
      // ends (Y = 0) carry none.
      const double scale = YY > 0 ? intact * vj / (s.bondLength[b] * std::sqrt(YY)) : 0.0;
      const double magnitude = (cI * (YY - YFiXi) + cJ * (YY - YFjXi)) * scale;
      h0 += magnitude * Y0;
      h1 += magnitude * Y1;
      h2 += magnitude * Y2;
    }
    hourglass_[3 * i] = h0;
    hourglass_[3 * i + 1] = h1;
    hourglass_[3 * i + 2] = h2;
    s.forceDensity[3 * i] = f0 + h0;
    s.forceDensity[3 * i + 1] = f1 + h1;
    s.forceDensity[3 * i + 2] = f2 + h2;
  }
}

void CorrespondenceMaterial::storedEnergyDensity(const ModelState&, const std::vector<int>& points,
                                                 double* out) const {
  for (int i : points) {
    if (rateForm()) {
      out[i] = correspondence::complementaryEnergyDensity(
          constants_.bulkModulus, constants_.shearModulus, unrotated_ + 9 * i);
      continue;
    }
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
