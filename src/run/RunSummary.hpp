// End-of-run table: Teuchos timers (min/mean/max over ranks) and the memory high-water mark.
#pragma once

#include "parallel/Comm.hpp"

namespace efg {

/// Peak resident memory of this process in bytes (getrusage).
long long peak_memory_bytes();

/// Prints the timer table and the memory high-water mark (max and sum over ranks) on rank 0.
void print_run_summary(const CommPtr& comm);

}  // namespace efg
