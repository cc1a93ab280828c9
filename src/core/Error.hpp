#pragma once
// Errors a user can cause carry the deck path (or file) they come from; the application
// prints them as one line and exits non-zero before any output file is written.
#include <stdexcept>
#include <string>

namespace peridot {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  // "Materials -> My Material -> Bulk Modulus: expected a positive number, got "abc""
  InputError(const std::string& path, const std::string& message)
      : std::runtime_error(path.empty() ? message : path + ": " + message) {}
};

// A failure during the run (non-finite force, I/O failure while writing), not the deck's fault.
class RunError : public std::runtime_error {
 public:
  explicit RunError(const std::string& message) : std::runtime_error(message) {}
  // Thrown on every rank alike (throwIfAnyRank): rank 0 alone reports it.
  bool collective() const { return collective_; }
  RunError& markCollective() {
    collective_ = true;
    return *this;
  }

 private:
  bool collective_ = false;
};

}  // namespace peridot
