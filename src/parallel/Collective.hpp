// Work that may fail on some ranks only (a singular moment matrix among one rank's points, a
// NaN in one rank's particles): every rank learns that something failed, so none waits forever
// in the next collective call. The failing rank rethrows its own error (and prints it); the
// others throw PeerFailure carrying the same exit code and print nothing.
#pragma once

#include <functional>
#include <stdexcept>

#include "parallel/Comm.hpp"

namespace efg {

class PeerFailure : public std::runtime_error {
 public:
  explicit PeerFailure(int exit_code)
      : std::runtime_error("failure on another rank"), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

/// Runs `work` on every rank, then agrees on the outcome (one reduction).
void run_collectively(const CommPtr& comm, const std::function<void()>& work);

}  // namespace efg
