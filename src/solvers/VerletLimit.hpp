#pragma once
// The true stability limit of velocity Verlet for the linearized problem: Δt_crit = 2/sqrt(λ_max)
// with λ_max the largest eigenvalue of ρ⁻¹K, K the stiffness (force density per displacement)
// at the reference configuration. Peridigm's estimate bounds λ_max from above by a row sum
// (Gershgorin-like), which on lattices is about twice too small a step; this one finds λ_max by
// Lanczos iteration on the matrix-free operator, K v taken by central differences of the force.
//
// ρ⁻¹K is self-adjoint in the inner product <u, w> = Σ_i ρ_i V_i u_i · w_i (V_i K_ij is the
// symmetric force-per-displacement matrix), so Lanczos runs in that inner product. Its dot
// products are summed in 64-bit fixed point, so that the estimate has the same bits at any rank
// count (nodal results stay rank-count independent).
#include <functional>
#include <string>

#include "parallel/Topology.hpp"

namespace peridot {

struct VerletLimitResult {
  double lambdaMax = 0;   // largest Ritz value of ρ⁻¹K
  double residual = 0;    // norm of its Ritz residual (in the mass inner product)
  double stableStep = 0;  // 2 / sqrt(lambdaMax + residual): the step the run may take
  int iterations = 0;
  bool converged = false;
};

// `applyStiffness(v, Kv)`: Kv = K v (force density per unit displacement, owned points, 3 per
// point) for a displacement v given on the owned points. `density` and `volume` per owned
// point; `dimension` 2 projects out z. Iterates until the largest Ritz value changes by less
// than `tolerance` (relative) or `maxIterations`. Collective.
VerletLimitResult estimateVerletLimit(
    const Topology& topology, const double* density, const double* volume, int dimension,
    const std::function<void(const double*, double*)>& applyStiffness, int maxIterations = 300,
    double tolerance = 1e-9);

class ModelEvaluator;

// The same estimate for the model's linearization about the configuration `base` (3 per owned
// point: the reference coordinates for the time step, x + u for dynamic relaxation): K v by
// central differences of the evaluator's internal force, y = base +- eps v with eps max|v| =
// 1e-6 of the smallest horizon (linear to round-off there, no critical stretch reached) and no
// bond breaking. `y` (overlap) and `f` (owned) are the evaluator's current coordinates and force
// density; both are restored. Collective.
VerletLimitResult estimateVerletLimitAbout(const Topology& topology, ModelEvaluator& evaluator,
                                           const double* base, double* y, double* f,
                                           const double* density, const double* volume,
                                           int dimension);

// Largest eigenvalue of the symmetric tridiagonal matrix (alpha on the diagonal, beta below),
// by bisection on the Sturm sequence. Exposed for tests.
double largestTridiagonalEigenvalue(const double* alpha, const double* beta, int n);

}  // namespace peridot
