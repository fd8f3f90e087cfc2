// What a failure means for the process's exit: its code (core/Errors.hpp's classes) and the line
// this rank prints for it. One classification for main's exit and the failure handlers that meet
// before their collective clean-up (parallel/FailureWatchdog.hpp), so that a run stopped by the
// watchdog prints the same line as one that stopped together.
#pragma once

#include <exception>
#include <string>

namespace efg {

struct ExitReport {
  int code = 0;
  std::string message;  ///< what this rank has to say; empty for a peer's failure (agreed)
};

/// The report of the exception `error` (non-null).
ExitReport exit_report(const std::exception_ptr& error);

/// In a catch handler: meets the other ranks with the current failure's code and message
/// (meet_in_failure) before collective clean-up, and returns its report.
ExitReport meet_with_current_failure();

}  // namespace efg
