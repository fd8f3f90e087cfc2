// The files a run writes are made anew under temporary names ("<name>.part") and renamed when
// complete. These helpers keep those writes inside the output folder and say why one failed.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace efg {

/// Removes whatever occupies `path` (a stale file, or a symbolic link: the link itself, never its
/// target) so that it can be created afresh. Returns "" or why it could not be cleared.
std::string clear_for_writing(const std::string& path);

/// Why `path` cannot be read as an input file ("" when it can): missing, a folder, a device or
/// pipe (/dev/zero would be read forever), or unreadable (with the OS's reason).
std::string unreadable_input_file(const std::string& path);

/// " (<the OS's reason>)" for an errno value, or "" for 0.
std::string os_reason(int error_number);

/// Opens `path` for writing as a new regular file (O_CREAT | O_EXCL | O_NOFOLLOW after
/// clear_for_writing): a link planted at the name is never followed. Throws std::runtime_error
/// naming the file and the OS's reason.
void create_fresh_file(const std::string& path);

/// Writes a whole small file (a report, a table) by `body` into a fresh "<path>.part", then
/// renames it to `path`: a link at either name is replaced, never followed, and a failed write
/// leaves an earlier file at `path` as it was. Throws std::runtime_error with the OS's reason.
void write_then_rename(const std::string& path, const std::function<void(std::ostream&)>& body);

}  // namespace efg
