// End-of-run table: Teuchos timers (min/mean/max over ranks) and the memory high-water mark.
#pragma once

#include <string>
#include <vector>

#include "model/Model.hpp"
#include "parallel/Comm.hpp"

namespace efg {

/// Peak resident memory of this process in bytes (getrusage).
long long peak_memory_bytes();

/// The memory account of the run (core/MemoryAccount): each phase's growth of the resident set,
/// summed over ranks, logged with its share per particle. Collective.
struct MemoryPhase {
  std::string phase;
  long long bytes = 0;  ///< resident growth over the phase
  double bytes_per_particle = 0;
  long long peak_bytes = 0;  ///< high-water mark (summed over ranks) when the phase raised it, else 0
};
std::vector<MemoryPhase> memory_by_phase(const CommPtr& comm, const Model& model);

/// Prints the timer table and the memory high-water mark (max and sum over ranks) on rank 0.
void print_run_summary(const CommPtr& comm);

}  // namespace efg
