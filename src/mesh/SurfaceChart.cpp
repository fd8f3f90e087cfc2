#include "mesh/SurfaceChart.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Errors.hpp"

namespace efg {
namespace {

using V3 = std::array<double, 3>;

V3 minus(const double* a, const double* b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V3 cross3(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot3(const V3& a, const V3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V3 unit(V3 a) {
  const double l = std::sqrt(dot3(a, a));
  for (auto& v : a) v /= l;
  return a;
}

/// Calls f(cell, corner a, b, c) for the triangles of every cell (a quad as (0 1 2), (0 2 3)).
template <class F>
void for_each_triangle(const BackgroundMesh& mesh, F&& f) {
  std::size_t cell = 0;
  for (const auto& block : mesh.blocks) {
    const auto n = static_cast<std::size_t>(cell_node_count(block.type));
    for (std::size_t c = 0; c < block.cell_count(); ++c, ++cell) {
      const auto* k = &block.connectivity[c * n];
      f(cell, block, k[0], k[1], k[2]);
      if (n == 4) f(cell, block, k[0], k[2], k[3]);
    }
  }
}

}  // namespace

bool is_surface_mesh(const BackgroundMesh& mesh) {
  if (mesh.dimension != 3 || mesh.blocks.empty()) return false;
  for (const auto& block : mesh.blocks)
    if (!is_surface_cell(block.type)) return false;
  return true;
}

std::array<double, 3> triangle_normal(const double* a, const double* b, const double* c) {
  return cross3(minus(b, a), minus(c, a));
}

SurfaceProjection projection_from(const V3& normal_sum, const V3& origin) {
  SurfaceProjection p;
  p.normal = unit(normal_sum);
  p.origin = origin;
  // x along the global x axis projected, unless that is within 25 degrees of the normal
  V3 axis = std::abs(p.normal[0]) < std::cos(25.0 * M_PI / 180.0) ? V3{1, 0, 0} : V3{0, 1, 0};
  const double along = dot3(axis, p.normal);
  for (std::size_t k = 0; k < 3; ++k) axis[k] -= along * p.normal[k];
  p.e1 = unit(axis);
  p.e2 = cross3(p.normal, p.e1);
  return p;
}

SurfaceProjection surface_projection(const BackgroundMesh& mesh) {
  if (!mesh.surface.empty()) return mesh.chart_plane;
  const auto& x = mesh.coordinates;
  V3 normal{}, origin{};
  for_each_triangle(
      mesh, [&](std::size_t, const ElementBlock&, LocalIndex a, LocalIndex b, LocalIndex c) {
        const auto n = triangle_normal(&x[3 * static_cast<std::size_t>(a)],
                                       &x[3 * static_cast<std::size_t>(b)],
                                       &x[3 * static_cast<std::size_t>(c)]);
        for (std::size_t k = 0; k < 3; ++k) normal[k] += n[k];  // twice the area-weighted normal
      });
  const std::size_t nodes = x.size() / 3;
  for (std::size_t i = 0; i < nodes; ++i)
    for (std::size_t k = 0; k < 3; ++k) origin[k] += x[3 * i + k] / static_cast<double>(nodes);
  return projection_from(normal, origin);
}

void check_chart_triangle(const SurfaceProjection& p, std::size_t cell, const std::string& block,
                          const double* a, const double* b, const double* c) {
  const auto n = triangle_normal(a, b, c);
  // A collapsed cell (coincident or collinear corners) has no normal to compare: say so, rather
  // than report the NaN angle as a turn of 0 degrees. Zero relative to the longest edge squared.
  double longest = 0;
  for (const auto& edge : {minus(b, a), minus(c, b), minus(a, c)})
    longest = std::max(longest, dot3(edge, edge));
  if (std::sqrt(dot3(n, n)) <= 1e-12 * longest) {
    std::ostringstream o;
    o.precision(6);
    o << "shell surface: cell " << cell + 1 << " (block '" << block
      << "') is collapsed: its corners";
    for (const double* corner : {a, b, c})
      o << (corner == a ? " (" : ", (") << corner[0] << ", " << corner[1] << ", " << corner[2]
        << ")";
    o << " enclose zero area (coincident or collinear nodes); expected cells of positive area";
    throw InputError(o.str());
  }
  const double cosine = dot3(n, p.normal) / std::sqrt(dot3(n, n));
  if (cosine > std::cos(80.0 * M_PI / 180.0)) return;
  const auto shown = [](double v) { return std::abs(v) < 1e-12 ? 0.0 : v; };  // no -1e-17
  std::ostringstream o;
  o.precision(4);
  o << "shell surface: cell " << cell + 1 << " (block '" << block << "') turns its normal by "
    << std::acos(std::max(-1.0, std::min(1.0, cosine))) * 180 / M_PI
    << " degrees from the surface's mean normal (" << shown(p.normal[0]) << ", "
    << shown(p.normal[1]) << ", " << shown(p.normal[2])
    << "); the chart projects the surface onto the plane normal to it and needs every cell "
       "within 80 degrees (cells oriented alike, no fold): split the surface into parts "
       "that are, or give it as a 2D mesh with parts[].shell.reference";
  throw InputError(o.str());
}

std::string surface_chart_summary(const BackgroundMesh& mesh, bool given_chart) {
  double least = 1e300, most = 0;
  const auto& X = mesh.surface;
  const auto& c = mesh.coordinates;
  for_each_triangle(
      mesh, [&](std::size_t, const ElementBlock&, LocalIndex a, LocalIndex b, LocalIndex d) {
        const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b),
                   k = static_cast<std::size_t>(d);
        const auto n = cross3(minus(&X[3 * j], &X[3 * i]), minus(&X[3 * k], &X[3 * i]));
        const double chart = std::abs((c[2 * j] - c[2 * i]) * (c[2 * k + 1] - c[2 * i + 1]) -
                                      (c[2 * k] - c[2 * i]) * (c[2 * j + 1] - c[2 * i + 1]));
        const double ratio = std::sqrt(dot3(n, n)) / chart;
        least = std::min(least, ratio);
        most = std::max(most, ratio);
      });
  std::ostringstream o;
  o.precision(3);
  o << "shell surface read in 3D (" << mesh.node_count() << " nodes), charted ";
  if (given_chart) {
    o << "by mesh.chart";
  } else {
    const auto p = surface_projection(mesh);
    const auto shown = [](double v) { return std::abs(v) < 1e-12 ? 0.0 : v; };
    o << "by projection onto the plane normal to (" << shown(p.normal[0]) << ", "
      << shown(p.normal[1]) << ", " << shown(p.normal[2]) << ")";
  }
  o << ": surface area per chart area " << least << " to " << most;
  return o.str();
}

std::array<double, 2> chart_coordinates(const SurfaceProjection& p, const double* X) {
  const V3 d = minus(X, p.origin.data());
  return {dot3(d, p.e1), dot3(d, p.e2)};
}

void chart_surface_mesh(BackgroundMesh& mesh, const SurfaceChartMap& chart) {
  const auto p = surface_projection(mesh);
  auto map = chart;
  if (!map) {  // the projection, once every cell is checked against it
    const double* x = mesh.coordinates.data();
    for_each_triangle(mesh, [&](std::size_t cell, const ElementBlock& block, LocalIndex a,
                                LocalIndex b, LocalIndex c) {
      check_chart_triangle(p, cell, block.name, x + 3 * static_cast<std::size_t>(a),
                           x + 3 * static_cast<std::size_t>(b),
                           x + 3 * static_cast<std::size_t>(c));
    });
    map = [p](const double* X, double* c) {
      const auto xy = chart_coordinates(p, X);
      c[0] = xy[0];
      c[1] = xy[1];
    };
  }
  const std::size_t nodes = mesh.node_count();
  mesh.surface = mesh.coordinates;
  mesh.chart_plane = p;
  std::vector<double> coordinates(2 * nodes);
  for (std::size_t i = 0; i < nodes; ++i) map(&mesh.surface[3 * i], &coordinates[2 * i]);
  mesh.coordinates = std::move(coordinates);
  mesh.dimension = 2;
}

}  // namespace efg
