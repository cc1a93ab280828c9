#include "materials/HypoelasticCorrespondence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"

namespace peridot {

namespace {

const char* const kSuffix[9] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
const char* const kVelocityGradient = "Velocity_Gradient";
const char* const kUnrotatedRate = "Unrotated_Rate_Of_Deformation";
const char* const kRotation = "Rotation_Tensor";
const char* const kLeftStretch = "Left_Stretch_Tensor";
const char* const kUnrotated = "Unrotated_Cauchy_Stress";
const char* const kCauchy = "Cauchy_Stress";
const char* const kVonMises = "Von_Mises_Stress";
const char* const kDeformationGradient = "Deformation_Gradient";
const char* const kGreenStrain = "Green_Lagrange_Strain";

int instances = 0;

void setIdentity(double* a) {
  for (int k = 0; k < 9; ++k) a[k] = k % 4 == 0 ? 1.0 : 0.0;
}

}  // namespace

HypoelasticCorrespondence::HypoelasticCorrespondence(ListReader& p, const std::string& name)
    : name_(name) {
  density_ = p.positiveNumber("Density");
  constants_ = readTwoElasticConstants(p);
  lame_ = constants_.bulkModulus - 2.0 * constants_.shearModulus / 3.0;
  if (!p.has("Actual Horizon"))
    throw InputError(p.pathOf("Actual Horizon"),
                     "required (a positive number: the horizon of the model's gradient; the "
                     "block's Horizon may be larger, as in Peridigm)");
  actualHorizon_ = p.positiveNumber("Actual Horizon");
  const long long order = p.integer("Gradient Order Of Accuracy", 1);
  if (order < 1 || order > gradient::kMaxOrder)
    throw InputError(p.pathOf("Gradient Order Of Accuracy"),
                     "must be an integer from 1 to " + std::to_string(gradient::kMaxOrder));
  order_ = static_cast<int>(order);
  op_ = gradient::Operator(order_, 3);
  // Peridigm refuses these three for the family.
  for (const char* key : {"Apply Automatic Differentiation Jacobian",
                          "Apply Shear Correction Factor", "Thermal Expansion Coefficient"})
    if (p.has(key))
      throw InputError(p.pathOf(key),
                       "not supported by the hypoelastic correspondence models (Peridigm refuses "
                       "it too)");
  // The family has no hourglass force; decks written for the plain correspondence models may
  // still carry the key.
  p.nonNegativeNumber("Hourglass Coefficient", 0.0);
  acceptCommonMaterialKeys(p);
  ++instances;
  family_ = "hypoelastic correspondence";
  if (instances > 1) family_ += " #" + std::to_string(instances);
}

void HypoelasticCorrespondence::declareFields(FieldManager& fields) {
  jacobian_ = fields.node(kJacobian, 1);
  weightedVolume_ = fields.node(kWeightedVolume, 1);
  for (int r = 0; r < 3; ++r) lRow_[r] = fields.node(kVelocityGradientRows[r], 3);
  velocityGradient_ = fields.node(kVelocityGradient, 9);
  unrotatedRate_ = fields.node(kUnrotatedRate, 9);
  rotation_ = fields.node(kRotation, 9);
  leftStretch_ = fields.node(kLeftStretch, 9);
  unrotated_ = fields.node(kUnrotated, 9);
  cauchy_ = fields.node(kCauchy, 9);
  vonMises_ = fields.node(kVonMises, 1);
  deformationGradient_ = fields.node(kDeformationGradient, 9);
  greenStrain_ = fields.node(kGreenStrain, 9);
  // Peridigm's bond field names; history, so checkpoints keep them.
  for (int k = 0; k < 9; ++k) {
    const double identity = k % 4 == 0 ? 1.0 : 0.0;
    bondV_[k] = &fields.bond(std::string("Left_Stretch_Tensor_") + kSuffix[k], identity);
    bondR_[k] = &fields.bond(std::string("Rotation_Tensor_") + kSuffix[k], identity);
    bondSigmaU_[k] = &fields.bond(std::string("Unrotated_Cauchy_Stress_") + kSuffix[k], 0.0);
  }
  bColumn_.clear();
  bNames_.clear();
  for (int k = 0; k < op_.size(); ++k) {
    bNames_.push_back("Hypoelastic_B_Column_" + std::to_string(k));
    bColumn_.push_back(fields.node(bNames_.back(), 3));
  }
}

std::vector<std::string> HypoelasticCorrespondence::outputFields() const {
  return {kVelocityGradient, kUnrotatedRate, kRotation,      kLeftStretch,
          kUnrotated,        kCauchy,        kVonMises,      kDeformationGradient,
          kGreenStrain,      kJacobian,      kWeightedVolume};
}

std::vector<std::string> HypoelasticCorrespondence::historyNodeFields() const {
  return {kUnrotated, kRotation, kLeftStretch, kDeformationGradient, kJacobian};
}

std::vector<std::string> HypoelasticCorrespondence::fieldsToSyncAfterInitialize() const {
  return {kJacobian};
}

std::vector<std::string> HypoelasticCorrespondence::fieldsToSyncAfterPrecompute() const {
  return {kVelocityGradientRows[0], kVelocityGradientRows[1], kVelocityGradientRows[2],
          kWeightedVolume};
}

void HypoelasticCorrespondence::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, name_);
  if (s.dimension != 3)
    throw InputError("Materials -> \"" + name_ + "\"", "3D discretizations only (as Peridigm)");
  points_.insert(points_.end(), points.begin(), points.end());
  const std::size_t bonds = static_cast<std::size_t>(s.topology->bondOffsets[s.topology->numOwned]);
  const std::size_t n = static_cast<std::size_t>(s.topology->numOverlap);
  g_.resize(3 * bonds);
  bondSigma_.resize(9 * bonds);
  bondVNew_.resize(9 * bonds);
  bondRNew_.resize(9 * bonds);
  bondUnrotatedNew_.resize(9 * bonds);
  Z_.resize(3 * static_cast<std::size_t>(op_.size()) * n);
  jacobianNew_.resize(n, 1.0);
  rotationNew_.resize(9 * n);
  stretchNew_.resize(9 * n);
  gradientNew_.resize(9 * n);
  unrotatedNew_.resize(9 * n);
  std::string message;
  // J = 1 at every point first (ghosts too: the check below reads the neighbours' J V).
  for (int k = 0; k < s.topology->numOverlap; ++k) jacobian_[k] = 1.0;
  for (int i : points) {
    jacobianNew_[i] = 1.0;
    for (double* a : {rotation_, leftStretch_, deformationGradient_}) setIdentity(a + 9 * i);
    for (double* a : {velocityGradient_, unrotatedRate_, unrotated_, cauchy_, greenStrain_})
      std::fill(a + 9 * i, a + 9 * i + 9, 0.0);
    vonMises_[i] = 0.0;
    gradientWeights(s, i, message);
  }
  if (!message.empty())
    message +=
        ": the gradient needs enough neighbours in general position for \"Gradient Order "
        "Of Accuracy\" " +
        std::to_string(order_) +
        " (Peridigm: \"failed to compute gradient weights\"); "
        "is the horizon too small?";
  throwIfAnyRank(message, s.topology->comm);
}

// g_b of point i's bonds on the current configuration (volumes J_j V_j), its weighted volume
// and Z_i; records the first singular point in `message`.
void HypoelasticCorrespondence::gradientWeights(const ModelState& s, int i, std::string& message) {
  const std::int64_t begin = s.topology->bondOffsets[i], end = s.topology->bondOffsets[i + 1];
  const std::size_t count = static_cast<std::size_t>(end - begin);
  // Scratch of the point (kept between points: no allocation once grown).
  thread_local std::vector<double> xi, w, vol;
  xi.resize(3 * count);
  w.resize(count);
  vol.resize(count);
  double m = 0;
  for (std::int64_t b = begin; b < end; ++b) {
    const int j = s.topology->neighbors[b];
    const std::size_t k = static_cast<std::size_t>(b - begin);
    for (int d = 0; d < 3; ++d) xi[3 * k + d] = s.y[3 * j + d] - s.y[3 * i + d];
    const bool apart = xi[3 * k] != 0 || xi[3 * k + 1] != 0 || xi[3 * k + 2] != 0;
    w[k] = apart ? intactFraction(s, b) : 0.0;
    vol[k] = jacobian_[j] * s.volume[j];
    m += w[k] * vol[k];
  }
  weightedVolume_[i] = m;
  const std::size_t q = static_cast<std::size_t>(op_.size());
  double* Z = Z_.data() + 3 * q * static_cast<std::size_t>(i);
  if (!op_.weights(count, xi.data(), w.data(), vol.data(), actualHorizon_, g_.data() + 3 * begin)) {
    std::fill(Z, Z + 3 * q, 0.0);
    if (message.empty()) {
      char when[64];
      std::snprintf(when, sizeof when, " at time %.9g", s.time);
      message = "Materials -> \"" + name_ + "\": the moment matrix of " +
                correspondence::describePoint(s, i) + " is singular" + when;
    }
    return;
  }
  std::copy(op_.rows(), op_.rows() + 3 * q, Z);
}

void HypoelasticCorrespondence::precompute(const ModelState& s, const std::vector<int>& points) {
  using namespace correspondence;
  // The neighbours' J at the start of the step: committed by the last evaluation, or restored
  // from a checkpoint (first call of this evaluation only; collective, as every rank calls).
  if (!pending_) s.fields->refreshGhosts(kJacobian);
  pending_ = true;
  std::string message;
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    gradientWeights(s, i, message);
    double L[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double vj = jacobian_[j] * s.volume[j];
      const double* g = g_.data() + 3 * b;
      for (int r = 0; r < 3; ++r) {
        const double dv = (s.velocity[3 * j + r] - s.velocity[3 * i + r]) * vj;
        for (int c = 0; c < 3; ++c) L[3 * r + c] += dv * g[c];
      }
    }
    std::copy(L, L + 9, velocityGradient_ + 9 * i);
    for (int k = 0; k < 9; ++k) lRow_[k / 3][3 * i + k % 3] = L[k];
    jacobianNew_[i] = jacobian_[i] * (1.0 + (L[0] + L[4] + L[8]) * s.dt);
    if (!(jacobianNew_[i] > 0) && message.empty()) {
      char what[96];
      std::snprintf(what, sizeof what, " has J = %.6g at time %.9g", jacobianNew_[i], s.time);
      message = "Materials -> \"" + name_ + "\": " + describePoint(s, i) + what +
                ": the material is inverted";
    }
    // Point-level kinematics, for output (as Peridigm): V, R, d, and F += L F dt.
    flanaganTaylorStep(L, leftStretch_ + 9 * i, rotation_ + 9 * i, s.dt, stretchNew_.data() + 9 * i,
                       rotationNew_.data() + 9 * i, unrotatedRate_ + 9 * i);
    double LF[9];
    multiply(L, deformationGradient_ + 9 * i, LF);
    for (int k = 0; k < 9; ++k)
      gradientNew_[9 * i + k] = deformationGradient_[9 * i + k] + LF[k] * s.dt;
  }
  pointStresses(s, points);
  for (int i : points) {
    const double* R = rotationNew_.data() + 9 * i;
    double tmp[9];
    multiply(R, unrotatedNew_.data() + 9 * i, tmp);
    multiplyTransposed(tmp, R, cauchy_ + 9 * i);
    vonMises_[i] = vonMises(cauchy_ + 9 * i);
    const double* F = gradientNew_.data() + 9 * i;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        greenStrain_[9 * i + 3 * r + c] =
            0.5 * (F[r] * F[c] + F[3 + r] * F[3 + c] + F[6 + r] * F[6 + c] - (r == c ? 1.0 : 0.0));
  }
  throwIfAnyRank(message, s.topology->comm, true);
}

void HypoelasticCorrespondence::computeForce(const ModelState& s, const std::vector<int>&) {
  // Once per evaluation, for every point of the model: B must be ghosted between the bond
  // stresses and the force, and a neighbour in another block of this model needs its B too.
  if (!pending_) return;
  pending_ = false;
  bondStresses(s);
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const std::size_t q = static_cast<std::size_t>(op_.size());
  nonhomogeneity_.resize(9 * static_cast<std::size_t>(s.topology->numOverlap));
  for (int i : points_) {
    double N[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    const double halfInverseMi = 0.5 / weightedVolume_[i];
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y[3] = {s.y[3 * j] - s.y[3 * i], s.y[3 * j + 1] - s.y[3 * i + 1],
                           s.y[3 * j + 2] - s.y[3 * i + 2]};
      const double YY = Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2];
      const double w = intactFraction(s, b);
      if (!(YY > 0) || w == 0.0) continue;
      const double scale =
          w * (halfInverseMi + 0.5 / weightedVolume_[j]) * jacobian_[j] * s.volume[j];
      const double* sigma = bondSigma_.data() + 9 * b;
      // sigma (I - Y Y^T / |Y|^2) = sigma - (sigma Y) Y^T / |Y|^2
      for (int r = 0; r < 3; ++r) {
        const double sY =
            (sigma[3 * r] * Y[0] + sigma[3 * r + 1] * Y[1] + sigma[3 * r + 2] * Y[2]) / YY;
        for (int c = 0; c < 3; ++c) N[3 * r + c] += scale * (sigma[3 * r + c] - sY * Y[c]);
      }
    }
    std::copy(N, N + 9, nonhomogeneity_.begin() + 9 * i);
    const double* Z = Z_.data() + 3 * q * static_cast<std::size_t>(i);
    for (std::size_t k = 0; k < q; ++k)
      for (int r = 0; r < 3; ++r)
        bColumn_[k][3 * i + r] =
            N[3 * r] * Z[k] + N[3 * r + 1] * Z[q + k] + N[3 * r + 2] * Z[2 * q + k];
  }
  for (const auto& name : bNames_) s.fields->refreshGhosts(name);
  forceLoop(s);
  if (s.commitHistory) {
    const std::size_t bonds = static_cast<std::size_t>(offsets[s.topology->numOwned]);
    for (int k = 0; k < 9; ++k) {
      std::vector<double>& V = *bondV_[k];
      std::vector<double>& R = *bondR_[k];
      std::vector<double>& S = *bondSigmaU_[k];
      for (std::size_t b = 0; b < bonds; ++b) {
        V[b] = bondVNew_[9 * b + k];
        R[b] = bondRNew_[9 * b + k];
        S[b] = bondUnrotatedNew_[9 * b + k];
      }
    }
    for (int i : points_) {
      jacobian_[i] = jacobianNew_[i];
      std::copy_n(unrotatedNew_.begin() + 9 * i, 9, unrotated_ + 9 * i);
      std::copy_n(rotationNew_.begin() + 9 * i, 9, rotation_ + 9 * i);
      std::copy_n(stretchNew_.begin() + 9 * i, 9, leftStretch_ + 9 * i);
      std::copy_n(gradientNew_.begin() + 9 * i, 9, deformationGradient_ + 9 * i);
    }
    commitLaw(s, points_);
  }
}

// f_i = J_i sum_j (T_ij - T_ji) J_j V_j with T_ij - T_ji = w (1/m_i + 1/m_j) sigma_ij Y / |Y|^2
// + N_i g_ij - B_j Q(-Y / delta) w / delta.
void HypoelasticCorrespondence::forceLoop(const ModelState& s) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const int q = op_.size();
  double Q[64];
  for (int i : points_) {
    const double* N = nonhomogeneity_.data() + 9 * i;
    const double inverseMi = 1.0 / weightedVolume_[i];
    double f[3] = {0, 0, 0};
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y[3] = {s.y[3 * j] - s.y[3 * i], s.y[3 * j + 1] - s.y[3 * i + 1],
                           s.y[3 * j + 2] - s.y[3 * i + 2]};
      const double YY = Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2];
      const double w = intactFraction(s, b);
      if (!(YY > 0) || w == 0.0) continue;
      const double* sigma = bondSigma_.data() + 9 * b;
      const double* g = g_.data() + 3 * b;
      const double pair = w * (inverseMi + 1.0 / weightedVolume_[j]) / YY;
      const double minusY[3] = {-Y[0], -Y[1], -Y[2]};
      op_.monomials(minusY, actualHorizon_, Q);
      const double reverse = w / actualHorizon_;
      const double vj = jacobian_[j] * s.volume[j];
      for (int r = 0; r < 3; ++r) {
        double t =
            pair * (sigma[3 * r] * Y[0] + sigma[3 * r + 1] * Y[1] + sigma[3 * r + 2] * Y[2]) +
            N[3 * r] * g[0] + N[3 * r + 1] * g[1] + N[3 * r + 2] * g[2];
        double bq = 0;
        for (int k = 0; k < q; ++k) bq += bColumn_[k][3 * j + r] * Q[k];
        t -= reverse * bq;
        f[r] += t * vj;
      }
    }
    for (int r = 0; r < 3; ++r) s.forceDensity[3 * i + r] = jacobian_[i] * f[r];
  }
}

void HypoelasticCorrespondence::storedEnergyDensity(const ModelState&,
                                                    const std::vector<int>& points,
                                                    double* out) const {
  for (int i : points)
    out[i] = correspondence::complementaryEnergyDensity(
        constants_.bulkModulus, constants_.shearModulus, unrotated_ + 9 * i);
}

}  // namespace peridot
