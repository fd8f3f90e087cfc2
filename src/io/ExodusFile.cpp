#include "io/ExodusFile.hpp"

#include <exodusII.h>

#include <stdexcept>

#include "core/Errors.hpp"
#include "io/NetcdfHeaderCheck.hpp"

namespace efg::exodus {

File File::open_read(const std::string& path) {
  ex_opts(0);  // errors are reported by efg, not printed by the library
  const auto problem = classic_header_problem(path);
  if (!problem.empty())
    throw InputError("mesh file '" + path + "': not a valid Exodus II (netCDF) file: " + problem);
  int cpu_ws = sizeof(double), io_ws = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ, &cpu_ws, &io_ws, &version);
  if (id < 0) throw InputError("mesh file '" + path + "': cannot be opened as Exodus II");
  ex_set_int64_status(id, EX_ALL_INT64_API);
  return File(id, path, false);
}

File File::create(const std::string& path) {
  ex_opts(0);
  int cpu_ws = sizeof(double), io_ws = sizeof(double);
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu_ws, &io_ws);
  if (id < 0) throw std::runtime_error("cannot create Exodus file '" + path + "'");
  ex_set_int64_status(id, EX_ALL_INT64_API);
  return File(id, path, true);
}

File::File(File&& other) noexcept
    : id_(other.id_), path_(std::move(other.path_)), writing_(other.writing_) {
  other.id_ = -1;
}

File::~File() {
  if (id_ >= 0) ex_close(id_);
}

void File::close() {
  if (id_ >= 0) {
    const int status = ex_close(id_);
    id_ = -1;
    if (status < 0) throw std::runtime_error("closing Exodus file '" + path_ + "' failed");
  }
}

void File::check(int status, const char* what) const {
  if (status >= 0) return;
  const std::string message = "Exodus file '" + path_ + "': " + what + " failed";
  if (writing_) throw std::runtime_error(message);
  throw InputError("mesh file '" + path_ + "': " + what + " failed (corrupt or truncated file?)");
}

}  // namespace efg::exodus
