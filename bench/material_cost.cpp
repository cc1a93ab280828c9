// Cost of one force evaluation (precompute + force, as the evaluator runs them on one rank) per
// bond entry for each ordinary state-based and correspondence model, against "Elastic" (LPS) on the
// same scene: a 40^3 cube, delta = 3.015 dx, stretched anisotropically (deviatoric strain ~1e-4) so
// that the plastic models yield at every step (sigma_Y = 1e-6 G) and take their plastic branch.
// The points move with the velocity of that stretch per unit time (dt = 1), so that the
// correspondence models' rate form (their default) accumulates stress and yields too; each
// correspondence model but the viscoplastic one (rate form only) is also measured with "Stress
// Integration: Total Lagrangian Green Strain". The hypoelastic correspondence family (Peridigm's:
// gradient on the current bonds, a stress per bond) is measured at gradient orders 1 and 2, the
// elastic bond-associated model at gradient orders 1, 2 and 3.
// Usage: bench_material_cost [--benchmark_min_time=1] [--benchmark_repetitions=5]
#include <benchmark/benchmark.h>
#include <mpi.h>

#include <Teuchos_ParameterList.hpp>
#include <map>
#include <memory>
#include <string>

#include "LatticeScene.hpp"

using namespace peridot;

namespace {

// The lattice stretched anisotropically, moving with the velocity of that stretch.
struct Scene : bench::LatticeScene {
  Scene(int n, const std::string& model, const std::string& integration) : LatticeScene(n) {
    const bool bondAssociatedHardening =
        model == "Isotropic Hardening Bond Associated Correspondence";
    double* vel = fields->node("Velocity", 3);
    for (int p = 0; p < topology.numOverlap; ++p) {
      y[3 * p] = x[3 * p] * (1 + 1e-4);
      y[3 * p + 1] = x[3 * p + 1] * (1 - 0.5e-4);
      vel[3 * p] = 1e-4 * x[3 * p];
      vel[3 * p + 1] = -0.5e-4 * x[3 * p + 1];
    }
    Teuchos::ParameterList m;
    m.set("Material Model", model);
    m.set("Density", 1.0);
    m.set("Bulk Modulus", 5.0 / 3.0);
    m.set("Shear Modulus", 1.0);
    if ((model.find("Plastic") != std::string::npos ||
         model.find("Hardening") != std::string::npos ||
         model.find("Viscoplastic") != std::string::npos) &&
        !bondAssociatedHardening)
      m.set("Yield Stress", 1e-6);
    if (bondAssociatedHardening) {
      // Flowing at every bond and step, on Peridigm's power law (a Newton return per bond).
      m.set("Hardening Rule", "Power-law");
      auto& h = m.sublist("Hardening Parameters");
      h.set("Yield Stress", 1e-6);
      h.set("Hardening Characteristic Strain", 1e-6);
      h.set("Hardening Exponent", 0.2);
    }
    if (model == "Elastic Plastic Hardening") m.set("Hardening Modulus", 1e-16);
    if (model.find("Correspondence") != std::string::npos) m.set("Hourglass Coefficient", 0.02);
    if (model == "Isotropic Hardening Correspondence") m.set("Hardening Modulus", 0.01);
    if (model == "Viscoplastic Needleman Correspondence") {
      // Flowing at every point and step: sigma_Y 1e-6 G, the scene's strain rate 1e-4 against
      // a reference rate of 1e-5, softening and hardening both active.
      m.set("Strain Hardening Exponent", 0.1);
      m.set("Rate Hardening Exponent", 0.05);
      m.set("Reference Strain Rate", 1e-5);
      m.set("Reference Strain 0", 1e-6);
      m.set("Reference Strain 1", 1e-3);
    }
    if (model.find("Hypoelastic") != std::string::npos) {
      // Peridigm's hypoelastic family: `integration` carries the gradient order here.
      m.set("Actual Horizon", bench::kLatticeHorizon);
      m.set("Gradient Order Of Accuracy", integration.empty() ? 1 : std::stoi(integration));
      if (model == "Isotropic Hardening Hypoelastic Correspondence") {
        m.set("Hardening Characteristic Strain", 1e-6);
        m.set("Hardening Exponent", 0.2);
      }
    } else if (model.find("Bond Associated") != std::string::npos) {
      // The bond-associated family: `integration` carries the gradient order.
      if (!integration.empty()) m.set("Gradient Order Of Accuracy", std::stoi(integration));
    } else if (!integration.empty()) {
      m.set("Stress Integration", integration);
    }
    if (model == "Viscoelastic") {
      m.set("lambda_i", 0.5);
      m.set("tau b", 10.0);
    }
    setBlock(m, nullptr, "One");
    evaluator->initialize();
  }
};

std::map<std::string, std::unique_ptr<Scene>> scenes;  // destroyed before MPI_Finalize

// n: points per side of the cubic scene (40 by default; the bond-associated models keep ~60
// doubles per bond entry, 3.7 GB at 40^3, so they and their `Elastic` reference run at 20^3).
void Evaluate(benchmark::State& state, const std::string& model,
              const std::string& integration = "", int n = 40) {
  auto& s = scenes[model + integration + std::to_string(n)];
  if (!s) s = std::make_unique<Scene>(n, model, integration);
  ModelState st = s->evaluator->state();
  st.dt = 1.0;
  st.halfBonds = s->evaluator->halfBondList();  // evaluate() sets it for its loops only
  Block& b = s->blocks[0];
  for (auto _ : state) {
    b.material->precompute(st, b.points);
    b.material->computeForce(st, b.points);
  }
  // Bond entries per evaluation: divide the CPU time by it for the cost per bond update.
  state.counters["bond_entries"] = static_cast<double>(s->topology.numBonds());
}

}  // namespace

BENCHMARK_CAPTURE(Evaluate, Elastic, std::string("Elastic"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticPlastic, std::string("Elastic Plastic"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticPlasticHardening, std::string("Elastic Plastic Hardening"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, Viscoelastic, std::string("Viscoelastic"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, Pals, std::string("Pals"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticCorrespondence, std::string("Elastic Correspondence"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticPlasticCorrespondence,
                  std::string("Elastic Plastic Correspondence"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, IsotropicHardeningCorrespondence,
                  std::string("Isotropic Hardening Correspondence"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ViscoplasticNeedlemanCorrespondence,
                  std::string("Viscoplastic Needleman Correspondence"))
    ->Unit(benchmark::kMillisecond);
const std::string kGreen = "Total Lagrangian Green Strain";
BENCHMARK_CAPTURE(Evaluate, ElasticCorrespondenceGreen, std::string("Elastic Correspondence"),
                  kGreen)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticPlasticCorrespondenceGreen,
                  std::string("Elastic Plastic Correspondence"), kGreen)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, IsotropicHardeningCorrespondenceGreen,
                  std::string("Isotropic Hardening Correspondence"), kGreen)
    ->Unit(benchmark::kMillisecond);

// The bond-associated family and its `Elastic` reference on the 20^3 scene.
BENCHMARK_CAPTURE(Evaluate, Elastic20, std::string("Elastic"), std::string(), 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticCorrespondence20, std::string("Elastic Correspondence"),
                  std::string(), 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticBondAssociatedCorrespondence20,
                  std::string("Elastic Bond Associated Correspondence"), std::string(), 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticBondAssociatedCorrespondenceOrder2_20,
                  std::string("Elastic Bond Associated Correspondence"), std::string("2"), 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticBondAssociatedCorrespondenceOrder3_20,
                  std::string("Elastic Bond Associated Correspondence"), std::string("3"), 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticPlasticBondAssociatedCorrespondence20,
                  std::string("Elastic Plastic Bond Associated Correspondence"), std::string(), 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, IsotropicHardeningBondAssociatedCorrespondence20,
                  std::string("Isotropic Hardening Bond Associated Correspondence"), std::string(),
                  20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticHypoelasticCorrespondence,
                  std::string("Elastic Hypoelastic Correspondence"), std::string("1"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticHypoelasticCorrespondenceOrder2,
                  std::string("Elastic Hypoelastic Correspondence"), std::string("2"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, ElasticPlasticHypoelasticCorrespondence,
                  std::string("Elastic Plastic Hypoelastic Correspondence"), std::string("1"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluate, IsotropicHardeningHypoelasticCorrespondence,
                  std::string("Isotropic Hardening Hypoelastic Correspondence"), std::string("1"))
    ->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  scenes.clear();
  MPI_Finalize();
  return 0;
}
