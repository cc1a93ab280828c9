#pragma once
// Page faults taken ahead, by a helper thread, for the large arrays the program allocates.
//
// On the VM we measure on, the first write to a page of fresh memory costs far more than any
// work done on it: the host backs the page only then (its balloon takes back whatever a process
// frees within a second or so), at 0.3-0.8 GB/s from one thread against ~15 GB/s for writing the
// same memory once it is resident (bench/RESULTS.md). A 128^3 set-up writes ~2.6 GB of fresh
// memory: 4-6 s of its 10. Two threads fault twice as fast, and a thread that faults an array in
// while the main thread still computes what goes into it hides the cost. So where a rank has a
// processor to spare (app/Application.cpp decides), each large allocation is handed to one
// helper thread, which populates it (MADV_POPULATE_WRITE: the faults without the writes) from its
// end towards its start, in 2 MiB steps, the newest allocation first: a caller that clears the
// array from its start meets the helper half way; a caller that fills it later finds it resident.
//
// The contents are not touched, so no result can change. An array freed before the helper is
// done with it is dropped (forgetBackgroundFaults waits for the step in flight), so the helper
// never makes memory resident that the program gave back.
#include <cstddef>

namespace peridot {

// Turns the helper on or off for later allocations (off: nothing is queued; already queued
// arrays are still populated). Off until a caller turns it on.
void setBackgroundFaults(bool enabled);
bool backgroundFaultsEnabled();

// Queues [data, data + bytes) for the helper, if it is on. Returns whether it was queued.
bool faultInBackground(void* data, std::size_t bytes);

// Before `data` (a pointer faultInBackground was given) is freed: takes it off the queue, and if
// the helper is populating it, waits until the helper has let go of it. Cheap when nothing is
// queued.
void forgetBackgroundFaults(void* data);

// Blocks until the helper has nothing queued (for tests and measurements).
void waitForBackgroundFaults();

}  // namespace peridot
