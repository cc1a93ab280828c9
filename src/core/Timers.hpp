#pragma once
// Wall-clock accounting by phase (setup, ghost exchange, damage, force, integration, output),
// printed at the end of a run as min/max/average over ranks.
#include <mpi.h>

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
        : timers_(timers), name_(name), start_(std::chrono::steady_clock::now()) {}
    ~Scope() {
      timers_.add(name_,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    }

   private:
    Timers& timers_;
    const char* name_;
    std::chrono::steady_clock::time_point start_;
  };
  void add(const std::string& name, double seconds) { seconds_[name] += seconds; }
  double get(const std::string& name) const {
    auto it = seconds_.find(name);
    return it == seconds_.end() ? 0.0 : it->second;
  }
  // Collective: every rank must call it with the same set of names.
  void report(std::ostream& out, MPI_Comm comm) const;

 private:
  std::map<std::string, double> seconds_;
};

}  // namespace peridot
