#include "run/OutputFields.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "io/ExodusWriter.hpp"
#include "materials/SolidMaterial.hpp"
#include "mesh/NodalVolume.hpp"

namespace efg {
namespace {

template <int Dim>
void particle_state(const physics::SolidMaterial& m, bool finite, const double* h,
                    double (&strain)[3][3], double (&sigma)[3][3]) {
  double H[Dim][Dim];
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) H[i][j] = h[i * 3 + j];
  physics::cauchy_stress<Dim>(m, H, sigma);
  for (auto& row : strain)
    for (auto& v : row) v = 0.0;
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) {
      strain[i][j] = 0.5 * (H[i][j] + H[j][i]);
      if (finite)  // Green-Lagrange: E = (H + H^T + H^T H) / 2
        for (int k = 0; k < Dim; ++k) strain[i][j] += 0.5 * H[k][i] * H[k][j];
    }
  // Plane stress: sigma_zz = 0 gives eps_zz = -nu/(1 - nu) (eps_xx + eps_yy), and with the
  // reduced lambda* = 2 lambda mu / (lambda + 2 mu) that the material carries,
  // nu/(1 - nu) = lambda/(lambda + 2 mu) = lambda*/(2 mu).
  if (Dim == 2 && m.plane_stress && !finite)
    strain[2][2] = -m.lambda / (2 * m.mu) * (strain[0][0] + strain[1][1]);
}

void push_tensor(std::vector<double>& out, const double (&t)[3][3], int dim,
                 std::size_t component) {
  static const int map3[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  static const int map2[4][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}};
  const auto& ij = dim == 2 ? map2[component] : map3[component];
  out.push_back(t[ij[0]][ij[1]]);
}

}  // namespace

std::vector<std::string> field_columns(const std::string& field, int dimension) {
  if (field == "displacement" || field == "velocity" || field == "acceleration" ||
      field == "generalized_displacement" || field == "generalized_velocity")
    return vector_component_names(field, dimension);
  if (field == "material_state") {  // the law's history in its own order (restart)
    std::vector<std::string> names;
    for (int k = 1; k <= kLargestStateCount; ++k) names.push_back(field + "_" + std::to_string(k));
    return names;
  }
  if (field == "stress" || field == "strain") {
    // Symmetric tensors; zz is kept in 2D (plane strain stress, plane stress strain).
    if (dimension == 2) return {field + "_xx", field + "_yy", field + "_zz", field + "_xy"};
    return {field + "_xx", field + "_yy", field + "_zz",
            field + "_xy", field + "_yz", field + "_zx"};
  }
  if (field == "von_mises" || field == "pressure" || field == "plastic_strain" ||
      field == "eroded" || field == "nodal_volume" || field == "owner_rank")
    return {field};
  throw std::logic_error("no output columns for field '" + field + "'");
}

bool is_cell_field(const std::string& field) {
  return field == "cell_pressure";
}

std::vector<std::string> cell_columns(const std::vector<std::string>& fields) {
  std::vector<std::string> columns;
  for (const auto& f : fields)
    if (is_cell_field(f)) columns.push_back(f);
  return columns;
}

std::vector<GlobalOrdinal> output_cells(const Model& model) {
  std::vector<GlobalOrdinal> cells;
  for (const auto& part : model.parts)  // the background cells of each owned pressure cell
    for (auto g : part.cells.group)
      for (auto k = part.pressure_cells.offsets[g]; k < part.pressure_cells.offsets[g + 1]; ++k)
        cells.push_back(static_cast<GlobalOrdinal>(
            model.mesh.global_cell(static_cast<std::size_t>(part.pressure_cells.cells[k]))));
  return cells;
}

std::vector<std::vector<double>> cell_values(const Model& model, const MixedPressure* mixed,
                                             const Vector& d_overlap) {
  std::vector<std::vector<double>> columns;
  for (const auto& field : cell_columns(model.scene.output.fields)) {
    std::vector<double> values;
    if (field == "cell_pressure" && mixed)  // the condensed pressure, on each background cell
      for (std::size_t p = 0; p < model.parts.size(); ++p)
        if (mixed->mixed(p)) {
          const auto pressure = mixed->cell_pressures(p, d_overlap);
          const auto& part = model.parts[p];
          for (std::size_t c = 0; c < pressure.size(); ++c) {
            const auto g = part.cells.group[c];
            values.insert(values.end(),
                          part.pressure_cells.offsets[g + 1] - part.pressure_cells.offsets[g],
                          pressure[c]);
          }
        }
    columns.push_back(std::move(values));
  }
  return columns;
}

std::vector<std::string> output_columns(const std::vector<std::string>& fields, int dimension) {
  std::vector<std::string> columns;
  for (const auto& f : fields) {
    if (is_cell_field(f)) continue;
    const auto c = field_columns(f, dimension);
    columns.insert(columns.end(), c.begin(), c.end());
  }
  return columns;
}

namespace {

using Tensor = std::array<std::array<double, 3>, 3>;

// Interpolated values at the owned particles (partition order): u, v, a, the displacement
// gradient H and the part of each particle (-1: in no part).
struct ParticleValues {
  explicit ParticleValues(std::size_t n)
      : u(n, {0, 0, 0}),
        v(n, {0, 0, 0}),
        a(n, {0, 0, 0}),
        h(n, std::array<double, 9>{}),
        part(n, -1) {}
  std::vector<std::array<double, 3>> u, v, a;
  std::vector<std::array<double, 9>> h;
  std::vector<int> part;
};

// Position of every owned mesh node in the partition order (the owned count for other nodes).
std::vector<std::size_t> owned_slots(const Model& model) {
  const auto& owned = model.partition.owned;
  std::vector<std::size_t> slot(model.mesh.node_count(), owned.size());
  for (std::size_t i = 0; i < owned.size(); ++i) slot[static_cast<std::size_t>(owned[i])] = i;
  return slot;
}

ParticleValues interpolate(const Model& model, const SolidOperator& op, const Vector& d_overlap,
                           const Vector* v_overlap, const Vector* a_overlap) {
  const auto udim = static_cast<std::size_t>(model.mesh.dimension);
  const auto& owned = model.partition.owned;
  ParticleValues out(owned.size());
  const auto slot = owned_slots(model);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  using HostView = decltype(d);
  const HostView no_values;
  const auto v = v_overlap ? v_overlap->getLocalViewHost(Tpetra::Access::ReadOnly) : no_values;
  const auto a = a_overlap ? a_overlap->getLocalViewHost(Tpetra::Access::ReadOnly) : no_values;
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& part = model.parts[p];
    const auto& node = op.overlap_node(p);
    for (std::size_t j = 0; j < part.cloud.owned_count; ++j) {
      const auto s = slot[static_cast<std::size_t>(part.cloud.mesh_node[j])];
      out.part[s] = static_cast<int>(p);
      for (auto k = part.particle_values().offsets[j]; k < part.particle_values().offsets[j + 1];
           ++k) {
        const auto n = static_cast<std::size_t>(
            node[static_cast<std::size_t>(part.particle_values().particles[k])]);
        for (std::size_t i = 0; i < udim; ++i) {
          const double phi = part.particle_values().values[k];
          out.u[s][i] += phi * d(n * udim + i, 0);
          if (v_overlap) out.v[s][i] += phi * v(n * udim + i, 0);
          if (a_overlap) out.a[s][i] += phi * a(n * udim + i, 0);
        }
      }
      for (auto k = part.particle_gradients().offsets[j];
           k < part.particle_gradients().offsets[j + 1]; ++k) {
        const auto n = static_cast<std::size_t>(
            node[static_cast<std::size_t>(part.particle_gradients().particles[k])]);
        for (std::size_t i = 0; i < udim; ++i)
          for (std::size_t c = 0; c < udim; ++c)
            out.h[s][i * 3 + c] +=
                d(n * udim + i, 0) * part.particle_gradients().values[k * udim + c];
      }
    }
  }
  return out;
}

// Strains and stresses once per particle (not once per output column).
// Mixed u-p parts: the deviatoric law (lambda = -2 mu / 3) at the particle, and -p I from the
// particle's pressure (the mean of its cells'), so that -tr(sigma)/3 is that pressure.
void particle_tensors(const Model& model, const ParticleValues& values,
                      const std::vector<double>& pressure, const MixedPressure* mixed,
                      std::vector<Tensor>& strains, std::vector<Tensor>& stresses) {
  const int dim = model.mesh.dimension;
  std::vector<physics::SolidMaterial> materials;
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& pd = model.parts[p];
    // Mixed parts: the deviatoric law their points integrate (model/MaterialLaws).
    materials.push_back(
        mixed && mixed->mixed(p)
            ? material_law(model.scene, *pd.part, dim).elastic
            : solid_material(*model.scene.find_material(pd.part->material), *pd.part, dim));
  }
  for (std::size_t s = 0; s < values.part.size(); ++s) {
    if (values.part[s] < 0) continue;
    const auto p = static_cast<std::size_t>(values.part[s]);
    const bool finite = model.parts[p].part->section.formulation == Formulation::total_lagrangian;
    double strain[3][3] = {}, sigma[3][3] = {};
    if (dim == 2)
      particle_state<2>(materials[p], finite, values.h[s].data(), strain, sigma);
    else
      particle_state<3>(materials[p], finite, values.h[s].data(), strain, sigma);
    const double p_s = mixed && mixed->mixed(p) ? pressure[s] : 0.0;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        strains[s][i][j] = strain[i][j];
        stresses[s][i][j] = sigma[i][j] - (i == j ? p_s : 0.0);
      }
  }
}

// Path-dependent parts: stress, plastic strain and erosion flag from the committed history of
// each particle's integration point (SCNI and nodal integration: one point per particle; SCNI
// subcells: the volume-weighted mean over the pieces of its nodal domain). Mixed
// u-p parts: the history stress is the deviatoric law's, and -p I (the particle's pressure, as in
// particle_tensors) completes it.
void history_values(const Model& model, const SolidOperator& op, const Vector& d_overlap,
                    const ParticleValues& values, const std::vector<double>& pressure,
                    const MixedPressure* mixed, std::vector<Tensor>& stresses,
                    std::vector<double>& plastic, std::vector<double>& eroded) {
  const auto slot = owned_slots(model);
  const std::size_t none = model.partition.owned.size();
  constexpr std::size_t columns = SolidOperator::history_columns;
  for (const auto& h : op.history_output(d_overlap)) {
    // Subcells: the volume-weighted mean of the pieces of each particle's domain.
    std::vector<double> sum(h.domain.empty() ? 0 : none * columns, 0.0),
        volume(h.domain.empty() ? 0 : none, 0.0);
    for (std::size_t q = 0; q < h.domain.size(); ++q) {
      const auto s = h.domain[q] >= 0 ? slot[static_cast<std::size_t>(h.domain[q])] : none;
      if (s == none) continue;
      volume[s] += h.weight[q];
      for (std::size_t c = 0; c < columns; ++c)
        sum[s * columns + c] += h.weight[q] * h.values[q * columns + c];
    }
    const auto put = [&](std::size_t s, const double* row) {
      const bool with_pressure =
          mixed && values.part[s] >= 0 && mixed->mixed(static_cast<std::size_t>(values.part[s]));
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
          stresses[s][i][j] = row[i * 3 + j] - (i == j && with_pressure ? pressure[s] : 0.0);
      plastic[s] = row[9];
      eroded[s] = row[10];
    };
    for (std::size_t s = 0; s < volume.size(); ++s)
      if (volume[s] > 0) {
        for (std::size_t c = 0; c < columns; ++c) sum[s * columns + c] /= volume[s];
        put(s, &sum[s * columns]);
      }
    for (std::size_t q = 0; q < h.node.size(); ++q) {
      const auto s = h.node[q] >= 0 ? slot[static_cast<std::size_t>(h.node[q])] : none;
      if (s != none) put(s, &h.values[q * columns]);
    }
  }
}

// The committed material state at every owned particle (column after column, kLargestStateCount
// columns; zero where a part keeps none): SCNI and nodal points are particles. Gauss points are
// not particles and are not written (a restart refuses path-dependent Gauss parts).
std::vector<std::vector<double>> committed_states(const Model& model, const SolidOperator& op) {
  const auto slot = owned_slots(model);
  const std::size_t none = model.partition.owned.size();
  std::vector<std::vector<double>> out(static_cast<std::size_t>(kLargestStateCount),
                                       std::vector<double>(none, 0.0));
  const auto& history = op.history();
  for (std::size_t p = 0; p < history.parts(); ++p) {
    const auto& part = history.part(p);
    if (part.count == 0) continue;
    const auto committed = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), part.committed);
    const auto& nodes = op.point_nodes(p);
    for (std::size_t q = 0; q < nodes.size(); ++q) {
      const auto s = nodes[q] >= 0 ? slot[static_cast<std::size_t>(nodes[q])] : none;
      if (s == none) continue;
      for (std::size_t k = 0; k < static_cast<std::size_t>(part.count); ++k)
        out[k][s] = committed(q, k);
    }
  }
  return out;
}

}  // namespace

std::vector<double> nodal_volume_column(const Model& model) {
  const auto& fields = model.scene.output.fields;
  if (std::find(fields.begin(), fields.end(), "nodal_volume") == fields.end()) return {};
  return lumped_nodal_volumes(model.mesh);
}

std::vector<std::vector<double>> state_columns(const Model& model, const SolidOperator& op,
                                               const Vector& d_overlap, const Vector* v_overlap,
                                               const Vector* a_overlap, const MixedPressure* mixed,
                                               const std::vector<double>& nodal_volume) {
  const int dim = model.mesh.dimension;
  const auto& owned = model.partition.owned;
  // (a conditional of the caller's column and a computed one would copy the caller's each record)
  std::vector<double> computed;
  if (nodal_volume.empty()) computed = nodal_volume_column(model);
  const auto& volume = nodal_volume.empty() ? computed : nodal_volume;
  const auto particles = interpolate(model, op, d_overlap, v_overlap, a_overlap);
  std::vector<Tensor> strains(owned.size(), Tensor{}), stresses(owned.size(), Tensor{});
  const auto& fields = model.scene.output.fields;
  const auto pressure = mixed ? mixed->particle_pressures(d_overlap) : std::vector<double>{};
  if (std::any_of(fields.begin(), fields.end(), [](const std::string& f) {
        return f == "stress" || f == "strain" || f == "von_mises" || f == "pressure";
      }))
    particle_tensors(model, particles, pressure, mixed, strains, stresses);
  std::vector<double> plastic(owned.size(), 0.0), eroded(owned.size(), 0.0);
  if (op.history().any())
    history_values(model, op, d_overlap, particles, pressure, mixed, stresses, plastic, eroded);
  const auto udim = static_cast<std::size_t>(dim);
  const auto material = std::find(fields.begin(), fields.end(), "material_state") != fields.end()
                            ? committed_states(model, op)
                            : std::vector<std::vector<double>>{};
  std::vector<std::vector<double>> columns;
  for (const auto& field : fields) {
    if (is_cell_field(field)) continue;  // cell_values
    const auto count = field_columns(field, dim).size();
    if (field == "generalized_displacement" || field == "generalized_velocity" ||
        field == "material_state") {  // the restart fields: the generalized values themselves
      const Vector* source = field == "generalized_displacement" ? &d_overlap : v_overlap;
      for (std::size_t c = 0; c < count; ++c) {
        std::vector<double> values(owned.size(), 0.0);
        if (field == "material_state") {
          values = material[c];
        } else if (source) {
          const auto x = source->getLocalViewHost(Tpetra::Access::ReadOnly);
          for (std::size_t s = 0; s < owned.size(); ++s) values[s] = x(s * udim + c, 0);
        }
        columns.push_back(std::move(values));
      }
      continue;
    }
    for (std::size_t c = 0; c < count; ++c) {
      std::vector<double> values;
      values.reserve(owned.size());
      for (std::size_t s = 0; s < owned.size(); ++s) {
        double strain[3][3], sigma[3][3];
        for (std::size_t i = 0; i < 3; ++i)
          for (std::size_t j = 0; j < 3; ++j) {
            strain[i][j] = strains[s][i][j];
            sigma[i][j] = stresses[s][i][j];
          }
        if (field == "displacement")
          values.push_back(particles.u[s][c]);
        else if (field == "velocity")
          values.push_back(particles.v[s][c]);
        else if (field == "acceleration")
          values.push_back(particles.a[s][c]);
        else if (field == "stress")
          push_tensor(values, sigma, dim, c);
        else if (field == "strain")
          push_tensor(values, strain, dim, c);
        else if (field == "von_mises")
          values.push_back(physics::von_mises(sigma));
        else if (field == "pressure")
          values.push_back(-(sigma[0][0] + sigma[1][1] + sigma[2][2]) / 3.0);
        else if (field == "plastic_strain")
          values.push_back(plastic[s]);
        else if (field == "eroded")
          values.push_back(eroded[s]);
        else if (field == "nodal_volume")
          values.push_back(volume[static_cast<std::size_t>(owned[s])]);
        else if (field == "owner_rank")
          values.push_back(model.partition.rank);
      }
      columns.push_back(std::move(values));
    }
  }
  return columns;
}

}  // namespace efg
