#include "io/WritePaths.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace efg {

std::string clear_for_writing(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::symlink_status(path, ec);
  if (ec || status.type() == fs::file_type::not_found) return "";
  if (status.type() == fs::file_type::directory) return "a folder of that name exists";
  fs::remove(path, ec);  // a link is removed itself, not followed
  return ec ? ec.message() : "";
}

std::string unreadable_input_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(path, ec);  // through links: the file they name counts
  if (status.type() == fs::file_type::not_found) return "it does not exist";
  if (status.type() == fs::file_type::directory) return "it is a folder";
  if (ec) return ec.message();
  if (status.type() != fs::file_type::regular)
    return "it is not a regular file (a device, pipe or socket)";
  std::ifstream probe(path, std::ios::binary);
  if (!probe) return "it cannot be opened" + os_reason(errno);
  return "";
}

std::string os_reason(int error_number) {
  return error_number == 0 ? "" : " (" + std::string(std::strerror(error_number)) + ")";
}

void create_fresh_file(const std::string& path) {
  const auto reason = clear_for_writing(path);
  if (!reason.empty()) throw std::runtime_error("cannot create '" + path + "': " + reason);
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot create '" + path + "'" + os_reason(errno));
  ::close(fd);
}

void write_then_rename(const std::string& path, const std::function<void(std::ostream&)>& body) {
  const std::string part = path + ".part";
  create_fresh_file(part);
  {
    std::ofstream out(part);
    body(out);
    out.flush();
    if (!out) {
      const int error = errno;
      std::error_code ec;
      std::filesystem::remove(part, ec);
      throw std::runtime_error("writing '" + part + "' failed" + os_reason(error));
    }
  }
  if (std::rename(part.c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot rename '" + part + "' to '" + path + "'" + os_reason(errno));
}

}  // namespace efg
