#include "scene/InitialStateInput.hpp"

#include <filesystem>
#include <fstream>

#include "core/Errors.hpp"
#include "io/WritePaths.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {

void read_initial_state_input(Scene& scene) {
  const auto& r = scene.resolved["initial_state"];
  if (!r) return;
  namespace fs = std::filesystem;
  const fs::path given = r["file"].as<std::string>();
  InitialStateSpec spec;
  spec.file =
      (given.is_absolute() ? given : fs::path(scene.directory) / given).lexically_normal().string();
  if (r["time"]) spec.time = r["time"].as<double>();
  const auto why = unreadable_input_file(spec.file);
  if (!why.empty())
    throw InputError(schema::located_message(
        scene.file, scene.document["initial_state"]["file"], "initial_state.file",
        "cannot read '" + spec.file + "': " + why +
            " (expected the Exodus results file of an earlier run)"));
  scene.initial_state = spec;
}

}  // namespace efg
