#include "scene/SceneNodeSets.hpp"

#include <algorithm>
#include <sstream>

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"
#include "scene/Suggest.hpp"

namespace efg {

void read_node_set_input(Scene& scene) {
  for (const auto& n : scene.resolved["node_sets"]) {
    NodeSetSpec spec;
    spec.name = n["name"].as<std::string>();
    for (const auto& v : n["lower"]) spec.lower.push_back(v.as<double>());
    for (const auto& v : n["upper"]) spec.upper.push_back(v.as<double>());
    if (n["within"]) spec.within = n["within"].as<std::string>();
    scene.node_sets.push_back(spec);
  }
}

void add_scene_node_sets(const Scene& scene, BackgroundMesh& mesh,
                         const std::function<bool(bool)>& held_anywhere) {
  // a shell surface read in 3D: boxes in 3D, around its nodes' 3D positions
  const bool surface = !mesh.surface.empty();
  const auto dim = surface ? std::size_t{3} : static_cast<std::size_t>(mesh.dimension);
  const auto& positions = surface ? mesh.surface : mesh.coordinates;
  std::int64_t next_id = 0;
  for (const auto& ns : mesh.node_sets) next_id = std::max(next_id, ns.id);
  for (std::size_t i = 0; i < scene.node_sets.size(); ++i) {
    const auto& spec = scene.node_sets[i];
    const YAML::Node doc = scene.document["node_sets"][i];
    const auto path = "node_sets[" + std::to_string(i) + "]";
    auto fail = [&](const char* key, const std::string& message) {
      throw InputError(schema::located_message(scene.file, key ? doc[key] : doc,
                                               key ? path + "." + key : path, message));
    };
    std::vector<std::string> names;
    for (const auto& ns : mesh.node_sets) names.push_back(ns.name);
    if (mesh.find_node_set(spec.name))
      fail("name",
           "the mesh already has a node set named '" + spec.name + "'; expected a new name");
    for (const char* key : {"lower", "upper"}) {
      const auto& v = std::string(key) == "lower" ? spec.lower : spec.upper;
      if (v.size() != dim)
        fail(key, "expected " + std::to_string(dim) + " entries for this " + std::to_string(dim) +
                      "D mesh, found " + std::to_string(v.size()));
    }
    for (std::size_t k = 0; k < dim; ++k)
      if (spec.lower[k] > spec.upper[k])
        fail("upper", "expected upper >= lower in every direction; direction " +
                          std::string(1, static_cast<char>('x' + k)) + " is inverted");
    std::vector<LocalIndex> candidates;
    if (!spec.within.empty()) {
      const auto* within = mesh.find_node_set(spec.within);
      if (!within) {
        std::string message = "no node set named '" + spec.within + "'";
        if (auto guess = closest_match(spec.within, names))
          message += " (did you mean '" + *guess + "'?)";
        fail("within", message);
      }
      candidates = within->nodes;
    } else {
      candidates.resize(mesh.node_count());
      for (std::size_t n = 0; n < candidates.size(); ++n)
        candidates[n] = static_cast<LocalIndex>(n);
    }
    NodeSet made{spec.name, ++next_id, {}};
    for (auto n : candidates) {
      bool inside = true;
      for (std::size_t k = 0; k < dim; ++k) {
        const double x = positions[static_cast<std::size_t>(n) * dim + k];
        inside = inside && x >= spec.lower[k] && x <= spec.upper[k];
      }
      if (inside) made.nodes.push_back(n);
    }
    const bool held = !made.nodes.empty();
    if (held_anywhere ? !held_anywhere(held) : !held) {
      std::ostringstream o;
      o << "the box holds no node" << (spec.within.empty() ? "" : " of '" + spec.within + "'")
        << "; expected a box around at least one node (bounds are included)";
      fail(nullptr, o.str());
    }
    std::sort(made.nodes.begin(), made.nodes.end());
    mesh.node_sets.push_back(std::move(made));
  }
}

}  // namespace efg
