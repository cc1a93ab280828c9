#include "app/Signals.hpp"

#include <chrono>
#include <csignal>
#include <initializer_list>

namespace peridot {

namespace {

volatile std::sig_atomic_t stopSignal = 0;
auto startTime = std::chrono::steady_clock::now();

extern "C" void onStopSignal(int signal) {
  // Only async-signal-safe work here: record the signal, and let a repeated one kill.
  if (stopSignal == 0) stopSignal = signal;
  if (signal != SIGUSR1) std::signal(signal, SIG_DFL);
}

}  // namespace

void installStopSignalHandlers() {
  startTime = std::chrono::steady_clock::now();
  struct sigaction action = {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  // SIGHUP (the terminal closed) too: a stop with a checkpoint beats being killed mid-step.
  for (int s : {SIGTERM, SIGINT, SIGUSR1, SIGHUP}) sigaction(s, &action, nullptr);
}

int pendingStopSignal() { return stopSignal; }

double secondsSinceStart() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - startTime).count();
}

const char* signalName(int signal) {
  switch (signal) {
    case SIGTERM:
      return "SIGTERM";
    case SIGINT:
      return "SIGINT";
    case SIGUSR1:
      return "SIGUSR1";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

}  // namespace peridot
