#include "core/Threads.hpp"

#include <mpi.h>
#include <sched.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

#include "core/DeviceArrays.hpp"

namespace efg {

int threads_option(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::string value;
    if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc)
      value = argv[i + 1];
    else if (std::strncmp(argv[i], "--threads=", 10) == 0)
      value = argv[i] + 10;
    else
      continue;
    try {
      std::size_t used = 0;
      const int n = std::stoi(value, &used);
      return used == value.size() && n > 0 ? n : 0;
    } catch (const std::exception&) {
      return 0;
    }
  }
  return 0;
}

LibraryArguments::LibraryArguments(int argc, char** argv) {
  setenv("OMP_PROC_BIND", "false", 0);
  const int threads = threads_option(argc, argv);
  threads_ = "--kokkos-threads=" + std::to_string(threads);
  args_.push_back(argv[0]);
  if (threads > 0) args_.push_back(threads_.data());
  argc_ = static_cast<int>(args_.size());
  args_.push_back(nullptr);  // argv is null-terminated (MPI_Init reads up to it)
  argv_ = args_.data();
}

int threads_per_rank() {
  return ExecSpace::concurrency();
}

std::string execution_summary() {
  const int n = threads_per_rank();
  return std::string("Kokkos ") + ExecSpace::name() + ", " + std::to_string(n) +
         (n == 1 ? " thread" : " threads") + " per rank";
}

std::vector<std::string> thread_warnings(int requested) {
  std::vector<std::string> warnings;
  const int n = threads_per_rank();
  if (requested > n)
    warnings.push_back("--threads " + std::to_string(requested) + " asked, but this build runs " +
                       execution_summary() +
                       " (Debian's Trilinos is Serial only; build against "
                       "scripts/build_trilinos_openmp.sh for threads, "
                       "docs/threads.md)");
  cpu_set_t set;
  CPU_ZERO(&set);
  if (n > 1 && sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) < n)
    warnings.push_back(std::to_string(n) + " threads per rank, but this process may run on " +
                       std::to_string(CPU_COUNT(&set)) +
                       " CPU(s) only: mpirun binds each rank to one core unless given --bind-to "
                       "none or --map-by slot:PE=" +
                       std::to_string(n));
  // Ranks sharing this node (MPI-3 shared-memory split) times threads against its CPUs.
  int ranks_here = 1, initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) {
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    MPI_Comm_size(node, &ranks_here);
    MPI_Comm_free(&node);
  }
  const auto cpus = static_cast<int>(std::thread::hardware_concurrency());
  const char* wait = std::getenv("OMP_WAIT_POLICY");
  const bool passive = wait && (std::string(wait) == "passive" || std::string(wait) == "PASSIVE");
  if (n > 1 && cpus > 0 && ranks_here * n > cpus && !passive)
    warnings.push_back(
        std::to_string(ranks_here) + " rank(s) x " + std::to_string(n) + " threads on " +
        std::to_string(cpus) +
        " CPUs: spinning OpenMP threads on shared cores can slow the run many times over; set "
        "OMP_WAIT_POLICY=passive or use fewer ranks or threads");
  return warnings;
}

}  // namespace efg
