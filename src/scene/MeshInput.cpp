#include "scene/MeshInput.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/Errors.hpp"
#include "io/WritePaths.hpp"
#include "mesh/MeshGenerator.hpp"
#include "scene/FieldInput.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const Scene& s, const YAML::Node& at, const std::string& path,
                       const std::string& message) {
  throw InputError(schema::located_message(s.file, at, path, message));
}

// The schema allows the scene names only.
CellType cell_type_of(const std::string& name) {
  for (auto type :
       {CellType::quad4, CellType::tri3, CellType::hex8, CellType::tet4, CellType::wedge6})
    if (cell_scene_name(type) == name) return type;
  throw std::logic_error("schema and cell types disagree on '" + name + "'");
}

GeneratorSpec generator_spec(const Scene& s, const YAML::Node& g, const YAML::Node& at,
                             const std::string& path) {
  GeneratorSpec spec;
  spec.element = cell_type_of(g["element"].as<std::string>());
  spec.dimension = cell_dimension(spec.element);
  const auto dim = static_cast<std::size_t>(spec.dimension);
  for (const char* key : {"lower", "upper", "cells"})
    if (g[key].size() != dim)
      fail(s, at[key], path + "." + key,
           "expected " + std::to_string(dim) + " entries for a " + std::to_string(dim) + "D " +
               g["element"].as<std::string>() + " mesh, found " + std::to_string(g[key].size()));
  for (std::size_t i = 0; i < dim; ++i) {
    spec.lower[i] = g["lower"][i].as<double>();
    spec.upper[i] = g["upper"][i].as<double>();
    spec.cells[i] = g["cells"][i].as<int>();
    if (!(spec.upper[i] > spec.lower[i]))
      fail(s, at["upper"][i], path + ".upper[" + std::to_string(i) + "]",
           "expected a value greater than lower[" + std::to_string(i) +
               "] = " + g["lower"][i].Scalar());
  }
  spec.perturbation = g["perturbation"].as<double>();
  spec.seed = g["seed"].as<std::uint64_t>();
  spec.block_name = g["block_name"].as<std::string>();
  if (g["map"]) {
    if (g["map"].size() != dim)
      fail(s, at["map"], path + ".map",
           "expected " + std::to_string(dim) + " expressions, one per coordinate, found " +
               std::to_string(g["map"].size()));
    const auto map =
        read_fields(s, g["map"], at["map"], path + ".map", ExpressionVariables::position);
    spec.coordinate_map = [map](const double* box, double* mapped) {
      for (std::size_t k = 0; k < map.size(); ++k) mapped[k] = map[k].at(box, 0.0);
    };
    for (std::size_t k = 0; k < map.size(); ++k)
      spec.map_text += (k ? ", " : "(") + (map[k].varies() ? map[k].expression->text()
                                                           : std::to_string(map[k].constant));
    spec.map_text += ")";
  }
  return spec;
}

void read_mesh(Scene& s, const YAML::Node& m, const YAML::Node& doc) {
  if (m["chart"]) {
    const auto chart =
        read_fields(s, m["chart"], doc["chart"], "mesh.chart", ExpressionVariables::position);
    s.surface_chart = [chart](const double* X, double* c) {
      for (std::size_t k = 0; k < 2; ++k) c[k] = chart[k].at(X, 0.0);
    };
  }
  if (m["file"]) {
    const fs::path given = m["file"].as<std::string>();
    const fs::path path = given.is_absolute() ? given : fs::path(s.directory) / given;
    s.mesh_file = path.lexically_normal().string();
    const auto why = unreadable_input_file(s.mesh_file);
    if (!why.empty())
      fail(s, doc["file"], "mesh.file",
           "cannot read mesh file '" + s.mesh_file + "': " + why +
               " (expected an existing, readable Exodus II file)");
    s.distributed_read = m["read"].as<std::string>() == "distributed";
    if (m["more_blocks"].size() > 0)
      fail(s, doc["more_blocks"], "mesh.more_blocks",
           "further generated blocks join a generated mesh only (expected mesh.generate, or "
           "the blocks in the Exodus file)");
    return;
  }
  // Distributed: each rank makes only its slice of the generated mesh (mesh/GeneratedSlice.hpp).
  s.distributed_read = m["read"].as<std::string>() == "distributed";
  s.generator = generator_spec(s, m["generate"], doc["generate"], "mesh.generate");
  for (std::size_t i = 0; i < m["more_blocks"].size(); ++i) {
    const auto path = "mesh.more_blocks[" + std::to_string(i) + "]";
    const auto& at = doc["more_blocks"][i];
    auto spec = generator_spec(s, m["more_blocks"][i], at, path);
    if (spec.dimension != s.generator->dimension)
      fail(s, at["element"], path + ".element",
           "a " + std::to_string(spec.dimension) + "D cell cannot join the " +
               std::to_string(s.generator->dimension) + "D mesh of mesh.generate (expected " +
               std::to_string(s.generator->dimension) + "D cells)");
    bool taken = spec.block_name == s.generator->block_name;
    for (const auto& other : s.more_blocks) taken = taken || other.block_name == spec.block_name;
    if (taken)
      fail(s, at["block_name"] ? at["block_name"] : at, path + ".block_name",
           "block name '" + spec.block_name +
               "' is taken by an earlier generated block (expected a name of its own)");
    s.more_blocks.push_back(std::move(spec));
  }
  // The node limit holds for the whole mesh, not each block alone (2.4e8 nodes in two blocks of
  // 1.2e8 were accepted).
  auto nodes = [](const GeneratorSpec& g) {
    double n = 1;
    for (int d = 0; d < g.dimension; ++d)
      n *= static_cast<double>(g.cells[static_cast<std::size_t>(d)]) + 1;
    return n;
  };
  double total = nodes(*s.generator);
  for (const auto& b : s.more_blocks) total += nodes(b);
  if (!s.more_blocks.empty() && total > kMaxGeneratedNodes) {
    std::ostringstream o;
    o << "the generated blocks have " << total << " nodes together; at most " << kMaxGeneratedNodes
      << " are supported (expected fewer cells)";
    fail(s, doc["more_blocks"], "mesh.more_blocks", o.str());
  }
}

}  // namespace

void read_mesh_input(Scene& scene) {
  read_mesh(scene, scene.resolved["mesh"], scene.document["mesh"]);
}

}  // namespace efg
