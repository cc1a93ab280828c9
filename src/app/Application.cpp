#include "app/Application.hpp"

#include <Tpetra_Core.hpp>
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <thread>
#if defined(__linux__)
#include <sched.h>
#endif

#include "app/Signals.hpp"
#include "app/Simulation.hpp"
#include "core/BackgroundFaults.hpp"
#include "core/Error.hpp"
#include "core/ProcessorsPerRank.hpp"
#include "damage/DamageModel.hpp"
#include "deck/Deck.hpp"
#include "deck/DeckScreen.hpp"
#include "deck/RunConfig.hpp"
#include "materials/MaterialModel.hpp"
#include "peridot/Commit.hpp"
#include "peridot/Version.hpp"

namespace peridot {

namespace {

// Every rank leaves the time loop after the same step: an orderly exit, no abort needed.
constexpr int kStoppedWithoutRestart = 5;

// The processors each rank may keep busy (core/ProcessorsPerRank.hpp): its share of the
// node's, where it may run on more than one. Ranks bound to one core each, or as many ranks as
// cores, leave none to spare: a helper thread would take time from a rank's own work. With one
// to spare, large arrays are also faulted in ahead of their use (core/BackgroundFaults.hpp;
// PERIDOT_BACKGROUND_FAULTS=0 turns that off). PERIDOT_THREADS=n sets the number instead.
void decideProcessorsPerRank(MPI_Comm comm) {
  int ranksOnNode = 1;
  MPI_Comm node;
  if (MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node) == MPI_SUCCESS) {
    MPI_Comm_size(node, &ranksOnNode);
    MPI_Comm_free(&node);
  }
  int usable = 1;
#if defined(__linux__)
  cpu_set_t mask;
  if (sched_getaffinity(0, sizeof mask, &mask) == 0) usable = CPU_COUNT(&mask);
#endif
  const int onNode = static_cast<int>(std::thread::hardware_concurrency());
  int processors = std::max(1, std::min(usable, onNode / std::max(ranksOnNode, 1)));
  if (const char* n = std::getenv("PERIDOT_THREADS")) processors = std::max(1, std::atoi(n));
  setProcessorsPerRank(processors);
  const char* v = std::getenv("PERIDOT_BACKGROUND_FAULTS");
  setBackgroundFaults(processors >= 2 && !(v != nullptr && std::strcmp(v, "0") == 0));
}

const char* kUsage =
    "Usage: peridot [options] DECK\n"
    "\n"
    "Runs the peridynamics simulation described by DECK, a Peridigm-style parameter list in\n"
    "XML (.xml) or YAML (.yaml, .yml). Run it under MPI for parallel runs:\n"
    "  mpirun -np 4 peridot deck.xml\n"
    "Each rank keeps only its share of the mesh (no pre-split files) and the output is\n"
    "one Exodus file whatever the number of ranks.\n"
    "\n"
    "Options:\n"
    "  -h, --help            print this help and exit\n"
    "  -v, --version         print the version, commit and build type, and exit\n"
    "  --list-models         list the material and damage models\n"
    "  --help-model NAME     describe a material or damage model and its parameters\n"
    "  --check               validate the deck and the mesh, print the points, bonds, stable\n"
    "                        time step and number of steps, check that the output files can\n"
    "                        be created (none is written), and exit without running\n"
    "\n"
    "The deck vocabulary is documented in doc/deck-reference.md.\n";

template <class R>
bool describe(const std::string& name, const char* kind) {
  const auto* entry = R::find(name);
  if (!entry) return false;
  std::cout << kind << " \"" << name << "\": " << entry->summary << "\nParameters:\n";
  for (const auto& p : entry->parameters)
    std::cout << "  " << p.name << ": " << p.description << "\n";
  return true;
}

int runDeck(const std::string& deckFile, bool checkOnly, int rank) {
  std::vector<std::string> warnings;
  auto deck = loadDeck(deckFile, &warnings);
  if (rank == 0)
    for (const auto& w : warnings) std::cerr << "peridot: warning: " << w << std::endl;
  RunConfig config = readRunConfig(*deck);
  if (rank == 0) std::cout << "Peridot " << PERIDOT_VERSION << ": " << deckFile << std::endl;
  Simulation simulation(std::move(config), MPI_COMM_WORLD, std::cout);
  if (checkOnly) {
    simulation.reportSetup();  // points, bonds, time step, steps; the outputs can be created
    if (rank == 0)
      std::cout << "The deck and its mesh are valid; the output files can be created (none was "
                   "written)."
                << std::endl;
    return 0;
  }
  simulation.run();
  simulation.timers().report(std::cout, MPI_COMM_WORLD);
  simulation.reportMemory(std::cout);
  simulation.reportCheckpoints(std::cout);
  if (!simulation.stopped()) {
    // Batch scripts look for this line to know that the run is complete.
    if (rank == 0) std::cout << "Done." << std::endl;
    return 0;
  }
  const std::string why = simulation.stopSignal() != 0
                              ? std::string("after ") + signalName(simulation.stopSignal())
                              : std::string("before the Wall Clock Limit");
  if (simulation.checkpoint()) {
    if (rank == 0) {
      std::cout << "Stopped " << why << " at step " << simulation.lastStep() << ", time "
                << simulation.time() << "; checkpoint written to "
                << simulation.checkpoint()->path() << ". To continue, run the same command again."
                << std::endl;
    }
    return 0;
  }
  if (rank == 0) {
    std::cout.flush();  // the reports above first, then the error line
    std::cerr << "peridot: error: stopped " << why << " at step " << simulation.lastStep()
              << ", time " << simulation.time()
              << " without a checkpoint (the outputs hold the records written so far; "
              << (simulation.stoppedInImplicitSolver()
                      ? "the QuasiStatic, NOXQuasiStatic, Implicit and Adaptive Dynamic "
                        "Relaxation solvers write no checkpoint)"
                      : "add \"Restart: true\" to the deck to be able to continue)")
              << std::endl;
  }
  return kStoppedWithoutRestart;
}

}  // namespace

int runApplication(int argc, char** argv) {
  std::string deckFile;
  bool checkOnly = false;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      return 0;
    }
    if (arg == "-v" || arg == "--version") {
      std::cout << "peridot " << PERIDOT_VERSION << "\ncommit: " << PERIDOT_COMMIT
                << "\nbuild type: " << PERIDOT_BUILD_TYPE << "\ncompiler: " << PERIDOT_CXX_COMPILER
                << "\nMPI: " << MPI_VERSION << "." << MPI_SUBVERSION << " interface" << std::endl;
      return 0;
    }
    if (arg == "--list-models") {
      std::cout << "Material models:\n";
      for (const auto& n : MaterialRegistry::names()) std::cout << "  " << n << "\n";
      std::cout << "Damage models:\n";
      for (const auto& n : DamageRegistry::names()) std::cout << "  " << n << "\n";
      return 0;
    }
    if (arg == "--help-model") {
      if (k + 1 >= argc) {
        std::cerr << "peridot: error: --help-model needs a model name\n";
        return 2;
      }
      const std::string name = argv[++k];
      if (describe<MaterialRegistry>(name, "Material model") ||
          describe<DamageRegistry>(name, "Damage model"))
        return 0;
      std::cerr << "peridot: error: no model named \"" << name << "\" (see --list-models)\n";
      return 2;
    }
    if (arg == "--check") {
      checkOnly = true;
      continue;
    }
    if (!arg.empty() && arg[0] == '-') {
      std::cerr << "peridot: error: unknown option \"" << arg << "\"\n" << kUsage;
      return 2;
    }
    if (!deckFile.empty()) {
      std::cerr << "peridot: error: more than one deck given\n" << kUsage;
      return 2;
    }
    deckFile = arg;
  }
  if (deckFile.empty()) {
    std::cerr << "peridot: error: no deck given\n" << kUsage;
    return 2;
  }

  installStopSignalHandlers();
  Tpetra::ScopeGuard mpi(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  decideProcessorsPerRank(MPI_COMM_WORLD);
  int status = 0;
  bool everyRankStopped = false;  // a collective error: every rank left the run alike
  try {
    status = runDeck(deckFile, checkOnly, rank);
  } catch (const InputError& e) {
    // Every rank reads the same deck and mesh (and rank-local findings are shared before they
    // are thrown), so every rank fails here alike.
    if (rank == 0) std::cerr << "peridot: error: " << shortenForMessage(e.what()) << std::endl;
    status = 1;
  } catch (const RunError& e) {
    // Shared findings (throwIfAnyRank) are printed by rank 0; an error of this rank alone (an
    // I/O failure) by this rank, before the abort below releases the others.
    if (rank == 0 || !e.collective())
      std::cerr << "peridot: error: " << shortenForMessage(e.what()) << std::endl;
    everyRankStopped = e.collective();
    status = 3;
  } catch (const std::bad_alloc&) {
    std::cerr << "peridot: error: out of memory on rank " << rank
              << " (the problem is too large for this machine; use more ranks or nodes)"
              << std::endl;
    status = 3;
  } catch (const std::exception& e) {
    std::cerr << "peridot: internal error: " << shortenForMessage(e.what()) << std::endl;
    status = 4;
  }
  std::cout.flush();
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  // Other ranks may be waiting in a collective call: only an abort releases them. Input errors
  // are printed by rank 0; the others wait a moment so their abort does not cut it short. A
  // collective run error (a divergence, a bad expression value) stopped every rank at the same
  // point: they finish normally with the error status, and no abort can cut rank 0's message
  // or the output files short (the likely cause of a diverged run's test failing under load).
  if (status != 0 && status != kStoppedWithoutRestart && size > 1 && !everyRankStopped) {
    if (rank != 0) std::this_thread::sleep_for(std::chrono::seconds(2));
    MPI_Abort(MPI_COMM_WORLD, status);
  }
  return status;
}

}  // namespace peridot
