#pragma once
// Large pages for the arrays a bond loop reads at random. A force loop gathers the positions of
// each row's neighbours and scatters forces to them: over a few planes of points, a few
// megabytes at 64^3, more than the processor's address-translation cache covers in 4 KiB
// pages. In 2 MiB pages those translations hit (3% less force time at 64^3).
#include <cstddef>

namespace peridot {

// Asks the kernel to back every 2 MiB block that [data, data + bytes) touches with one large
// page now (Linux 6.1's MADV_COLLAPSE, whatever the system's transparent-huge-page setting).
// The contents do not change. Where the kernel cannot (an older kernel, another system, a block
// that is not all one anonymous mapping, no large page free) the pages stay as they are.
// Returns the bytes it was granted (0 where nothing was asked or granted).
std::size_t collapseToHugePages(const void* data, std::size_t bytes);

// Asks the kernel to back the 2 MiB blocks that lie wholly inside [data, data + bytes) with large
// pages when they are first touched (MADV_HUGEPAGE): one fault and one clearing of 2 MiB instead
// of 512 faults. Pages already touched stay as they are. Returns the bytes advised (0 where
// nothing was, or on a system without it).
std::size_t adviseHugePages(void* data, std::size_t bytes);

// Whether the process's large allocations are advised (app/LargeAllocations.cpp): yes unless
// the environment sets PERIDOT_HUGE_PAGES=0, read once.
bool largeAllocationsInHugePages();

}  // namespace peridot
