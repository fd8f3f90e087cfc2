// How an efg process prepares Open MPI before MPI_Init when no mpirun started it (a singleton:
// `efg run` on one rank, every unit test). Two settings, both ignored under mpirun and by other
// MPI libraries, and neither overriding what the user set:
// - ess_singleton_isolated: Open MPI 4.1 otherwise forks an `orted` daemon for the singleton
//   (0.13 s of a 0.5 s start here); efg never spawns processes.
// - a session folder of its own (orte_tmpdir_base): singletons started side by side (ctest -j)
//   share /tmp/ompi.<host>.<uid> and race to create it again once the last user removed it;
//   the loser stops in orte_init ("mkdir ... File exists", seen in the test suite). Removed on
//   destruction, after MPI_Finalize.
#pragma once

#include <string>

namespace efg {

class MpiSingletonSetup {
 public:
  MpiSingletonSetup();
  ~MpiSingletonSetup();
  MpiSingletonSetup(const MpiSingletonSetup&) = delete;
  MpiSingletonSetup& operator=(const MpiSingletonSetup&) = delete;

 private:
  std::string session_;
};

}  // namespace efg
