#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

#include <climits>

#include "app/Application.hpp"

int main(int argc, char** argv) {
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
