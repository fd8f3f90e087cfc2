// Threads per MPI rank: the Kokkos execution space that efg's kernels and Tpetra run on, and
// how many threads it has. Chosen by `efg run --threads N` (else OMP_NUM_THREADS, else the
// backend's default) before Kokkos starts; reported in the run log and report (docs/threads.md).
#pragma once

#include <string>
#include <vector>

namespace efg {

/// The value of `--threads N` (or `--threads=N`) among the raw arguments, 0 when absent or not a
/// positive integer (the command-line parser then reports the error).
int threads_option(int argc, char** argv);

/// The arguments MPI and Kokkos get (Tpetra::ScopeGuard): the program name and, when `--threads N`
/// was given, `--kokkos-threads=N`; efg's own options (e.g. --help) stay away from Kokkos.
/// OMP_PROC_BIND is set to false when unset: unbound threads, which the OpenMP runtime already
/// assumed when it loaded, and no Kokkos warning on every run.
class LibraryArguments {
 public:
  LibraryArguments(int argc, char** argv);
  int* argc() { return &argc_; }
  char*** argv() { return &argv_; }

 private:
  std::string threads_;
  std::vector<char*> args_;
  int argc_ = 0;
  char** argv_ = nullptr;
};

/// Threads per rank of the default execution space (1 for Serial).
int threads_per_rank();

/// "Kokkos OpenMP, 2 thread(s) per rank" or "Kokkos Serial, 1 thread per rank".
std::string execution_summary();

/// Warnings about the thread setup: more threads asked than the backend has (Serial build);
/// more threads than the CPUs this process may run on (mpirun binds each rank to one core unless
/// told --bind-to none or --map-by slot:PE=N); more ranks x threads on this node than CPUs
/// without OMP_WAIT_POLICY=passive (measured: 3 ranks x 2 threads on 2 cores ran the MPI test
/// suite in 10 s passive and did not finish in 300 s spinning). Collective over MPI_COMM_WORLD.
std::vector<std::string> thread_warnings(int requested);

}  // namespace efg
