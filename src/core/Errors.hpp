// The three kinds of failure efg distinguishes, each mapped to one process exit code by main().
#pragma once

#include <stdexcept>
#include <string>

namespace efg {

/// Exit codes documented in `efg --help` and the README.
enum class ExitCode : int {
  success = 0,
  other = 1,
  bad_input = 2,
  numerical = 3,
  verification = 4
};

/// Bad user input: scene file, mesh file, command line. Carries the whole user-facing message,
/// which already names the file, line and key path.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

/// Numerical trouble found where it happened (singular moment matrix, NaN, negative Jacobian,
/// unstable time step, Newton divergence); the message names the particle, step and time.
class NumericalError : public std::runtime_error {
 public:
  explicit NumericalError(const std::string& message) : std::runtime_error(message) {}
};

/// The run completed and wrote its results, but a verification check of the scene failed.
class VerificationError : public std::runtime_error {
 public:
  explicit VerificationError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace efg
