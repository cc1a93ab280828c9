// Roofline of the bond loop: how fast can one core stream the arrays a PMB + critical-stretch
// force loop must read (CSR neighbour indices, reference bond lengths, bond damage, and the
// neighbours' current coordinates and micromoduli, gathered), and how fast does Peridot's
// actual force loop (and damage loop) run over the same arrays? Reported as bond visits per
// second; the force loop's fraction of the streaming rate is the figure of merit.
// Usage: bench_roofline [--benchmark_min_time=1]   (Google Benchmark options)
#include <benchmark/benchmark.h>
#include <mpi.h>

#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "LatticeScene.hpp"
#include "neighbor/HalfBondList.hpp"

using namespace peridot;

namespace {

// The lattice stretched 1e-4 and 2e-4 along y and z in its reference (no strain), PMB with a
// critical stretch that no bond reaches.
struct Scene : bench::LatticeScene {
  explicit Scene(int n) : LatticeScene(n) {
    for (int p = 0; p < topology.numOverlap; ++p)
      for (int d = 0; d < 3; ++d) x[3 * p + d] = y[3 * p + d] = x[3 * p + d] * (1 + 1e-4 * d);
    Teuchos::ParameterList m;
    m.set("Material Model", "Elastic Bond Based");
    m.set("Density", 1.0);
    m.set("Bulk Modulus", 1.0);
    Teuchos::ParameterList d;
    d.set("Damage Model", "Critical Stretch");
    d.set("Critical Stretch", 0.5);
    setBlock(m, &d, "One");
    evaluator->setHalfBondListAllowed(
        false);  // the full lists' loops; the half list is built apart
    evaluator->initialize();
  }
};

std::unique_ptr<Scene> theScene;  // destroyed before MPI_Finalize

Scene& scene() {
  if (!theScene) theScene = std::make_unique<Scene>(48);  // 110592 points, 13 M bonds
  return *theScene;
}

// The floor: read every array the force loop reads, once, with the same gather pattern, and
// do nothing with it but add.
void StreamBondArrays(benchmark::State& state) {
  Scene& s = scene();
  const ModelState& st = s.evaluator->state();
  const std::int64_t* off = s.topology.bondOffsets.data();
  const int* nb = s.topology.neighbors.data();
  const double* c = s.fields->node("PMB_Micromodulus", 1);
  for (auto _ : state) {
    double sum = 0;
    for (int i = 0; i < s.topology.numOwned; ++i) {
      double local = 0;
      for (std::int64_t b = off[i]; b < off[i + 1]; ++b) {
        const int j = nb[b];
        local += st.bondLength[b] + st.bondDamage[b] + st.y[3 * j] + st.y[3 * j + 1] +
                 st.y[3 * j + 2] + c[j] + st.volume[j];
      }
      sum += local;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["bonds/s"] = benchmark::Counter(
      static_cast<double>(s.topology.numBonds()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(StreamBondArrays)->Unit(benchmark::kMillisecond);

void PMBForceLoop(benchmark::State& state) {
  Scene& s = scene();
  for (auto _ : state) s.blocks[0].material->computeForce(s.evaluator->state(), s.blocks[0].points);
  state.counters["bonds/s"] = benchmark::Counter(
      static_cast<double>(s.topology.numBonds()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(PMBForceLoop)->Unit(benchmark::kMillisecond);

void CriticalStretchLoop(benchmark::State& state) {
  Scene& s = scene();
  float* damage = const_cast<float*>(s.evaluator->state().bondDamage);
  for (auto _ : state)
    s.blocks[0].damage->computeDamage(s.evaluator->state(), s.blocks[0].points, damage);
  state.counters["bonds/s"] = benchmark::Counter(
      static_cast<double>(s.topology.numBonds()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(CriticalStretchLoop)->Unit(benchmark::kMillisecond);

// What a PMB + critical-stretch step runs: the stretch check fused into the force loop (the
// evaluator's default), against PMBForceLoop + CriticalStretchLoop done separately.
void PMBForceLoopFusedCriticalStretch(benchmark::State& state) {
  Scene& s = scene();
  ModelState st = s.evaluator->state();
  st.breakableBondDamage = const_cast<float*>(st.bondDamage);
  st.fusedCriticalStretch = s.blocks[0].damage->fusableCriticalStretch();
  for (auto _ : state) s.blocks[0].material->computeForce(st, s.blocks[0].points);
  state.counters["bonds/s"] = benchmark::Counter(
      static_cast<double>(s.topology.numBonds()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(PMBForceLoopFusedCriticalStretch)->Unit(benchmark::kMillisecond);

// The same step over the half bond list that runs do (neighbor/HalfBondList.hpp): each bond once,
// the pair force added to one end and subtracted from the other, rank-count identical.
void PMBHalfBondListFusedCriticalStretch(benchmark::State& state) {
  Scene& s = scene();
  ModelState st = s.evaluator->state();
  st.breakableBondDamage = const_cast<float*>(st.bondDamage);
  st.fusedCriticalStretch = s.blocks[0].damage->fusableCriticalStretch();
  // Built as the evaluator builds it for a run (the scene's evaluator keeps the full lists).
  HalfBondList half;
  if (!buildHalfBondList(s.topology, half)) {
    state.SkipWithError("no half bond list");
    return;
  }
  half.storeLengths(st.x);
  half.gatherDamage(s.topology, st.bondDamage, nullptr);
  st.halfBonds = &half;
  for (auto _ : state) s.blocks[0].material->computeForce(st, s.blocks[0].points);
  state.counters["bonds/s"] = benchmark::Counter(
      static_cast<double>(s.topology.numBonds()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(PMBHalfBondListFusedCriticalStretch)->Unit(benchmark::kMillisecond);

// An experiment for issue 16 (not what Peridot runs): the full list walked by plain scalar code
// (no vector lanes, no gathers: without `omp simd` GCC keeps the force sum in order, so it does
// not vectorize the loop), to tell what the vector lanes of PMBForceLoop buy.
void PMBFullListScalarExperiment(benchmark::State& state) {
  Scene& s = scene();
  const ModelState& st = s.evaluator->state();
  const std::int64_t* off = s.topology.bondOffsets.data();
  const int* nb = s.topology.neighbors.data();
  const double* c = s.fields->node("PMB_Micromodulus", 1);
  const int n = s.topology.numOwned;
  std::vector<float> damage(s.topology.numBonds(), 0.0f);
  std::vector<double> f(3 * n);
  const double criticalStretch = 0.5;
  for (auto _ : state) {
    for (int i = 0; i < n; ++i) {
      const double yi0 = st.y[3 * i], yi1 = st.y[3 * i + 1], yi2 = st.y[3 * i + 2];
      const double ci = c[i];
      double f0 = 0, f1 = 0, f2 = 0;
      for (std::int64_t b = off[i]; b < off[i + 1]; ++b) {
        const int j = nb[b];
        const double zb = st.bondLength[b];
        const double Y0 = st.y[3 * j] - yi0, Y1 = st.y[3 * j + 1] - yi1, Y2 = st.y[3 * j + 2] - yi2;
        const double dY = std::sqrt(Y0 * Y0 + Y1 * Y1 + Y2 * Y2);
        if ((dY - zb) / zb > criticalStretch) damage[b] = 1.0f;
        const double g =
            (ci + c[j]) * (1.0 - damage[b]) * (dY - zb) * st.volume[j] / (2.0 * zb * dY);
        f0 += g * Y0;
        f1 += g * Y1;
        f2 += g * Y2;
      }
      f[3 * i] = f0;
      f[3 * i + 1] = f1;
      f[3 * i + 2] = f2;
    }
    benchmark::DoNotOptimize(f.data());
  }
  state.counters["bonds/s"] = benchmark::Counter(
      static_cast<double>(s.topology.numBonds()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(PMBFullListScalarExperiment)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  theScene.reset();
  MPI_Finalize();
  return 0;
}
