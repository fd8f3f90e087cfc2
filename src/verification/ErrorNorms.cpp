#include "verification/ErrorNorms.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "discretization/CellOwner.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "mesh/GaussRules.hpp"
#include "model/GradedMaterials.hpp"
#include "model/PointOwner.hpp"

namespace efg {

namespace {

// Gauss points (order 5) of the owned cells of a part's blocks, with weights x thickness. A
// mixed part's cells go with their pressure cell (on the rank that owns its row).
struct PartQuadrature {
  std::vector<double> x, w;
  std::vector<std::size_t> group;  ///< mixed parts: the point's row in part.cells
};

// Mixed parts: the entry of part.cells of every global cell of an owned pressure cell.
std::vector<std::size_t> row_of_cells(const PartDiscretization& part, std::size_t cell_count) {
  std::vector<std::size_t> row(cell_count, std::numeric_limits<std::size_t>::max());
  const auto& groups = part.pressure_cells;
  for (std::size_t c = 0; c < part.cells.size(); ++c) {
    const auto g = part.cells.group[c];
    for (auto k = groups.offsets[g]; k < groups.offsets[g + 1]; ++k) row[groups.cells[k]] = c;
  }
  return row;
}

PartQuadrature part_quadrature(const Model& model, const PartDiscretization& part) {
  const auto& mesh = model.mesh;
  const auto udim = static_cast<std::size_t>(mesh.dimension);
  const double thickness = mesh.dimension == 2 ? part.part->thickness : 1.0;
  PartQuadrature out;
  const bool mixed = part.pressure_cells.size() > 0;
  const auto row = mixed ? row_of_cells(part, mesh.cell_count()) : std::vector<std::size_t>{};
  std::size_t global_cell = 0;
  for (const auto& b : mesh.blocks) {
    const std::size_t first_cell = global_cell;
    global_cell += b.cell_count();
    if (std::find(part.part->blocks.begin(), part.part->blocks.end(), b.name) ==
        part.part->blocks.end())
      continue;
    const auto npc = static_cast<std::size_t>(cell_node_count(b.type));
    const auto rule = reference_rule(b.type, 5);
    std::vector<double> cx(npc * udim);
    for (std::size_t c = 0; c < b.cell_count(); ++c) {
      const auto* node = &b.connectivity[c * npc];
      if (mixed ? row[first_cell + c] == std::numeric_limits<std::size_t>::max()
                : cell_owner(node, npc, model.partition.owner) != model.partition.rank)
        continue;
      for (std::size_t a = 0; a < npc; ++a)
        for (std::size_t k = 0; k < udim; ++k)
          cx[a * udim + k] = mesh.coordinates[static_cast<std::size_t>(node[a]) * udim + k];
      for (std::size_t q = 0; q < rule.weight.size(); ++q) {
        double point[3];
        const double det = map_to_cell(b.type, cx.data(), &rule.xi[q * udim], point);
        out.x.insert(out.x.end(), point, point + udim);
        out.w.push_back(rule.weight[q] * det * thickness);
        if (mixed) out.group.push_back(row[first_cell + c]);
      }
    }
  }
  return out;
}

// The largest nodal error |u^h(X_J) - u(X_J)| over the part's owned particles.
double largest_nodal_error(
    const PartDiscretization& part, const std::vector<int>& nodes, const ExactSolution& exact,
    std::size_t udim,
    const Kokkos::View<const double**, Kokkos::LayoutLeft, Kokkos::HostSpace>& d) {
  double largest = 0;
  for (std::size_t j = 0; j < part.cloud.owned_count; ++j) {
    double uh[3] = {0, 0, 0}, u[3] = {0, 0, 0};
    for (auto k = part.particle_values().offsets[j]; k < part.particle_values().offsets[j + 1];
         ++k) {
      const auto n = static_cast<std::size_t>(
          nodes[static_cast<std::size_t>(part.particle_values().particles[k])]);
      for (std::size_t i = 0; i < udim; ++i)
        uh[i] += part.particle_values().values[k] * d(n * udim + i, 0);
    }
    exact.displacement(part.cloud.x(j), u);
    for (std::size_t i = 0; i < udim; ++i) largest = std::max(largest, std::abs(uh[i] - u[i]));
  }
  return largest;
}

}  // namespace

ErrorNorms error_norms(const Model& model, const SolidOperator& op, const MixedPressure* mixed,
                       const Vector& d_overlap, const ExactSolution& exact) {
  const int dim = model.mesh.dimension;
  const auto udim = static_cast<std::size_t>(dim);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  // sums: |e|^2, |u|^2, a(e,e), a(u,u), |p^h - p|^2, |p|^2
  double local[6] = {0, 0, 0, 0, 0, 0}, max_nodal = 0;
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& part = model.parts[p];
    auto m = solid_material(*model.scene.find_material(part.part->material), *part.part, dim);
    // Mixed parts: the deviatoric energy at the points (lambda -> -2 mu / 3, as the law the
    // operator integrates) and the pressure term per cell.
    const bool is_mixed = mixed && mixed->mixed(p);
    const double kappa = is_mixed ? mixed->bulk_modulus(p) : 0.0;
    if (is_mixed) m.lambda = -2.0 * m.mu / 3.0;
    const auto theta_c = is_mixed ? mixed->cell_dilatations(p, d_overlap) : std::vector<double>{};
    const auto quadrature = part_quadrature(model, part);
    const auto& x = quadrature.x;
    const auto& w = quadrature.w;
    const auto v = evaluate_shape_functions(part.cloud, x.data(), w.size(), true);
    const auto& nodes = op.overlap_node(p);
    // Graded materials: C scales with E(x_q)/E_ref at each Gauss point.
    const auto scale =
        modulus_scale(*model.scene.find_material(part.part->material), x.data(), w.size(), dim);
    // a(e, e) with the elasticity tensor: eps : C : eps = lambda tr(eps)^2 + 2 mu eps : eps.
    auto energy = [&](const double(&g)[3][3]) {
      double tr = 0, ee = 0;
      for (std::size_t i = 0; i < udim; ++i) tr += g[i][i];
      for (std::size_t i = 0; i < udim; ++i)
        for (std::size_t j = 0; j < udim; ++j)
          ee += 0.25 * (g[i][j] + g[j][i]) * (g[i][j] + g[j][i]);
      return m.lambda * tr * tr + 2 * m.mu * ee;
    };
    for (std::size_t q = 0; q < w.size(); ++q) {
      double uh[3] = {0, 0, 0}, gh[3][3] = {};
      for (auto k = v.neighbors.offsets[q]; k < v.neighbors.offsets[q + 1]; ++k) {
        const auto n =
            static_cast<std::size_t>(nodes[static_cast<std::size_t>(v.neighbors.particles[k])]);
        for (std::size_t i = 0; i < udim; ++i) {
          uh[i] += v.phi[k] * d(n * udim + i, 0);
          for (std::size_t j = 0; j < udim; ++j)
            gh[i][j] += d(n * udim + i, 0) * v.grad[k * udim + j];
        }
      }
      double u[3] = {0, 0, 0}, g[3][3] = {};
      exact.displacement(&x[q * udim], u);
      exact_gradient(exact, &x[q * udim], udim, g);
      double e[3][3] = {};
      for (std::size_t i = 0; i < udim; ++i) {
        local[0] += w[q] * (uh[i] - u[i]) * (uh[i] - u[i]);
        local[1] += w[q] * u[i] * u[i];
        for (std::size_t j = 0; j < udim; ++j) e[i][j] = gh[i][j] - g[i][j];
      }
      const double c = scale.empty() ? 1.0 : scale[q];
      local[2] += c * w[q] * energy(e);
      local[3] += c * w[q] * energy(g);
      if (is_mixed) {
        double theta = 0;
        for (std::size_t i = 0; i < udim; ++i) theta += g[i][i];
        const double ph = -kappa * theta_c[quadrature.group[q]], pe = -kappa * theta;
        local[2] += w[q] * (ph - pe) * (ph - pe) / kappa;
        local[3] += w[q] * pe * pe / kappa;
        local[4] += w[q] * (ph - pe) * (ph - pe);
        local[5] += w[q] * pe * pe;
      }
    }
    max_nodal = std::max(max_nodal, largest_nodal_error(part, nodes, exact, udim, d));
  }
  const auto& comm = *model.maps.owned_dofs->getComm();
  double global[6] = {0, 0, 0, 0, 0, 0}, max_all = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 6, local, global);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, max_nodal, Teuchos::outArg(max_all));
  ErrorNorms out;
  out.l2_relative = std::sqrt(global[0] / global[1]);
  out.energy_relative = std::sqrt(global[2] / global[3]);
  out.max_nodal = max_all;
  if (mixed) out.pressure_relative = global[5] > 0 ? std::sqrt(global[4] / global[5]) : 0.0;
  return out;
}

std::array<double, 3> displacement_at(const Model& model, const SolidOperator& op,
                                      const Vector& d_overlap, const double* point) {
  const int dim = model.mesh.dimension;
  const auto udim = static_cast<std::size_t>(dim);
  // The rank owning the particle nearest to the point evaluates (it has the whole support).
  const int best_part = evaluating_part(model, point);
  const auto& comm = *model.maps.owned_dofs->getComm();
  double local[3] = {0, 0, 0}, global[3] = {0, 0, 0};
  if (best_part >= 0) {
    const auto& part = model.parts[static_cast<std::size_t>(best_part)];
    const auto v = evaluate_shape_functions(part.cloud, point, 1, false);
    const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (auto k = v.neighbors.offsets[0]; k < v.neighbors.offsets[1]; ++k) {
      const auto n = static_cast<std::size_t>(op.overlap_node(
          static_cast<std::size_t>(best_part))[static_cast<std::size_t>(v.neighbors.particles[k])]);
      for (std::size_t i = 0; i < udim; ++i) local[i] += v.phi[k] * d(n * udim + i, 0);
    }
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 3, local, global);
  return {global[0], global[1], global[2]};
}

}  // namespace efg
