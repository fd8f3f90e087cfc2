#include "parallel/FaultInjection.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/Errors.hpp"

namespace efg {
namespace {

struct Fault {
  std::string phase;  ///< empty: no fault injected
  int rank = -1;
  int exit_code = static_cast<int>(ExitCode::numerical);
  bool malformed_reported = false;
};

// Parsed once; a malformed EFG_FAULT is bad input (the tests must not pass by injecting nothing).
Fault& fault() {
  static Fault f = [] {
    Fault parsed;
    const char* text = std::getenv("EFG_FAULT");
    if (!text || !*text) return parsed;
    const std::string s(text);
    const auto colon = s.find(':');
    const auto second = colon == std::string::npos ? colon : s.find(':', colon + 1);
    parsed.phase = s.substr(0, colon);
    const bool known =
        std::find(kFaultPhases.begin(), kFaultPhases.end(), parsed.phase) != kFaultPhases.end();
    try {
      if (colon == std::string::npos || !known) throw 0;
      parsed.rank = std::stoi(s.substr(colon + 1, second - colon - 1));
      if (second != std::string::npos) parsed.exit_code = std::stoi(s.substr(second + 1));
    } catch (...) {
      parsed.exit_code = -1;
    }
    return parsed;
  }();
  return f;
}

}  // namespace

void fault_point(std::string_view phase) {
  auto& f = fault();
  if (f.phase.empty()) return;
  if (f.exit_code != 2 && f.exit_code != 3) {
    if (f.malformed_reported) return;
    f.malformed_reported = true;
    throw InputError("EFG_FAULT='" + std::string(std::getenv("EFG_FAULT")) +
                     "': expected PHASE:RANK[:EXIT] with EXIT 2 or 3 and a known phase");
  }
  if (phase != f.phase) return;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != f.rank) return;
  const std::string message =
      "fault injected by EFG_FAULT in phase '" + f.phase + "' on rank " + std::to_string(rank);
  if (f.exit_code == 2) throw InputError(message);
  throw NumericalError(message);
}

}  // namespace efg
