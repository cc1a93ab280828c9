#pragma once
// Wall-clock accounting by phase (setup, ghost exchange, damage, force, integration, output),
// printed at the end of a run as min/max/average over ranks, followed by the CPU time of the
// same phases (the calling thread's: on a shared or oversubscribed machine, the work done).
#include <mpi.h>
#include <time.h>

#include <chrono>
#include <map>
#include <ostream>
#include <string>

namespace peridot {

class Timers {
 public:
  class Scope {
   public:
    Scope(Timers& timers, const char* name)
        : timers_(timers),
          name_(name),
          start_(std::chrono::steady_clock::now()),
          cpuStart_(threadCpuSeconds()) {}
    ~Scope() {
      timers_.add(name_,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
      timers_.cpuSeconds_[name_] += threadCpuSeconds() - cpuStart_;
    }

   private:
    Timers& timers_;
    const char* name_;
    std::chrono::steady_clock::time_point start_;
    double cpuStart_;
  };
  static double threadCpuSeconds() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  }
  void add(const std::string& name, double seconds) { seconds_[name] += seconds; }
  double get(const std::string& name) const {
    auto it = seconds_.find(name);
    return it == seconds_.end() ? 0.0 : it->second;
  }
  // Collective: every rank must call it with the same set of names.
  void report(std::ostream& out, MPI_Comm comm) const;

 private:
  std::map<std::string, double> seconds_;
  std::map<std::string, double> cpuSeconds_;  // phases timed by a Scope
};

}  // namespace peridot
