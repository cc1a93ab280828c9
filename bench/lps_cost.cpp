// Cost of one model evaluation (what a time step runs: damage, precompute, ghost refresh, force)
// of LPS ("Elastic") against PMB ("Elastic Bond Based"), both with "Critical Stretch", on the
// same N^3 lattice (delta = 3.015 dx, one rank), the evaluations of the models interleaved so
// that a shared machine's load hits them alike. Issue 16 item 3: LPS <= 2x PMB per step.
// LPS is run with omega = 1 and with omega = 1/|xi| (run_bench.py's LPS scene, LAMMPS's choice).
// The lattice is stretched 1e-4 anisotropically (no bond breaks; every bond is still checked).
// Prints the median CPU time per evaluation over the repeats, per bond entry, and the ratios;
// then the LPS phases measured alone (critical-stretch pass, dilatation pass, force pass).
// Usage: bench_lps_cost [N=48] [repeats=7] [evaluations per repeat=5]
#include <mpi.h>

#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "LatticeScene.hpp"

using namespace peridot;

namespace {

// The lattice stretched 1e-4 anisotropically; one block of `model` with critical stretch.
struct Scene : bench::LatticeScene {
  Scene(int n, const std::string& model, const std::string& influence) : LatticeScene(n) {
    for (int p = 0; p < topology.numOverlap; ++p) {
      y[3 * p] = x[3 * p] * (1 + 1e-4);
      y[3 * p + 1] = x[3 * p + 1] * (1 - 0.5e-4);
    }
    Teuchos::ParameterList m;
    m.set("Material Model", model);
    m.set("Density", 1.0);
    m.set("Bulk Modulus", 5.0 / 3.0);
    if (model == "Elastic") m.set("Shear Modulus", 1.0);
    Teuchos::ParameterList d;
    d.set("Damage Model", "Critical Stretch");
    d.set("Critical Stretch", 0.01);
    setBlock(m, &d, influence);
    evaluator->initialize();
  }
};

double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// CPU seconds per call of `work`, `count` calls.
double timeOf(int count, const std::function<void()>& work) {
  const double t0 = cpuSeconds();
  for (int k = 0; k < count; ++k) work();
  return (cpuSeconds() - t0) / count;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const int n = argc > 1 ? std::atoi(argv[1]) : 48;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 7;
  const int evaluations = argc > 3 ? std::atoi(argv[3]) : 5;
  {
    struct Case {
      const char* name;
      std::unique_ptr<Scene> scene;
      std::vector<double> seconds;
    };
    std::vector<Case> cases;
    cases.push_back({"PMB", std::make_unique<Scene>(n, "Elastic Bond Based", "One"), {}});
    cases.push_back({"LPS omega=1", std::make_unique<Scene>(n, "Elastic", "One"), {}});
    cases.push_back({"LPS omega=1/|xi|", std::make_unique<Scene>(n, "Elastic", "1.0/zeta"), {}});
    const double bonds = static_cast<double>(cases[0].scene->topology.numBonds());
    std::printf("%d^3 points, %.0f bond entries, %d repeats x %d evaluations, load %s\n", n, bonds,
                repeats, evaluations, loadAverage().c_str());
    for (auto& c : cases) c.scene->evaluator->evaluate(1.0);  // first touch
    for (int r = 0; r < repeats; ++r)
      for (auto& c : cases)
        c.seconds.push_back(timeOf(evaluations, [&] { c.scene->evaluator->evaluate(1.0); }));
    const double pmb = median(cases[0].seconds);
    std::printf("%-18s %12s %10s %10s\n", "model", "CPU ms/eval", "ns/bond", "/ PMB");
    for (auto& c : cases) {
      const double t = median(c.seconds);
      std::printf("%-18s %12.2f %10.2f %10.3f\n", c.name, 1e3 * t, 1e9 * t / bonds, t / pmb);
    }
    // LPS phases alone (the evaluator's order), interleaved likewise.
    for (std::size_t k = 1; k < cases.size(); ++k) {
      Scene& s = *cases[k].scene;
      Block& b = s.blocks[0];
      ModelState st = s.evaluator->state();
      st.halfBonds = s.evaluator->halfBondList();  // evaluate() sets it for its loops only
      // The separate damage pass writes float damage; where the evaluator keeps broken-bond
      // flags instead (compact damage, the usual case) it is timed on a buffer of its own.
      std::vector<float> floatDamage(st.bondDamage ? 0 : s.topology.neighbors.size(), 0.0f);
      float* damage = st.bondDamage ? const_cast<float*>(st.bondDamage) : floatDamage.data();
      // The dilatation pass as the evaluator runs it: with the critical stretch when it is fused
      // there (Elastic::breaksInPrecompute), in the damage form the evaluator keeps; else after
      // the separate damage pass.
      ModelState pre = st;
      const bool fused = b.material->breaksInPrecompute();
      if (fused) {
        if (st.bondDamage)
          pre.breakableBondDamage = damage;
        else
          pre.breakableBondBroken = const_cast<unsigned char*>(st.bondBroken);
        pre.fusedCriticalStretch = b.damage->fusableCriticalStretch();
      }
      std::vector<double> tDamage, tPre, tForce;
      for (int r = 0; r < repeats; ++r) {
        tDamage.push_back(
            timeOf(evaluations, [&] { b.damage->computeDamage(st, b.points, damage); }));
        tPre.push_back(timeOf(evaluations, [&] { b.material->precompute(pre, b.points); }));
        tForce.push_back(timeOf(evaluations, [&] { b.material->computeForce(st, b.points); }));
      }
      std::printf(
          "%s phases, CPU ms (ns/bond): separate damage pass %.2f (%.2f%s), "
          "precompute%s %.2f (%.2f), force %.2f (%.2f)\n",
          cases[k].name, 1e3 * median(tDamage), 1e9 * median(tDamage) / bonds,
          fused ? ", not run by the evaluator" : "", fused ? " with the critical stretch" : "",
          1e3 * median(tPre), 1e9 * median(tPre) / bonds, 1e3 * median(tForce),
          1e9 * median(tForce) / bonds);
    }
    std::printf("load at the end %s\n", loadAverage().c_str());
  }
  MPI_Finalize();
  return 0;
}
