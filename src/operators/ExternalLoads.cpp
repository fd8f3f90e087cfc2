#include "operators/ExternalLoads.hpp"

#include <Tpetra_Export.hpp>

#include <algorithm>

#include "core/Errors.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "operators/SideQuadrature.hpp"

namespace efg {
namespace {

// Adds phi_I(x_p) * value_p * weight_p for a batch of points of one part.
void add_point_loads(const PartDiscretization& part, const std::vector<int>& overlap_node,
                     const std::vector<double>& x, const std::vector<std::array<double, 3>>& value,
                     const std::vector<double>& weight, int dim, Vector& f_overlap) {
  if (weight.empty()) return;
  const auto v =
      evaluate_shape_functions(part.cloud, x.data(), weight.size(), false,
                               [](std::size_t p) { return "load point " + std::to_string(p); });
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t p = 0; p < weight.size(); ++p)
    for (auto k = v.neighbors.offsets[p]; k < v.neighbors.offsets[p + 1]; ++k) {
      const auto node = static_cast<std::size_t>(
          overlap_node[static_cast<std::size_t>(v.neighbors.particles[k])]);
      for (int i = 0; i < dim; ++i)
        f(node * static_cast<std::size_t>(dim) + static_cast<std::size_t>(i), 0) +=
            v.phi[k] * value[p][static_cast<std::size_t>(i)] * weight[p];
    }
}

}  // namespace

int part_of_block(const Scene& scene, const std::string& name) {
  for (std::size_t p = 0; p < scene.parts.size(); ++p)
    if (std::find(scene.parts[p].blocks.begin(), scene.parts[p].blocks.end(), name) !=
        scene.parts[p].blocks.end())
      return static_cast<int>(p);
  return -1;
}

namespace {

// Point loads gathered per part, then spread to the particles by the shape functions.
struct PointLoads {
  explicit PointLoads(std::size_t parts) : x(parts), w(parts), value(parts) {}
  void add(std::size_t part, const double* point, int dim, const std::array<double, 3>& v,
           double weight) {
    x[part].insert(x[part].end(), point, point + dim);
    value[part].push_back(v);
    w[part].push_back(weight);
  }
  void scatter(const Model& model, const SolidOperator& op, Vector& f_overlap) const {
    for (std::size_t p = 0; p < x.size(); ++p)
      add_point_loads(model.parts[p], op.overlap_node(p), x[p], value[p], w[p],
                      model.mesh.dimension, f_overlap);
  }
  std::vector<std::vector<double>> x, w;
  std::vector<std::vector<std::array<double, 3>>> value;
};

// Tractions and pressures on a side set, at the SCNI boundary points of its owned sides.
void add_surface_load(const Model& model, const SolidOperator& op, const LoadSpec& spec,
                      const ExactSolution* exact, Vector& f_overlap) {
  const auto& mesh = model.mesh;
  const int dim = mesh.dimension;
  const auto udim = static_cast<std::size_t>(dim);
  PointLoads loads(model.parts.size());
  const auto* set = mesh.find_side_set(spec.set);
  for (std::size_t i = 0; i < set->cells.size(); ++i) {
    const auto cell = static_cast<std::size_t>(set->cells[i]);
    const auto nodes = mesh.side_node_indices(cell, set->sides[i]);
    const auto first = *std::min_element(nodes.begin(), nodes.end());
    if (model.partition.owner[static_cast<std::size_t>(first)] != model.partition.rank) continue;
    const int part = part_of_block(model.scene, mesh.locate_cell(cell).first->name);
    if (part < 0) continue;
    const double thickness =
        dim == 2 ? model.scene.parts[static_cast<std::size_t>(part)].thickness : 1.0;
    for (const auto& q : side_quadrature(mesh, cell, set->sides[i])) {
      std::array<double, 3> t{0, 0, 0};
      if (spec.type == "pressure") {
        for (std::size_t d = 0; d < 3; ++d) t[d] = -spec.value[0] * q.normal[d];
      } else if (spec.from_exact) {
        double P[3][3];
        exact->nominal_stress(q.x.data(), P);
        for (std::size_t a = 0; a < 3; ++a)
          for (std::size_t b = 0; b < 3; ++b) t[a] += P[a][b] * q.normal[b];
      } else {
        for (std::size_t d = 0; d < udim; ++d) t[d] = spec.value[d];
      }
      loads.add(static_cast<std::size_t>(part), q.x.data(), dim, t, q.weight * thickness);
    }
  }
  loads.scatter(model, op, f_overlap);
}

// A force on a node set, shared equally by its nodes (at each owned particle of the set).
void add_nodal_force(const Model& model, const SolidOperator& op, const LoadSpec& spec,
                     Vector& f_overlap) {
  const auto udim = static_cast<std::size_t>(model.mesh.dimension);
  PointLoads loads(model.parts.size());
  const auto* set = model.mesh.find_node_set(spec.set);
  const double share = 1.0 / static_cast<double>(set->nodes.size());
  for (auto node : set->nodes) {
    if (model.partition.owner[static_cast<std::size_t>(node)] != model.partition.rank) continue;
    for (std::size_t p = 0; p < model.parts.size(); ++p) {
      const auto& c = model.parts[p].cloud;
      const auto end = c.mesh_node.begin() + static_cast<std::ptrdiff_t>(c.owned_count);
      const auto it = std::find(c.mesh_node.begin(), end, node);
      if (it == end) continue;
      std::array<double, 3> force{0, 0, 0};
      for (std::size_t d = 0; d < udim; ++d) force[d] = spec.value[d];
      loads.add(p, c.x(static_cast<std::size_t>(it - c.mesh_node.begin())), model.mesh.dimension,
                force, share);
    }
  }
  loads.scatter(model, op, f_overlap);
}

// A body force per unit volume over the named parts (all when none), at the integration points.
void add_body_force(const Model& model, const SolidOperator& op, const LoadSpec& spec,
                    const ExactSolution* exact, Vector& f_overlap) {
  const int dim = model.mesh.dimension;
  const auto udim = static_cast<std::size_t>(dim);
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& part = *model.parts[p].part;
    if (!spec.parts.empty() &&
        std::find(spec.parts.begin(), spec.parts.end(), part.name) == spec.parts.end())
      continue;
    const auto& ip = model.parts[p].points;
    const double thickness = dim == 2 ? part.thickness : 1.0;
    for (std::size_t q = 0; q < ip.size(); ++q) {
      double b[3] = {0, 0, 0};
      if (spec.from_exact) {
        if (exact->body_force) exact->body_force(&ip.x[q * udim], b);
      } else {
        for (std::size_t d = 0; d < udim; ++d) b[d] = spec.value[d];
      }
      for (auto k = ip.values.offsets[q]; k < ip.values.offsets[q + 1]; ++k) {
        const auto node = static_cast<std::size_t>(
            op.overlap_node(p)[static_cast<std::size_t>(ip.values.particles[k])]);
        for (std::size_t i = 0; i < udim; ++i)
          f(node * udim + i, 0) += ip.values.values[k] * b[i] * ip.weight[q] * thickness;
      }
    }
  }
}

}  // namespace

ExternalLoads::ExternalLoads(const Model& model, const SolidOperator& op,
                             const ExactSolution* exact) {
  Tpetra::Export<> to_owned(model.maps.overlap_dofs, model.maps.owned_dofs);
  for (const auto& spec : model.scene.loads) {
    Vector f_overlap(model.maps.overlap_dofs);
    if (spec.type == "traction" || spec.type == "pressure")
      add_surface_load(model, op, spec, exact, f_overlap);
    else if (spec.type == "nodal_force")
      add_nodal_force(model, op, spec, f_overlap);
    else if (spec.type == "body_force")
      add_body_force(model, op, spec, exact, f_overlap);
    auto owned = Teuchos::rcp(new Vector(model.maps.owned_dofs));
    owned->doExport(f_overlap, to_owned, Tpetra::ADD);
    loads_.push_back({spec.curve, owned});
  }
}

void ExternalLoads::assemble(const LoadFactor& factor, Vector& f_owned) const {
  f_owned.putScalar(0.0);
  for (const auto& l : loads_) f_owned.update(factor(l.curve), *l.force, 1.0);
}

}  // namespace efg
