#include "discretization/IntegrationPoints.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "core/Errors.hpp"
#include "discretization/CellOwner.hpp"
#include "discretization/ScniGradients.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "discretization/SmoothingFacets.hpp"
#include "mesh/GaussRules.hpp"

namespace efg {
namespace {

// Particles whose SCNI rows are built together (see build_scni).
constexpr std::size_t kScniBatch = 2048;

// Appends the rows of `rows` (a batch's) to `table`.
void append_rows(const CsrTable& rows, CsrTable& table) {
  const auto base = table.particles.size();
  table.particles.insert(table.particles.end(), rows.particles.begin(), rows.particles.end());
  table.values.insert(table.values.end(), rows.values.begin(), rows.values.end());
  for (std::size_t l = 1; l < rows.offsets.size(); ++l)
    table.offsets.push_back(base + rows.offsets[l]);
}

// Points at particle positions (SCNI and nodal): the owned particles of the cloud.
void add_nodal_points(const ParticleCloud& cloud, IntegrationPoints& ip) {
  const auto dim = static_cast<std::size_t>(cloud.dimension);
  for (std::size_t i = 0; i < cloud.owned_count; ++i) {
    ip.x.insert(ip.x.end(), cloud.x(i), cloud.x(i) + dim);
    ip.node.push_back(cloud.mesh_node[i]);
  }
}

PointLabel node_label(const IntegrationPoints& ip, const char* what) {
  return [&ip, what](std::size_t p) {
    return std::string(what) + " at particle " + std::to_string(ip.node[p] + 1);
  };
}

void build_nodal(const BackgroundMesh& mesh, const ParticleCloud& cloud, IntegrationPoints& ip) {
  (void)mesh;
  add_nodal_points(cloud, ip);
  ip.weight.assign(cloud.volume.begin(),
                   cloud.volume.begin() + static_cast<std::ptrdiff_t>(cloud.owned_count));
  const auto v = evaluate_shape_functions(cloud, ip.x.data(), ip.node.size(), true,
                                          node_label(ip, "nodal integration point"));
  ip.values = table_from(v, false, cloud.dimension);
  ip.gradients = table_from(v, true, cloud.dimension);
}

// The smoothing points of each batch of kScniBatch owned particles (those next to a particle of
// the batch on either side), in ascending point order, as compressed rows: one pass over the
// points instead of one per batch (quadratic in the particle count: 5 % of a 131k-particle
// setup, measured).
struct BatchPoints {
  std::vector<std::size_t> offsets;
  std::vector<std::uint32_t> entries;  // half the size_t's: 24 million points at 1e6 particles
};
BatchPoints points_by_batch(const ParticleCloud& cloud, const std::vector<SmoothingPoint>& points,
                            std::size_t node_count) {
  std::vector<std::int64_t> batch_of(node_count, -1);
  for (std::size_t l = 0; l < cloud.owned_count; ++l)
    batch_of[static_cast<std::size_t>(cloud.mesh_node[l])] =
        static_cast<std::int64_t>(l / kScniBatch);
  const auto batches = (cloud.owned_count + kScniBatch - 1) / kScniBatch;
  if (points.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("SCNI: more than 2^32 smoothing points on one rank");
  BatchPoints out;
  out.offsets.assign(batches + 1, 0);
  auto for_each_batch = [&](const SmoothingPoint& p, auto&& act) {
    const auto a = p.plus < 0 ? -1 : batch_of[static_cast<std::size_t>(p.plus)];
    const auto b = p.minus < 0 ? -1 : batch_of[static_cast<std::size_t>(p.minus)];
    if (a >= 0) act(static_cast<std::size_t>(a));
    if (b >= 0 && b != a) act(static_cast<std::size_t>(b));
  };
  for (const auto& p : points) for_each_batch(p, [&](std::size_t b) { ++out.offsets[b + 1]; });
  for (std::size_t b = 0; b < batches; ++b) out.offsets[b + 1] += out.offsets[b];
  out.entries.resize(out.offsets[batches]);
  auto next = out.offsets;
  for (std::size_t i = 0; i < points.size(); ++i)
    for_each_batch(points[i],
                   [&](std::size_t b) { out.entries[next[b]++] = static_cast<std::uint32_t>(i); });
  return out;
}

// SCNI over the pieces of the nodal domains (integration scni_subcells): every background cell
// cuts the domain of each of its nodes into one piece (2D quad: the node, two side midpoints and
// the centroid), and each piece is a smoothing domain and an integration point of its own, at
// the particle's position with the piece's volume. The pieces' boundaries are the SCNI facets
// plus the cells' sides (every side, split among its nodes: inside a nodal domain they separate
// two pieces instead of cancelling). Each piece satisfies the divergence identity, so linear
// fields stay exact (the patch test); with 2^dim times the points, the smoothed strain follows
// the field inside the nodal domain, which plain SCNI averages away: on perturbed particles its
// energy error then converges at the rate of exact integration (docs/discretization.md). The
// smoothing over several cells per element of the smoothed FEM (Liu, Dai & Nguyen 2007,
// Comput. Mech. 39) is the same idea for finite elements.
void build_scni_subcells(const BackgroundMesh& mesh, const PartSpec& part,
                         const ParticleCloud& cloud, const std::vector<int>& owner, int rank,
                         IntegrationPoints& ip) {
  const auto dim = static_cast<std::size_t>(cloud.dimension);
  std::vector<char> owned(mesh.node_count(), 0);
  for (std::size_t n = 0; n < owned.size(); ++n) owned[n] = owner[n] == rank;
  std::vector<std::size_t> cell_of_point;
  const auto points = smoothing_points(mesh, part.blocks, owned, &cell_of_point, true,
                                       facet_rule(part.section, cloud.dimension));
  const auto index = index_cloud(cloud);  // searched batch after batch
  const auto at_particles = evaluate_shape_functions(
      index, cloud, cloud.position.data(), cloud.owned_count, false, [&](std::size_t p) {
        return "SCNI node at particle " +
               std::to_string(mesh.global_node(static_cast<std::size_t>(cloud.mesh_node[p])) + 1);
      });
  ip.values.width = 1;
  ip.values.offsets.assign(1, 0);
  ip.gradients.width = cloud.dimension;
  ip.gradients.offsets.assign(1, 0);
  std::vector<LocalIndex> batch_row(mesh.node_count(), -1);
  const auto batch_points = points_by_batch(cloud, points, mesh.node_count());
  double extent = 0;  // the part's size, for matching coincident points
  for (std::size_t d = 0; d < dim; ++d) {
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (std::size_t i = 0; i < cloud.owned_count; ++i) {
      lo = std::min(lo, cloud.x(i)[d]);
      hi = std::max(hi, cloud.x(i)[d]);
    }
    extent = std::max(extent, hi - lo);
  }
  const double match_grid = 1e-10 * std::max(extent, std::numeric_limits<double>::min());
  for (std::size_t first = 0, b = 0; first < cloud.owned_count; first += kScniBatch, ++b) {
    const std::size_t rows = std::min(kScniBatch, cloud.owned_count - first);
    for (std::size_t l = 0; l < rows; ++l)
      batch_row[static_cast<std::size_t>(cloud.mesh_node[first + l])] = static_cast<LocalIndex>(l);
    // The batch's pieces, (particle row, cell), ascending: their index is the domain id.
    using Piece = std::pair<LocalIndex, std::size_t>;
    std::vector<Piece> pieces;
    auto row_of = [&](LocalIndex node) {
      return node < 0 ? LocalIndex{-1} : batch_row[static_cast<std::size_t>(node)];
    };
    for (auto k = batch_points.offsets[b]; k < batch_points.offsets[b + 1]; ++k) {
      const auto p = batch_points.entries[k];
      for (const auto node : {points[p].plus, points[p].minus})
        if (row_of(node) >= 0) pieces.push_back({row_of(node), cell_of_point[p]});
    }
    std::sort(pieces.begin(), pieces.end());
    pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
    auto piece_of = [&](LocalIndex node, std::size_t cell) {
      if (row_of(node) < 0) return LocalIndex{-1};
      const auto at = std::lower_bound(pieces.begin(), pieces.end(), Piece{row_of(node), cell});
      return static_cast<LocalIndex>(at - pieces.begin());
    };
    std::vector<SmoothingPoint> batch;
    std::vector<double> coords, volume(pieces.size(), 0.0);
    for (auto k = batch_points.offsets[b]; k < batch_points.offsets[b + 1]; ++k) {
      const auto p = batch_points.entries[k];
      SmoothingPoint q = points[p];
      q.plus = piece_of(points[p].plus, cell_of_point[p]);
      q.minus = piece_of(points[p].minus, cell_of_point[p]);
      double xn = 0;  // V = 1/dim sum x . n w over the piece's boundary
      for (std::size_t d = 0; d < dim; ++d) xn += q.x[d] * q.weighted_normal[d];
      if (q.plus >= 0) volume[static_cast<std::size_t>(q.plus)] += xn / static_cast<double>(dim);
      if (q.minus >= 0) volume[static_cast<std::size_t>(q.minus)] -= xn / static_cast<double>(dim);
      batch.push_back(q);
      coords.insert(coords.end(), q.x.begin(), q.x.begin() + static_cast<std::ptrdiff_t>(dim));
    }
    for (std::size_t k = 0; k < pieces.size(); ++k)
      if (!(volume[k] > 0))
        throw NumericalError(
            "SCNI subcells: the piece of background cell " +
            std::to_string(mesh.global_cell(pieces[k].second) + 1) + " around particle " +
            std::to_string(
                mesh.global_node(static_cast<std::size_t>(
                    cloud.mesh_node[first + static_cast<std::size_t>(pieces[k].first)])) +
                1) +
            " has volume " + std::to_string(volume[k]) + " <= 0 (an inverted cell?)");
    // A cell side inside the part is emitted by both its cells (for each one's pieces): its
    // points are evaluated once (a third of the points in 2D and 3D). Coincident points differ
    // in the last bits (computed from either cell's node order): matched on a grid 1e-10 of
    // the part's size, which separates distinct points (a fraction of a spacing apart).
    std::vector<std::size_t> evaluated;  // per point: its row among the unique ones
    std::vector<std::size_t> first_of;   // per unique point: the first point there
    std::vector<double> unique_coords;
    {
      std::map<std::array<long long, 3>, std::size_t> seen;
      for (std::size_t k = 0; k < batch.size(); ++k) {
        std::array<long long, 3> key{0, 0, 0};
        for (std::size_t d = 0; d < dim; ++d)
          key[d] = std::llround(coords[k * dim + d] / match_grid);
        const auto [at, fresh] = seen.emplace(key, first_of.size());
        if (fresh) {
          first_of.push_back(k);
          unique_coords.insert(unique_coords.end(),
                               coords.begin() + static_cast<std::ptrdiff_t>(k * dim),
                               coords.begin() + static_cast<std::ptrdiff_t>((k + 1) * dim));
        }
        evaluated.push_back(at->second);
      }
    }
    const auto phi = select_rows(
        evaluate_shape_functions(
            index, cloud, unique_coords.data(), first_of.size(), false,
            [&](std::size_t u) {
              return "SCNI subcell smoothing point of background cell " +
                     std::to_string(cell_of_point[batch_points.entries[batch_points.offsets[b] +
                                                                       first_of[u]]] +
                                    1);
            }),
        evaluated, cloud.dimension);
    std::vector<LocalIndex> identity(pieces.size());
    for (std::size_t k = 0; k < pieces.size(); ++k) identity[k] = static_cast<LocalIndex>(k);
    const auto rows_here =
        smoothed_gradients(cloud, batch, phi, identity, volume, index.cloud.global_id);
    append_rows(rows_here, ip.gradients);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const auto i = first + static_cast<std::size_t>(pieces[k].first);
      ip.x.insert(ip.x.end(), cloud.x(i), cloud.x(i) + dim);
      ip.node.push_back(-1);                    // not the particle's own point ...
      ip.domain.push_back(cloud.mesh_node[i]);  // ... but a piece of its domain
      ip.weight.push_back(volume[k]);
      const auto from = at_particles.neighbors.offsets[i],
                 to = at_particles.neighbors.offsets[i + 1];
      ip.values.particles.insert(
          ip.values.particles.end(),
          at_particles.neighbors.particles.begin() + static_cast<std::ptrdiff_t>(from),
          at_particles.neighbors.particles.begin() + static_cast<std::ptrdiff_t>(to));
      ip.values.values.insert(ip.values.values.end(),
                              at_particles.phi.begin() + static_cast<std::ptrdiff_t>(from),
                              at_particles.phi.begin() + static_cast<std::ptrdiff_t>(to));
      ip.values.offsets.push_back(ip.values.particles.size());
    }
    for (std::size_t l = 0; l < rows; ++l)
      batch_row[static_cast<std::size_t>(cloud.mesh_node[first + l])] = -1;
  }
}

void build_scni(const BackgroundMesh& mesh, const PartSpec& part, const ParticleCloud& cloud,
                const std::vector<int>& owner, int rank, IntegrationPoints& ip) {
  const auto dim = static_cast<std::size_t>(cloud.dimension);
  add_nodal_points(cloud, ip);
  // The cloud's search bins and device copy, built once for the nodes and every batch of
  // smoothing points (per batch they cost O(particles) each: quadratic in the part's size).
  const auto index = index_cloud(cloud);
  const auto values = evaluate_shape_functions(index, cloud, ip.x.data(), ip.node.size(), false,
                                               node_label(ip, "SCNI node"));
  ip.values = table_from(values, false, cloud.dimension);

  std::vector<char> owned(mesh.node_count(), 0);
  for (std::size_t n = 0; n < owned.size(); ++n) owned[n] = owner[n] == rank;
  const auto points = smoothing_points(mesh, part.blocks, owned, nullptr, false,
                                       facet_rule(part.section, cloud.dimension));
  const auto volume = smoothing_domain_volumes(points, mesh.node_count(), cloud.dimension);
  // The shape functions at the smoothing points (some 24-48 points per particle in 3D, each
  // with its whole neighbour list) are about ten times the rows of B~ they make: evaluated for a
  // batch of particles at a time (the points on their domains' boundaries, those shared by two
  // batches twice), the rows appended batch after batch. Each row sums the same points in the
  // same order as in one pass, so the rows are identical. Memory: docs/discretization.md.
  std::vector<LocalIndex> row_index(mesh.node_count(), -1);
  ip.gradients.width = cloud.dimension;
  ip.gradients.offsets.assign(1, 0);
  const auto batch_points = points_by_batch(cloud, points, mesh.node_count());
  for (std::size_t first = 0, b = 0; first < cloud.owned_count; first += kScniBatch, ++b) {
    const std::size_t rows = std::min(kScniBatch, cloud.owned_count - first);
    for (std::size_t l = 0; l < rows; ++l)
      row_index[static_cast<std::size_t>(cloud.mesh_node[first + l])] = static_cast<LocalIndex>(l);
    std::vector<SmoothingPoint> batch;
    std::vector<double> coords;
    for (auto k = batch_points.offsets[b]; k < batch_points.offsets[b + 1]; ++k) {
      const auto& p = points[batch_points.entries[k]];
      batch.push_back(p);
      coords.insert(coords.end(), p.x.begin(), p.x.begin() + static_cast<std::ptrdiff_t>(dim));
    }
    const auto phi = evaluate_shape_functions(
        index, cloud, coords.data(), batch.size(), false, [&](std::size_t p) {
          return "SCNI smoothing point next to particle " + std::to_string(batch[p].plus + 1);
        });
    std::vector<double> row_volume(rows);
    for (std::size_t l = 0; l < rows; ++l)
      row_volume[l] = volume[static_cast<std::size_t>(cloud.mesh_node[first + l])];
    const auto rows_here =
        smoothed_gradients(cloud, batch, phi, row_index, row_volume, index.cloud.global_id);
    append_rows(rows_here, ip.gradients);
    for (std::size_t l = 0; l < rows; ++l)
      row_index[static_cast<std::size_t>(cloud.mesh_node[first + l])] = -1;
  }
  ip.gradients.offsets.shrink_to_fit();  // appended batch by batch: no spare capacity kept
  ip.gradients.particles.shrink_to_fit();
  ip.gradients.values.shrink_to_fit();
  for (std::size_t l = 0; l < cloud.owned_count; ++l)
    ip.weight.push_back(volume[static_cast<std::size_t>(cloud.mesh_node[l])]);
}

void build_gauss(const BackgroundMesh& mesh, const PartSpec& part, const ParticleCloud& cloud,
                 const std::vector<int>& owner, int rank, IntegrationPoints& ip) {
  const auto dim = static_cast<std::size_t>(cloud.dimension);
  std::vector<std::size_t> cell_of_point;
  std::size_t global_cell = 0;
  for (const auto& b : mesh.blocks) {
    const bool in_part =
        std::find(part.blocks.begin(), part.blocks.end(), b.name) != part.blocks.end();
    const auto npc = static_cast<std::size_t>(cell_node_count(b.type));
    const auto rule = reference_rule(b.type, part.section.gauss_order);
    std::vector<double> x(npc * dim);
    for (std::size_t c = 0; c < b.cell_count(); ++c, ++global_cell) {
      if (!in_part) continue;
      const auto* node = &b.connectivity[c * npc];
      if (cell_owner(node, npc, owner) != rank) continue;
      for (std::size_t a = 0; a < npc; ++a)
        for (std::size_t d = 0; d < dim; ++d)
          x[a * dim + d] = mesh.coordinates[static_cast<std::size_t>(node[a]) * dim + d];
      for (std::size_t q = 0; q < rule.weight.size(); ++q) {
        double point[3];
        const double det = map_to_cell(b.type, x.data(), &rule.xi[q * dim], point);
        ip.x.insert(ip.x.end(), point, point + dim);
        ip.weight.push_back(rule.weight[q] * det);
        ip.node.push_back(-1);
        cell_of_point.push_back(global_cell);
      }
    }
  }
  const auto v = evaluate_shape_functions(
      cloud, ip.x.data(), ip.weight.size(), true,
      [&](std::size_t p) { return "Gauss point of cell " + std::to_string(cell_of_point[p] + 1); });
  ip.values = table_from(v, false, cloud.dimension);
  ip.gradients = table_from(v, true, cloud.dimension);
}

}  // namespace

CsrTable table_from(const ShapeFunctionValues& v, bool gradients, int dim) {
  CsrTable t;
  t.width = gradients ? dim : 1;
  t.offsets = v.neighbors.offsets;
  t.particles = v.neighbors.particles;
  t.values = gradients ? v.grad : v.phi;
  return t;
}

IntegrationPoints integrate_part(const BackgroundMesh& mesh, const PartSpec& part,
                                 const ParticleCloud& cloud, const std::vector<int>& owner,
                                 int rank) {
  IntegrationPoints ip;
  ip.dimension = cloud.dimension;
  ip.scheme = part.section.integration;
  switch (part.section.integration) {
    case Integration::scni:
      build_scni(mesh, part, cloud, owner, rank, ip);
      break;
    case Integration::scni_subcells:
      build_scni_subcells(mesh, part, cloud, owner, rank, ip);
      break;
    case Integration::nodal:
      build_nodal(mesh, cloud, ip);
      break;
    case Integration::gauss:
      build_gauss(mesh, part, cloud, owner, rank, ip);
      break;
  }
  return ip;
}

double ghost_radius(const BackgroundMesh& mesh, const PartSpec& part, double group_diameter) {
  const auto a = support_sizes(mesh, part.blocks, part.section);
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  double reach = 0;
  for (std::size_t n = 0; n < mesh.node_count(); ++n) {
    double r2 = 0;
    for (std::size_t d = 0; d < dim; ++d) r2 += a[n * dim + d] * a[n * dim + d];
    reach =
        std::max(reach, part.section.support == SupportShape::sphere ? a[n * dim] : std::sqrt(r2));
  }
  double diameter = 0;
  for (const auto& b : mesh.blocks) {
    if (std::find(part.blocks.begin(), part.blocks.end(), b.name) == part.blocks.end()) continue;
    const auto npc = static_cast<std::size_t>(cell_node_count(b.type));
    for (std::size_t c = 0; c < b.cell_count(); ++c)
      for (std::size_t i = 0; i < npc; ++i)
        for (std::size_t j = i + 1; j < npc; ++j) {
          double d2 = 0;
          for (std::size_t d = 0; d < dim; ++d) {
            const double dx =
                mesh.coordinates[static_cast<std::size_t>(b.connectivity[c * npc + i]) * dim + d] -
                mesh.coordinates[static_cast<std::size_t>(b.connectivity[c * npc + j]) * dim + d];
            d2 += dx * dx;
          }
          diameter = std::max(diameter, std::sqrt(d2));
        }
  }
  // Rows of ghost particles are assembled here and added on their owners, whose matrix columns
  // must hold every particle coupled to them: two supports apart (P and G share a point q when
  // |q - X_P| < a_P and |q - X_G| < a_G). Hence 2 x reach, plus a cell (or a group of cells
  // with one pressure) for the points.
  return 2 * reach + std::max(diameter, group_diameter);
}

}  // namespace efg
