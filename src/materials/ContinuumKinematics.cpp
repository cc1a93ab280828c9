#include "materials/ContinuumKinematics.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace peridot {

namespace {

const double kPi = 3.14159265358979323846;

inline void cross(const double* u, const double* v, double* w) {
  w[0] = u[1] * v[2] - u[2] * v[1];
  w[1] = u[2] * v[0] - u[0] * v[2];
  w[2] = u[0] * v[1] - u[1] * v[0];
}

// Reference and current corner vectors of an interaction centred at point i.
struct Corners {
  double X[3][3], Y[3][3];
  void set(int c, const double* x, const double* y, int i, int j) {
    for (int d = 0; d < 3; ++d) {
      X[c][d] = x[3 * j + d] - x[3 * i + d];
      Y[c][d] = y[3 * j + d] - y[3 * i + d];
    }
  }
};

}  // namespace

ContinuumKinematics::ContinuumKinematics(ListReader& p) {
  density_ = p.positiveNumber("Density");
  mode_ = readPlaneMode(p);
  const ElasticConstants e = readTwoElasticConstants(p);
  youngs_ = e.youngsModulus;
  poisson_ = e.poissonsRatio;
  // Positive definite (3D, plane stress of a 3D material, plane strain): -1 < nu < 1/2.
  if (!(poisson_ > -1.0 && poisson_ < 0.5) || !(youngs_ > 0)) {
    throw InputError(p.path(),
                     "the continuum-kinematics material needs E > 0 and -1 < nu < 1/2 "
                     "(got E = " +
                         std::to_string(youngs_) + ", nu = " + std::to_string(poisson_) + ")");
  }
  const int dimension = mode_ == PlaneMode::ThreeD ? 3 : 2;
  // A constant is zero when lambda = mu (nu = 1/4 in 3D and plane strain, 1/3 in plane stress).
  const double mu = youngs_ / (2.0 * (1.0 + poisson_));
  const bool excess = std::fabs(lambdaExcess(dimension)) > 1e-12 * mu;
  one_ = p.boolean("One-Neighbor Interactions", true);
  two_ = p.boolean("Two-Neighbor Interactions", dimension == 2 && excess);
  three_ = p.boolean("Three-Neighbor Interactions", dimension == 3 && excess);
  if (two_ && dimension == 3) {
    throw InputError(p.pathOf("Two-Neighbor Interactions"),
                     "in 3D the two-neighbour constant is C2 = 0 (paper 004, eq. 4.2): the "
                     "interactions would carry no stiffness");
  }
  if (three_ && dimension == 2) {
    throw InputError(p.pathOf("Three-Neighbor Interactions"),
                     "a planar discretization has no three-neighbour (volume) interactions");
  }
  if (!one_ && !two_ && !three_) {
    throw InputError(p.path(), "every interaction type is switched off");
  }
  acceptCommonMaterialKeys(p);
}

double ContinuumKinematics::lambdaExcess(int dimension) const {
  const double E = youngs_, nu = poisson_;
  const double mu = E / (2.0 * (1.0 + nu));
  // Plane stress: the in-plane lambda of a thin sheet, E nu / (1 - nu^2); plane strain and 3D:
  // the Lame constant E nu / ((1 + nu)(1 - 2 nu)).
  const double lambda = (dimension == 2 && mode_ == PlaneMode::PlaneStress)
                            ? E * nu / (1.0 - nu * nu)
                            : E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  return lambda - mu;
}

void ContinuumKinematics::constants(double delta, int dimension, double& c1, double& c2,
                                    double& c3) const {
  const double mu = youngs_ / (2.0 * (1.0 + poisson_));
  const double excess = lambdaExcess(dimension);
  if (dimension == 3) {
    // Bonds alone: lambda = mu = C1 pi delta^4 / 30. Tetrahedra add 1/4 * 1/2 C3 theta^2 V_H^3
    // <|V|> = (lambda - mu) theta^2 / 2, <|V|> = kMeanVolume3D delta^3.
    c1 = 30.0 * mu / (kPi * std::pow(delta, 4));
    c2 = 0.0;
    c3 = 27.0 * excess / (16.0 * kPi * kPi * kPi * kMeanVolume3D * std::pow(delta, 12));
  } else {
    // Bonds alone: lambda = mu = C1 pi delta^3 / 24. Triangles add 1/3 * 1/2 C2 theta^2 V_H^2
    // <A> = (lambda - mu) theta^2 / 2, <A> = kMeanArea2D delta^2.
    c1 = 24.0 * mu / (kPi * std::pow(delta, 3));
    c2 = 3.0 * excess / (kPi * kPi * kMeanArea2D * std::pow(delta, 6));
    c3 = 0.0;
  }
}

void ContinuumKinematics::paperConstants(double delta, int dimension, double& c2,
                                         double& c3) const {
  const double E = youngs_, nu = poisson_;
  c2 = c3 = 0.0;
  if (dimension == 3) {
    const double mu = E / (2.0 * (1.0 + nu)), lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    c3 = 32.0 * (lambda - mu) / (std::pow(kPi, 4) * std::pow(delta, 12));
  } else {
    // Eq. (4.1) is plane stress; plane strain by E -> E/(1-nu^2), nu -> nu/(1-nu).
    double e2 = E, n2 = nu;
    if (mode_ == PlaneMode::PlaneStrain) {
      e2 = E / (1.0 - nu * nu);
      n2 = nu / (1.0 - nu);
    }
    c2 = 27.0 * e2 * (1.0 - 3.0 * n2) / (16.0 * kPi * std::pow(delta, 6) * (n2 * n2 - 1.0));
  }
}

void ContinuumKinematics::declareFields(FieldManager& fields) {
  weights_ = fields.node(kWeights, 3);
}

std::int64_t ContinuumKinematics::countTriples(const ModelState& s, int i) const {
  std::int64_t count = 0;
  if (lists_.pairOffsets.empty()) return 0;
  const Topology& t = *s.topology;
  const int* nb = t.neighbors.data() + t.bondOffsets[i];
  const double minVolume = 1e-10 * std::pow(s.horizon[i], 3);
  scan_.reset(t, lists_, i);
  Corners c;
  scan_.forEach(lists_, i, [&](int a, int b, int cc, std::int64_t, std::int64_t, std::int64_t) {
    c.set(0, s.x, s.x, i, nb[a]);
    c.set(1, s.x, s.x, i, nb[b]);
    c.set(2, s.x, s.x, i, nb[cc]);
    double A[3];
    cross(c.X[0], c.X[1], A);
    const double V = A[0] * c.X[2][0] + A[1] * c.X[2][1] + A[2] * c.X[2][2];
    if (std::fabs(V) > minVolume) ++count;
  });
  return count;
}

void ContinuumKinematics::initialize(const ModelState& s, const std::vector<int>& points) {
  checkDimension(s, "Continuum Kinematics");
  checkAssumedInfluenceFunction(s);
  const Topology& t = *s.topology;
  if (!t.bondSides.empty()) {
    throw InputError("Blocks",
                     "the continuum-kinematics material needs one horizon for all "
                     "bonded points (its triangles and tetrahedra are shared by "
                     "their corners)");
  }
  points_.insert(points_.end(), points.begin(), points.end());
  if (two_ || three_) {
    lists_ = buildPairLists(t, s.x, s.horizon, points_, s.bondFilters);
    edgeDamage_.assign(static_cast<std::size_t>(lists_.numPairs()), 0.0f);
  }
  const int dim = s.dimension;
  for (int i : points) {
    const double delta = s.horizon[i];
    double c1, c2, c3;
    constants(delta, dim, c1, c2, c3);
    const double full = dim == 3 ? 4.0 / 3.0 * kPi * delta * delta * delta : kPi * delta * delta;
    double neighbourhood = 0;  // area in 2D
    for (std::int64_t b = t.bondOffsets[i]; b < t.bondOffsets[i + 1]; ++b)
      neighbourhood += s.volume[t.neighbors[b]];
    if (dim == 2) neighbourhood /= s.thickness;
    // beta: the fullness of the neighbourhood (paper eq. 2.10), at most 1.
    const double vh = std::min(1.0, neighbourhood / full) * full;
    const double n1 = t.numNeighbors(i);
    const double n2 = lists_.pairOffsets.empty()
                          ? 0.0
                          : static_cast<double>(lists_.pairOffsets[i + 1] - lists_.pairOffsets[i]);
    const double n3 = three_ ? static_cast<double>(countTriples(s, i)) : 0.0;
    weights_[3 * i] = one_ && n1 > 0 ? c1 * vh / n1 * s.volume[i] : 0.0;
    weights_[3 * i + 1] = two_ && n2 > 0 ? c2 * vh * vh / n2 * s.volume[i] : 0.0;
    weights_[3 * i + 2] = three_ && n3 > 0 ? c3 * vh * vh * vh / n3 * s.volume[i] : 0.0;
  }
}

// Forces (kForce) or the stored energy of the point's own interactions, with an optional
// critical-stretch check (kBreak) that updates the bond damage and the tracked bonds j-k first.
namespace {

struct Kernel {
  const Topology* t;
  const double *x, *y, *w, *volume, *horizon, *bondLength;
  const float* damage;  // null: intact
  float* breakable;     // with kBreak
  double criticalStretch;
  const InteractionLists* lists;
  float* edge;  // per pair
  TripleScan* scan;
  bool one, two, three;
};

template <bool kForce, bool kBreak>
void pointTerms(const Kernel& k, int i, double* out) {
  const Topology& t = *k.t;
  const std::int64_t b0 = t.bondOffsets[i];
  const int n = t.numNeighbors(i);
  const int* nb = t.neighbors.data() + b0;
  const double* y = k.y;
  const double* w = k.w;
  double f[3] = {0, 0, 0}, energy = 0;
  // Bonds: force on i from both ends' potentials, 1/2 (w1_i + w1_j) (l - L)/(L l) Y.
  for (int a = 0; a < n; ++a) {
    const int j = nb[a];
    const double Y0 = y[3 * j] - y[3 * i], Y1 = y[3 * j + 1] - y[3 * i + 1],
                 Y2 = y[3 * j + 2] - y[3 * i + 2];
    const double l = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2), L = k.bondLength[b0 + a];
    if (kBreak && (l - L) / L > k.criticalStretch) k.breakable[b0 + a] = 1.0f;
    if (!k.one) continue;
    const double alive = k.damage ? 1.0 - k.damage[b0 + a] : 1.0;
    if (kForce) {
      const double q = l > 0 ? 0.5 * (w[3 * i] + w[3 * j]) * alive * (l - L) / (L * l) : 0.0;
      f[0] += q * Y0;
      f[1] += q * Y1;
      f[2] += q * Y2;
    } else {
      energy += 0.5 * w[3 * i] * alive * 0.5 * (l - L) * (l - L) / L;
    }
  }
  if (k.lists && !k.lists->pairOffsets.empty()) {
    const std::uint16_t* slots = k.lists->pairSlots.data();
    const std::int64_t q0 = k.lists->pairOffsets[i], q1 = k.lists->pairOffsets[i + 1];
    if (kBreak) {
      // The bond j-k between two neighbours, checked as j's owner checks it.
      for (std::int64_t q = q0; q < q1; ++q) {
        const int j = nb[slots[2 * q]], kk = nb[slots[2 * q + 1]];
        const double X0 = k.x[3 * kk] - k.x[3 * j], X1 = k.x[3 * kk + 1] - k.x[3 * j + 1],
                     X2 = k.x[3 * kk + 2] - k.x[3 * j + 2];
        const double Y0 = y[3 * kk] - y[3 * j], Y1 = y[3 * kk + 1] - y[3 * j + 1],
                     Y2 = y[3 * kk + 2] - y[3 * j + 2];
        const double L = std::sqrt(X0 * X0 + X1 * X1 + X2 * X2);
        const double l = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
        if ((l - L) / L > k.criticalStretch) k.edge[q] = 1.0f;
      }
    }
    auto intact = [&](int slot) { return k.damage ? 1.0 - k.damage[b0 + slot] : 1.0; };
    if (k.two) {
      for (std::int64_t q = q0; q < q1; ++q) {
        const int sa = slots[2 * q], sb = slots[2 * q + 1];
        const int j = nb[sa], kk = nb[sb];
        Corners c;
        c.set(0, k.x, y, i, j);
        c.set(1, k.x, y, i, kk);
        double Av[3], av[3];
        cross(c.X[0], c.X[1], Av);
        cross(c.Y[0], c.Y[1], av);
        const double A = std::sqrt(Av[0] * Av[0] + Av[1] * Av[1] + Av[2] * Av[2]);
        const double area = std::sqrt(av[0] * av[0] + av[1] * av[1] + av[2] * av[2]);
        const double dj = intact(sa), dk = intact(sb), e = 1.0 - k.edge[q];
        if (kForce) {
          // -d psi2/d y_i = (y_k - y_j) x g, g = (a - A)/(A a) a_vec; all three owners' terms.
          const double weight =
              w[3 * i + 1] * dj * dk + w[3 * j + 1] * dj * e + w[3 * kk + 1] * dk * e;
          const double s = area > 0 ? weight / 3.0 * (area - A) / (A * area) : 0.0;
          const double g[3] = {s * av[0], s * av[1], s * av[2]};
          const double jk[3] = {c.Y[1][0] - c.Y[0][0], c.Y[1][1] - c.Y[0][1],
                                c.Y[1][2] - c.Y[0][2]};
          double h[3];
          cross(jk, g, h);
          f[0] += h[0];
          f[1] += h[1];
          f[2] += h[2];
        } else {
          energy += w[3 * i + 1] * dj * dk / 3.0 * 0.5 * (area - A) * (area - A) / A;
        }
      }
    }
    if (k.three) {
      const double minVolume = 1e-10 * std::pow(k.horizon[i], 3);
      k.scan->reset(t, *k.lists, i);
      k.scan->forEach(
          *k.lists, i,
          [&](int sa, int sb, int sc, std::int64_t qab, std::int64_t qac, std::int64_t qbc) {
            const int j = nb[sa], kk = nb[sb], l = nb[sc];
            Corners c;
            c.set(0, k.x, y, i, j);
            c.set(1, k.x, y, i, kk);
            c.set(2, k.x, y, i, l);
            double Av[3], av[3];
            cross(c.X[0], c.X[1], Av);
            cross(c.Y[0], c.Y[1], av);
            const double V = std::fabs(Av[0] * c.X[2][0] + Av[1] * c.X[2][1] + Av[2] * c.X[2][2]);
            if (!(V > minVolume)) return;
            const double v = av[0] * c.Y[2][0] + av[1] * c.Y[2][1] + av[2] * c.Y[2][2];
            const double av3 = std::fabs(v);
            const double dj = intact(sa), dk = intact(sb), dl = intact(sc);
            const double ejk = 1.0 - k.edge[qab], ejl = 1.0 - k.edge[qac], ekl = 1.0 - k.edge[qbc];
            if (kForce) {
              const double weight = w[3 * i + 2] * dj * dk * dl + w[3 * j + 2] * dj * ejk * ejl +
                                    w[3 * kk + 2] * dk * ejk * ekl + w[3 * l + 2] * dl * ejl * ekl;
              // -d psi3/d y_i = (|v| - |V|)/|V| sign(v) (y_k - y_j) x (y_l - y_j).
              const double sign = v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0;
              const double s = weight / 4.0 * (av3 - V) / V * sign;
              const double u[3] = {c.Y[1][0] - c.Y[0][0], c.Y[1][1] - c.Y[0][1],
                                   c.Y[1][2] - c.Y[0][2]};
              const double r[3] = {c.Y[2][0] - c.Y[0][0], c.Y[2][1] - c.Y[0][1],
                                   c.Y[2][2] - c.Y[0][2]};
              double h[3];
              cross(u, r, h);
              f[0] += s * h[0];
              f[1] += s * h[1];
              f[2] += s * h[2];
            } else {
              energy += w[3 * i + 2] * dj * dk * dl / 4.0 * 0.5 * (av3 - V) * (av3 - V) / V;
            }
          });
    }
  }
  const double vi = k.volume[i];
  if (kForce) {
    out[3 * i] = f[0] / vi;
    out[3 * i + 1] = f[1] / vi;
    out[3 * i + 2] = f[2] / vi;
  } else {
    out[i] = energy / vi;
  }
}

}  // namespace

void ContinuumKinematics::computeForce(const ModelState& s, const std::vector<int>& points) {
  Kernel k{s.topology,
           s.x,
           s.y,
           weights_,
           s.volume,
           s.horizon,
           s.bondLength,
           s.bondDamage,
           s.breakableBondDamage,
           s.fusedCriticalStretch,
           &lists_,
           edgeDamage_.data(),
           &scan_,
           one_,
           two_,
           three_};
  const bool breaking = s.breakableBondDamage && s.fusedCriticalStretch > 0;
  if (breaking) {
    k.damage = s.breakableBondDamage;
    for (int i : points) pointTerms<true, true>(k, i, s.forceDensity);
  } else {
    for (int i : points) pointTerms<true, false>(k, i, s.forceDensity);
  }
}

void ContinuumKinematics::storedEnergyDensity(const ModelState& s, const std::vector<int>& points,
                                              double* energyDensity) const {
  Kernel k{s.topology, s.x,       s.y,          weights_,
           s.volume,   s.horizon, s.bondLength, s.bondDamage,
           nullptr,    0.0,       &lists_,      const_cast<float*>(edgeDamage_.data()),
           &scan_,     one_,      two_,         three_};
  for (int i : points) pointTerms<false, false>(k, i, energyDensity);
}

void ContinuumKinematics::stiffnessSum(const ModelState& s, const std::vector<int>& points,
                                       double* sum) const {
  // Diagonal of the Hessian of the energy at rest, per unit volume of p, with |C2|, |C3| (a
  // negative constant only softens: the bound stays safe).
  const Topology& t = *s.topology;
  const double* w = weights_;
  for (int i : points) {
    const std::int64_t b0 = t.bondOffsets[i];
    const int* nb = t.neighbors.data() + b0;
    double total = 0;
    for (int a = 0; a < t.numNeighbors(i); ++a) {
      const double L = s.bondLength[b0 + a];
      total += 0.5 * (w[3 * i] + w[3 * nb[a]]) / L;
    }
    if (two_) {
      for (std::int64_t q = lists_.pairOffsets[i]; q < lists_.pairOffsets[i + 1]; ++q) {
        const int j = nb[lists_.pairSlots[2 * q]], k = nb[lists_.pairSlots[2 * q + 1]];
        Corners c;
        c.set(0, s.x, s.x, i, j);
        c.set(1, s.x, s.x, i, k);
        double Av[3];
        cross(c.X[0], c.X[1], Av);
        const double A = std::sqrt(Av[0] * Av[0] + Av[1] * Av[1] + Av[2] * Av[2]);
        double jk2 = 0;
        for (int d = 0; d < 3; ++d) jk2 += (c.X[1][d] - c.X[0][d]) * (c.X[1][d] - c.X[0][d]);
        total += (std::fabs(w[3 * i + 1]) + std::fabs(w[3 * j + 1]) + std::fabs(w[3 * k + 1])) /
                 3.0 * jk2 / A;
      }
    }
    if (three_) {
      const double minVolume = 1e-10 * std::pow(s.horizon[i], 3);
      scan_.reset(t, lists_, i);
      scan_.forEach(
          lists_, i, [&](int sa, int sb, int sc, std::int64_t, std::int64_t, std::int64_t) {
            const int j = nb[sa], k = nb[sb], l = nb[sc];
            Corners c;
            c.set(0, s.x, s.x, i, j);
            c.set(1, s.x, s.x, i, k);
            c.set(2, s.x, s.x, i, l);
            double Av[3];
            cross(c.X[0], c.X[1], Av);
            const double V = std::fabs(Av[0] * c.X[2][0] + Av[1] * c.X[2][1] + Av[2] * c.X[2][2]);
            if (!(V > minVolume)) return;
            const double u[3] = {c.X[1][0] - c.X[0][0], c.X[1][1] - c.X[0][1],
                                 c.X[1][2] - c.X[0][2]};
            const double r[3] = {c.X[2][0] - c.X[0][0], c.X[2][1] - c.X[0][1],
                                 c.X[2][2] - c.X[0][2]};
            double h[3];
            cross(u, r, h);
            total += (std::fabs(w[3 * i + 2]) + std::fabs(w[3 * j + 2]) + std::fabs(w[3 * k + 2]) +
                      std::fabs(w[3 * l + 2])) /
                     4.0 * (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]) / V;
          });
    }
    sum[i] = total / s.volume[i];
  }
}

PERIDOT_REGISTER_MATERIAL(
    "Continuum Kinematics", ContinuumKinematics,
    "continuum-kinematics-inspired peridynamics (paper 004): bonds, triangles and tetrahedra "
    "of neighbours mutually within the horizon; any Poisson's ratio in (-1, 1/2)",
    (std::vector<ParameterDoc>{
        {"Density", "positive number, required: mass density"},
        {"Young's Modulus", "positive number: E (any two of E, nu, K, G)"},
        {"Poisson's Ratio", "number in (-1, 1/2): nu"},
        {"Bulk Modulus", "positive number: K"},
        {"Shear Modulus", "positive number: G"},
        {"Plane Stress",
         "bool, default false: planar, plane stress (C1 = 24 mu/(pi delta^3), C2 from "
         "lambda_2D - mu with lambda_2D = E nu/(1-nu^2))"},
        {"Plane Strain", "bool, default false: planar, plane strain (lambda_2D = lambda)"},
        {"One-Neighbor Interactions", "bool, default true: the bonds (C1)"},
        {"Two-Neighbor Interactions",
         "bool, default: planar and C2 != 0 (nu != 1/3 plane stress, != 1/4 plane strain); "
         "the triangles; an error in 3D (C2 = 0)"},
        {"Three-Neighbor Interactions",
         "bool, default: 3D and C3 != 0 (nu != 1/4); the tetrahedra; an error in 2D"}}))

}  // namespace peridot
