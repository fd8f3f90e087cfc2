// RAII handle on an open Exodus II file plus the error check every call goes through.
#pragma once

#include <string>

namespace efg::exodus {

/// Owns an Exodus file id; closes it on destruction.
class File {
 public:
  /// `kind` names the file in messages: "mesh file", or "results file" for a restart record.
  static File open_read(const std::string& path, const std::string& kind = "mesh file");
  static File create(const std::string& path);
  File(File&& other) noexcept;
  File& operator=(File&&) = delete;
  File(const File&) = delete;
  ~File();

  int id() const { return id_; }
  const std::string& path() const { return path_; }
  /// Throws InputError (reading) or std::runtime_error (writing) when `status` is an error.
  void check(int status, const char* what) const;
  void close();

 private:
  File(int id, std::string path, bool writing, std::string kind = "mesh file")
      : id_(id), path_(std::move(path)), kind_(std::move(kind)), writing_(writing) {}
  int id_ = -1;
  std::string path_, kind_;
  bool writing_ = false;
};

}  // namespace efg::exodus
