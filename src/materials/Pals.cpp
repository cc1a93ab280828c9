#include "materials/Pals.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "solvers/TangentBlocks.hpp"

namespace peridot {

namespace {

constexpr int N = Pals::kMultipliers;

Pals::Kernel readKernel(ListReader& p, const std::string& key) {
  const std::string name = p.choice(key, {"One", "Parabolic Decay", "Gaussian"}, "One");
  if (name == "Parabolic Decay") return Pals::Kernel::ParabolicDecay;
  if (name == "Gaussian") return Pals::Kernel::Gaussian;
  return Pals::Kernel::One;
}

// The dilatation basis h_k(xi) (xi . Lambda . xi = sum_k lambda_k h_k) and the extensions g_k of
// the six matching deformations E_k (g_k = xi . E_k . xi / |xi|): uniaxial-deviatoric
// e_a e_a - I/3 (a = x, y, z) and the shears e_a e_b + e_b e_a (xy, xz, yz).
void bases(const double xi[3], double h[N], double g[N]) {
  const double a = xi[0], b = xi[1], c = xi[2];
  const double r = std::sqrt(a * a + b * b + c * c), third = r / 3.0;
  h[0] = a * a;
  h[1] = b * b;
  h[2] = c * c;
  h[3] = 2 * a * b;
  h[4] = 2 * a * c;
  h[5] = 2 * b * c;
  for (int k = 0; k < 3; ++k) g[k] = h[k] / r - third;
  for (int k = 3; k < N; ++k) g[k] = h[k] / r;
}

// Solves A u = rhs (A N x N, row-major, overwritten) by Gaussian elimination with partial
// pivoting; false if a pivot is negligible against the largest diagonal entry (`scale`).
bool solve(double A[N * N], double rhs[N], double scale) {
  for (int c = 0; c < N; ++c) {
    int pivot = c;
    for (int r = c + 1; r < N; ++r)
      if (std::abs(A[r * N + c]) > std::abs(A[pivot * N + c])) pivot = r;
    if (!(std::abs(A[pivot * N + c]) > 1e-12 * scale)) return false;
    if (pivot != c) {
      for (int k = 0; k < N; ++k) std::swap(A[c * N + k], A[pivot * N + k]);
      std::swap(rhs[c], rhs[pivot]);
    }
    for (int r = c + 1; r < N; ++r) {
      const double f = A[r * N + c] / A[c * N + c];
      for (int k = c; k < N; ++k) A[r * N + k] -= f * A[c * N + k];
      rhs[r] -= f * rhs[c];
    }
  }
  for (int c = N - 1; c >= 0; --c) {
    double v = rhs[c];
    for (int k = c + 1; k < N; ++k) v -= A[c * N + k] * rhs[k];
    rhs[c] = v / A[c * N + c];
  }
  return true;
}

}  // namespace

Pals::Pals(ListReader& p) {
  density_ = p.positiveNumber("Density");
  constants_ = readTwoElasticConstants(p);
  dilatationKernel_ = readKernel(p, "Dilatation Influence Function");
  deviatoricKernel_ = readKernel(p, "Deviatoric Influence Function");
  // Peridigm reads the hourglass coefficient only in its correspondence models (Peridigm's
  // Interface Aware decks carry one on Pals).
  if (p.has("Hourglass Coefficient")) p.nonNegativeNumber("Hourglass Coefficient", 0.0);
  acceptCommonMaterialKeys(p);
}

double Pals::kernel(Kernel k, double zeta, double delta) {
  switch (k) {
    case Kernel::ParabolicDecay: {
      const double r = zeta / delta;
      return r < 0.5 ? 1.0 : -4.0 * r * r + 4.0 * r;
    }
    case Kernel::Gaussian:  // Peridigm's built-in for Pals: exp(-zeta^2 / delta^2)
      return std::exp(-zeta * zeta / (delta * delta));
    default:
      return 1.0;
  }
}

std::string Pals::dilatationMultiplierName(int n) {
  return "Lagrange_Multiplier_Dilatation_" + std::to_string(n);
}
std::string Pals::deviatoricMultiplierName(int n) {
  return "Lagrange_Multiplier_Deviatoric_" + std::to_string(n);
}

void Pals::declareFields(FieldManager& fields) {
  weightedVolume_ = fields.node(kWeightedVolume, 1);
  dilatation_ = fields.node(kDilatation, 1);
  pressure_ = fields.node(kPressure, 1);
  dilatationNormalization_ = fields.node(kDilatationNormalization, 1);
  deviatoricNormalization_ = fields.node(kDeviatoricNormalization, 1);
  for (int k = 0; k < N; ++k) {
    lambda_[k] = fields.node(dilatationMultiplierName(k + 1), 1);
    tau_[k] = fields.node(deviatoricMultiplierName(k + 1), 1);
  }
}

std::vector<std::string> Pals::fieldsToSyncAfterInitialize() const {
  std::vector<std::string> names;
  for (int k = 1; k <= N; ++k) {
    names.push_back(dilatationMultiplierName(k));
    names.push_back(deviatoricMultiplierName(k));
  }
  return names;
}

std::vector<std::string> Pals::outputFields() const {
  std::vector<std::string> names = {kWeightedVolume, kDilatation, kPressure,
                                    kDilatationNormalization, kDeviatoricNormalization};
  for (const auto& n : fieldsToSyncAfterInitialize()) names.push_back(n);
  return names;
}

double Pals::omegaAt(const ModelState& s, int point, const double xi[3]) const {
  double h[N], g[N];
  bases(xi, h, g);
  double w = kernel(dilatationKernel_, std::sqrt(h[0] + h[1] + h[2]), s.horizon[point]);
  for (int k = 0; k < N; ++k) w += lambda_[k][point] * h[k];
  return w;
}

double Pals::sigmaAt(const ModelState& s, int point, const double xi[3]) const {
  double h[N], g[N];
  bases(xi, h, g);
  double w = kernel(deviatoricKernel_, std::sqrt(h[0] + h[1] + h[2]), s.horizon[point]);
  for (int k = 0; k < N; ++k) w += tau_[k][point] * g[k] * g[k];
  return w;
}

// The two linear systems of point i (doc/theory/pals.md):
//   dilatation: sum_j omega_i h_k V_j = (1, 1, 1, 0, 0, 0)_k (sum omega xi (x) xi V = I),
//   deviatoric: sum_j sigma_i g_k^2 V_j = E_k : E_k = (2/3, 2/3, 2/3, 2, 2, 2)_k,
// both linear in the multipliers. As in Peridigm, a multiplier whose dilatation diagonal is
// negligible (below 1e-15 of the trace: all bonds in a coordinate plane, e.g. one layer of
// points) is dropped from both systems with its equation.
std::string Pals::computeMultipliers(const ModelState& s, int i) {
  double Kd[N * N] = {}, Ks[N * N] = {}, rd[N] = {}, rs[N] = {};
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double delta = s.horizon[i];
  for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
    if (!s.topology->ownSide(b)) continue;
    const int j = neighbors[b];
    const double xi[3] = {s.x[3 * j] - s.x[3 * i], s.x[3 * j + 1] - s.x[3 * i + 1],
                          s.x[3 * j + 2] - s.x[3 * i + 2]};
    double h[N], g[N];
    bases(xi, h, g);
    const double v = s.volume[j], zeta = s.bondLength[b];
    const double w0 = kernel(dilatationKernel_, zeta, delta) * v;
    const double s0 = kernel(deviatoricKernel_, zeta, delta) * v;
    for (int k = 0; k < N; ++k) {
      for (int l = 0; l < N; ++l) {
        Kd[k * N + l] += h[k] * h[l] * v;
        Ks[k * N + l] += g[k] * g[k] * g[l] * g[l] * v;
      }
      rd[k] += w0 * h[k];
      rs[k] += s0 * g[k] * g[k];
    }
  }
  static const double dilatationTarget[N] = {1, 1, 1, 0, 0, 0};
  static const double deviatoricTarget[N] = {2.0 / 3, 2.0 / 3, 2.0 / 3, 2, 2, 2};
  double trace = 0, scaleD = 0, scaleS = 0;
  for (int k = 0; k < N; ++k) trace += Kd[k * N + k];
  for (int k = 0; k < N; ++k) {
    rd[k] = dilatationTarget[k] - rd[k];
    rs[k] = deviatoricTarget[k] - rs[k];
  }
  if (!(trace > 0)) {  // no bond: no multipliers, no force
    for (int k = 0; k < N; ++k) lambda_[k][i] = tau_[k][i] = 0.0;
    return "";
  }
  for (int k = 0; k < N; ++k) {
    if (Kd[k * N + k] / trace < 1e-15) {
      for (int l = 0; l < N; ++l) Kd[k * N + l] = Kd[l * N + k] = Ks[k * N + l] = Ks[l * N + k] = 0;
      Kd[k * N + k] = Ks[k * N + k] = 1.0;
      rd[k] = rs[k] = 0.0;
    }
    scaleD = std::max(scaleD, Kd[k * N + k]);
    scaleS = std::max(scaleS, Ks[k * N + k]);
  }
  const bool okD = solve(Kd, rd, scaleD);
  const bool okS = okD && solve(Ks, rs, scaleS);
  if (!okD || !okS) {
    std::ostringstream m;
    m << "Pals: the bonds of point " << s.topology->overlapGlobalId[i] + 1 << " ("
      << offsets[i + 1] - offsets[i]
      << " bonds) do not determine its Lagrange multipliers (singular "
      << (okD ? "deviatoric" : "dilatation")
      << " system): a point needs bonds in at least six independent directions; enlarge the "
         "horizon";
    return m.str();
  }
  for (int k = 0; k < N; ++k) {
    lambda_[k][i] = rd[k];
    tau_[k][i] = rs[k];
  }
  return "";
}

void Pals::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, "Pals");
  if (s.partialVolumes) {
    throw InputError("Discretization -> Partial Volumes",
                     "not supported with the \"Pals\" material (its influence functions are its "
                     "own, Dilatation/Deviatoric Influence Function)");
  }
  std::string message;
  for (int i : points) {
    dilatationNormalization_[i] = deviatoricNormalization_[i] = 1.0;  // Peridigm: scaling off
    const std::string m = computeMultipliers(s, i);
    if (message.empty()) message = m;
  }
  throwIfAnyRank(message, s.topology->comm);
  // Weighted volume with the corrected deviatoric influence function (Peridigm's output).
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    double m = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      if (!s.topology->ownSide(b)) continue;
      const int j = neighbors[b];
      const double xi[3] = {s.x[3 * j] - s.x[3 * i], s.x[3 * j + 1] - s.x[3 * i + 1],
                            s.x[3 * j + 2] - s.x[3 * i + 2]};
      m += sigmaAt(s, i, xi) * s.bondLength[b] * s.bondLength[b] * s.volume[j];
    }
    weightedVolume_[i] = m;
  }
  const std::size_t bonds = s.topology->neighbors.size();
  if (omegaOwn_.size() != bonds) {
    omegaOwn_.assign(bonds, 0.0);
    sigmaOwn_.assign(bonds, 0.0);
    omegaFar_.assign(bonds, 0.0);
    sigmaFar_.assign(bonds, 0.0);
    tabulated_.assign(s.topology->numOwned, 0);
  }
}

void Pals::tabulateInfluence(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  for (int i : points) {
    if (tabulated_[i]) continue;
    tabulated_[i] = 1;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double xi[3] = {s.x[3 * j] - s.x[3 * i], s.x[3 * j + 1] - s.x[3 * i + 1],
                            s.x[3 * j + 2] - s.x[3 * i + 2]};
      // Both functions are even in xi: the far end's value on the reversed bond is its value
      // at xi. An end whose horizon does not hold the bond gets 0 (it exerts no force on it).
      const double own = s.topology->ownSide(b) ? 1.0 : 0.0;
      const double far = s.bondSides ? ((s.bondSides[b] >> 1) & 1) : 1.0;
      omegaOwn_[b] = own * omegaAt(s, i, xi);
      sigmaOwn_[b] = own * sigmaAt(s, i, xi);
      omegaFar_[b] = far * omegaAt(s, j, xi);
      sigmaFar_[b] = far * sigmaAt(s, j, xi);
    }
  }
}

void Pals::precompute(const ModelState& s, const std::vector<int>& points) {
  tabulateInfluence(s, points);
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double K = constants_.bulkModulus, G = constants_.shearModulus;
  for (int i : points) {
    const double yi0 = s.y[3 * i], yi1 = s.y[3 * i + 1], yi2 = s.y[3 * i + 2];
    double theta = 0, q = 0, m = 0;  // sum omega zeta e V, sum sigma zeta e V, sum sigma zeta^2 V
#pragma omp simd reduction(+ : theta, q, m)
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = s.y[3 * j] - yi0, Y1 = s.y[3 * j + 1] - yi1, Y2 = s.y[3 * j + 2] - yi2;
      const double zeta = s.bondLength[b];
      const double e = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2) - zeta;
      const double v = (s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0) * s.volume[j] * zeta;
      theta += omegaOwn_[b] * e * v;
      q += sigmaOwn_[b] * e * v;
      m += sigmaOwn_[b] * zeta * v;
    }
    dilatation_[i] = theta;
    // sum sigma zeta e^d V = q - theta m / 3
    pressure_[i] = K * theta - 2.0 * G / 3.0 * (q - theta * m / 3.0);
  }
}

void Pals::computeForce(const ModelState& s, const std::vector<int>& points) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double twoG = 2.0 * constants_.shearModulus;
  const double* y = s.y;
  const double* theta = dilatation_;
  const double* p = pressure_;
  const double* omegaOwn = omegaOwn_.data();
  const double* sigmaOwn = sigmaOwn_.data();
  const double* omegaFar = omegaFar_.data();
  const double* sigmaFar = sigmaFar_.data();
  for (int i : points) {
    double f0 = 0, f1 = 0, f2 = 0;
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    const double pi = p[i], thirdThetaI = theta[i] / 3.0;
#pragma omp simd reduction(+ : f0, f1, f2)
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = y[3 * j] - yi0, Y1 = y[3 * j + 1] - yi1, Y2 = y[3 * j + 2] - yi2;
      const double length = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
      const double dY = length > 0 ? length : 1.0;  // coincident ends add +0
      const double zeta = s.bondLength[b];
      const double e = length - zeta;
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      // Force state of i on the bond and of j on the reversed bond (pull form).
      const double ti = pi * omegaOwn[b] * zeta + twoG * sigmaOwn[b] * (e - thirdThetaI * zeta);
      const double tj =
          p[j] * omegaFar[b] * zeta + twoG * sigmaFar[b] * (e - theta[j] / 3.0 * zeta);
      const double scale = intact * (ti + tj) * s.volume[j] / dY;
      f0 += scale * Y0;
      f1 += scale * Y1;
      f2 += scale * Y2;
    }
    s.forceDensity[3 * i] = f0;
    s.forceDensity[3 * i + 1] = f1;
    s.forceDensity[3 * i + 2] = f2;
  }
}

void Pals::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                               double* energyDensity) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double K = constants_.bulkModulus, G = constants_.shearModulus;
  for (int i : points) {
    const double yi0 = s.y[3 * i], yi1 = s.y[3 * i + 1], yi2 = s.y[3 * i + 2];
    double deviatoric = 0;
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      const double Y0 = s.y[3 * j] - yi0, Y1 = s.y[3 * j + 1] - yi1, Y2 = s.y[3 * j + 2] - yi2;
      const double zeta = s.bondLength[b];
      const double ed = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2) - zeta - dilatation_[i] * zeta / 3;
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      deviatoric += intact * sigmaOwn_[b] * ed * ed * s.volume[j];
    }
    // The deviatoric term has no 1/2: sigma is normalized so that it gives G E:E (Peridigm).
    energyDensity[i] = 0.5 * K * dilatation_[i] * dilatation_[i] + G * deviatoric;
  }
}

// Tangent, family by family (as Elastic::addStiffness). Family i exerts p_b = t_b V_b n_b on i
// and -(V_i / V_b) p_b on j(b). With a_c = (1-d) omega zeta V (d theta / d e_c),
// s_c = (1-d) sigma zeta V (d q / d e_c), m = sum (1-d) sigma zeta^2 V:
//   d p / d e_c = pi_c = (K + 2 G m / 9) a_c - (2 G / 3) s_c,
//   d t_b / d e_c = delta_bc alpha_b + u_b pi_c - w_b a_c,
// alpha_b = (1-d) 2 G sigma, u_b = (1-d) omega zeta, w_b = (1-d) (2G/3) sigma zeta, so
//   d p_b / d y_j(c) = delta_bc D_b + V_b (u_b pi_c - w_b a_c) n_b n_c^T,
//   D_b = V_b [alpha_b n_b n_b^T + t_b (I - n_b n_b^T) / |Y_b|],
// and d / d y_i is minus the sum over c. Stiffness K = -V_row d f / d y.
void Pals::addStiffness(const ModelState& s, const std::vector<int>& points,
                        TangentBlocks& K) const {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const double Kb = constants_.bulkModulus, G = constants_.shearModulus;
  std::vector<double> n, D, a, piC, u, w;  // per bond of the family, reused
  for (int i : points) {
    const std::int64_t first = offsets[i], count = offsets[i + 1] - first;
    if (count == 0) continue;
    n.assign(3 * count, 0.0);
    D.assign(9 * count, 0.0);
    a.assign(count, 0.0);
    piC.assign(count, 0.0);
    u.assign(count, 0.0);
    w.assign(count, 0.0);
    const double vi = s.volume[i];
    double m = 0;
    for (std::int64_t k = 0; k < count; ++k) {
      const std::int64_t b = first + k;
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double zeta = s.bondLength[b], vj = s.volume[neighbors[b]];
      m += intact * sigmaOwn_[b] * zeta * zeta * vj;
    }
    double S1[3] = {0, 0, 0}, S2[3] = {0, 0, 0}, G1[3] = {0, 0, 0}, G2[3] = {0, 0, 0};
    for (std::int64_t k = 0; k < count; ++k) {
      const std::int64_t b = first + k;
      const int j = neighbors[b];
      double Y[3];
      for (int d = 0; d < 3; ++d) Y[d] = s.y[3 * j + d] - s.y[3 * i + d];
      const double length = std::sqrt(Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2]);
      if (!(length > 0)) continue;  // no direction: no force, no stiffness (as the force loop)
      const double intact = s.bondDamage ? 1.0 - s.bondDamage[b] : 1.0;
      const double zeta = s.bondLength[b], vj = s.volume[j];
      const double omega = omegaOwn_[b], sigma = sigmaOwn_[b];
      const double e = length - zeta;
      const double t = intact * (pressure_[i] * omega * zeta +
                                 2.0 * G * sigma * (e - dilatation_[i] * zeta / 3.0));
      const double alpha = intact * 2.0 * G * sigma;
      a[k] = intact * omega * zeta * vj;
      const double sk = intact * sigma * zeta * vj;
      piC[k] = (Kb + 2.0 * G * m / 9.0) * a[k] - 2.0 * G / 3.0 * sk;
      u[k] = intact * omega * zeta;
      w[k] = intact * 2.0 * G / 3.0 * sigma * zeta;
      for (int d = 0; d < 3; ++d) n[3 * k + d] = Y[d] / length;
      const double* nb = &n[3 * k];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          D[9 * k + 3 * r + c] =
              vj * (alpha * nb[r] * nb[c] + t * ((r == c ? 1.0 : 0.0) - nb[r] * nb[c]) / length);
      for (int d = 0; d < 3; ++d) {
        S1[d] += vj * u[k] * nb[d];
        S2[d] += vj * w[k] * nb[d];
        G1[d] += piC[k] * nb[d];
        G2[d] += a[k] * nb[d];
      }
    }
    // Row i.
    double Dsum[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (std::int64_t k = 0; k < count; ++k) {
      const int j = neighbors[first + k];
      K.add(i, j, -vi, &D[9 * k]);
      K.addOuter(i, j, -vi * piC[k], S1, &n[3 * k]);
      K.addOuter(i, j, vi * a[k], S2, &n[3 * k]);
      for (int r = 0; r < 9; ++r) Dsum[r] += D[9 * k + r];
    }
    K.add(i, i, vi, Dsum);
    K.addOuter(i, i, vi, S1, G1);
    K.addOuter(i, i, -vi, S2, G2);
    // Rows j(b): K_j,j(c) = V_i [delta_bc D_b + V_b (u_b pi_c - w_b a_c) n_b n_c^T], and column
    // i minus their sum.
    for (std::int64_t k = 0; k < count; ++k) {
      const int j = neighbors[first + k];
      const double vj = s.volume[j];
      K.add(j, j, vi, &D[9 * k]);
      K.add(j, i, -vi, &D[9 * k]);
      for (std::int64_t l = 0; l < count; ++l) {
        const double c = vi * vj * (u[k] * piC[l] - w[k] * a[l]);
        if (c != 0.0) K.addOuter(j, neighbors[first + l], c, &n[3 * k], &n[3 * l]);
      }
      K.addOuter(j, i, -vi * vj * u[k], &n[3 * k], G1);
      K.addOuter(j, i, vi * vj * w[k], &n[3 * k], G2);
    }
  }
}

PERIDOT_REGISTER_MATERIAL(
    "Pals", Pals,
    "Position-aware linear solid (Mitchell, Silling, Littlewood 2015): LPS with per-point "
    "Lagrange multipliers that make homogeneous deformations exact near surfaces",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Bulk Modulus", "positive number: K (exactly two of K, G, E, nu)"},
        {"Shear Modulus", "positive number: G"},
        {"Young's Modulus", "positive number: E"},
        {"Poisson's Ratio", "number in (-1, 0.5): nu"},
        {"Dilatation Influence Function",
         "\"One\" (default), \"Parabolic Decay\" or \"Gaussian\" (exp(-zeta^2/delta^2)): omega_0, "
         "the trial influence function of the dilatation that the multipliers correct"},
        {"Deviatoric Influence Function",
         "\"One\" (default), \"Parabolic Decay\" or \"Gaussian\": sigma_0, the trial influence "
         "function of the deviatoric energy"},
        {"Apply Automatic Differentiation Jacobian", "bool: accepted; the tangent is analytic"},
        {"Finite Difference Probe Length",
         "positive number: accepted; the probe is Solver -> Finite Difference Probe Length"},
        {"Hourglass Coefficient",
         "number >= 0: accepted and ignored (Peridigm reads it only in correspondence models)"}}))

}  // namespace peridot
