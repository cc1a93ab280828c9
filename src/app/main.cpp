#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

#include <climits>
#include <cstdlib>
#include <initializer_list>

#include "app/Application.hpp"

namespace {

// A process started without a launcher (`peridot deck.xml`: an MPI singleton) runs alone, and
// Open MPI's default start-up for it costs ~0.35 s here (bench/RESULTS.md): it starts a helper
// daemon, and it opens the Omni-Path transport, whose library calibrates a clock at load. Alone,
// neither is needed: the singleton is told to stay isolated and to use the plain point-to-point
// layer, unless the user set these (setenv does not overwrite). A process started by mpirun,
// srun or another launcher (its rank in the environment) is left as its site configures it.
void quickSingletonStart() {
  for (const char* launched : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(launched)) return;
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_pml", "ob1", 0);
}

}  // namespace

int main(int argc, char** argv) {
  quickSingletonStart();
#if defined(__GLIBC__)
  // The set-up allocates and frees many arrays of tens to hundreds of MB (point batches, the
  // search's grids, exchange buffers) before the bond arrays. By default glibc maps each
  // allocation above 32 MB anew and unmaps it when freed, so every one of them is page-faulted
  // from fresh zeroed pages, which on a VM costs ~1 s per GB (bench/RESULTS.md: 128^3 faulted
  // 6.8 GB for a 5.3 GB peak). Kept in the heap, freed memory is reused without faults; the
  // Simulation hands back what is left unused when its set-up is over (malloc_trim).
  mallopt(M_MMAP_THRESHOLD, INT_MAX);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
#endif
  return peridot::runApplication(argc, argv);
}
