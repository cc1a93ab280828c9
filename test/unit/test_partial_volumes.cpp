// Partial-volume quadrature (`Discretization -> Partial Volumes`): the cell-fraction formula
// against brute-force sampling, the neighbourhood volume against the ball's, and the energy
// density of homogeneous deformations against the continuum's 1/2 sigma : epsilon in 3D, plane
// stress and plane strain, for LPS at four Poisson's ratios and for the bond-based models.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "Materials.hpp"
#include "SerialProblem.hpp"
#include "neighbor/PartialVolume.hpp"

namespace peridot {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The fraction of the cell [-h/2, h/2]^d around xi inside the ball of radius `horizon`, by
// sampling n^d sub-cell centres.
double sampledFraction(const double xi[3], double h, double horizon, int dim, int n) {
  long inside = 0, total = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < (dim == 3 ? n : 1); ++c) {
        const double u[3] = {(a + 0.5) / n - 0.5, (b + 0.5) / n - 0.5,
                             dim == 3 ? (c + 0.5) / n - 0.5 : 0.0};
        double r2 = 0;
        for (int k = 0; k < dim; ++k) r2 += (xi[k] + h * u[k]) * (xi[k] + h * u[k]);
        inside += r2 <= horizon * horizon;
        ++total;
      }
  return double(inside) / double(total);
}

TEST(PartialVolumes, CellFractionMatchesSampling) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int dim : {2, 3}) {
    double worst = 0;
    for (int trial = 0; trial < 200; ++trial) {
      double xi[3] = {4 * U(rng), 4 * U(rng), dim == 3 ? 4 * U(rng) : 0.0};
      if (trial % 5 == 0) xi[1] = 0;  // axis-parallel planes: the degenerate closed form
      double zeta = std::sqrt(xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]);
      if (zeta < 2) {  // horizons of at least two cells
        for (double& c : xi) c *= 2 / zeta;
        zeta = 2;
      }
      const double h = 0.5 + 0.5 * std::fabs(U(rng));
      const double horizon = zeta + 0.9 * h * U(rng);  // the plane crosses the cell
      const double exact = cellFractionInHorizon(xi, zeta, h, horizon, dim);
      const double sampled = sampledFraction(xi, h, horizon, dim, dim == 3 ? 80 : 400);
      worst = std::max(worst, std::fabs(exact - sampled));
      EXPECT_NEAR(exact, sampled, 0.005) << "dim " << dim << " trial " << trial;
    }
    std::printf("  dim %d: largest difference to sampling %.4f\n", dim, worst);
    // Whole inside or outside beyond half the cell diagonal.
    const double x[3] = {3, 0, 0};
    EXPECT_EQ(cellFractionInHorizon(x, 3, 1, 3.0 + 0.5 * std::sqrt(dim), dim), 1.0);
    EXPECT_EQ(cellFractionInHorizon(x, 3, 1, 3.0 - 0.5 * std::sqrt(dim), dim), 0.0);
  }
}

// A periodic lattice of spacing 1 in `dim` dimensions, large enough that no point sees its own
// image within the reach of partial volumes.
testing::Problem lattice(std::shared_ptr<MaterialModel> m, double delta, int dim, double thickness,
                         bool partial, const std::string& influence = "One") {
  const int n = static_cast<int>(std::ceil(2 * (delta + cellOverlapReach(1.0, dim)))) + 1;
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < (dim == 3 ? n : 1); ++k) pts.push_back({double(i), double(j), double(k)});
  PeriodicBox box;
  for (int d = 0; d < dim; ++d) {
    box.periodic[d] = true;
    box.lower[d] = -0.5;
    box.upper[d] = n - 0.5;
  }
  return testing::Problem(pts, delta, std::move(m), nullptr, box, dim == 3 ? 1.0 : thickness,
                          influence, dim == 3 ? 0.0 : thickness, partial);
}

// Continuum energy density of the strain eps (3x3, symmetric): 3D, or in-plane for a mode.
double continuumEnergy(const std::string& mode, double E, double nu, const double eps[3][3]) {
  const double mu = E / (2 * (1 + nu));
  const double lambda = mode.empty()             ? E * nu / ((1 + nu) * (1 - 2 * nu))
                        : mode == "Plane Stress" ? E * nu / (1 - nu * nu)
                                                 : E * nu / ((1 + nu) * (1 - 2 * nu));
  const double tr = eps[0][0] + eps[1][1] + eps[2][2];
  double ee = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) ee += eps[a][b] * eps[a][b];
  return 0.5 * lambda * tr * tr + mu * ee;
}

// The three homogeneous deformations: dilatation, simple shear along the lattice axes, and
// the same shear turned by 45 degrees (pure shear along the axes).
struct Deformation {
  const char* name;
  double H[3][3];
  double eps[3][3];
};
std::vector<Deformation> deformations(int dim) {
  const double s = 1e-4, g = 1e-4;
  const double sz = dim == 3 ? s : 0;
  return {
      {"dilatation", {{s, 0, 0}, {0, s, 0}, {0, 0, sz}}, {{s, 0, 0}, {0, s, 0}, {0, 0, sz}}},
      {"simple shear",
       {{0, g, 0}, {0, 0, 0}, {0, 0, 0}},
       {{0, g / 2, 0}, {g / 2, 0, 0}, {0, 0, 0}}},
      {"45-degree shear", {{g, 0, 0}, {0, -g, 0}, {0, 0, 0}}, {{g, 0, 0}, {0, -g, 0}, {0, 0, 0}}}};
}

// The neighbourhood's weights add up to the ball's volume (disk's area x thickness), which is
// what makes the analytic micromoduli right.
TEST(PartialVolumes, NeighbourhoodVolumeIsTheBall) {
  for (int dim : {3, 2}) {
    for (double delta : {3.0, 4.0, 5.0}) {
      const double t = 0.5;
      testing::Problem pr =
          lattice(testing::material("Elastic", dim == 3 ? "" : "Plane Strain", 1.0, 0.25), delta,
                  dim, t, true);
      const ModelState& s = pr.evaluator->state();
      double sum = 0, sumCentres = 0;
      for (std::int64_t b = pr.topology.bondOffsets[0]; b < pr.topology.bondOffsets[1]; ++b) {
        sum += s.influence[b] * s.volume[pr.topology.neighbors[b]];
        sumCentres += s.bondLength[b] <= delta ? s.volume[pr.topology.neighbors[b]] : 0.0;
      }
      // The point's own cell is part of the ball too.
      sum += s.volume[0];
      sumCentres += s.volume[0];
      const double ball =
          dim == 3 ? 4.0 / 3.0 * kPi * delta * delta * delta : kPi * delta * delta * t;
      std::printf("  dim %d delta %.0f: partial volumes %+.3f%%, centres inside %+.3f%%\n", dim,
                  delta, 100 * (sum / ball - 1), 100 * (sumCentres / ball - 1));
      EXPECT_NEAR(sum / ball, 1.0, 0.003) << dim << " " << delta;
    }
  }
}

// Relative errors of the three deformations' energies on a lattice.
std::vector<double> errors(std::shared_ptr<MaterialModel> m, const std::string& mode, double E,
                           double nu, double delta, bool partial,
                           const std::string& influence = "One") {
  const int dim = mode.empty() ? 3 : 2;
  testing::Problem pr = lattice(std::move(m), delta, dim, 0.5, partial, influence);
  std::vector<double> e;
  for (const Deformation& d : deformations(dim))
    e.push_back(pr.energyDensityUnder(d.H) / continuumEnergy(mode, E, nu, d.eps) - 1);
  return e;
}

const char* modeName(const std::string& mode) { return mode.empty() ? "3D" : mode.c_str(); }

// LPS (`Elastic`, Le et al. 2014 in 2D) and the linearized LPS: dilatation exact (as without
// partial volumes); shear within 1% of the continuum from delta = 4 dx (3D) and 5 dx (2D) on,
// at every Poisson's ratio and along or across the lattice axes. The same lattices with the
// centre-inside rule (delta + 0.015 dx) miss by up to 2.9% (3D, 4 dx) and 8.7% (2D, 5 dx).
TEST(PartialVolumes, LPSHomogeneousEnergyWithinOnePercent) {
  const double E = 2.0;
  std::printf(
      "  %-18s %-12s  nu    delta  partial volumes: dilatation, shear, 45-degree shear"
      " | centres inside\n",
      "model", "mode");
  for (const std::string model : {"Elastic", "Linearized LPS"}) {
    for (const std::string mode : {"", "Plane Stress", "Plane Strain"}) {
      const int dim = mode.empty() ? 3 : 2;
      for (double nu : {0.1, 0.22, 0.3, 0.45}) {
        for (double delta : dim == 3 ? std::vector<double>{3, 4} : std::vector<double>{4, 5}) {
          const auto e = errors(testing::material(model, mode, E, nu), mode, E, nu, delta, true);
          const auto c =
              errors(testing::material(model, mode, E, nu), mode, E, nu, delta + 0.015, false);
          std::printf(
              "  %-18s %-12s  %4.2f  %5.1f  %+8.3f%% %+8.3f%% %+8.3f%% | %+8.3f%% %+8.3f%%"
              " %+8.3f%%\n",
              model.c_str(), modeName(mode), nu, delta, 100 * e[0], 100 * e[1], 100 * e[2],
              100 * c[0], 100 * c[1], 100 * c[2]);
          EXPECT_NEAR(e[0], 0.0, 1e-8) << model << " " << mode << " nu " << nu << " " << delta;
          if (delta >= (dim == 3 ? 4 : 5)) {
            EXPECT_LT(std::fabs(e[1]), 0.01) << model << " " << mode << " nu " << nu;
            EXPECT_LT(std::fabs(e[2]), 0.01) << model << " " << mode << " nu " << nu;
          }
        }
      }
    }
  }
}

// Bond-based models at their fixed Poisson's ratio (1/4 in 3D and plane strain, 1/3 in plane
// stress), PMB with its analytic micromodulus and the normalized PMB: all three energies within
// 1% with omega = 1 from delta = 6 dx (3D) and 8 dx (2D), with the conical influence function
// in 2D from 16 dx. Their error comes from the cells near the centre, where one direction stands
// for a whole cell (the bond-based energy weighs them as much as far ones; LPS's by |xi|^2), so
// it falls like (dx/delta)^2 and partial volumes do not remove it; 3D conical: DISABLED_ study.
TEST(PartialVolumes, BondBasedHomogeneousEnergyWithinOnePercent) {
  const double E = 3.0;
  struct Case {
    std::string mode, influence;
    double delta;
  };
  const std::vector<Case> cases = {{"", "One", 6},
                                   {"Plane Stress", "One", 8},
                                   {"Plane Strain", "One", 8},
                                   {"Plane Stress", "Conical", 16},
                                   {"Plane Strain", "Conical", 16}};
  for (const Case& k : cases) {
    const double nu = k.mode == "Plane Stress" ? 1.0 / 3.0 : 0.25;
    for (const std::string model : {"Elastic Bond Based", "Normalized PMB"}) {
      const auto e =
          errors(testing::material(model, k.mode, E), k.mode, E, nu, k.delta, true, k.influence);
      std::printf(
          "  %-18s %-12s %-8s delta %4.1f: dilatation %+7.3f%%, shear %+7.3f%%, "
          "45-degree shear %+7.3f%%\n",
          model.c_str(), modeName(k.mode), k.influence.c_str(), k.delta, 100 * e[0], 100 * e[1],
          100 * e[2]);
      for (double x : e)
        EXPECT_LT(std::fabs(x), 0.01) << model << " " << k.mode << " " << k.influence;
    }
  }
}

// The convergence study behind the figures above (ctest -L long): bond-based errors with and
// without partial volumes at growing delta, 3D and 2D, omega = 1 and conical.
TEST(PartialVolumes, DISABLED_BondBasedConvergenceStudy) {
  const double E = 3.0;
  for (const std::string mode : {"", "Plane Strain"}) {
    const double nu = 0.25;
    for (const std::string influence : {"One", "Conical"}) {
      for (double delta : mode.empty() ? std::vector<double>{3, 4, 5, 6, 8}
                                       : std::vector<double>{3, 4, 5, 6, 8, 12, 16}) {
        for (const std::string model : {"Elastic Bond Based", "Normalized PMB"}) {
          const auto e =
              errors(testing::material(model, mode, E), mode, E, nu, delta, true, influence);
          const auto c = errors(testing::material(model, mode, E), mode, E, nu, delta + 0.015,
                                false, influence);
          std::printf(
              "  %-18s %-12s %-8s %4.1f  partial %+7.3f%% %+7.3f%% %+7.3f%% | centres "
              "%+7.3f%% %+7.3f%% %+7.3f%%\n",
              model.c_str(), modeName(mode), influence.c_str(), delta, 100 * e[0], 100 * e[1],
              100 * e[2], 100 * c[0], 100 * c[1], 100 * c[2]);
          if (delta >= 8 && mode.empty()) {
            for (double x : e) EXPECT_LT(std::fabs(x), 0.01) << model << " " << influence;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace peridot
