#include "shells/ShellReference.hpp"

#include <algorithm>
#include <cmath>

#include "discretization/ShapeFunctions.hpp"
#include "scene/ShellReferenceMap.hpp"

namespace efg {

namespace {

/// A point of the frame and metric from the tangents (the conventions of shell_reference_at).
ShellReferencePoint reference_from_tangents(const Vec3& position, const Vec3& A1, const Vec3& A2) {
  ShellReferencePoint r;
  r.position = position;
  r.tangent[0] = A1;
  r.tangent[1] = A2;
  Vec3 t1 = A1, t3 = cross(A1, A2);
  const double n1 = std::sqrt(dot(t1, t1)), n3 = std::sqrt(dot(t3, t3));
  for (auto& v : t1) v /= n1;
  for (auto& v : t3) v /= n3;
  r.frame = {t1, cross(t3, t1), t3};
  r.metric = shell_metric(r.tangent, r.frame);
  return r;
}

}  // namespace

ShellReferencePoint shell_reference_at(const std::vector<ScalarField>& map, const double* xy,
                                       double step) {
  const auto point = shell_map_point(map, xy, step);
  return reference_from_tangents(point.position, point.tangent[0], point.tangent[1]);
}

bool curved_part(const Model& model, std::size_t part) {
  const auto& spec = *model.parts.at(part).part;
  return !model.mesh.surface.empty() || (spec.shell && !spec.shell->reference.empty());
}

std::optional<ShellReferencePoint> part_reference_at(const Model& model, std::size_t part,
                                                     const double* xy) {
  const auto& spec = *model.parts.at(part).part;
  if (!model.mesh.surface.empty()) {
    const auto& cloud = model.parts[part].cloud;
    const auto v = evaluate_shape_functions(cloud, xy, 1, true, [&](std::size_t) {
      return "shell surface point (" + std::to_string(xy[0]) + ", " + std::to_string(xy[1]) + ")";
    });
    Vec3 X{}, A1{}, A2{};
    for (auto k = v.neighbors.offsets[0]; k < v.neighbors.offsets[1]; ++k) {
      const auto node = static_cast<std::size_t>(
          cloud.mesh_node[static_cast<std::size_t>(v.neighbors.particles[k])]);
      for (std::size_t c = 0; c < 3; ++c) {
        const double P = model.mesh.surface[3 * node + c];
        X[c] += v.phi[k] * P;
        A1[c] += v.grad[2 * k] * P;
        A2[c] += v.grad[2 * k + 1] * P;
      }
    }
    return reference_from_tangents(X, A1, A2);
  }
  if (!spec.shell || spec.shell->reference.empty()) return std::nullopt;
  return shell_reference_at(spec.shell->reference, xy, shell_map_step(model.mesh));
}

std::vector<ShellFrame> surface_node_frames(const BackgroundMesh& mesh) {
  const std::size_t nodes = mesh.node_count();
  std::vector<Vec3> A1(nodes, Vec3{}), A2(nodes, Vec3{});
  const auto& P = mesh.surface;
  const auto& c = mesh.coordinates;
  const auto add_triangle = [&](LocalIndex a, LocalIndex b, LocalIndex d) {
    const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b),
               k = static_cast<std::size_t>(d);
    // chart edges C = [c_j - c_i, c_k - c_i] (2 x 2), surface edges E (3 x 2): dX/dchart = E C^-1
    const double C00 = c[2 * j] - c[2 * i], C10 = c[2 * j + 1] - c[2 * i + 1],
                 C01 = c[2 * k] - c[2 * i], C11 = c[2 * k + 1] - c[2 * i + 1];
    const double det = C00 * C11 - C01 * C10;
    Vec3 t[2]{}, e1{}, e2{};
    for (std::size_t m = 0; m < 3; ++m) {
      e1[m] = P[3 * j + m] - P[3 * i + m];
      e2[m] = P[3 * k + m] - P[3 * i + m];
      t[0][m] = (e1[m] * C11 - e2[m] * C10) / det;
      t[1][m] = (-e1[m] * C01 + e2[m] * C00) / det;
    }
    const Vec3 n = cross(e1, e2);
    const double area = std::sqrt(dot(n, n));
    for (auto node : {i, j, k})
      for (std::size_t m = 0; m < 3; ++m) {
        A1[node][m] += area * t[0][m];
        A2[node][m] += area * t[1][m];
      }
  };
  for (const auto& block : mesh.blocks) {
    const auto n = static_cast<std::size_t>(cell_node_count(block.type));
    for (std::size_t e = 0; e < block.cell_count(); ++e) {
      const auto* k = &block.connectivity[e * n];
      add_triangle(k[0], k[1], k[2]);
      if (n == 4) add_triangle(k[0], k[2], k[3]);
    }
  }
  std::vector<ShellFrame> frames(nodes);
  for (std::size_t i = 0; i < nodes; ++i)
    if (dot(A1[i], A1[i]) > 0) frames[i] = reference_from_tangents({}, A1[i], A2[i]).frame;
  return frames;
}

void align_frames_to_supports(const Model& model, std::vector<ShellFrame>& frames) {
  const auto& mesh = model.mesh;
  for (const auto& bc : model.scene.boundary_conditions) {
    if (!bc.rotations[0] && !bc.rotations[1]) continue;
    const auto* set = mesh.find_node_set(bc.node_set);
    if (!set) continue;  // (ShellConstraints names it)
    std::vector<char> in(mesh.node_count(), 0);
    for (auto n : set->nodes) in[static_cast<std::size_t>(n)] = 1;
    std::vector<Vec3> along(mesh.node_count(), Vec3{});
    for (const auto& block : mesh.blocks) {
      const auto n = static_cast<std::size_t>(cell_node_count(block.type));
      for (std::size_t e = 0; e < block.cell_count(); ++e)
        for (std::size_t k = 0; k < n; ++k) {
          const auto a = static_cast<std::size_t>(block.connectivity[e * n + k]),
                     b = static_cast<std::size_t>(block.connectivity[e * n + (k + 1) % n]);
          if (!in[a] || !in[b]) continue;
          Vec3 side{};
          for (std::size_t c = 0; c < 3; ++c)
            side[c] = mesh.surface[3 * b + c] - mesh.surface[3 * a + c];
          for (auto node : {a, b}) {  // sides met at a node added head to tail
            const double sign = dot(along[node], side) < 0 ? -1.0 : 1.0;
            for (std::size_t c = 0; c < 3; ++c) along[node][c] += sign * side[c];
          }
        }
    }
    for (auto node : set->nodes) {
      const auto i = static_cast<std::size_t>(node);
      auto& f = frames[i];
      Vec3 t1 = along[i];
      const double normal = dot(t1, f.t3);
      for (std::size_t c = 0; c < 3; ++c) t1[c] -= normal * f.t3[c];
      const double length = std::sqrt(dot(t1, t1));
      if (!(length > 0)) continue;  // a pin: no edge, the frame stays
      for (auto& v : t1) v /= length;
      f.t1 = t1;
      f.t2 = cross(f.t3, t1);
    }
  }
}

double edge_stretch(const Model& model, std::size_t part, const double* xy, const double* normal) {
  const auto r = part_reference_at(model, part, xy);
  if (!r) return 1.0;
  Vec3 along{};
  for (std::size_t c = 0; c < 3; ++c)
    along[c] = -normal[1] * r->tangent[0][c] + normal[0] * r->tangent[1][c];
  return std::sqrt(dot(along, along));
}

BackgroundMesh shell_reference_mesh(const Model& model) {
  const auto& flat = model.mesh;
  BackgroundMesh shown;
  shown.dimension = 3;
  shown.blocks = flat.blocks;
  shown.node_sets = flat.node_sets;
  shown.source = flat.source;
  const std::size_t nodes = flat.node_count();
  shown.coordinates.assign(3 * nodes, 0.0);
  for (std::size_t n = 0; n < nodes; ++n)
    for (std::size_t c = 0; c < 2; ++c) shown.coordinates[3 * n + c] = flat.coordinates[2 * n + c];
  if (!flat.surface.empty()) {  // a shell surface read in 3D: its own positions
    shown.coordinates = flat.surface;
    return shown;
  }
  for (const auto& part : model.scene.parts) {
    if (!part.shell || part.shell->reference.empty()) continue;
    for (const auto& block : flat.blocks) {
      if (std::find(part.blocks.begin(), part.blocks.end(), block.name) == part.blocks.end())
        continue;
      for (auto node : block.connectivity) {
        const auto n = static_cast<std::size_t>(node);
        const auto x = shell_map_position(part.shell->reference, flat.coordinates.data() + 2 * n);
        std::copy(x.begin(), x.end(),
                  shown.coordinates.begin() + static_cast<std::ptrdiff_t>(3 * n));
      }
    }
  }
  return shown;
}

}  // namespace efg
