#include "io/ExodusFile.hpp"

#include <exodusII.h>

#include <cerrno>
#include <stdexcept>

#include "core/Errors.hpp"
#include "io/NetcdfHeaderCheck.hpp"
#include "io/WritePaths.hpp"

namespace efg::exodus {

File File::open_read(const std::string& path, const std::string& kind) {
  ex_opts(0);  // errors are reported by efg, not printed by the library
  const auto problem = classic_header_problem(path);
  if (!problem.empty())
    throw InputError(kind + " '" + path + "': not a valid Exodus II (netCDF) file: " + problem);
  int cpu_ws = sizeof(double), io_ws = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ, &cpu_ws, &io_ws, &version);
  if (id < 0) throw InputError(kind + " '" + path + "': cannot be opened as Exodus II");
  ex_set_int64_status(id, EX_ALL_INT64_API);
  return File(id, path, false, kind);
}

File File::create(const std::string& path) {
  ex_opts(0);
  // A temporary name of ours: whatever holds it (a stale partial file, a symbolic link planted
  // there) is removed, not followed, and the file is made anew (O_EXCL through NOCLOBBER), so
  // the results never land outside the output folder through a link.
  const auto reason = clear_for_writing(path);
  if (!reason.empty()) throw std::runtime_error("cannot create '" + path + "': " + reason);
  int cpu_ws = sizeof(double), io_ws = sizeof(double);
  errno = 0;
  const int id = ex_create(path.c_str(), EX_NOCLOBBER, &cpu_ws, &io_ws);
  if (id < 0)
    throw std::runtime_error("cannot create Exodus file '" + path + "'" + os_reason(errno));
  ex_set_int64_status(id, EX_ALL_INT64_API);
  return File(id, path, true);
}

File::File(File&& other) noexcept
    : id_(other.id_),
      path_(std::move(other.path_)),
      kind_(std::move(other.kind_)),
      writing_(other.writing_) {
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
  // The library's status says only that the call failed; the OS's reason (no space left on the
  // device, a quota) is what the user can act on.
  if (writing_) throw std::runtime_error(message + os_reason(errno));
  throw InputError(kind_ + " '" + path_ + "': " + what + " failed (corrupt or truncated file?)");
}

}  // namespace efg::exodus
