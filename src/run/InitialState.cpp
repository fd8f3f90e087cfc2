#include "run/InitialState.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "io/ExodusReader.hpp"
#include "model/MaterialLaws.hpp"
#include "run/OutputFields.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {
namespace {

bool path_dependent(const Scene& scene, const PartSpec& part) {
  return scene.find_material(part.material)->model == "j2_plasticity";
}

}  // namespace

std::optional<RestartRecord> read_initial_state(const Scene& scene, const BackgroundMesh& mesh) {
  if (!scene.initial_state) return std::nullopt;
  const auto& spec = *scene.initial_state;
  const YAML::Node at = scene.document["initial_state"];
  auto fail = [&](const char* key, const std::string& message) -> void {
    throw InputError(schema::located_message(
        scene.file, key && at[key] ? at[key] : at,
        std::string("initial_state") + (key ? "." : "") + (key ? key : ""), message));
  };
  ExodusResults results;
  BackgroundMesh written;
  try {
    results = read_exodus_results(spec.file);
    written = read_exodus_mesh(spec.file);
  } catch (const InputError& e) {
    fail("file", e.what());
  }
  if (results.times.empty()) fail("file", "'" + spec.file + "' holds no record");
  // The record: the last one, or the one at the given time (to 1e-9 of the time scale).
  std::size_t record = results.times.size() - 1;
  if (spec.time) {
    const double scale = std::max(1e-300, std::abs(results.times.back()));
    auto nearest = std::min_element(
        results.times.begin(), results.times.end(),
        [&](double a, double b) { return std::abs(a - *spec.time) < std::abs(b - *spec.time); });
    if (std::abs(*nearest - *spec.time) > 1e-9 * scale) {
      std::ostringstream o;
      o << "no record at time " << *spec.time << " in '" << spec.file << "'; its records are at";
      for (std::size_t k = 0; k < results.times.size() && k < 12; ++k) o << " " << results.times[k];
      if (results.times.size() > 12) o << " ... " << results.times.back();
      fail("time", o.str());
    }
    record = static_cast<std::size_t>(nearest - results.times.begin());
  }
  // The same mesh: node count and coordinates.
  if (written.node_count() != mesh.node_count() || written.dimension != mesh.dimension)
    fail("file", "'" + spec.file + "' was written for a " + std::to_string(written.dimension) +
                     "D mesh of " + std::to_string(written.node_count()) +
                     " nodes; this scene's mesh is " + std::to_string(mesh.dimension) + "D with " +
                     std::to_string(mesh.node_count()) + " nodes (expected the same mesh)");
  double size = 0, worst = 0;
  for (std::size_t i = 0; i < mesh.coordinates.size(); ++i) {
    size = std::max(size, std::abs(mesh.coordinates[i]));
    worst = std::max(worst, std::abs(mesh.coordinates[i] - written.coordinates[i]));
  }
  if (worst > 1e-9 * std::max(size, 1e-300))
    fail("file", "the nodes of '" + spec.file + "' are not where this scene's mesh has them (" +
                     "largest distance " + std::to_string(worst) + "; expected the same mesh)");
  // The restart columns.
  RestartRecord out;
  out.time = results.times[record];
  std::vector<std::string> needed = field_columns("generalized_displacement", mesh.dimension);
  bool history = false;
  for (std::size_t p = 0; p < scene.parts.size(); ++p) {
    if (!path_dependent(scene, scene.parts[p])) continue;
    history = true;
    if (scene.parts[p].section.integration == Integration::gauss ||
        scene.parts[p].section.integration == Integration::scni_subcells)
      fail(nullptr, "part '" + scene.parts[p].name +
                        "' keeps a material history at points other than its particles, which "
                        "results files do not hold; expected a part integrated at its particles "
                        "(scni or nodal)");
  }
  if (history) {
    const auto state = field_columns("material_state", mesh.dimension);
    needed.insert(needed.end(), state.begin(), state.end());
  }
  for (const auto& name : needed) {
    const auto it = results.nodal.find(name);
    if (it == results.nodal.end())
      fail("file", "'" + spec.file + "' has no nodal variable '" + name +
                       "'; the run that wrote it needs output.fields generalized_displacement, "
                       "generalized_velocity" +
                       (history ? std::string(" and material_state") : std::string()));
    out.nodal[name] = it->second[record];
  }
  for (const auto& name : field_columns("generalized_velocity", mesh.dimension)) {
    const auto it = results.nodal.find(name);  // optional: an implicit run has none to give
    out.nodal[name] = it == results.nodal.end() ? std::vector<double>(mesh.node_count(), 0.0)
                                                : it->second[record];
  }
  for (const auto& [name, values] : out.nodal)
    for (double v : values)
      if (!std::isfinite(v))
        fail("file", "'" + spec.file + "' holds a non-finite value of '" + name +
                         "' at the record of time " + std::to_string(out.time));
  if (!scene.stages.empty() && !(scene.stages.front().end_time > out.time))
    throw InputError(schema::located_message(
        scene.file, scene.document["stages"][0]["end_time"], "stages[0].end_time",
        "the run starts at the record's time " + std::to_string(out.time) +
            "; expected the first stage to end after it"));
  return out;
}

void apply_initial_state(const Model& model, const SolidOperator& op, RunState& state) {
  const auto record = read_initial_state(model.scene, model.mesh);
  if (!record) return;
  const int dim = model.mesh.dimension;
  const auto udim = static_cast<std::size_t>(dim);
  const auto& owned = model.partition.owned;
  const auto d_names = field_columns("generalized_displacement", dim);
  const auto v_names = field_columns("generalized_velocity", dim);
  {
    auto d = state.d.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto v = state.v.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t s = 0; s < owned.size(); ++s)
      for (std::size_t c = 0; c < udim; ++c) {
        const auto node = static_cast<std::size_t>(owned[s]);
        d(s * udim + c, 0) = record->nodal.at(d_names[c])[node];
        v(s * udim + c, 0) = record->nodal.at(v_names[c])[node];
      }
  }
  state.time = record->time;
  // The committed history of every integration point at a particle (this rank's points).
  auto& history = op.history();
  const auto columns = field_columns("material_state", dim);
  for (std::size_t p = 0; p < history.parts(); ++p) {
    const auto& part = history.part(p);
    if (part.count == 0) continue;
    auto host = Kokkos::create_mirror_view(part.committed);
    const auto& nodes = op.point_nodes(p);
    for (std::size_t q = 0; q < nodes.size(); ++q)
      for (std::size_t k = 0; nodes[q] >= 0 && k < static_cast<std::size_t>(part.count); ++k)
        host(q, k) = record->nodal.at(columns[k])[static_cast<std::size_t>(nodes[q])];
    Kokkos::deep_copy(part.committed, host);
    Kokkos::deep_copy(part.trial, host);
  }
}

}  // namespace efg
