#include "run/OutputPaths.hpp"

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
    if (p.empty() || fs::is_directory(p, ec)) return;
    ec = std::make_error_code(std::errc::not_a_directory);
  }
  throw InputError(scene.file + ": output.file: cannot create the output folder '" +
                   folder.string() + "' (" + ec.message() + ")");
}

}  // namespace

std::string prepare_output_paths(const CommPtr& comm, const Scene& scene,
                                 const std::string& output_dir, bool create) {
  const fs::path path = fs::path(output_dir) / scene.output.file;
  run_collectively(comm, [&] {
    if (comm->getRank() != 0) return;  // rank 0 writes every file
    require_not_a_folder(scene, path, "file");
    if (!scene.output.history.empty())
      require_not_a_folder(scene, path.parent_path() / scene.output.history, "history");
    if (path.has_parent_path()) require_creatable_folder(scene, path.parent_path(), create);
  });
  return path.string();
}

}  // namespace efg
