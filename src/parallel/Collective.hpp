// Work that may fail on some ranks only (a singular moment matrix among one rank's points, a
// NaN in one rank's particles): every rank learns that something failed, so none waits forever
// in the next collective call. The failing rank rethrows its own error (and prints it); the
// others throw PeerFailure carrying the same exit code and the failing rank's message (the
// lowest such rank's), which they do not print at exit but may quote (a Newton cutback's reason).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

#include "parallel/Comm.hpp"

namespace efg {

class PeerFailure : public std::runtime_error {
 public:
  explicit PeerFailure(int exit_code, const std::string& message = "failure on another rank")
      : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

/// Runs `work` on every rank, then agrees on the outcome (one reduction).
void run_collectively(const CommPtr& comm, const std::function<void()>& work);

}  // namespace efg
