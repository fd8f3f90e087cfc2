#include "discretization/SmoothingFacets.hpp"

#include "discretization/CellSides.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>

namespace efg {
namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class Points>
Vec average(const Points& pts) {
  Vec c{0, 0, 0};
  for (const auto& p : pts)
    for (int d = 0; d < 3; ++d) c[static_cast<std::size_t>(d)] += p[static_cast<std::size_t>(d)];
  for (auto& v : c) v /= static_cast<double>(pts.size());
  return c;
}
// A braced list of points, without the heap (some 60 averages per cell).
Vec average(std::initializer_list<Vec> pts) {
  return average<std::initializer_list<Vec>>(pts);
}
// The points x[k] for k in `which`, summed in that order (as average), without a copy.
Vec average_at(const std::vector<Vec>& x, const std::vector<int>& which) {
  Vec c{0, 0, 0};
  for (int k : which)
    for (std::size_t d = 0; d < 3; ++d) c[d] += x[static_cast<std::size_t>(k)][d];
  for (auto& v : c) v /= static_cast<double>(which.size());
  return c;
}

// One triangle's point: its centroid (t0 + t1 + t2) / 3, exact for linear functions, with its
// vector area (t1 - t0) x (t2 - t0) / 2 as the weighted normal.
SmoothingPoint triangle_point(const Vec& t0, const Vec& t1, const Vec& t2) {
  const Vec n = cross(sub(t1, t0), sub(t2, t0));
  SmoothingPoint s;
  for (std::size_t d = 0; d < 3; ++d) {
    s.x[d] = (t0[d] + t1[d] + t2[d]) / 3.0;
    s.weighted_normal[d] = 0.5 * n[d];
  }
  return s;
}

// The split rule of a quadrilateral facet p0..p3: 4 triangles about its vertex average.
std::array<SmoothingPoint, 4> split_triangles(const std::array<Vec, 4>& p) {
  const Vec c = average({p[0], p[1], p[2], p[3]});
  std::array<SmoothingPoint, 4> t;
  for (std::size_t i = 0; i < 4; ++i) t[i] = triangle_point(c, p[i], p[(i + 1) % 4]);
  return t;
}

// The facets inside a cell of one type, one per cell edge (a, e), a < e ascending, with the
// sides that border it (3D: two; 2D: the edge is a side), in the order smoothing_points has
// always emitted them. Built once per block instead of once per cell.
struct CellFacets {
  struct Edge {
    int a = 0, e = 0;
    std::vector<int> sides;
  };
  std::vector<std::vector<int>> side_nodes;
  std::vector<Edge> edges;
};

CellFacets cell_facets(CellType type) {
  CellFacets f;
  const bool two_d = cell_dimension(type) == 2;
  std::map<std::pair<int, int>, std::vector<int>> edge_sides;
  for (int s = 0; s < cell_side_count(type); ++s) {
    f.side_nodes.push_back(cell_side_nodes(type, s));
    const auto& sn = f.side_nodes.back();
    for (std::size_t i = 0; i < sn.size(); ++i) {
      const int a = sn[i], e = sn[(i + 1) % sn.size()];
      if (two_d && i + 1 == sn.size()) break;  // a 2D side is one edge
      edge_sides[{std::min(a, e), std::max(a, e)}].push_back(s);
    }
  }
  for (const auto& [edge, sides] : edge_sides) f.edges.push_back({edge.first, edge.second, sides});
  return f;
}

class Emitter {
 public:
  Emitter(int dim, std::vector<SmoothingPoint>& out) : dim_(dim), out_(out) {}

  // A 2D segment p -> q whose normal (dy, -dx) points out of `plus`: 2 Gauss points, or its
  // midpoint alone (exact for linear functions) when `one_point`.
  void segment(const Vec& p, const Vec& q, LocalIndex plus, LocalIndex minus,
               bool one_point = false) {
    const double g = 0.5 / std::sqrt(3.0);
    const Vec n = {q[1] - p[1], -(q[0] - p[0]), 0.0};
    const int count = one_point ? 1 : 2;
    const double at[2] = {one_point ? 0.5 : 0.5 - g, 0.5 + g};
    for (int i = 0; i < count; ++i) {
      SmoothingPoint s;
      for (std::size_t d = 0; d < 2; ++d) {
        s.x[d] = p[d] + at[i] * (q[d] - p[d]);
        s.weighted_normal[d] = n[d] / count;
      }
      s.plus = plus;
      s.minus = minus;
      out_.push_back(s);
    }
  }

  // A 3D quadrilateral facet p0..p3 (possibly warped) whose right-hand normal points out of
  // `plus`: four triangles about the vertex average, one centroid point each; or, when
  // `merge_flat`, one point if the facet is flat (flat_facet_point), else two.
  void quad(const std::array<Vec, 4>& p, LocalIndex plus, LocalIndex minus,
            bool merge_flat = false) {
    auto emit = [&](SmoothingPoint s) {
      s.plus = plus;
      s.minus = minus;
      out_.push_back(s);
    };
    if (merge_flat) {
      SmoothingPoint one;
      if (flat_facet_point(p, one)) return emit(one);
      // Warped: the two triangles on the diagonal p0 p2, one centroid point each. They span the
      // facet's boundary loop as the 4 triangles about the centre do; the surface between two
      // domains may be any surface on that loop, since both domains take these same points and
      // V_L comes from them as well, so linear consistency holds with half the points. (p0 and
      // p2 are the edge midpoint and the cell centroid, or the node and the side centre: the
      // same diagonal for the cells on either side of a shared side.)
      emit(triangle_point(p[0], p[1], p[2]));
      emit(triangle_point(p[0], p[2], p[3]));
      return;
    }
    for (const auto& t : split_triangles(p)) emit(t);
  }

  int dim() const { return dim_; }

 private:
  int dim_;
  std::vector<SmoothingPoint>& out_;
};

// The boundary facets of one side, split among its nodes (see side_smoothing_points); with
// `one_point`, one point per flat facet, two per warped one (SCNI subcells' sides inside the
// part).
void emit_side(Emitter& emit, const std::vector<Vec>& x, const std::vector<LocalIndex>& node,
               bool one_point = false) {
  auto mid = [&](std::size_t a, std::size_t b) { return average({x[a], x[b]}); };
  if (emit.dim() == 2) {
    const Vec m = mid(0, 1);
    emit.segment(x[0], m, node[0], -1, one_point);
    emit.segment(m, x[1], node[1], -1, one_point);
    return;
  }
  const Vec sc = average(x);
  const std::size_t m = x.size();
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t prev = (i + m - 1) % m, next = (i + 1) % m;
    emit.quad({x[i], mid(i, next), sc, mid(prev, i)}, node[i], -1, one_point);
  }
}

}  // namespace

std::vector<SmoothingPoint> smoothing_points(const BackgroundMesh& mesh,
                                             const std::vector<std::string>& blocks,
                                             const std::vector<char>& node_wanted,
                                             std::vector<std::size_t>* cell_of_point,
                                             bool every_side, SmoothingQuadrature inside) {
  const bool one_point = inside == SmoothingQuadrature::centroid;
  std::vector<SmoothingPoint> out;
  std::size_t global_first = 0;
  Emitter emit(mesh.dimension, out);
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  // The part's boundary sides, (global cell, side) ascending: the only sides emitted, or with
  // every_side the ones that keep the split rule (tractions and Nitsche terms share it).
  const bool need_outer = !every_side || one_point;
  const auto outer = need_outer ? outer_sides(mesh, cells_of_blocks(mesh, blocks))
                                : std::vector<std::pair<std::size_t, int>>{};
  for (const auto& b : mesh.blocks) {
    const std::size_t first_cell = global_first;
    global_first += b.cell_count();
    if (std::find(blocks.begin(), blocks.end(), b.name) == blocks.end()) continue;
    const int npc = cell_node_count(b.type);
    const int nsides = cell_side_count(b.type);
    const auto facets = cell_facets(b.type);
    std::vector<Vec> x(static_cast<std::size_t>(npc), Vec{0, 0, 0});
    for (std::size_t c = 0; c < b.cell_count(); ++c) {
      const LocalIndex* node = &b.connectivity[c * static_cast<std::size_t>(npc)];
      if (!node_wanted.empty()) {
        bool any = false;
        for (int a = 0; a < npc; ++a) any = any || node_wanted[static_cast<std::size_t>(node[a])];
        if (!any) continue;
      }
      for (int a = 0; a < npc; ++a)
        for (std::size_t d = 0; d < dim; ++d)
          x[static_cast<std::size_t>(a)][d] =
              mesh.coordinates[static_cast<std::size_t>(node[a]) * dim + d];
      const Vec centroid = average(x);
      auto mid = [&](int a, int bnode) {
        return average({x[static_cast<std::size_t>(a)], x[static_cast<std::size_t>(bnode)]});
      };

      // Interior facets, one per cell edge (a, b): they separate the domains of a and b.
      // In 2D the edges are the sides; in 3D each edge borders two sides.
      for (const auto& [a, e, sides] : facets.edges) {
        const Vec m = mid(a, e);
        const Vec toward = sub(x[static_cast<std::size_t>(e)], x[static_cast<std::size_t>(a)]);
        if (emit.dim() == 2) {
          // Segment from the edge midpoint to the centroid; orient its normal from a to e.
          const Vec n = {centroid[1] - m[1], -(centroid[0] - m[0]), 0.0};
          if (dot(n, toward) >= 0)
            emit.segment(m, centroid, node[a], node[e], one_point);
          else
            emit.segment(centroid, m, node[a], node[e], one_point);
        } else {
          const auto& side = facets.side_nodes;
          std::array<Vec, 4> q = {m, average_at(x, side[static_cast<std::size_t>(sides[0])]),
                                  centroid,
                                  average_at(x, side[static_cast<std::size_t>(sides[1])])};
          const Vec n = cross(sub(q[2], q[0]), sub(q[3], q[1]));
          if (dot(n, toward) < 0) std::swap(q[1], q[3]);
          emit.quad(q, node[a], node[e], one_point);
        }
      }

      // Sides on the part's boundary, split among their nodes; the side tables order nodes so
      // that the right-hand normal points out of the cell.
      for (int s = 0; s < nsides; ++s) {
        const auto& sn = facets.side_nodes[static_cast<std::size_t>(s)];
        const bool on_boundary =
            need_outer &&
            std::binary_search(outer.begin(), outer.end(), std::make_pair(first_cell + c, s));
        if (!every_side && !on_boundary) continue;
        std::vector<Vec> side_x;
        std::vector<LocalIndex> side_nodes;
        for (int k : sn) {
          side_x.push_back(x[static_cast<std::size_t>(k)]);
          side_nodes.push_back(node[k]);
        }
        emit_side(emit, side_x, side_nodes, one_point && !on_boundary);
      }
      if (cell_of_point) cell_of_point->resize(out.size(), first_cell + c);
    }
  }
  return out;
}

bool flat_facet_point(const std::array<Vec, 4>& p, SmoothingPoint& out) {
  // The split rule's 4 triangles: vector areas n_i / 2, centroids g_i. A flat facet's n_i are
  // parallel to their sum N, so the facet's integral of a linear f n, sum_i f(g_i) n_i / 2,
  // equals f(x*) N / 2 at x* = sum_i (n_i . N / N . N) g_i.
  const auto t = split_triangles(p);
  Vec total{0, 0, 0};  // N / 2
  for (const auto& ti : t)
    for (std::size_t d = 0; d < 3; ++d) total[d] += ti.weighted_normal[d];
  const double nn = dot(total, total);
  if (!(nn > 0.0)) return false;
  constexpr double flat = 1e-10;  // sine of the largest angle between a triangle and the facet
  for (const auto& ti : t) {
    const Vec off = cross(ti.weighted_normal, total);
    if (dot(off, off) > flat * flat * dot(ti.weighted_normal, ti.weighted_normal) * nn)
      return false;
  }
  out.x = {0, 0, 0};
  for (const auto& ti : t) {
    const double share = dot(ti.weighted_normal, total) / nn;
    for (std::size_t d = 0; d < 3; ++d) out.x[d] += share * ti.x[d];
  }
  out.weighted_normal = total;
  return true;
}

std::vector<std::pair<std::size_t, int>> boundary_sides(const BackgroundMesh& mesh,
                                                        const std::vector<std::string>& blocks) {
  return outer_sides(mesh, cells_of_blocks(mesh, blocks));
}

std::vector<SmoothingPoint> side_smoothing_points(const std::vector<std::array<double, 3>>& side_x,
                                                  const std::vector<LocalIndex>& side_nodes,
                                                  int dim) {
  std::vector<SmoothingPoint> out;
  Emitter emit(dim, out);
  emit_side(emit, side_x, side_nodes);
  return out;
}

std::vector<double> smoothing_domain_volumes(const std::vector<SmoothingPoint>& points,
                                             std::size_t node_count, int dim) {
  std::vector<double> volume(node_count, 0.0);
  for (const auto& p : points) {
    double xn = 0;
    for (std::size_t d = 0; d < static_cast<std::size_t>(dim); ++d)
      xn += p.x[d] * p.weighted_normal[d];
    volume[static_cast<std::size_t>(p.plus)] += xn / dim;
    if (p.minus >= 0) volume[static_cast<std::size_t>(p.minus)] -= xn / dim;
  }
  return volume;
}

SmoothingQuadrature facet_rule(const SectionSpec& section, int dimension) {
  if (section.smoothing_quadrature != SmoothingQuadrature::automatic)
    return section.smoothing_quadrature;
  const bool centroid =
      dimension == 3 && section.basis == Basis::linear && section.integration == Integration::scni;
  return centroid ? SmoothingQuadrature::centroid : SmoothingQuadrature::split;
}

}  // namespace efg
