#pragma once
// SIGTERM, SIGINT and SIGUSR1 (what batch systems send before a time limit) only set a flag;
// the time loop looks at it once per step on every rank together and stops cleanly at the end of
// the step (with Restart: after writing a checkpoint).
namespace peridot {

// Installs the handlers (SA_RESTART, so MPI's system calls are not cut short). A second SIGINT
// or SIGTERM gets the default action: a user pressing Ctrl-C twice stops the run at once.
void installStopSignalHandlers();
// The number of the first stop signal received, 0 if none. Local to this rank.
int pendingStopSignal();
// Wall-clock seconds since the handlers were installed (the start of the program), for the
// Wall Clock Limit.
double secondsSinceStart();
// "SIGTERM", "SIGINT", "SIGUSR1".
const char* signalName(int signal);

}  // namespace peridot
