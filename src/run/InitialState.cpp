#include "run/InitialState.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>

#include "core/Errors.hpp"
#include "io/ExodusRecordReader.hpp"
#include "mesh/MeshSlice.hpp"
#include "model/MaterialLaws.hpp"
#include "parallel/Collective.hpp"
#include "parallel/FaultInjection.hpp"
#include "parallel/SliceLookup.hpp"
#include "run/OutputFields.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {
namespace {

bool path_dependent(const Scene& scene, const PartSpec& part) {
  return scene.find_material(part.material)->path_dependent();
}

}  // namespace

namespace {

// The record's coordinates and `names` at the mesh's nodes: the whole file on a whole mesh; on a
// rank's part of a distributed read each rank reads its slice of the file's nodes and fetches
// its part's nodes from the slices' holders (collective).
NodalRecordSlice record_at_mesh_nodes(const CommPtr& comm, const std::string& path,
                                      const ResultsHeader& header, std::size_t record,
                                      const std::vector<std::string>& names,
                                      const BackgroundMesh& mesh) {
  if (!mesh.is_part()) return read_nodal_record(path, header, record, names, 0, header.nodes);
  NodalRecordSlice slice;
  run_collectively(comm, [&] {
    const auto first = slice_begin(header.nodes, comm->getRank(), comm->getSize());
    const auto end = slice_begin(header.nodes, comm->getRank() + 1, comm->getSize());
    slice = read_nodal_record(path, header, record, names, first, end - first);
  });
  // Node after node: its coordinates, then each name's value.
  const auto dim = static_cast<std::size_t>(header.dimension);
  const std::size_t width = dim + names.size();
  const std::size_t held_nodes = slice.coordinates.size() / dim;
  std::vector<double> held(held_nodes * width);
  for (std::size_t n = 0; n < held_nodes; ++n) {
    for (std::size_t d = 0; d < dim; ++d) held[n * width + d] = slice.coordinates[n * dim + d];
    for (std::size_t k = 0; k < names.size(); ++k)
      held[n * width + dim + k] = slice.values[names[k]][n];
  }
  slice = NodalRecordSlice();
  const auto got = fetch_from_slices(comm, header.nodes, width, held, mesh.global.nodes);
  NodalRecordSlice mine;
  const std::size_t nodes = mesh.node_count();
  mine.coordinates.resize(nodes * dim);
  for (const auto& name : names) mine.values[name].resize(nodes);
  for (std::size_t n = 0; n < nodes; ++n) {
    for (std::size_t d = 0; d < dim; ++d) mine.coordinates[n * dim + d] = got[n * width + d];
    for (std::size_t k = 0; k < names.size(); ++k)
      mine.values[names[k]][n] = got[n * width + dim + k];
  }
  return mine;
}

// The largest of `value` over the ranks (on a part; a whole mesh's ranks agree already).
double largest_over_ranks(const CommPtr& comm, const BackgroundMesh& mesh, double value) {
  if (!mesh.is_part()) return value;
  double largest = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, value, Teuchos::outArg(largest));
  return largest;
}

}  // namespace

std::optional<RestartRecord> read_initial_state(const CommPtr& comm, const Scene& scene,
                                                const BackgroundMesh& mesh) {
  if (!scene.initial_state) return std::nullopt;
  const auto& spec = *scene.initial_state;
  const YAML::Node at = scene.document["initial_state"];
  auto fail = [&](const char* key, const std::string& message) -> void {
    throw InputError(schema::located_message(
        scene.file, key && at[key] ? at[key] : at,
        std::string("initial_state") + (key ? "." : "") + (key ? key : ""), message));
  };
  ResultsHeader header;
  // Every rank reads the header itself: a file one rank cannot read (another node's disk) is
  // learned by all.
  run_collectively(comm, [&] {
    try {
      fault_point("initial_state");
      header = read_results_header(spec.file);
    } catch (const InputError& e) {
      fail("file", e.what());
    }
  });
  if (header.times.empty()) fail("file", "'" + spec.file + "' holds no record");
  // The record: the last one, or the one at the given time (to 1e-9 of the time scale).
  std::size_t record = header.times.size() - 1;
  if (spec.time) {
    const double scale = std::max(1e-300, std::abs(header.times.back()));
    auto nearest = std::min_element(
        header.times.begin(), header.times.end(),
        [&](double a, double b) { return std::abs(a - *spec.time) < std::abs(b - *spec.time); });
    if (std::abs(*nearest - *spec.time) > 1e-9 * scale) {
      std::ostringstream o;
      o << "no record at time " << *spec.time << " in '" << spec.file << "'; its records are at";
      for (std::size_t k = 0; k < header.times.size() && k < 12; ++k) o << " " << header.times[k];
      if (header.times.size() > 12) o << " ... " << header.times.back();
      fail("time", o.str());
    }
    record = static_cast<std::size_t>(nearest - header.times.begin());
  }
  // The same mesh: node count (the whole mesh's) and dimension, then the coordinates below.
  if (header.nodes != mesh.whole_node_count() || header.dimension != mesh.dimension)
    fail("file", "'" + spec.file + "' was written for a " + std::to_string(header.dimension) +
                     "D mesh of " + std::to_string(header.nodes) + " nodes; this scene's mesh is " +
                     std::to_string(mesh.dimension) + "D with " +
                     std::to_string(mesh.whole_node_count()) + " nodes (expected the same mesh)");
  // The restart columns.
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
  auto written = [&](const std::string& name) {
    return std::find(header.nodal_names.begin(), header.nodal_names.end(), name) !=
           header.nodal_names.end();
  };
  for (const auto& name : needed)
    if (!written(name))
      fail("file", "'" + spec.file + "' has no nodal variable '" + name +
                       "'; the run that wrote it needs output.fields generalized_displacement, "
                       "generalized_velocity" +
                       (history ? std::string(" and material_state") : std::string()));
  const auto velocity = field_columns("generalized_velocity", mesh.dimension);
  std::vector<std::string> read = needed;
  for (const auto& name : velocity)  // optional: an implicit run has none to give
    if (written(name)) read.push_back(name);
  // The record's bytes as the run wrote them (a flipped bit is still a plausible number): rank 0
  // reads it whole once against its checksum; every rank learns the verdict.
  run_collectively(comm, [&] {
    if (comm->getRank() != 0) return;
    std::string problem;
    try {
      problem = record_checksum_problem(spec.file, record);
    } catch (const InputError& e) {
      problem = e.what();
    }
    if (!problem.empty()) fail("file", "'" + spec.file + "': " + problem);
  });
  NodalRecordSlice values;
  try {
    values = record_at_mesh_nodes(comm, spec.file, header, record, read, mesh);
  } catch (const InputError& e) {
    fail("file", e.what());
  }
  double size = 0, worst = 0;
  for (std::size_t i = 0; i < mesh.coordinates.size(); ++i) {
    size = std::max(size, std::abs(mesh.coordinates[i]));
    worst = std::max(worst, std::abs(mesh.coordinates[i] - values.coordinates[i]));
  }
  size = largest_over_ranks(comm, mesh, size);
  worst = largest_over_ranks(comm, mesh, worst);
  if (worst > 1e-9 * std::max(size, 1e-300))
    fail("file", "the nodes of '" + spec.file + "' are not where this scene's mesh has them (" +
                     "largest distance " + std::to_string(worst) + "; expected the same mesh)");
  RestartRecord out;
  out.time = header.times[record];
  out.nodal = std::move(values.values);
  for (const auto& name : velocity)
    if (!out.nodal.count(name)) out.nodal[name].assign(mesh.node_count(), 0.0);
  for (const auto& [name, column] : out.nodal) {
    double bad = 0;
    for (double v : column)
      if (!std::isfinite(v)) bad = 1;
    if (largest_over_ranks(comm, mesh, bad) > 0)
      fail("file", "'" + spec.file + "' holds a non-finite value of '" + name +
                       "' at the record of time " + std::to_string(out.time));
  }
  if (!scene.stages.empty() && !(scene.stages.front().end_time > out.time))
    throw InputError(schema::located_message(
        scene.file, scene.document["stages"][0]["end_time"], "stages[0].end_time",
        "the run starts at the record's time " + std::to_string(out.time) +
            "; expected the first stage to end after it"));
  return out;
}

void apply_initial_state(const Model& model, const SolidOperator& op, RunState& state) {
  const auto record = read_initial_state(model.maps.owned_dofs->getComm(), model.scene, model.mesh);
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
