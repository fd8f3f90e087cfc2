#include "model/RigidMeshBlocks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "core/Errors.hpp"
#include "discretization/OrientedFacets.hpp"
#include "geometry/FacetNormal.hpp"
#include "model/WeldedBlocks.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {

InputError rigid_blocks_error(const Scene& scene, std::size_t body, const std::string& message) {
  return InputError(
      schema::located_message(scene.file, scene.document["rigid_bodies"][body]["blocks"],
                              "rigid_bodies[" + std::to_string(body) + "].blocks", message));
}

namespace {

[[noreturn]] void fail(const Scene& scene, std::size_t body, const std::string& message) {
  throw rigid_blocks_error(scene, body, message);
}

bool is_surface_block(const BackgroundMesh& mesh, const std::string& name) {
  return cell_dimension(mesh.find_block(name)->type) == mesh.dimension - 1;
}

// The cells of surface blocks as facets in their own node order (quadrilaterals cut along
// their 0-2 diagonal), appended to s after the solid blocks' (which alone carry volume).
void add_surface_cells(const BackgroundMesh& mesh, const std::vector<std::string>& blocks,
                       RigidSurface& s) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  for (const auto& name : blocks) {
    if (!is_surface_block(mesh, name)) continue;
    const auto& block = *mesh.find_block(name);
    const auto per = static_cast<std::size_t>(cell_node_count(block.type));
    for (std::size_t c = 0; c < block.cell_count(); ++c) {
      const auto* cell = &block.connectivity[c * per];
      std::vector<std::array<LocalIndex, 3>> pieces = {{cell[0], cell[1], cell[2]}};
      if (per == 4) pieces.push_back({cell[0], cell[2], cell[3]});
      for (const auto& piece : pieces) {
        double x[3][3] = {};
        for (std::size_t a = 0; a < 3; ++a)
          for (std::size_t k = 0; k < dim; ++k)
            x[a][k] = mesh.coordinates[static_cast<std::size_t>(piece[a]) * dim + k];
        for (const auto& corner : x) s.corners.insert(s.corners.end(), corner, corner + 3);
        s.reference_size.push_back(longest_edge(x, 3));
      }
    }
  }
}

// Corners, volume and centroid of the blocks' cells from their outward boundary facets; the
// surface blocks' cells as further facets.
RigidSurface surface_of(const BackgroundMesh& mesh, const std::vector<std::string>& blocks) {
  std::vector<std::string> solid;
  for (const auto& name : blocks)
    if (!is_surface_block(mesh, name)) solid.push_back(name);
  // Nodes at the same place welded (model/WeldedBlocks.hpp: a tube's seam is no boundary).
  const auto welded = welded_blocks(mesh, solid);
  const auto facets = oriented_boundary_facets(welded, solid);
  RigidSurface s;
  s.dim = mesh.dimension;
  s.nodes_per_facet = mesh.dimension == 2 ? 2 : 3;
  s.reference_size = facets.reference_size;
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  for (auto n : facets.nodes)
    for (std::size_t k = 0; k < 3; ++k)
      s.corners.push_back(k < dim ? welded.coordinates[static_cast<std::size_t>(n) * dim + k]
                                  : 0.0);
  // The origin's simplex on each facet, signed by the facet's outward order: 2D (a x b) / 2 with
  // centroid (a + b) / 3 and int x_i x_j = A / 12 (a_i a_j + b_i b_j + s_i s_j), s = a + b; 3D
  // a . (b x c) / 6 with centroid (a + b + c) / 4 and int x_i x_j = V / 20 (a_i a_j + b_i b_j +
  // c_i c_j + s_i s_j), s = a + b + c (the simplex's exact moments, its fourth vertex the origin).
  const auto per = static_cast<std::size_t>(s.nodes_per_facet);
  std::array<double, 3> moment{};
  double second[3][3] = {};
  for (std::size_t f = 0; f < s.count(); ++f) {
    const double* a = &s.corners[3 * per * f];
    const double* b = a + 3;
    double v = 0;
    if (per == 2) {
      v = 0.5 * (a[0] * b[1] - a[1] * b[0]);
    } else {
      const double* c = b + 3;
      v = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0])) /
          6.0;
    }
    s.volume += v;
    double sum[3] = {0, 0, 0};
    for (std::size_t k = 0; k < 3; ++k) {
      for (std::size_t q = 0; q < per; ++q) sum[k] += a[3 * q + k];
      moment[k] += v * sum[k] / static_cast<double>(per + 1);
    }
    const double scale = v / (per == 2 ? 12.0 : 20.0);
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        double corners = 0;
        for (std::size_t q = 0; q < per; ++q) corners += a[3 * q + i] * a[3 * q + j];
        second[i][j] += scale * (corners + sum[i] * sum[j]);
      }
  }
  for (std::size_t k = 0; k < 3; ++k) s.centroid[k] = s.volume > 0 ? moment[k] / s.volume : 0.0;
  // About the centroid: S_c = S_o - V c c^T.
  const std::size_t pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  for (std::size_t p = 0; p < 6; ++p) {
    const auto [i, j] = pairs[p];
    s.second_moment[p] = second[i][j] - s.volume * s.centroid[i] * s.centroid[j];
  }
  const std::size_t solid_facets = s.count();
  add_surface_cells(mesh, blocks, s);
  if (!(s.volume > 0)) {  // a skin only: moments about the centroid of its area
    double area = 0;
    std::array<double, 3> sum{};
    for (std::size_t f = solid_facets; f < s.count(); ++f) {
      double x[3][3];
      for (std::size_t q = 0; q < 3; ++q)
        for (std::size_t k = 0; k < 3; ++k) x[q][k] = s.corners[9 * f + 3 * q + k];
      const double* a = x[0];
      double w[3];
      facet_normal(x, 3, w);  // twice the triangle's area, along its normal
      const double piece = 0.5 * std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      area += piece;
      for (std::size_t k = 0; k < 3; ++k) sum[k] += piece * (a[k] + a[3 + k] + a[6 + k]) / 3.0;
    }
    for (std::size_t k = 0; k < 3; ++k) s.centroid[k] = area > 0 ? sum[k] / area : 0.0;
  }
  return s;
}

}  // namespace

std::vector<std::string> rigid_block_names(const Scene& scene) {
  std::vector<std::string> names;
  for (const auto& body : scene.rigid_bodies)
    if (body.shape == "mesh") names.insert(names.end(), body.blocks.begin(), body.blocks.end());
  return names;
}

void extract_rigid_blocks(Scene& scene, BackgroundMesh& mesh) {
  std::vector<std::string> rigid;  // every mesh body's blocks
  for (std::size_t i = 0; i < scene.rigid_bodies.size(); ++i) {
    auto& body = scene.rigid_bodies[i];
    if (body.shape != "mesh") continue;
    for (const auto& name : body.blocks) {
      if (!mesh.find_block(name)) {
        std::string names;
        for (const auto& b : mesh.blocks) names += (names.empty() ? "" : ", ") + b.name;
        fail(scene, i, "the mesh has no element block '" + name + "'; expected one of: " + names);
      }
      for (const auto& part : scene.parts)
        if (std::find(part.blocks.begin(), part.blocks.end(), name) != part.blocks.end())
          fail(scene, i,
               "block '" + name + "' is also in part '" + part.name +
                   "'; expected a block of the body only (its nodes are no particles)");
      if (std::find(rigid.begin(), rigid.end(), name) != rigid.end())
        fail(scene, i, "block '" + name + "' is named by two rigid bodies");
      rigid.push_back(name);
    }
    auto surface = surface_of(mesh, body.blocks);
    const bool skin = std::all_of(body.blocks.begin(), body.blocks.end(),
                                  [&](const auto& name) { return is_surface_block(mesh, name); });
    if (!skin && !(surface.volume > 0))
      fail(scene, i, "the blocks' cells enclose no volume; expected cells of positive volume");
    if (!(surface.volume > 0) && !body.angular_velocity.empty())
      fail(scene, i,
           "a body of surface cells has no volume to take an inertia from; expected no "
           "angular_velocity, or solid cells");
    body.surface = std::make_shared<const RigidSurface>(std::move(surface));
  }
  if (rigid.empty()) return;
  // Nodes of the rigid blocks go; one also in a remaining block would be both.
  const auto is_rigid = [&rigid](const ElementBlock& b) {
    return std::find(rigid.begin(), rigid.end(), b.name) != rigid.end();
  };
  std::vector<char> in_rigid(mesh.node_count(), 0), in_other(mesh.node_count(), 0);
  for (const auto& b : mesh.blocks)
    for (auto n : b.connectivity)
      (is_rigid(b) ? in_rigid : in_other)[static_cast<std::size_t>(n)] = 1;
  for (std::size_t n = 0; n < mesh.node_count(); ++n)
    if (in_rigid[n] && in_other[n])
      for (std::size_t i = 0; i < scene.rigid_bodies.size(); ++i)
        if (scene.rigid_bodies[i].shape == "mesh")
          fail(scene, i,
               "the rigid blocks share node " + std::to_string(n + 1) +
                   " with the parts' blocks; expected a body with nodes of its own");
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  std::vector<LocalIndex> new_index(mesh.node_count(), -1);
  std::vector<double> coordinates;
  LocalIndex next = 0;
  for (std::size_t n = 0; n < mesh.node_count(); ++n) {
    if (in_rigid[n]) continue;
    new_index[n] = next++;
    coordinates.insert(coordinates.end(), mesh.coordinates.begin() + static_cast<long>(n * dim),
                       mesh.coordinates.begin() + static_cast<long>((n + 1) * dim));
  }
  // Global cells renumbered in the order of the remaining blocks (-1: a rigid cell).
  std::vector<LocalIndex> new_cell;
  std::vector<ElementBlock> blocks;
  LocalIndex cells = 0;
  for (auto& b : mesh.blocks) {
    const bool drop = is_rigid(b);
    for (std::size_t c = 0; c < b.cell_count(); ++c) new_cell.push_back(drop ? -1 : cells++);
    if (drop) continue;
    for (auto& n : b.connectivity) n = new_index[static_cast<std::size_t>(n)];
    blocks.push_back(std::move(b));
  }
  for (auto& set : mesh.node_sets) {
    std::vector<LocalIndex> kept;
    for (auto n : set.nodes)
      if (new_index[static_cast<std::size_t>(n)] >= 0)
        kept.push_back(new_index[static_cast<std::size_t>(n)]);
    set.nodes = std::move(kept);
  }
  for (auto& set : mesh.side_sets) {
    SideSet kept{set.name, set.id, {}, {}};
    for (std::size_t k = 0; k < set.cells.size(); ++k) {
      const auto c = new_cell[static_cast<std::size_t>(set.cells[k])];
      if (c < 0) continue;
      kept.cells.push_back(c);
      kept.sides.push_back(set.sides[k]);
    }
    set = std::move(kept);
  }
  mesh.coordinates = std::move(coordinates);
  mesh.blocks = std::move(blocks);
}

}  // namespace efg
