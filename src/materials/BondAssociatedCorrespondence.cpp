#include "materials/BondAssociatedCorrespondence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "materials/BondAssociatedKinematics.hpp"
#include "materials/Correspondence.hpp"
#include "materials/CorrespondenceRate.hpp"

namespace peridot {

namespace {

const double kIdentity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

// Mean stress over von Mises stress (0 for a stress without deviator).
double triaxialityOf(const double* sigma) {
  const double q = correspondence::vonMises(sigma);
  return q > 0 ? (sigma[0] + sigma[4] + sigma[8]) / (3.0 * q) : 0.0;
}

}  // namespace

BondAssociatedCorrespondence::BondAssociatedCorrespondence(ListReader& p, const std::string& name)
    : name_(name) {
  density_ = p.positiveNumber("Density");
  constants_ = readTwoElasticConstants(p);
  lame_ = constants_.bulkModulus - 2.0 * constants_.shearModulus / 3.0;
  const long long order = p.integer("Gradient Order Of Accuracy", 1);
  if (order < 1) throw InputError(p.pathOf("Gradient Order Of Accuracy"), "must be at least 1");
  if (order > gradient::kMaxOrder) {
    throw InputError(p.pathOf("Gradient Order Of Accuracy"),
                     "gradient order " + std::to_string(order) +
                         ": Peridot's gradient weights go up to order " +
                         std::to_string(gradient::kMaxOrder) +
                         " (Peridigm sets no limit); orders above are not supported");
  }
  order_ = static_cast<int>(order);
  if (order_ > 1) {
    op_ = gradient::Operator(order_, 3);
    // Monomials degree by degree (materials/GradientOperator.hpp): (d + 1)(d + 2) / 2 of degree d.
    for (int degree = 1; degree <= order_; ++degree)
      parity_.insert(parity_.end(), static_cast<std::size_t>((degree + 1) * (degree + 2) / 2),
                     degree % 2 ? -1.0 : 1.0);
  }
  // As Peridigm: no hourglass control (the point of the model); the key is read and ignored.
  if (p.has("Hourglass Coefficient")) p.nonNegativeNumber("Hourglass Coefficient", 0.0);
  if (p.has("Apply Automatic Differentiation Jacobian")) {
    throw InputError(p.pathOf("Apply Automatic Differentiation Jacobian"),
                     "not available for the bond-associated correspondence models (as in "
                     "Peridigm); they run with explicit dynamics only");
  }
  if (p.has("Apply Shear Correction Factor")) {
    throw InputError(p.pathOf("Apply Shear Correction Factor"),
                     "not available for the bond-associated correspondence models (as in "
                     "Peridigm)");
  }
  acceptCommonMaterialKeys(p);
}

void BondAssociatedCorrespondence::setPlasticity(const correspondence::Hardening& hardening) {
  plastic_ = true;
  hardening_ = hardening;
}

void BondAssociatedCorrespondence::declareFields(FieldManager& fields) {
  shapeTensorInverse_ = fields.node(kShapeTensorInverse, 9);
  deformationGradient_ = fields.node(kDeformationGradient, 9);
  cauchy_ = fields.node(kCauchyStress, 9);
  unrotated_ = fields.node(kUnrotatedCauchyStress, 9);
  vonMises_ = fields.node(kVonMisesStress, 1);
  rotation_ = fields.node(kRotationTensor, 9);
  leftStretch_ = fields.node(kLeftStretchTensor, 9);
  velocityGradient_ = fields.node(kVelocityGradient, 9);
  unrotatedRate_ = fields.node(kUnrotatedRateOfDeformation, 9);
  weightedVolume_ = fields.node(kWeightedVolume, 1);
  inverseWeightedVolume_ = fields.node(kInverseWeightedVolume, 1);
  for (int r = 0; r < 3; ++r) {
    fRow_[r] = fields.node(kDeformationGradientRows[r], 3);
    fdotRow_[r] = fields.node(kDeformationRateRows[r], 3);
    if (order_ == 1) bRow_[r] = fields.node(kStressIntegralRows[r], 3);
  }
  bColumn_.clear();
  bColumnNames_.clear();
  if (order_ > 1)
    for (int k = 0; k < op_.size(); ++k) {
      bColumnNames_.push_back(kStressIntegralColumnPrefix + std::to_string(k));
      bColumn_.push_back(fields.node(bColumnNames_.back(), 3));
    }
  for (int k = 0; k < 9; ++k) {
    bondSigma_[k] = fields.bond(kBondUnrotatedCauchyStress[k], 0.0).data();
    bondRotation_[k] = fields.bond(kBondRotationTensor[k], k % 4 == 0 ? 1.0 : 0.0).data();
    bondStretch_[k] = fields.bond(kBondLeftStretchTensor[k], k % 4 == 0 ? 1.0 : 0.0).data();
  }
  bondEqps_ = fields.bond(kBondEquivalentPlasticStrain, 0.0).data();
  if (plastic_) {
    eqps_ = fields.node(kEquivalentPlasticStrain, 1);
    triaxiality_ = fields.node(kStressTriaxiality, 1);
    bondVonMises_ = fields.bond(kBondVonMisesStress, 0.0).data();
    bondTriaxiality_ = fields.bond(kBondStressTriaxiality, 0.0).data();
  }
}

std::vector<std::string> BondAssociatedCorrespondence::fieldsToSyncAfterPrecompute() const {
  if (order_ > 1) return bColumnNames_;
  return {kStressIntegralRows[0], kStressIntegralRows[1], kStressIntegralRows[2]};
}

std::string BondAssociatedCorrespondence::family() const {
  if (order_ == 1) return "bond-associated correspondence";
  return "bond-associated correspondence (gradient order " + std::to_string(order_) + ")";
}

std::vector<std::string> BondAssociatedCorrespondence::outputFields() const {
  std::vector<std::string> names = {
      kShapeTensorInverse,    kDeformationGradient, kCauchyStress,
      kUnrotatedCauchyStress, kVonMisesStress,      kRotationTensor,
      kLeftStretchTensor,     kVelocityGradient,    kUnrotatedRateOfDeformation,
      kWeightedVolume};
  if (plastic_) {
    names.push_back(kEquivalentPlasticStrain);
    names.push_back(kStressTriaxiality);
  }
  return names;
}

std::vector<std::string> BondAssociatedCorrespondence::historyNodeFields() const {
  std::vector<std::string> names = {kUnrotatedCauchyStress, kRotationTensor, kLeftStretchTensor};
  if (plastic_) names.push_back(kEquivalentPlasticStrain);
  return names;
}

void BondAssociatedCorrespondence::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, name_);
  const std::size_t n = static_cast<std::size_t>(s.topology->numOverlap);
  const std::size_t bonds = static_cast<std::size_t>(s.topology->bondOffsets[s.topology->numOwned]);
  unrotatedNew_.resize(9 * n, 0.0);
  rotationNew_.resize(9 * n, 0.0);
  stretchNew_.resize(9 * n, 0.0);
  eqpsNew_.resize(n, 0.0);
  for (int k = 0; k < 9; ++k) {
    bondSigmaNew_[k].resize(bonds, 0.0);
    bondRotationNew_[k].resize(bonds, 0.0);
    bondStretchNew_[k].resize(bonds, 0.0);
  }
  bondEqpsNew_.resize(bonds, 0.0);
  bondTraction_.resize(3 * bonds, 0.0);
  if (order_ > 1) scaledRows_.resize(3 * static_cast<std::size_t>(op_.size()) * n, 0.0);
  std::string message;
  for (int i : points) {
    double F[9];
    if (!correspondence::shapeTensorAndDeformationGradient(s, i, shapeTensorInverse_ + 9 * i, F) &&
        message.empty()) {
      message = "Materials -> \"" + name_ + "\": the shape tensor of " +
                correspondence::describePoint(s, i) +
                " is singular: a bond-associated correspondence model needs at least three "
                "non-coplanar neighbours per point (Peridigm stops with \"failed to compute "
                "gradient weights\"); is the horizon too small?";
    }
    if (order_ > 1 && !higherOrderWeights(s, i) && message.empty()) {
      message = "Materials -> \"" + name_ + "\": the moment matrix of " +
                correspondence::describePoint(s, i) +
                " is singular: \"Gradient Order Of Accuracy\" " + std::to_string(order_) +
                " needs enough neighbours in general position to fit every monomial of that "
                "degree (Peridigm stops with \"failed to compute gradient weights\"); is the "
                "horizon too small?";
    }
    weightedVolume_[i] = bondassociated::weightedVolume(s, i);
    for (int k = 0; k < 9; ++k) {
      deformationGradient_[9 * i + k] = rotation_[9 * i + k] = leftStretch_[9 * i + k] =
          kIdentity[k];
      unrotated_[9 * i + k] = 0.0;
      velocityGradient_[9 * i + k] = unrotatedRate_[9 * i + k] = cauchy_[9 * i + k] = 0.0;
    }
    vonMises_[i] = 0.0;
    if (plastic_) triaxiality_[i] = 0.0;
  }
  throwIfAnyRank(message, s.topology->comm);
}

double BondAssociatedCorrespondence::updateStress(const double* d, double dt, const double* sigmaN,
                                                  double eqpsN, double* sigma) const {
  const double mu = constants_.shearModulus;
  correspondence::hypoelasticIncrement(lame_, mu, d, dt, sigmaN, sigma);
  if (!plastic_) return eqpsN;
  return eqpsN + correspondence::radialReturn(mu, hardening_, eqpsN, sigma);
}

bool BondAssociatedCorrespondence::pointKinematics(const ModelState& s, int i,
                                                   std::string& message) {
  using namespace correspondence;
  double* Kinv = shapeTensorInverse_ + 9 * i;
  double* F = deformationGradient_ + 9 * i;
  double M[9], Fdot[9];
  bool regular = shapeTensorAndDeformationGradient(s, i, Kinv, F, true, M);
  if (order_ == 1) {
    multiply(M, Kinv, Fdot);
  } else {
    // K^-1 stays an output; F and Fdot come from the higher-order weights.
    regular = regular && higherOrderWeights(s, i);
    if (regular) higherOrderGradients(s, i, F, Fdot);
  }
  const double m = bondassociated::weightedVolume(s, i);
  weightedVolume_[i] = m;
  inverseWeightedVolume_[i] = m > 0 ? 1.0 / m : 0.0;
  for (int k = 0; k < 9; ++k) {
    fRow_[k / 3][3 * i + k % 3] = F[k];
    fdotRow_[k / 3][3 * i + k % 3] = regular ? Fdot[k] : 0.0;
  }
  double* sigmaNew = unrotatedNew_.data() + 9 * i;
  double* Rnew = rotationNew_.data() + 9 * i;
  double* Vnew = stretchNew_.data() + 9 * i;
  double* L = velocityGradient_ + 9 * i;
  double* d = unrotatedRate_ + 9 * i;
  double Finv[9];
  if (!regular || !(determinant(F) > 0) || !invert(F, Finv)) {
    if (message.empty()) {
      char when[64];
      std::snprintf(when, sizeof when, " at time %.9g", s.time);
      message = "Materials -> \"" + name_ + "\": " + describePoint(s, i) +
                (regular ? " has an inverted or singular deformation gradient"
                 : order_ == 1
                     ? " has a singular shape tensor (its intact bonds no longer span three "
                       "non-coplanar directions)"
                     : " has a singular shape tensor or moment matrix (its intact bonds no longer "
                       "fit the monomials of \"Gradient Order Of Accuracy\" " +
                           std::to_string(order_) + ")") +
                when + "; Peridigm stops here too";
    }
    std::copy(unrotated_ + 9 * i, unrotated_ + 9 * i + 9, sigmaNew);
    std::copy(rotation_ + 9 * i, rotation_ + 9 * i + 9, Rnew);
    std::copy(leftStretch_ + 9 * i, leftStretch_ + 9 * i + 9, Vnew);
    if (plastic_) eqpsNew_[i] = eqps_[i];
    std::fill(L, L + 9, 0.0);
    std::fill(d, d + 9, 0.0);
    return false;
  }
  // The point-level stress (outputs only): the bond update driven by the point's F.
  multiply(Fdot, Finv, L);
  flanaganTaylorStep(L, leftStretch_ + 9 * i, rotation_ + 9 * i, s.dt, Vnew, Rnew, d);
  const double eqps =
      updateStress(d, s.dt, unrotated_ + 9 * i, plastic_ ? eqps_[i] : 0.0, sigmaNew);
  if (plastic_) eqpsNew_[i] = eqps;
  double tmp[9];
  double* sigma = cauchy_ + 9 * i;
  multiply(Rnew, sigmaNew, tmp);
  multiplyTransposed(tmp, Rnew, sigma);
  vonMises_[i] = vonMises(sigma);
  if (plastic_) triaxiality_[i] = triaxialityOf(sigma);
  return true;
}

void BondAssociatedCorrespondence::bondStresses(const ModelState& s, int i, std::string& message) {
  using namespace correspondence;
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* x = s.x;
  const double* y = s.y;
  const double* v = s.velocity;
  const double* invm = inverseWeightedVolume_;
  double S[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
    const int j = neighbors[b];
    const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
    const double omega = s.influence ? s.influence[b] : 1.0;
    const double ownI = s.bondSides ? (s.bondSides[b] & 1) : 1.0;
    const double ownJ = s.bondSides ? ((s.bondSides[b] >> 1) & 1) : 1.0;
    double sigmaNew[9], Rnew[9], Vnew[9];
    double* traction = bondTraction_.data() + 3 * b;
    double sigmaN[9], Rn[9], Vn[9];
    for (int k = 0; k < 9; ++k) {
      sigmaN[k] = bondSigma_[k][b];
      Rn[k] = bondRotation_[k][b];
      Vn[k] = bondStretch_[k][b];
    }
    const double wI = omega * intact * ownI;
    double Fb[9], Finv[9];
    const double xi[3] = {x[3 * j] - x[3 * i], x[3 * j + 1] - x[3 * i + 1],
                          x[3 * j + 2] - x[3 * i + 2]};
    const double Y[3] = {y[3 * j] - y[3 * i], y[3 * j + 1] - y[3 * i + 1],
                         y[3 * j + 2] - y[3 * i + 2]};
    const double len = s.bondLength ? s.bondLength[b] : referenceBondLength(x, i, j);
    const double invXi2 = 1.0 / (len * len);
    bool active = intact > 0 && omega > 0 && (ownI > 0 || ownJ > 0);
    if (active) {
      bondassociated::bondTensor(fRow_, i, j, xi, Y, invXi2, Fb);
      active = determinant(Fb) > 0 && invert(Fb, Finv);
      if (!active && message.empty()) {
        char what[200];
        std::snprintf(what, sizeof what,
                      ": the deformation gradient of its bond to point %lld is inverted or "
                      "singular (det F_b = %.6g) at time %.9g",
                      s.topology->overlapGlobalId[j] + 1, determinant(Fb), s.time);
        message = "Materials -> \"" + name_ + "\": " + describePoint(s, i) + what +
                  "; Peridigm stops here too (\"failed to compute rotation tensor\")";
      }
    }
    if (!active) {
      // A broken bond (or a failed one, with the run about to stop) keeps its history.
      for (int k = 0; k < 9; ++k) {
        bondSigmaNew_[k][b] = sigmaN[k];
        bondRotationNew_[k][b] = Rn[k];
        bondStretchNew_[k][b] = Vn[k];
      }
      bondEqpsNew_[b] = bondEqps_[b];
      traction[0] = traction[1] = traction[2] = 0.0;
      continue;
    }
    const double dv[3] = {v[3 * j] - v[3 * i], v[3 * j + 1] - v[3 * i + 1],
                          v[3 * j + 2] - v[3 * i + 2]};
    double Fdotb[9], L[9], d[9];
    bondassociated::bondTensor(fdotRow_, i, j, xi, dv, invXi2, Fdotb);
    multiply(Fdotb, Finv, L);
    flanaganTaylorStep(L, Vn, Rn, s.dt, Vnew, Rnew, d);
    bondEqpsNew_[b] = updateStress(d, s.dt, sigmaN, bondEqps_[b], sigmaNew);
    for (int k = 0; k < 9; ++k) {
      bondSigmaNew_[k][b] = sigmaNew[k];
      bondRotationNew_[k][b] = Rnew[k];
      bondStretchNew_[k][b] = Vnew[k];
    }
    // sigma_b = R sigma_u R^T, P_b = J sigma_b F_b^-T
    double tmp[9], sigma[9], P[9];
    multiply(Rnew, sigmaNew, tmp);
    multiplyTransposed(tmp, Rnew, sigma);
    multiplyTransposed(sigma, Finv, P);
    const double J = determinant(Fb);
    for (int k = 0; k < 9; ++k) P[k] *= J;
    if (plastic_) {
      bondVonMises_[b] = vonMises(sigma);
      bondTriaxiality_[b] = triaxialityOf(sigma);
    }
    for (int r = 0; r < 3; ++r)
      traction[r] = (P[3 * r] * xi[0] + P[3 * r + 1] * xi[1] + P[3 * r + 2] * xi[2]) * invXi2;
    // S_i += w (1/(2 m_i) + 1/(2 m_j)) V_j P (I - xi (x) xi / |xi|^2) = c (P - t (x) xi)
    const double c = wI * (0.5 * invm[i] + 0.5 * invm[j]) * s.volume[j];
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) S[3 * r + k] += c * (P[3 * r + k] - traction[r] * xi[k]);
  }
  if (order_ == 1) {
    double B[9];
    multiply(S, shapeTensorInverse_ + 9 * i, B);
    for (int k = 0; k < 9; ++k) bRow_[k / 3][3 * i + k % 3] = B[k];
    return;
  }
  // B = S Zs, column k (a 3-vector) per monomial.
  const std::size_t q = static_cast<std::size_t>(op_.size());
  const double* Z = scaledRows_.data() + 3 * q * static_cast<std::size_t>(i);
  for (std::size_t k = 0; k < q; ++k)
    for (int r = 0; r < 3; ++r)
      bColumn_[k][3 * i + r] =
          S[3 * r] * Z[k] + S[3 * r + 1] * Z[q + k] + S[3 * r + 2] * Z[2 * q + k];
}

bool BondAssociatedCorrespondence::higherOrderWeights(const ModelState& s, int i) {
  const std::int64_t begin = s.topology->bondOffsets[i], end = s.topology->bondOffsets[i + 1];
  const std::size_t count = static_cast<std::size_t>(end - begin);
  bondXi_.resize(3 * count);
  bondWeight_.resize(count);
  bondVolume_.resize(count);
  bondPhi_.resize(3 * count);
  for (std::int64_t b = begin; b < end; ++b) {
    const int j = s.topology->neighbors[b];
    const std::size_t k = static_cast<std::size_t>(b - begin);
    for (int d = 0; d < 3; ++d) bondXi_[3 * k + d] = s.x[3 * j + d] - s.x[3 * i + d];
    double w = s.influence ? s.influence[b] : 1.0;
    if (s.bondDamage) w *= 1.0 - s.bondDamage[b];
    if (s.bondSides) w *= (s.bondSides[b] & 1);
    bondWeight_[k] = w;
    bondVolume_[k] = s.volume[j];
  }
  // The horizon only scales the monomials (conditioning); the weights do not depend on it.
  const double delta = s.horizon[i];
  const std::size_t q = static_cast<std::size_t>(op_.size());
  double* Z = scaledRows_.data() + 3 * q * static_cast<std::size_t>(i);
  if (!op_.weights(count, bondXi_.data(), bondWeight_.data(), bondVolume_.data(), delta,
                   bondPhi_.data())) {
    std::fill(Z, Z + 3 * q, 0.0);
    return false;
  }
  // phi_b = (w_b / delta) z_a . q(xi_b / delta) = w_b (z_a / delta^(1 + degree)) . q(xi_b).
  const double* rows = op_.rows();
  std::size_t k = 0;
  double power = delta * delta;  // delta^(1 + degree) for degree 1
  for (int degree = 1; degree <= order_; ++degree, power *= delta)
    for (int c = 0; c < (degree + 1) * (degree + 2) / 2; ++c, ++k)
      for (int a = 0; a < 3; ++a) Z[a * q + k] = rows[a * q + k] / power;
  return true;
}

void BondAssociatedCorrespondence::higherOrderGradients(const ModelState& s, int i, double* F,
                                                        double* Fdot) const {
  // Peridigm's form: F from the displacements u = y - x (small next to y for small strains).
  double G[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, Gdot[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  const std::int64_t begin = s.topology->bondOffsets[i], end = s.topology->bondOffsets[i + 1];
  for (std::int64_t b = begin; b < end; ++b) {
    const int j = s.topology->neighbors[b];
    const double* phi = bondPhi_.data() + 3 * (b - begin);
    const double vj = s.volume[j];
    for (int r = 0; r < 3; ++r) {
      const double du =
          ((s.y[3 * j + r] - s.x[3 * j + r]) - (s.y[3 * i + r] - s.x[3 * i + r])) * vj;
      const double dv = (s.velocity[3 * j + r] - s.velocity[3 * i + r]) * vj;
      for (int c = 0; c < 3; ++c) {
        G[3 * r + c] += du * phi[c];
        Gdot[3 * r + c] += dv * phi[c];
      }
    }
  }
  for (int k = 0; k < 9; ++k) {
    F[k] = (k % 4 == 0 ? 1.0 : 0.0) + G[k];
    Fdot[k] = Gdot[k];
  }
}

void BondAssociatedCorrespondence::precompute(const ModelState& s, const std::vector<int>& points) {
  std::string message;
  for (int i : points) pointKinematics(s, i, message);
  throwIfAnyRank(message, s.topology->comm, true);
  // Pass 2 reads F, Fdot and 1/m of the neighbours: ghost them now (every rank calls precompute
  // for every block, so the refresh is collective).
  for (int r = 0; r < 3; ++r) {
    s.fields->refreshGhosts(kDeformationGradientRows[r]);
    s.fields->refreshGhosts(kDeformationRateRows[r]);
  }
  s.fields->refreshGhosts(kInverseWeightedVolume);
  for (int i : points) bondStresses(s, i, message);
  throwIfAnyRank(message, s.topology->comm, true);
}

// The force, then (committing evaluations) the history.
void BondAssociatedCorrespondence::computeForce(const ModelState& s,
                                                const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  if (order_ > 1)
    higherOrderForce(s, points);
  else
    firstOrderForce(s, points);
  // A trial keeps the history of the step's start (precompute wrote only the scratch copies).
  if (!s.commitHistory) return;
  for (int i : points) {
    std::copy(unrotatedNew_.begin() + 9 * i, unrotatedNew_.begin() + 9 * i + 9, unrotated_ + 9 * i);
    std::copy(rotationNew_.begin() + 9 * i, rotationNew_.begin() + 9 * i + 9, rotation_ + 9 * i);
    std::copy(stretchNew_.begin() + 9 * i, stretchNew_.begin() + 9 * i + 9, leftStretch_ + 9 * i);
    if (plastic_) eqps_[i] = eqpsNew_[i];
    const std::int64_t first = offsets[i], last = offsets[i + 1];
    for (int k = 0; k < 9; ++k) {
      std::copy(bondSigmaNew_[k].begin() + first, bondSigmaNew_[k].begin() + last,
                bondSigma_[k] + first);
      std::copy(bondRotationNew_[k].begin() + first, bondRotationNew_[k].begin() + last,
                bondRotation_[k] + first);
      std::copy(bondStretchNew_[k].begin() + first, bondStretchNew_[k].begin() + last,
                bondStretch_[k] + first);
    }
    std::copy(bondEqpsNew_.begin() + first, bondEqpsNew_.begin() + last, bondEqps_ + first);
  }
}

// f_i = sum_j [(w_ij / m_i + w_ji / m_j) t_b + (w_ij B_i + w_ji B_j) xi] V_j, t_b = P_b xi /
// |xi|^2; one vectorisable pass.
void BondAssociatedCorrespondence::firstOrderForce(const ModelState& s,
                                                   const std::vector<int>& points) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double *B0 = bRow_[0], *B1 = bRow_[1], *B2 = bRow_[2];
  const double* invm = inverseWeightedVolume_;
  const double* t = bondTraction_.data();
  const double* x = s.x;
  for (int i : points) {
    const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
    const double b00 = B0[3 * i], b01 = B0[3 * i + 1], b02 = B0[3 * i + 2];
    const double b10 = B1[3 * i], b11 = B1[3 * i + 1], b12 = B1[3 * i + 2];
    const double b20 = B2[3 * i], b21 = B2[3 * i + 1], b22 = B2[3 * i + 2];
    const double invmI = invm[i];
    double f0 = 0, f1 = 0, f2 = 0;
#pragma omp simd reduction(+ : f0, f1, f2)
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double omega = s.influence ? s.influence[b] : 1.0;
      const double ownI = s.bondSides ? (s.bondSides[b] & 1) : 1.0;
      const double ownJ = s.bondSides ? ((s.bondSides[b] >> 1) & 1) : 1.0;
      const double wI = ownI * omega * intact, wJ = ownJ * omega * intact;
      const double e0 = x[3 * j] - xi0, e1 = x[3 * j + 1] - xi1, e2 = x[3 * j + 2] - xi2;
      const double a = wI * invmI + wJ * invm[j];
      const double vj = s.volume[j];
      f0 += (a * t[3 * b] + wI * (b00 * e0 + b01 * e1 + b02 * e2) +
             wJ * (B0[3 * j] * e0 + B0[3 * j + 1] * e1 + B0[3 * j + 2] * e2)) *
            vj;
      f1 += (a * t[3 * b + 1] + wI * (b10 * e0 + b11 * e1 + b12 * e2) +
             wJ * (B1[3 * j] * e0 + B1[3 * j + 1] * e1 + B1[3 * j + 2] * e2)) *
            vj;
      f2 += (a * t[3 * b + 2] + wI * (b20 * e0 + b21 * e1 + b22 * e2) +
             wJ * (B2[3 * j] * e0 + B2[3 * j + 1] * e1 + B2[3 * j + 2] * e2)) *
            vj;
    }
    s.forceDensity[3 * i] = f0;
    s.forceDensity[3 * i + 1] = f1;
    s.forceDensity[3 * i + 2] = f2;
  }
}

// f_i = sum_j [(w_ij / m_i + w_ji / m_j) t_b + w_ij B_i q(xi) - w_ji B_j q(-xi)] V_j, q the
// monomials of xi and q(-xi) = parity q(xi).
void BondAssociatedCorrespondence::higherOrderForce(const ModelState& s,
                                                    const std::vector<int>& points) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double* invm = inverseWeightedVolume_;
  const double* t = bondTraction_.data();
  const double* x = s.x;
  const int q = op_.size();
  const double* parity = parity_.data();
  double mono[64];
  for (int i : points) {
    const double invmI = invm[i];
    double f[3] = {0, 0, 0};
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double omega = s.influence ? s.influence[b] : 1.0;
      const double ownI = s.bondSides ? (s.bondSides[b] & 1) : 1.0;
      const double ownJ = s.bondSides ? ((s.bondSides[b] >> 1) & 1) : 1.0;
      const double wI = ownI * omega * intact, wJ = ownJ * omega * intact;
      if (wI == 0.0 && wJ == 0.0) continue;
      const double xi[3] = {x[3 * j] - x[3 * i], x[3 * j + 1] - x[3 * i + 1],
                            x[3 * j + 2] - x[3 * i + 2]};
      op_.monomials(xi, 1.0, mono);
      const double a = wI * invmI + wJ * invm[j];
      const double vj = s.volume[j];
      for (int r = 0; r < 3; ++r) {
        double gradientTerm = 0;
        for (int k = 0; k < q; ++k)
          gradientTerm +=
              (wI * bColumn_[k][3 * i + r] - wJ * parity[k] * bColumn_[k][3 * j + r]) * mono[k];
        f[r] += (a * t[3 * b + r] + gradientTerm) * vj;
      }
    }
    for (int r = 0; r < 3; ++r) s.forceDensity[3 * i + r] = f[r];
  }
}

void BondAssociatedCorrespondence::storedEnergyDensity(const ModelState&,
                                                       const std::vector<int>& points,
                                                       double* out) const {
  // The complementary energy of the point's unrotated stress, p^2 / (2K) + s:s / (4 mu), as the
  // rate form of the plain correspondence models.
  for (int i : points)
    out[i] = correspondence::complementaryEnergyDensity(
        constants_.bulkModulus, constants_.shearModulus, unrotated_ + 9 * i);
}

}  // namespace peridot
