#include "run/RunHistory.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>

#include "run/Probes.hpp"

namespace efg {
namespace {
std::string short_name(const std::string& prefix, const std::string& name,
                       const std::string& suffix) {
  return (prefix + name).substr(0, 32 - suffix.size()) + suffix;
}
bool has_mixed_parts(const Scene& scene) {
  for (const auto& p : scene.parts)
    if (p.formulation == PartFormulation::mixed_up) return true;
  return false;
}

// The contacts between deformable parts, in scene order.
std::vector<const ContactSpec*> part_contacts(const Scene& scene) {
  std::vector<const ContactSpec*> out;
  for (const auto& c : scene.contacts)
    if (!c.target_parts.empty()) out.push_back(&c);
  return out;
}

bool erodes(const Scene& scene) {
  for (const auto& m : scene.materials)
    if (m.constants.count("failure_strain")) return true;
  return false;
}

bool damps(const Scene& scene) {
  for (const auto& stage : scene.stages)
    if (stage.driver == "explicit" && stage.settings["damping"].as<double>() > 0) return true;
  return false;
}
}  // namespace

std::vector<std::string> history_names(const Scene& scene, int dimension) {
  std::vector<std::string> names = {
      "time_step", "kinetic_energy", "internal_energy",      "external_work",
      "wall_work", "total_energy",   "energy_balance_error", "strain_energy"};
  // Erosion: the energy of failed particles (part of internal_energy), only when a material can
  // erode (the columns of other scenes stay as they were).
  if (erodes(scene)) names.push_back("eroded_energy");
  // Mixed u-p cells: the work their bulk viscosity dissipated (explicit stages; 0 otherwise).
  if (has_mixed_parts(scene)) names.push_back("bulk_viscosity_work");
  // Mass damping: its work, only when a stage damps (other scenes' columns stay as they were).
  if (damps(scene)) names.push_back("mass_damping_work");
  const std::string axes = "xyz";
  const auto dim = static_cast<std::size_t>(dimension);
  for (const auto& w : scene.rigid_walls) names.push_back(short_name("wall_", w.name, "_force"));
  // Contacts between deformable parts: the force of the parts on the target parts.
  for (const auto* c : part_contacts(scene))
    for (std::size_t d = 0; d < dim; ++d)
      names.push_back(short_name("contact_", c->name, std::string("_F") + axes[d]));
  // Rigid bodies or contacts between parts: the momentum of particles and free bodies; per body
  // the contact force on it, its displacement and velocity.
  if (!scene.rigid_bodies.empty() || !part_contacts(scene).empty())
    for (std::size_t d = 0; d < dim; ++d) names.push_back(std::string("momentum_") + axes[d]);
  // ... and the moment of the contact forces about its reference point (2D: z only).
  for (const auto& b : scene.rigid_bodies) {
    for (const char* what : {"_F", "_u", "_v"})
      for (std::size_t d = 0; d < dim; ++d)
        names.push_back(short_name("rb_", b.name, std::string(what) + axes[d]));
    for (const char* what : {"_M", "_w"})  // contact moment, angular velocity
      for (std::size_t d = dim == 2 ? 2 : 0; d < 3; ++d)
        names.push_back(short_name("rb_", b.name, std::string(what) + axes[d]));
  }
  // Contacts with rigid bodies: the deepest particle over its spacing since the last record.
  for (const auto& c : scene.contacts)
    if (!c.rigid_body.empty()) names.push_back(short_name("contact_", c.name, "_pen"));
  // ... and the same for each rigid wall.
  for (const auto& w : scene.rigid_walls) names.push_back(short_name("wall_", w.name, "_pen"));
  for (const auto& bc : scene.boundary_conditions)
    for (std::size_t d = 0; d < dim; ++d)
      names.push_back(short_name("R_", bc.name, std::string("_") + axes[d]));
  for (const auto& set : scene.output.history_node_sets) {
    for (std::size_t d = 0; d < dim; ++d)
      names.push_back(short_name("u_", set, std::string("_") + axes[d]));
    for (std::size_t d = 0; d < dim; ++d)
      names.push_back(short_name("v_", set, std::string("_") + axes[d]));
  }
  for (const auto& name : probe_names(scene, dimension)) names.push_back(name);
  return names;
}

RunHistory::RunHistory(const Model& model)
    : model_(model), names_(history_names(model.scene, model.mesh.dimension)) {}

std::string RunHistory::csv_header() const {
  std::string header = "time";
  for (const auto& n : names_) header += "," + n;
  return header;
}

std::vector<double> RunHistory::values(const ModelOperators& ops, const RunState& state,
                                       const Vector& d_overlap, const Vector& v_overlap,
                                       const std::vector<std::array<double, 3>>& reactions) const {
  const auto& comm = *model_.maps.owned_dofs->getComm();
  const auto dim = static_cast<std::size_t>(model_.mesh.dimension);
  const double mine = ops.strain_energy(d_overlap);
  double strain_energy = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(strain_energy));
  std::vector<double> out = {state.dt,
                             state.kinetic,
                             state.internal,
                             state.external_work,
                             state.wall_work,
                             state.kinetic + state.internal,
                             state.balance_error(),
                             strain_energy};
  if (erodes(model_.scene)) {
    double eroded = 0;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, ops.solid().eroded_energy(),
                       Teuchos::outArg(eroded));
    out.push_back(eroded);
  }
  if (has_mixed_parts(model_.scene)) out.push_back(state.damping_work);
  if (damps(model_.scene)) out.push_back(state.mass_damping_work);
  for (std::size_t w = 0; w < model_.scene.rigid_walls.size(); ++w)
    out.push_back(w < state.wall_forces.size() ? state.wall_forces[w] : 0.0);
  // After the walls' normal forces: 3 components per contact between deformable parts.
  const auto walls = model_.scene.rigid_walls.size();
  const auto between_parts = part_contacts(model_.scene).size();
  for (std::size_t c = 0; c < between_parts; ++c)
    for (std::size_t d = 0; d < dim; ++d) {
      const auto at = walls + 3 * c + d;
      out.push_back(at < state.wall_forces.size() ? state.wall_forces[at] : 0.0);
    }
  if (!model_.scene.rigid_bodies.empty() || between_parts > 0)
    for (std::size_t d = 0; d < dim; ++d) out.push_back(state.momentum[d]);
  for (std::size_t b = 0; b < model_.scene.rigid_bodies.size(); ++b) {
    const RigidBodyState none;
    const auto& s = b < state.bodies.size() ? state.bodies[b] : none;
    for (const auto* v : {&s.force, &s.displacement, &s.velocity})
      for (std::size_t d = 0; d < dim; ++d) out.push_back((*v)[d]);
    for (const auto* v : {&s.moment, &s.angular_velocity})
      for (std::size_t d = dim == 2 ? 2 : 0; d < 3; ++d) out.push_back((*v)[d]);
  }
  const auto& pen = state.contact_penetrations;
  for (std::size_t c = 0; c < model_.scene.contacts.size(); ++c)
    if (!model_.scene.contacts[c].rigid_body.empty()) out.push_back(c < pen.size() ? pen[c] : 0.0);
  for (std::size_t w = 0, at = model_.scene.contacts.size(); w < model_.scene.rigid_walls.size();
       ++w, ++at)
    out.push_back(at < pen.size() ? pen[at] : 0.0);
  for (std::size_t c = 0; c < model_.scene.boundary_conditions.size(); ++c)
    for (std::size_t d = 0; d < dim; ++d)
      out.push_back(c < reactions.size() ? reactions[c][d] : 0.0);
  // Mean physical displacement and velocity of each history set over its owned particles.
  const auto du = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto dv = v_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (const auto& name : model_.scene.output.history_node_sets) {
    std::vector<char> in(model_.mesh.node_count(), 0);
    for (auto n : model_.mesh.find_node_set(name)->nodes) in[static_cast<std::size_t>(n)] = 1;
    std::vector<double> local(2 * dim + 1, 0.0), total(2 * dim + 1, 0.0);
    for (std::size_t p = 0; p < model_.parts.size(); ++p) {
      const auto& part = model_.parts[p];
      for (std::size_t j = 0; j < part.cloud.owned_count; ++j) {
        if (!in[static_cast<std::size_t>(part.cloud.mesh_node[j])]) continue;
        local[2 * dim] += 1;
        for (auto k = part.particle_values().offsets[j]; k < part.particle_values().offsets[j + 1];
             ++k) {
          const auto n = static_cast<std::size_t>(ops.solid().overlap_node(
              p)[static_cast<std::size_t>(part.particle_values().particles[k])]);
          for (std::size_t i = 0; i < dim; ++i) {
            local[i] += part.particle_values().values[k] * du(n * dim + i, 0);
            local[dim + i] += part.particle_values().values[k] * dv(n * dim + i, 0);
          }
        }
      }
    }
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                       total.data());
    const double count = std::max(1.0, total[2 * dim]);
    for (std::size_t i = 0; i < 2 * dim; ++i) out.push_back(total[i] / count);
  }
  for (double v : probe_values(model_, ops.solid(), d_overlap, ops.mixed())) out.push_back(v);
  return out;
}

}  // namespace efg
