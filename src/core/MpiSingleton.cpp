#include "core/MpiSingleton.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace efg {

MpiSingletonSetup::MpiSingletonSetup() {
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  // Under mpirun the launcher's session folder is the one to use.
  if (std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("OMPI_MCA_orte_tmpdir_base")) return;
  char path[] = "/tmp/efgXXXXXX";  // short: the folder holds Unix sockets (108-byte paths)
  if (!mkdtemp(path)) return;      // then Open MPI's shared default, as before
  session_ = path;
  setenv("OMPI_MCA_orte_tmpdir_base", path, 1);
}

MpiSingletonSetup::~MpiSingletonSetup() {
  if (session_.empty()) return;
  std::error_code ignored;
  std::filesystem::remove_all(session_, ignored);
}

}  // namespace efg
