#include "run/OutputPaths.hpp"

#include <stdlib.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <system_error>

#include "core/Errors.hpp"
#include "parallel/Collective.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {
namespace {

namespace fs = std::filesystem;

void require_not_a_folder(const Scene& scene, const fs::path& path, const char* key) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw InputError(schema::located_message(
        scene.file, scene.document["output"] ? scene.document["output"][key] : YAML::Node(),
        std::string("output.") + key,
        "'" + path.string() + "' is an existing folder; expected a file name for the results"));
}

// The first existing ancestor must be a folder we can create the rest in.
void require_creatable_folder(const Scene& scene, const fs::path& folder, bool create) {
  std::error_code ec;
  if (create) {
    fs::create_directories(folder, ec);
    if (!ec) return;
  } else {
    fs::path p = folder;
    while (!p.empty() && !fs::exists(p, ec)) p = p.parent_path();
    if (p.empty()) p = ".";
    if (!fs::is_directory(p, ec)) {
      ec = std::make_error_code(std::errc::not_a_directory);
    } else {
      // `check` creates nothing, but must refuse what `run` will refuse: a folder may look
      // writable and still take no new entries (/proc, a read-only mount). A probe folder made
      // and removed at once answers it.
      std::string probe = (p / ".efg-check-XXXXXX").string();
      if (::mkdtemp(probe.data()) != nullptr) {
        fs::remove(probe, ec);
        return;
      }
      ec = std::error_code(errno, std::generic_category());
    }
  }
  throw InputError(scene.file + ": output.file: cannot create the output folder '" +
                   folder.string() + "' (" + ec.message() + ")");
}

// The results and the history stay inside the output folder: a path through a symbolic link
// (output.file: link/x.e with link pointing elsewhere) or up out of it is refused.
void require_inside(const Scene& scene, const fs::path& folder, const fs::path& path,
                    const char* key) {
  std::error_code ec;
  const auto root = fs::weakly_canonical(folder.empty() ? fs::path(".") : folder, ec);
  const auto where =
      fs::weakly_canonical(path.parent_path().empty() ? fs::path(".") : path.parent_path(), ec);
  if (!ec &&
      std::mismatch(root.begin(), root.end(), where.begin(), where.end()).first == root.end())
    return;
  throw InputError(schema::located_message(
      scene.file, scene.document["output"] ? scene.document["output"][key] : YAML::Node(),
      std::string("output.") + key,
      "'" + path.string() + "' leads outside the output folder '" + folder.string() + "' (to '" +
          where.string() +
          "', through a symbolic link or '..'); expected a path inside the output folder"));
}

}  // namespace

std::string prepare_output_paths(const CommPtr& comm, const Scene& scene,
                                 const std::string& output_dir, bool create) {
  const fs::path path = fs::path(output_dir) / scene.output.file;
  run_collectively(comm, [&] {
    if (comm->getRank() != 0) return;  // rank 0 writes every file
    require_not_a_folder(scene, path, "file");
    require_inside(scene, output_dir, path, "file");
    if (!scene.output.history.empty()) {
      require_not_a_folder(scene, path.parent_path() / scene.output.history, "history");
      require_inside(scene, output_dir, path.parent_path() / scene.output.history, "history");
    }
    if (path.has_parent_path()) require_creatable_folder(scene, path.parent_path(), create);
  });
  return path.string();
}

}  // namespace efg
