#include "shells/ShellBoundary.hpp"

#include <Teuchos_CommHelpers.hpp>

#include "discretization/ShapeFunctions.hpp"
#include "operators/SideQuadrature.hpp"
#include "shells/ShellSpacing.hpp"

namespace efg {

std::vector<ShellEdgePoint> shell_edge_points(const Model& model, const std::string& node_set,
                                              long long* sides_found) {
  const auto& mesh = model.mesh;
  std::vector<char> in_set(mesh.node_count(), 0);
  if (const auto* set = mesh.find_node_set(node_set))
    for (auto n : set->nodes) in_set[static_cast<std::size_t>(n)] = 1;
  std::vector<ShellEdgePoint> out;
  if (sides_found) *sides_found = 0;
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& d = model.parts[p];
    std::vector<SidePoint> sides;
    const auto covered =
        node_set_sides(mesh, d.part->blocks, in_set, model.partition.owner, model.partition.rank);
    if (sides_found) *sides_found += static_cast<long long>(covered.here.size());
    for (const auto& [cell, side] : covered.here)
      for (const auto& q : side_quadrature(mesh, cell, side)) sides.push_back(q);
    if (sides.empty()) continue;
    std::vector<double> x;
    for (const auto& q : sides) x.insert(x.end(), {q.x[0], q.x[1]});
    const auto v =
        evaluate_shape_functions(d.cloud, x.data(), sides.size(), true, [&](std::size_t q) {
          return "edge point " + std::to_string(q) + " of node set '" + node_set + "'";
        });
    for (std::size_t q = 0; q < sides.size(); ++q) {
      ShellEdgePoint e;
      e.part = p;
      e.x = {sides[q].x[0], sides[q].x[1]};
      e.normal = {sides[q].normal[0], sides[q].normal[1]};
      e.length = sides[q].weight;
      double largest = -1;  // the spacing of the particle whose function is largest there
      for (auto k = v.neighbors.offsets[q]; k < v.neighbors.offsets[q + 1]; ++k) {
        const auto particle = static_cast<std::size_t>(v.neighbors.particles[k]);
        if (v.phi[k] > largest) {
          largest = v.phi[k];
          e.spacing = shell_spacing(d.cloud, particle);
        }
        e.node.push_back(d.cloud.mesh_node[static_cast<std::size_t>(v.neighbors.particles[k])]);
        e.phi.push_back(v.phi[k]);
        e.grad.insert(e.grad.end(), {v.grad[2 * k], v.grad[2 * k + 1]});
      }
      out.push_back(std::move(e));
    }
  }
  if (sides_found) {  // over the ranks: each integrates its own
    long long all = 0;
    Teuchos::reduceAll(*model.maps.owned_dofs->getComm(), Teuchos::REDUCE_SUM, *sides_found,
                       Teuchos::outArg(all));
    *sides_found = all;
  }
  return out;
}

}  // namespace efg
